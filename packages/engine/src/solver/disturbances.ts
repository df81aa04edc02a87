import type { BodyStore } from '../store/body-store.js';
import { SlotList, type Queries } from '../query/queries.js';
import { grow, grownCapacity } from '../util/grow.js';

/** Sleepers this far beyond touching (a fraction of the two radii) still count as touching. */
const TOUCH_MARGIN = 1e-3;

/**
 * Sleepers that a call may have taken support from. Sleep keeps no islands (see sleep.ts): a
 * sleeper wakes when a faster body touches it, so a body destroyed, moved, re-filtered or
 * re-typed under a sleeping pile used to leave the pile asleep in mid-air (found by an audit: a
 * stack of two asleep, its bottom body destroyed). Box2D wakes the bodies touching a body it
 * destroys; here each such call, while any body sleeps, notes the body's circle (setPosition its
 * old and its new one), and the next step first wakes every sleeper touching a noted circle
 * (within the contact slop, plus TOUCH_MARGIN for pairs left tangent). Worlds that make no such
 * call, or have no sleeper, pay nothing, and their bits are unchanged.
 */
export class Disturbances {
  /** x, y, radius per noted circle. */
  private circles = new Float64Array(3 * 8);
  private count = 0;
  private readonly found = new SlotList();
  private readonly box = new Float64Array(4);

  /** Notes body `slot`'s circle as it is now, if anything sleeps. */
  note(bodies: BodyStore, slot: number): void {
    this.noteCircle(bodies, bodies.x[slot], bodies.y[slot], bodies.radius[slot]);
  }

  /** Notes the circle at (x, y) of radius r, if anything sleeps. */
  noteCircle(bodies: BodyStore, x: number, y: number, r: number): void {
    if (bodies.sleepingCount === 0) return;
    if (3 * (this.count + 1) > this.circles.length) this.circles = grow(this.circles, grownCapacity(this.circles.length, 3 * (this.count + 1)));
    const at = 3 * this.count++;
    this.circles[at] = x;
    this.circles[at + 1] = y;
    this.circles[at + 2] = r;
  }

  /** Wakes the sleepers touching a noted circle, then forgets the circles. */
  wakeTouching(bodies: BodyStore, queries: Queries, geometryVersion: number, contactSlop: number): void {
    const noted = this.count;
    if (noted === 0) return;
    this.count = 0;
    if (bodies.sleepingCount === 0) return;
    const { x, y, radius, asleep } = bodies;
    const widest = bodies.maxRadius();
    for (let k = 0; k < noted; k++) {
      const cx = this.circles[3 * k];
      const cy = this.circles[3 * k + 1];
      const r = this.circles[3 * k + 2];
      const pad = (r + widest) * (1 + TOUCH_MARGIN) + contactSlop;
      const box = this.box;
      box[0] = cx - pad;
      box[1] = cy - pad;
      box[2] = cx + pad;
      box[3] = cy + pad;
      const found = queries.slotsInBox(geometryVersion, box, this.found);
      for (let f = 0; f < found.count; f++) {
        const s = found.slots[f];
        if (!asleep[s]) continue;
        const reach = (r + radius[s]) * (1 + TOUCH_MARGIN) + contactSlop;
        const dx = x[s] - cx;
        const dy = y[s] - cy;
        if (dx * dx + dy * dy <= reach * reach) bodies.wake(s);
      }
    }
  }
}
