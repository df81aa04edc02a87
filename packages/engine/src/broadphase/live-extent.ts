import type { BodyStore } from '../store/body-store.js';
import { TypeCode } from '../store/body-types.js';
import { COORD_PAD } from './fat-bounds.js';

/**
 * The live bodies of a step: their slots in ascending order, the box around their centres and
 * their smallest and largest radius. Grids are laid over this extent, so they need no world box.
 */
export class LiveExtent {
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

  measure(bodies: BodyStore): void {
    if (this.slots.length < bodies.liveCount) this.slots = new Int32Array(Math.max(bodies.liveCount, 2 * this.slots.length));
    const { x, y, radius, type, slotCount } = bodies;
    const slots = this.slots;
    let minX = Infinity;
    let minY = Infinity;
    let maxX = -Infinity;
    let maxY = -Infinity;
    let minR = Infinity;
    let maxR = 0;
    let n = 0;
    for (let i = 0; i < slotCount; i++) {
      if (type[i] === TypeCode.free) continue;
      const px = x[i];
      const py = y[i];
      const r = radius[i];
      if (px < minX) minX = px;
      if (px > maxX) maxX = px;
      if (py < minY) minY = py;
      if (py > maxY) maxY = py;
      if (r < minR) minR = r;
      if (r > maxR) maxR = r;
      slots[n++] = i;
    }
    this.count = n;
    this.minX = minX;
    this.minY = minY;
    this.maxX = maxX;
    this.maxY = maxY;
    this.minRadius = minR;
    this.maxRadius = maxR;
    this.coordPad = Math.max(Math.abs(minX), Math.abs(maxX), Math.abs(minY), Math.abs(maxY)) * COORD_PAD;
  }

  memoryBytes(): number {
    return this.slots.byteLength;
  }
}
