import type { BroadPhase } from './broadphase.js';
import type { BodyStore } from '../store/body-store.js';
import type { PairSink } from '../store/pair-sink.js';
import { TypeCode } from '../store/body-types.js';
import { sortByKey } from '../util/sort-by-key.js';
import { grownCapacity } from '../util/grow.js';
import { paddedRadius } from './fat-bounds.js';
import { sweepSorted } from './axis-sweep.js';

/**
 * Persistent sweep-and-prune on x (report 3.1.4.1; Tracy, Buss & Woods 2009). The sorted order of
 * interval starts is kept between steps. Bodies move little per step, so insertion sort restores
 * the order in close to linear time, and a sleeping body's entry does not move at all. Pairs of
 * two sleepers are skipped in the sweep.
 *
 * When the body set changes the order is rebuilt from scratch, and when insertion sort has to do
 * too much work (a teleport, a reset) it gives up and a merge sort finishes the job, so the worst
 * step is O(n log n), never O(n^2).
 */
export class PersistentSapBroadPhase implements BroadPhase {
  readonly name = 'sap-persistent';
  private low = new Float64Array(0);
  private high = new Float64Array(0);
  private slot = new Int32Array(0);
  private scratchKeys = new Float64Array(0);
  private scratchSlots = new Int32Array(0);
  private count = 0;
  private builtFor = -1;
  /** Element moves made by the last insertion sort: how much order it had to restore. */
  lastShifts = 0;

  findPairs(bodies: BodyStore, out: PairSink): number {
    if (this.builtFor !== bodies.membershipVersion) this.rebuild(bodies);
    const { low, high, slot, count } = this;
    const { x, radius } = bodies;
    for (let k = 0; k < count; k++) {
      const s = slot[k];
      low[k] = x[s] - paddedRadius(radius[s], x[s]);
    }
    this.restoreOrder();
    for (let k = 0; k < count; k++) {
      const s = slot[k];
      high[k] = x[s] + paddedRadius(radius[s], x[s]);
    }
    return sweepSorted(low, high, slot, count, out, bodies.sleepingCount > 0 ? bodies.asleep : null);
  }

  memoryBytes(): number {
    return this.low.byteLength * 3 + this.slot.byteLength * 2;
  }

  private rebuild(bodies: BodyStore): void {
    const n = bodies.proxyCount;
    if (this.low.length < n) {
      const capacity = grownCapacity(this.low.length, n);
      this.low = new Float64Array(capacity);
      this.high = new Float64Array(capacity);
      this.slot = new Int32Array(capacity);
      this.scratchKeys = new Float64Array(capacity);
      this.scratchSlots = new Int32Array(capacity);
    }
    let k = 0;
    for (let i = 0; i < bodies.slotCount; i++) if (bodies.isProxyType(bodies.type[i])) this.slot[k++] = i;
    this.count = k;
    // Keys are refreshed on every step; start from "unsorted" so the first restore sorts fully.
    this.low.fill(0, 0, k);
    this.builtFor = bodies.membershipVersion;
  }

  /** Insertion sort with a work budget; past it, a merge sort from the current state. */
  private restoreOrder(): void {
    const { low, slot, count } = this;
    const budget = 8 * count + 64;
    let shifts = 0;
    for (let i = 1; i < count; i++) {
      const key = low[i];
      if (low[i - 1] <= key) continue;
      const s = slot[i];
      let j = i - 1;
      while (j >= 0 && low[j] > key) {
        low[j + 1] = low[j];
        slot[j + 1] = slot[j];
        j--;
        shifts++;
      }
      low[j + 1] = key;
      slot[j + 1] = s;
      if (shifts > budget) {
        sortByKey(low, slot, count, this.scratchKeys, this.scratchSlots);
        break;
      }
    }
    this.lastShifts = shifts;
  }
}
