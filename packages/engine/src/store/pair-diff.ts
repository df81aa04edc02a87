import { grownCapacity, grow } from '../util/grow.js';

/** What owns the slots of one side of a pair: BodyStore or SegmentStore. */
export interface SlotOwner {
  handleOf(slot: number): number;
}

/**
 * Which of last step's touching pairs that this step's list lacks still touch: pairs asleep (see
 * ContactEvents), whose contacts the step does not compute. Given their slots and the handles they
 * had then, so that a slot since emptied or reused is told apart.
 */
export interface Dormancy {
  dormant(a: number, b: number, handleA: number, handleB: number): boolean;
}

/**
 * Begin and end touch events from comparing this step's touching pairs with the last step's. Both
 * lists are in ascending (a, b) slot order, so one merge finds the differences in linear time with
 * no hashing. A pair whose slot was reused by a new body or segment in between has a different
 * handle, and counts as one end and one begin. A pair of last step's that this step lacks ends,
 * unless `dormancy` says it still touches, asleep: it is kept, with no event, until it wakes.
 * Arrays are reused, and replaced only when they grow.
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
  private nextA = new Int32Array(16);
  private nextB = new Int32Array(16);
  private nextHandleA = new Float64Array(16);
  private nextHandleB = new Float64Array(16);
  private nextCount = 0;

  clear(): void {
    this.beginCount = 0;
    this.endCount = 0;
  }

  /** Diffs pairs (a[k], b[k]), k < count, in ascending order, against the last call's, then keeps them and the dormant ones. */
  update(a: Int32Array, b: Int32Array, count: number, ownerA: SlotOwner, ownerB: SlotOwner, dormancy: Dormancy | null = null): void {
    const { prevA, prevB, prevHandleA, prevHandleB, prevCount } = this;
    this.nextCount = 0;
    let p = 0;
    let c = 0;
    while (p < prevCount || c < count) {
      let order: number;
      if (p === prevCount) order = 1;
      else if (c === count) order = -1;
      else order = prevA[p] !== a[c] ? prevA[p] - a[c] : prevB[p] - b[c];
      if (order < 0) {
        if (dormancy !== null && dormancy.dormant(prevA[p], prevB[p], prevHandleA[p], prevHandleB[p])) {
          this.pushNext(prevA[p], prevB[p], prevHandleA[p], prevHandleB[p]);
        } else {
          this.pushEnd(prevHandleA[p], prevHandleB[p]);
        }
        p++;
        continue;
      }
      const handleA = ownerA.handleOf(a[c]);
      const handleB = ownerB.handleOf(b[c]);
      if (order > 0) {
        this.pushBegin(handleA, handleB);
      } else {
        if (handleA !== prevHandleA[p] || handleB !== prevHandleB[p]) {
          this.pushEnd(prevHandleA[p], prevHandleB[p]);
          this.pushBegin(handleA, handleB);
        }
        p++;
      }
      this.pushNext(a[c], b[c], handleA, handleB);
      c++;
    }
    // The kept list becomes last step's; its arrays take the next list's turn.
    const { nextA, nextB, nextHandleA, nextHandleB } = this;
    this.nextA = prevA;
    this.nextB = prevB;
    this.nextHandleA = prevHandleA;
    this.nextHandleB = prevHandleB;
    this.prevA = nextA;
    this.prevB = nextB;
    this.prevHandleA = nextHandleA;
    this.prevHandleB = nextHandleB;
    this.prevCount = this.nextCount;
  }

  memoryBytes(): number {
    return (this.beginA.byteLength + this.endA.byteLength + this.prevA.byteLength + this.prevHandleA.byteLength) * 2 + (this.nextA.byteLength + this.nextHandleA.byteLength) * 2;
  }

  private pushNext(a: number, b: number, handleA: number, handleB: number): void {
    const n = this.nextCount;
    if (n === this.nextA.length) {
      const capacity = grownCapacity(this.nextA.length, n + 1);
      this.nextA = grow(this.nextA, capacity);
      this.nextB = grow(this.nextB, capacity);
      this.nextHandleA = grow(this.nextHandleA, capacity);
      this.nextHandleB = grow(this.nextHandleB, capacity);
    }
    this.nextA[n] = a;
    this.nextB[n] = b;
    this.nextHandleA[n] = handleA;
    this.nextHandleB[n] = handleB;
    this.nextCount = n + 1;
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
