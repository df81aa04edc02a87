import { grownCapacity, grow } from '../util/grow.js';

/**
 * What owns the slots of one side of a pair: BodyStore, ShapeStore or SegmentStore. Handles pass
 * through typed arrays, never as a call's argument or result: they lie past 2^31, and V8 boxes
 * such a number at a call it does not inline, an allocation per touch and step.
 */
export interface SlotOwner {
  /** Writes the handle of the thing in `slot` into out[at]. */
  writeHandle(slot: number, out: Float64Array, at: number): void;
  /** Whether the thing in `slot` has the handle handles[at]. */
  holdsHandle(slot: number, handles: Float64Array, at: number): boolean;
}

/**
 * Which of last step's touching pairs that this step's list lacks still touch: pairs asleep (see
 * ContactEvents), whose contacts the step does not compute. Asked only of pairs whose slots hold
 * the same things as then (PairDiff compares their handles), by slot alone: a handle is past 2^31,
 * and V8 would box it as an argument, an allocation per sleeping touch and step.
 */
export interface Dormancy {
  dormant(a: number, b: number): boolean;
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

  clear(): void {
    this.beginCount = 0;
    this.endCount = 0;
  }

  /** Diffs pairs (a[k], b[k]), k < count, in ascending order, against the last call's, then keeps them and the dormant ones. */
  update(a: Int32Array, b: Int32Array, count: number, ownerA: SlotOwner, ownerB: SlotOwner, dormancy: Dormancy | null = null): void {
    const { prevA, prevB, prevHandleA, prevHandleB, prevCount } = this;
    let { nextA, nextB, nextHandleA, nextHandleB } = this;
    let n = 0;
    let p = 0;
    let c = 0;
    while (p < prevCount || c < count) {
      let order: number;
      if (p === prevCount) order = 1;
      else if (c === count) order = -1;
      else order = prevA[p] !== a[c] ? prevA[p] - a[c] : prevB[p] - b[c];
      if (order < 0) {
        if (dormancy !== null && ownerA.holdsHandle(prevA[p], prevHandleA, p) && ownerB.holdsHandle(prevB[p], prevHandleB, p) && dormancy.dormant(prevA[p], prevB[p])) {
          if (n === nextA.length) {
            this.growNext(n + 1);
            ({ nextA, nextB, nextHandleA, nextHandleB } = this);
          }
          nextA[n] = prevA[p];
          nextB[n] = prevB[p];
          nextHandleA[n] = prevHandleA[p];
          nextHandleB[n++] = prevHandleB[p];
        } else {
          this.pushEnd(prevHandleA[p], prevHandleB[p]);
        }
        p++;
        continue;
      }
      if (n === nextA.length) {
        this.growNext(n + 1);
        ({ nextA, nextB, nextHandleA, nextHandleB } = this);
      }
      nextA[n] = a[c];
      nextB[n] = b[c];
      ownerA.writeHandle(a[c], nextHandleA, n);
      ownerB.writeHandle(b[c], nextHandleB, n);
      if (order > 0) {
        this.pushBegin(nextHandleA[n], nextHandleB[n]);
      } else {
        if (nextHandleA[n] !== prevHandleA[p] || nextHandleB[n] !== prevHandleB[p]) {
          this.pushEnd(prevHandleA[p], prevHandleB[p]);
          this.pushBegin(nextHandleA[n], nextHandleB[n]);
        }
        p++;
      }
      n++;
      c++;
    }
    // The kept list becomes last step's; its arrays take the next list's turn.
    this.nextA = prevA;
    this.nextB = prevB;
    this.nextHandleA = prevHandleA;
    this.nextHandleB = prevHandleB;
    this.prevA = nextA;
    this.prevB = nextB;
    this.prevHandleA = nextHandleA;
    this.prevHandleB = nextHandleB;
    this.prevCount = n;
  }

  memoryBytes(): number {
    return (this.beginA.byteLength + this.endA.byteLength + this.prevA.byteLength + this.prevHandleA.byteLength) * 2 + (this.nextA.byteLength + this.nextHandleA.byteLength) * 2;
  }

  /** Room in the next list for `count` pairs, keeping those written. */
  private growNext(count: number): void {
    const capacity = grownCapacity(this.nextA.length, count);
    this.nextA = grow(this.nextA, capacity);
    this.nextB = grow(this.nextB, capacity);
    this.nextHandleA = grow(this.nextHandleA, capacity);
    this.nextHandleB = grow(this.nextHandleB, capacity);
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
