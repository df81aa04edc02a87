import type { BroadPhase } from './broadphase.js';
import type { BodyStore } from '../store/body-store.js';
import type { PairSink } from '../store/pair-sink.js';
import { AxisSweep } from './axis-sweep.js';
import { PairSet } from '../store/pair-set.js';

/**
 * Sweep-and-prune on both axes (report 5.11.1): the x sweep's pairs go into an integer pair set,
 * and the y sweep keeps only the pairs already in it. Fewer false positives than `sap` for the
 * price of a second sort and the set.
 */
export class SapXyBroadPhase implements BroadPhase {
  readonly name = 'sap-xy';
  private readonly sweepX = new AxisSweep();
  private readonly sweepY = new AxisSweep();
  private readonly overlapsOnX = new PairSet();

  findPairs(bodies: BodyStore, out: PairSink): number {
    const set = this.overlapsOnX;
    set.clear();
    let examined = 0;
    this.sweepX.build(bodies, 0);
    {
      const { low, high, slot, count } = this.sweepX;
      for (let k = 0; k < count; k++) {
        const end = high[k];
        const a = slot[k];
        let m = k + 1;
        for (; m < count && low[m] <= end; m++) set.add(a, slot[m]);
        examined += m - k - 1;
      }
    }
    this.sweepY.build(bodies, 1);
    {
      const { low, high, slot, count } = this.sweepY;
      for (let k = 0; k < count; k++) {
        const end = high[k];
        const a = slot[k];
        let m = k + 1;
        for (; m < count && low[m] <= end; m++) {
          const b = slot[m];
          if (set.has(a, b)) out.push(a, b);
        }
        examined += m - k - 1;
      }
    }
    return examined;
  }

  memoryBytes(): number {
    return this.sweepX.memoryBytes() + this.sweepY.memoryBytes() + this.overlapsOnX.memoryBytes();
  }
}
