import { grownCapacity, grow } from '../util/grow.js';

/** What owns the slots of one side of a pair: BodyStore or SegmentStore. */
export interface SlotOwner {
  handleOf(slot: number): number;
}

/**
 * Begin and end touch events from comparing this step's touching pairs with the last step's. Both
 * lists are in ascending (a, b) slot order, so one merge finds the differences in linear time with
 * no hashing. A pair whose slot was reused by a new body or segment in between has a different
 * handle, and counts as one end and one begin. Arrays are reused, and replaced only when they grow.
 */
export class PairDiff {
  beginCount = 0;
  beginA = new Float64Array(16);
  beginB = new Float64Array(16);
  endCount = 0;
  endA = new Float64Array(16);
  endB = new Float64Array(16);

  private prevCount = 0;
  private prevA = new Int32Array(16);
  private prevB = new Int32Array(16);
  private prevHandleA = new Float64Array(16);
  private prevHandleB = new Float64Array(16);

  clear(): void {
    this.beginCount = 0;
    this.endCount = 0;
  }

  /** Diffs pairs (a[k], b[k]), k < count, in ascending order, against the last call's, then keeps them. */
  update(a: Int32Array, b: Int32Array, count: number, ownerA: SlotOwner, ownerB: SlotOwner): void {
    const { prevA, prevB, prevHandleA, prevHandleB, prevCount } = this;
    let p = 0;
    let c = 0;
    while (p < prevCount || c < count) {
      let order: number;
      if (p === prevCount) order = 1;
      else if (c === count) order = -1;
      else order = prevA[p] !== a[c] ? prevA[p] - a[c] : prevB[p] - b[c];
      if (order < 0) {
        this.pushEnd(prevHandleA[p], prevHandleB[p]);
        p++;
      } else if (order > 0) {
        this.pushBegin(ownerA.handleOf(a[c]), ownerB.handleOf(b[c]));
        c++;
      } else {
        const handleA = ownerA.handleOf(a[c]);
        const handleB = ownerB.handleOf(b[c]);
        if (handleA !== prevHandleA[p] || handleB !== prevHandleB[p]) {
          this.pushEnd(prevHandleA[p], prevHandleB[p]);
          this.pushBegin(handleA, handleB);
        }
        p++;
        c++;
      }
    }
    this.keep(a, b, count, ownerA, ownerB);
  }

  memoryBytes(): number {
    return (this.beginA.byteLength + this.endA.byteLength + this.prevA.byteLength + this.prevHandleA.byteLength) * 2;
  }

  private keep(a: Int32Array, b: Int32Array, count: number, ownerA: SlotOwner, ownerB: SlotOwner): void {
    if (this.prevA.length < count) {
      const capacity = grownCapacity(this.prevA.length, count);
      this.prevA = grow(this.prevA, capacity);
      this.prevB = grow(this.prevB, capacity);
      this.prevHandleA = grow(this.prevHandleA, capacity);
      this.prevHandleB = grow(this.prevHandleB, capacity);
    }
    for (let k = 0; k < count; k++) {
      this.prevA[k] = a[k];
      this.prevB[k] = b[k];
      this.prevHandleA[k] = ownerA.handleOf(a[k]);
      this.prevHandleB[k] = ownerB.handleOf(b[k]);
    }
    this.prevCount = count;
  }

  private pushBegin(a: number, b: number): void {
    if (this.beginCount === this.beginA.length) {
      const capacity = grownCapacity(this.beginA.length, this.beginCount + 1);
      this.beginA = grow(this.beginA, capacity);
      this.beginB = grow(this.beginB, capacity);
    }
    this.beginA[this.beginCount] = a;
    this.beginB[this.beginCount++] = b;
  }

  private pushEnd(a: number, b: number): void {
    if (this.endCount === this.endA.length) {
      const capacity = grownCapacity(this.endA.length, this.endCount + 1);
      this.endA = grow(this.endA, capacity);
      this.endB = grow(this.endB, capacity);
    }
    this.endA[this.endCount] = a;
    this.endB[this.endCount++] = b;
  }
}
