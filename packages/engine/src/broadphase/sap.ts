import type { BroadPhase } from './broadphase.js';
import type { BodyStore } from '../store/body-store.js';
import type { PairSink } from '../store/pair-sink.js';
import { AxisSweep, sweepSorted } from './axis-sweep.js';

/**
 * Sweep-and-prune on x (report 3.1.4.1, 5.11.1): sort intervals by their start, then for each
 * interval walk forward while the next start is within its end. Intervals are closed, so
 * tangent circles are reported.
 */
export class SapBroadPhase implements BroadPhase {
  readonly name = 'sap';
  private readonly sweep = new AxisSweep();

  findPairs(bodies: BodyStore, out: PairSink): number {
    const sweep = this.sweep;
    sweep.build(bodies, 0);
    return sweepSorted(sweep.low, sweep.high, sweep.slot, sweep.count, out, bodies.sleepingCount > 0 ? bodies.asleep : null);
  }

  memoryBytes(): number {
    return this.sweep.memoryBytes();
  }
}
