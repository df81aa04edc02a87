import type { ContactSink } from '../store/contact-buffer.js';

/**
 * A thread's contact list on shared memory. It never grows (only the caller may allocate shared
 * memory that every thread sees): past its capacity it keeps counting, and the caller enlarges
 * it and runs the scan again, which is pure, so nothing is lost.
 */
export class BoundedContactList implements ContactSink {
  count = 0;
  constructor(
    public lo: Int32Array,
    public hi: Int32Array,
  ) {}

  push(lo: number, hi: number): void {
    const k = this.count++;
    if (k < this.lo.length) {
      this.lo[k] = lo;
      this.hi[k] = hi;
    }
  }

  pushPairs(pairs: Int32Array, from: number, to: number): void {
    const { lo, hi } = this;
    let k = this.count;
    for (let p = from; p < to; p += 2, k++) {
      if (k < lo.length) {
        lo[k] = pairs[p];
        hi[k] = pairs[p + 1];
      }
    }
    this.count = k;
  }
}
