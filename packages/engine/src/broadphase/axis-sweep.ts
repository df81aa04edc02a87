import type { BodyStore } from '../store/body-store.js';
import type { PairSink } from '../store/pair-sink.js';
import { TypeCode } from '../store/body-types.js';
import { sortByKey } from '../util/sort-by-key.js';
import { grownCapacity } from '../util/grow.js';
import { paddedRadius } from './fat-bounds.js';

/**
 * One axis of sweep-and-prune: live bodies sorted by the low end of their interval on an axis,
 * with the high ends alongside. Shared by `sap` (one axis) and `sap-xy` (both axes).
 */
export class AxisSweep {
  count = 0;
  /** Sorted interval starts (centre - padded radius, see fat-bounds.ts). */
  low = new Float64Array(0);
  /** Interval ends, in the same order as `low`. */
  high = new Float64Array(0);
  /** Slot of each sorted entry. */
  slot = new Int32Array(0);

  private scratchKeys = new Float64Array(0);
  private scratchSlots = new Int32Array(0);

  /** Sorts the live bodies' intervals along x (`axis` 0) or y (`axis` 1). */
  build(bodies: BodyStore, axis: 0 | 1): void {
    const centre = axis === 0 ? bodies.x : bodies.y;
    const { radius, type, slotCount } = bodies;
    this.ensure(bodies.proxyCount);
    const apart = bodies.staticsApart;
    const low = this.low;
    const slot = this.slot;
    let n = 0;
    for (let i = 0; i < slotCount; i++) {
      if (type[i] === TypeCode.free || (apart && type[i] === TypeCode.static)) continue;
      low[n] = centre[i] - paddedRadius(radius[i], centre[i]);
      slot[n++] = i;
    }
    this.count = n;
    sortByKey(low, slot, n, this.scratchKeys, this.scratchSlots);
    const high = this.high;
    for (let k = 0; k < n; k++) {
      const s = slot[k];
      high[k] = centre[s] + paddedRadius(radius[s], centre[s]);
    }
  }

  memoryBytes(): number {
    return this.low.byteLength * 2 + this.high.byteLength + this.slot.byteLength * 2;
  }

  private ensure(n: number): void {
    if (this.low.length >= n) return;
    const capacity = grownCapacity(this.low.length, n);
    this.low = new Float64Array(capacity);
    this.high = new Float64Array(capacity);
    this.slot = new Int32Array(capacity);
    this.scratchKeys = new Float64Array(capacity);
    this.scratchSlots = new Int32Array(capacity);
  }
}

/**
 * Sweeps intervals sorted by start: pushes each pair whose intervals overlap (closed, so tangent
 * circles count), skipping pairs of two sleepers when `asleep` is given. Returns pairs examined.
 */
export function sweepSorted(
  low: Float64Array,
  high: Float64Array,
  slot: Int32Array,
  count: number,
  out: PairSink,
  asleep: Uint8Array | null,
): number {
  let examined = 0;
  for (let k = 0; k < count; k++) {
    const end = high[k];
    const a = slot[k];
    const aSleeps = asleep !== null && asleep[a] === 1;
    let m = k + 1;
    for (; m < count && low[m] <= end; m++) {
      if (aSleeps && asleep[slot[m]] === 1) continue;
      out.push(a, slot[m]);
    }
    examined += m - k - 1;
  }
  return examined;
}
