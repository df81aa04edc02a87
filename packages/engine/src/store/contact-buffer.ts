import { grownCapacity, grow } from '../util/grow.js';
import { ContactSorter } from './contact-sorter.js';
import { bodyKernelEnabled } from './body-kernel.js';

/** Where the narrow-phase records touching pairs. */
export interface ContactSink {
  push(lo: number, hi: number): void;
  /** Pushes the pairs (pairs[p], pairs[p + 1]) for p = from, from + 2, ... below `to`. */
  pushPairs(pairs: Int32Array, from: number, to: number): void;
}

/**
 * Touching pairs found by the narrow-phase, as (lo, hi) slots with lo < hi.
 *
 * `sortCanonical` puts them in ascending (lo, hi) order. The solver resolves contacts
 * sequentially, so this order is what makes a step's result independent of the broad-phase that
 * found the pairs. Pairs are unique, so any correct sort gives the same order; which one runs is a
 * matter of cost. With many contacts per slot, two stable counting passes keyed by slot (by hi,
 * then by lo): O(slots + contacts). With few, as in sparse elastic scenes, byte-wise LSD radix
 * passes over the contacts alone: O(contacts x bytes), independent of the world's size.
 * Nothing is allocated once the scratch has grown. Where WebAssembly is available the same sorts
 * run there (ContactSorter), on copies of the pairs.
 */
export class ContactBuffer implements ContactSink {
  lo: Int32Array = new Int32Array(64);
  hi: Int32Array = new Int32Array(64);
  count = 0;
  /** The pair arrays live on shared memory, for the threads of a parallel step. */
  shared = false;
  /** Bumped whenever `lo` and `hi` are reallocated. */
  layoutVersion = 0;

  private scratchLo: Int32Array = new Int32Array(64);
  private scratchHi: Int32Array = new Int32Array(64);
  private counts = new Int32Array(64);
  private readonly buckets = new Int32Array(256);
  /** The pairs are in canonical order: nothing changed them since clear, sortCanonical or a merge. */
  private ordered = true;
  /** The WebAssembly sort: undefined until the first sort, null on the TypeScript path. */
  private sorter: ContactSorter | null | undefined = undefined;
  /** Whether kernels were enabled when this buffer was made (see setBodyKernelEnabled). */
  private readonly sorterWanted = bodyKernelEnabled();

  clear(): void {
    this.count = 0;
    this.ordered = true;
  }

  /** Moves the pair arrays onto shared memory (or back). */
  setShared(shared: boolean): void {
    if (shared === this.shared) return;
    this.shared = shared;
    this.lo = grow(this.lo, this.lo.length, shared);
    this.hi = grow(this.hi, this.hi.length, shared);
    this.layoutVersion++;
  }

  push(lo: number, hi: number): void {
    this.ordered = false;
    if (this.count === this.lo.length) this.growPairs(this.count + 1);
    this.lo[this.count] = lo;
    this.hi[this.count] = hi;
    this.count++;
  }

  pushPairs(pairs: Int32Array, from: number, to: number): void {
    if (to > from) this.ordered = false;
    const at = this.count;
    const count = (to - from) >> 1;
    if (at + count > this.lo.length) this.growPairs(at + count);
    const toLo = this.lo;
    const toHi = this.hi;
    for (let k = 0; k < count; k++) {
      toLo[at + k] = pairs[from + 2 * k];
      toHi[at + k] = pairs[from + 2 * k + 1];
    }
    this.count = at + count;
  }

  /**
   * Appends `count` pairs from other arrays (a worker thread's contacts). A loop, not
   * `set(subarray(...))`: a subarray is a new object, and this runs every parallel step.
   */
  append(lo: Int32Array, hi: Int32Array, count: number): void {
    if (count > 0) this.ordered = false;
    const at = this.count;
    if (at + count > this.lo.length) this.growPairs(at + count);
    const toLo = this.lo;
    const toHi = this.hi;
    for (let k = 0; k < count; k++) {
      toLo[at + k] = lo[k];
      toHi[at + k] = hi[k];
    }
    this.count = at + count;
  }

  memoryBytes(): number {
    return (this.lo.byteLength + this.scratchLo.byteLength) * 2 + this.counts.byteLength + (this.sorter?.memoryBytes() ?? 0);
  }

  /**
   * Adds `count` pairs that are in canonical order themselves (a parallel step's thread sorted its
   * list): merged in, from the back, when this buffer is in canonical order too, so that
   * sortCanonical then has nothing to do; appended otherwise.
   */
  mergeSorted(lo: Int32Array, hi: Int32Array, count: number): void {
    if (!this.ordered) return this.append(lo, hi, count);
    const total = this.count + count;
    if (total > this.lo.length) this.growPairs(total);
    const toLo = this.lo;
    const toHi = this.hi;
    let a = this.count - 1;
    let b = count - 1;
    for (let at = total - 1; b >= 0; at--) {
      // Pairs are unique, so the two never tie.
      if (a >= 0 && (toLo[a] > lo[b] || (toLo[a] === lo[b] && toHi[a] > hi[b]))) {
        toLo[at] = toLo[a];
        toHi[at] = toHi[a--];
      } else {
        toLo[at] = lo[b];
        toHi[at] = hi[b--];
      }
    }
    this.count = total;
  }

  sortCanonical(slotCount: number): void {
    if (this.ordered) return;
    this.ordered = true;
    if (this.count < 2) return;
    if (this.sorter === undefined) this.sorter = this.sorterWanted ? ContactSorter.create() : null;
    if (this.sorter) return this.sorter.sort(this.lo, this.hi, this.count, slotCount);
    if (this.counts.length < slotCount + 1) this.counts = new Int32Array(grownCapacity(this.counts.length, slotCount + 1));
    if (this.scratchLo.length < this.lo.length) {
      this.scratchLo = new Int32Array(this.lo.length);
      this.scratchHi = new Int32Array(this.lo.length);
    }
    if (this.count * 8 < slotCount) {
      this.radixSort(slotCount);
      return;
    }
    // Pass 1 by hi into scratch, pass 2 by lo back into the live arrays: LSD order gives (lo, hi).
    this.countingPass(this.hi, this.lo, this.hi, this.scratchLo, this.scratchHi, slotCount);
    this.countingPass(this.scratchLo, this.scratchLo, this.scratchHi, this.lo, this.hi, slotCount);
  }

  /** LSD radix by bytes: hi's bytes, then lo's, least significant first; ends in the live arrays. */
  private radixSort(slotCount: number): void {
    let bytes = 1;
    while (bytes < 4 && slotCount > 2 ** (8 * bytes)) bytes++;
    let srcLo = this.lo;
    let srcHi = this.hi;
    let dstLo = this.scratchLo;
    let dstHi = this.scratchHi;
    for (let pass = 0; pass < 2 * bytes; pass++) {
      const keyIsHi = pass < bytes;
      const shift = 8 * (keyIsHi ? pass : pass - bytes);
      this.radixPass(keyIsHi ? srcHi : srcLo, shift, srcLo, srcHi, dstLo, dstHi);
      const tl = srcLo;
      srcLo = dstLo;
      dstLo = tl;
      const th = srcHi;
      srcHi = dstHi;
      dstHi = th;
    }
    // An even number of passes always ends back in the live arrays.
  }

  private radixPass(key: Int32Array, shift: number, srcLo: Int32Array, srcHi: Int32Array, dstLo: Int32Array, dstHi: Int32Array): void {
    const buckets = this.buckets;
    const n = this.count;
    buckets.fill(0);
    for (let k = 0; k < n; k++) buckets[(key[k] >>> shift) & 255]++;
    for (let b = 0, sum = 0; b < 256; b++) {
      const c = buckets[b];
      buckets[b] = sum;
      sum += c;
    }
    for (let k = 0; k < n; k++) {
      const at = buckets[(key[k] >>> shift) & 255]++;
      dstLo[at] = srcLo[k];
      dstHi[at] = srcHi[k];
    }
  }

  private countingPass(
    key: Int32Array,
    srcLo: Int32Array,
    srcHi: Int32Array,
    dstLo: Int32Array,
    dstHi: Int32Array,
    slotCount: number,
  ): void {
    const counts = this.counts;
    const n = this.count;
    counts.fill(0, 0, slotCount + 1);
    for (let k = 0; k < n; k++) counts[key[k] + 1]++;
    for (let s = 0; s < slotCount; s++) counts[s + 1] += counts[s];
    for (let k = 0; k < n; k++) {
      const at = counts[key[k]]++;
      dstLo[at] = srcLo[k];
      dstHi[at] = srcHi[k];
    }
  }

  private growPairs(needed: number): void {
    const capacity = grownCapacity(this.lo.length, needed);
    this.lo = grow(this.lo, capacity, this.shared);
    this.hi = grow(this.hi, capacity, this.shared);
    this.layoutVersion++;
  }
}
