import { grownCapacity } from '../util/grow.js';

/**
 * A set of unordered slot pairs, keyed by the integers (lo, hi) rather than by strings as in the
 * report's 5.11.1. Open addressing with linear probing. `clear` is O(1): each entry carries the
 * epoch it was written in, and bumping the epoch empties the table without touching it.
 */
export class PairSet {
  private lo = new Int32Array(0);
  private hi = new Int32Array(0);
  private epochOf = new Uint32Array(0);
  private epoch = 1;
  private mask = 0;
  size = 0;

  constructor(initialCapacity = 1024) {
    this.allocate(grownCapacity(0, initialCapacity));
  }

  clear(): void {
    this.size = 0;
    this.epoch++;
    if (this.epoch === 0xffffffff) {
      this.epochOf.fill(0);
      this.epoch = 1;
    }
  }

  add(a: number, b: number): void {
    const lo = a < b ? a : b;
    const hi = a < b ? b : a;
    // Keep the load under one half so probes stay short.
    if ((this.size + 1) * 2 > this.lo.length) this.rehash(this.lo.length * 2);
    let e = this.slotFor(lo, hi);
    const { epochOf, epoch } = this;
    while (epochOf[e] === epoch) {
      if (this.lo[e] === lo && this.hi[e] === hi) return;
      e = (e + 1) & this.mask;
    }
    epochOf[e] = epoch;
    this.lo[e] = lo;
    this.hi[e] = hi;
    this.size++;
  }

  has(a: number, b: number): boolean {
    const lo = a < b ? a : b;
    const hi = a < b ? b : a;
    let e = this.slotFor(lo, hi);
    const { epochOf, epoch } = this;
    while (epochOf[e] === epoch) {
      if (this.lo[e] === lo && this.hi[e] === hi) return true;
      e = (e + 1) & this.mask;
    }
    return false;
  }

  memoryBytes(): number {
    return this.lo.byteLength + this.hi.byteLength + this.epochOf.byteLength;
  }

  private slotFor(lo: number, hi: number): number {
    const h = Math.imul(lo, 0x9e3779b1) ^ Math.imul(hi + 0x7f4a7c15, 0x85ebca77);
    return (h ^ (h >>> 15)) & this.mask;
  }

  private allocate(capacity: number): void {
    this.lo = new Int32Array(capacity);
    this.hi = new Int32Array(capacity);
    this.epochOf = new Uint32Array(capacity);
    this.mask = capacity - 1;
    this.epoch = 1;
    this.size = 0;
  }

  private rehash(capacity: number): void {
    const { lo, hi, epochOf, epoch } = this;
    this.allocate(capacity);
    for (let e = 0; e < lo.length; e++) {
      if (epochOf[e] === epoch) this.add(lo[e], hi[e]);
    }
  }
}
