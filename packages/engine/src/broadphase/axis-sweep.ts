import type { BodyStore } from '../store/body-store.js';
import type { PairSink } from '../store/pair-sink.js';
import { TypeCode } from '../store/body-types.js';
import { sortByKey } from '../util/sort-by-key.js';
import { grownCapacity } from '../util/grow.js';
import { paddedRadius } from './fat-bounds.js';

/** Intervals on one axis sorted by their low end, with the high ends and the bodies' slots alongside. */
export class SortedIntervals {
  count = 0;
  /** Sorted interval starts (centre - padded radius, see fat-bounds.ts). */
  low = new Float64Array(0);
  /** Interval ends, in the same order as `low`. */
  high = new Float64Array(0);
  /** Slot of each sorted entry. */
  slot = new Int32Array(0);
  private scratchKeys = new Float64Array(0);
  private scratchSlots = new Int32Array(0);

  ensure(n: number): void {
    if (this.low.length >= n) return;
    const capacity = grownCapacity(this.low.length, n);
    this.low = new Float64Array(capacity);
    this.high = new Float64Array(capacity);
    this.slot = new Int32Array(capacity);
    this.scratchKeys = new Float64Array(capacity);
    this.scratchSlots = new Int32Array(capacity);
  }

  /** Fills `low` from the centres, sorts, then fills `high`. */
  sortFrom(centre: Float64Array, radius: Float64Array): void {
    const { low, high, slot, count } = this;
    for (let k = 0; k < count; k++) low[k] = centre[slot[k]] - paddedRadius(radius[slot[k]], centre[slot[k]]);
    sortByKey(low, slot, count, this.scratchKeys, this.scratchSlots);
    this.fillHigh(centre, radius);
  }

  /**
   * Refreshes `low` from the centres and restores the order kept from the last call by insertion
   * sort, which is close to linear when bodies moved little; past a budget of element moves a
   * merge sort finishes the job, so the worst case is O(n log n). Returns the moves made.
   */
  resortFrom(centre: Float64Array, radius: Float64Array): number {
    const { low, slot, count } = this;
    for (let k = 0; k < count; k++) low[k] = centre[slot[k]] - paddedRadius(radius[slot[k]], centre[slot[k]]);
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
    this.fillHigh(centre, radius);
    return shifts;
  }

  memoryBytes(): number {
    return this.low.byteLength * 2 + this.high.byteLength + this.slot.byteLength * 2;
  }

  private fillHigh(centre: Float64Array, radius: Float64Array): void {
    const { high, slot, count } = this;
    for (let k = 0; k < count; k++) high[k] = centre[slot[k]] + paddedRadius(radius[slot[k]], centre[slot[k]]);
  }
}

/**
 * The bodies a sweep covers, split in two: moving ones (dynamic and kinematic) and static ones.
 * Statics are sorted apart so that the sweep pairs them with moving bodies only: a wall of
 * static circles whose intervals all overlap costs nothing, where sweeping it with the rest
 * examined every static-static pair, none of which can ever collide.
 */
export class SweepSets {
  readonly moving = new SortedIntervals();
  readonly fixed = new SortedIntervals();

  /** Lists the broad-phase's bodies into the two sets, in slot order (unsorted). */
  gather(bodies: BodyStore): void {
    const { type, slotCount } = bodies;
    const n = bodies.proxyCount;
    this.moving.ensure(n);
    this.fixed.ensure(bodies.staticsApart ? 0 : Math.min(n, bodies.staticCount));
    const apart = bodies.staticsApart;
    const moving = this.moving.slot;
    const fixed = this.fixed.slot;
    let m = 0;
    let f = 0;
    for (let i = 0; i < slotCount; i++) {
      const t = type[i];
      if (t === TypeCode.free) continue;
      if (t === TypeCode.static) {
        if (!apart) fixed[f++] = i;
      } else moving[m++] = i;
    }
    this.moving.count = m;
    this.fixed.count = f;
  }

  memoryBytes(): number {
    return this.moving.memoryBytes() + this.fixed.memoryBytes();
  }
}

/**
 * The other axis's intervals by slot, for `sap-xy`: a pair the sweep finds is kept only if these
 * overlap too (closed intervals, as on the swept axis).
 */
export interface CrossAxis {
  low: Float64Array;
  high: Float64Array;
}

/**
 * Sweeps two sets of intervals sorted by start and pushes each overlapping pair (closed
 * intervals, so tangent circles count) of two moving bodies, or a moving body and a static one,
 * skipping pairs of two sleepers when `asleep` is given and pairs whose `cross` intervals do not
 * overlap. Returns the pairs examined: pairs overlapping on the swept axis, static-static ones
 * never among them.
 */
export function sweepSets(sets: SweepSets, out: PairSink, asleep: Uint8Array | null, cross: CrossAxis | null): number {
  const { low, high, slot, count } = sets.moving;
  const fixed = sets.fixed;
  let examined = 0;
  for (let k = 0; k < count; k++) {
    const end = high[k];
    const a = slot[k];
    const aSleeps = asleep !== null && asleep[a] === 1;
    let m = k + 1;
    for (; m < count && low[m] <= end; m++) {
      const b = slot[m];
      if (aSleeps && asleep[b] === 1) continue;
      if (cross !== null && (cross.low[b] > cross.high[a] || cross.low[a] > cross.high[b])) continue;
      out.push(a, b);
    }
    examined += m - k - 1;
  }
  if (fixed.count === 0) return examined;
  // A moving and a static interval overlap when the later-starting one starts within the other:
  // statics starting at or after a moving body's start, then moving bodies starting strictly
  // after a static's, so that each pair is found exactly once.
  const fLow = fixed.low;
  const fHigh = fixed.high;
  const fSlot = fixed.slot;
  const fCount = fixed.count;
  let first = 0;
  for (let k = 0; k < count; k++) {
    const start = low[k];
    const end = high[k];
    const a = slot[k];
    while (first < fCount && fLow[first] < start) first++;
    let m = first;
    for (; m < fCount && fLow[m] <= end; m++) {
      const b = fSlot[m];
      if (cross !== null && (cross.low[b] > cross.high[a] || cross.low[a] > cross.high[b])) continue;
      out.push(a, b);
    }
    examined += m - first;
  }
  first = 0;
  for (let k = 0; k < fCount; k++) {
    const start = fLow[k];
    const end = fHigh[k];
    const a = fSlot[k];
    while (first < count && low[first] <= start) first++;
    let m = first;
    for (; m < count && low[m] <= end; m++) {
      const b = slot[m];
      if (cross !== null && (cross.low[b] > cross.high[a] || cross.low[a] > cross.high[b])) continue;
      out.push(a, b);
    }
    examined += m - first;
  }
  return examined;
}

/** Index of the first of the `count` sorted values above `value` (or at or above it, `inclusive`). */
function firstAbove(values: Float64Array, count: number, value: number, inclusive: boolean): number {
  let lo = 0;
  let hi = count;
  while (lo < hi) {
    const mid = (lo + hi) >>> 1;
    if (inclusive ? values[mid] < value : values[mid] <= value) lo = mid + 1;
    else hi = mid;
  }
  return lo;
}

/**
 * The pairs `sweepSets` would examine on these sorted sets, counted by binary search in
 * O(n log n) without visiting them: how `sap-xy` picks the axis to sweep.
 */
export function overlapCount(sets: SweepSets): number {
  const { low, high, count } = sets.moving;
  const fixed = sets.fixed;
  let total = 0;
  for (let k = 0; k < count; k++) {
    total += firstAbove(low, count, high[k], false) - k - 1;
    if (fixed.count > 0) total += firstAbove(fixed.low, fixed.count, high[k], false) - firstAbove(fixed.low, fixed.count, low[k], true);
  }
  for (let k = 0; k < fixed.count; k++) total += firstAbove(low, count, fixed.high[k], false) - firstAbove(low, count, fixed.low[k], false);
  return total;
}
