import type { BodyStore } from '../store/body-store.js';
import { TypeCode } from '../store/body-types.js';
import { COORD_PAD, RADIUS_PAD } from './fat-bounds.js';
import { ExtentFitter, cellsOver, type Extent } from './extent-fit.js';

/**
 * The live bodies of a step: their slots in ascending order, the box around their centres and
 * their smallest and largest radius. Grids are laid over this extent, so they need no world box.
 */
export class LiveExtent implements Extent {
  /** Live slots in ascending order; filled only when the slots have holes (see `dense`). */
  slots = new Int32Array(0);
  count = 0;
  minX = 0;
  minY = 0;
  maxX = 0;
  maxY = 0;
  minRadius = 0;
  maxRadius = 0;
  /** Absolute padding for boxes far from the origin (see fat-bounds.ts). */
  coordPad = 0;

  /** True when every slot below slotCount is live: then slot k is live body k, and `slots` is unused. */
  dense = false;
  /** The extent is the world's box, not measured from the bodies (see measure). */
  private boxExtent = false;
  private readonly fitter = new ExtentFitter();

  /**
   * Call after the boundary stage, when a boxed world's bodies are all inside its box. Measures
   * the bodies the broad-phase covers (BodyStore.isProxyType), or with `everyBody` every live one,
   * statics included, as queries need.
   */
  measure(bodies: BodyStore, everyBody = false): void {
    const { x, y, radius, type, slotCount } = bodies;
    const apart = bodies.staticsApart && !everyBody;
    const count = everyBody ? bodies.liveCount : bodies.proxyCount;
    let minX = Infinity;
    let minY = Infinity;
    let maxX = -Infinity;
    let maxY = -Infinity;
    let minRadius = Infinity;
    let maxRadius = 0;
    // With statics apart, the store's radius range leaves them out: measure every body here.
    const measured = everyBody && bodies.staticsApart;
    this.dense = count === slotCount && !measured;
    const box = bodies.box;
    this.boxExtent = this.dense && box !== null;
    if (this.dense && box) {
      minX = 0;
      minY = 0;
      maxX = box.width;
      maxY = box.height;
    } else if (this.dense) {
      for (let i = 0; i < slotCount; i++) {
        const px = x[i];
        const py = y[i];
        if (px < minX) minX = px;
        if (px > maxX) maxX = px;
        if (py < minY) minY = py;
        if (py > maxY) maxY = py;
      }
    } else {
      if (this.slots.length < count) this.slots = new Int32Array(Math.max(count, 2 * this.slots.length));
      const slots = this.slots;
      let n = 0;
      for (let i = 0; i < slotCount; i++) {
        const t = type[i];
        if (t === TypeCode.free || (apart && t === TypeCode.static)) continue;
        const px = x[i];
        const py = y[i];
        if (px < minX) minX = px;
        if (px > maxX) maxX = px;
        if (py < minY) minY = py;
        if (py > maxY) maxY = py;
        if (measured) {
          const r = radius[i];
          if (r < minRadius) minRadius = r;
          if (r > maxRadius) maxRadius = r;
        }
        slots[n++] = i;
      }
    }
    this.count = count;
    this.minX = minX;
    this.minY = minY;
    this.maxX = maxX;
    this.maxY = maxY;
    this.minRadius = measured ? minRadius : bodies.minRadius();
    this.maxRadius = measured ? maxRadius : bodies.maxRadius();
    this.coordPad = Math.max(Math.abs(minX), Math.abs(maxX), Math.abs(minY), Math.abs(maxY)) * COORD_PAD;
  }

  /**
   * Narrows the extent to where the bodies are when a grid of `cellSize` over it would need more
   * than `budget` cells (see ExtentFitter): the bodies' own box rather than the world's (a crowd
   * in a corner of a huge box), then all but 1/256 of them (a few far away). Call after measure,
   * whose box it narrows in place: read that box first where it is needed (Queries does).
   */
  fit(bodies: BodyStore, cellSize: number, budget: number): void {
    if (this.count < 2 || cellsOver(this.minX, this.minY, this.maxX, this.maxY, cellSize) <= budget) return;
    const slots = this.dense ? null : this.slots;
    if (this.boxExtent) {
      this.fitter.measure(bodies.x, bodies.y, slots, 0, this.count, this);
      this.boxExtent = false;
    }
    this.fitter.fit(bodies.x, bodies.y, slots, 0, this.count, cellSize, budget, this);
  }

  /**
   * The smallest conservative cell for circles up to `radius`: their diameter, padded as
   * fat-bounds.ts explains, so that touching circles are never more than one cell apart.
   */
  cellSizeFor(radius: number): number {
    return 2 * radius * (1 + RADIUS_PAD) + this.coordPad;
  }

  memoryBytes(): number {
    return this.slots.byteLength;
  }
}
