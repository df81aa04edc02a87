import type { BroadPhase } from './broadphase.js';
import type { BodyStore } from '../store/body-store.js';
import type { PairSink } from '../store/pair-sink.js';
import { SweepSets, sweepSets, overlapCount, type CrossAxis, type SortedIntervals } from './axis-sweep.js';
import { grownCapacity } from '../util/grow.js';

/**
 * Sweep-and-prune on both axes (report 5.11.1): pairs whose intervals overlap on x and on y.
 * Both axes are sorted, the overlaps on each counted by binary search, and only the axis with
 * fewer is swept, each pair it finds tested against the other axis's intervals. Fewer false
 * positives than `sap`, for the price of a second sort; memory linear in the bodies, where
 * keeping the x overlaps in a set to match against the y sweep's needed a slot per x overlap
 * (10,000 bodies on one vertical line: 50 million), and a column of bodies is swept along y.
 */
export class SapXyBroadPhase implements BroadPhase {
  readonly name = 'sap-xy';
  private readonly setsX = new SweepSets();
  private readonly setsY = new SweepSets();
  private readonly cross: CrossAxis = { low: new Float64Array(0), high: new Float64Array(0) };
  /** The axis swept in the last step (0 = x). */
  lastAxis: 0 | 1 = 0;

  findPairs(bodies: BodyStore, out: PairSink): number {
    const { setsX, setsY } = this;
    setsX.gather(bodies);
    setsX.moving.sortFrom(bodies.x, bodies.radius);
    setsX.fixed.sortFrom(bodies.x, bodies.radius);
    setsY.gather(bodies);
    setsY.moving.sortFrom(bodies.y, bodies.radius);
    setsY.fixed.sortFrom(bodies.y, bodies.radius);
    const alongY = overlapCount(setsY) < overlapCount(setsX);
    this.lastAxis = alongY ? 1 : 0;
    const swept = alongY ? setsY : setsX;
    const other = alongY ? setsX : setsY;
    const cross = this.cross;
    if (cross.low.length < bodies.slotCount) {
      const capacity = grownCapacity(cross.low.length, bodies.slotCount);
      cross.low = new Float64Array(capacity);
      cross.high = new Float64Array(capacity);
    }
    scatter(other.moving, cross);
    scatter(other.fixed, cross);
    return sweepSets(swept, out, bodies.sleepingCount > 0 ? bodies.asleep : null, cross);
  }

  memoryBytes(): number {
    return this.setsX.memoryBytes() + this.setsY.memoryBytes() + this.cross.low.byteLength * 2;
  }
}

function scatter(set: SortedIntervals, cross: CrossAxis): void {
  for (let k = 0; k < set.count; k++) {
    cross.low[set.slot[k]] = set.low[k];
    cross.high[set.slot[k]] = set.high[k];
  }
}
