import type { BroadPhase } from './broadphase.js';
import type { BodyStore } from '../store/body-store.js';
import type { PairSink } from '../store/pair-sink.js';
import { AxisSweep } from './axis-sweep.js';

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
    const { low, high, slot, count } = sweep;
    let examined = 0;
    for (let k = 0; k < count; k++) {
      const end = high[k];
      const a = slot[k];
      let m = k + 1;
      for (; m < count && low[m] <= end; m++) out.push(a, slot[m]);
      examined += m - k - 1;
    }
    return examined;
  }

  memoryBytes(): number {
    return this.sweep.memoryBytes();
  }
}
