import type { BodyStore } from './body-store.js';
import type { SegmentStore } from './segment-store.js';
import type { ContactBuffer } from './contact-buffer.js';
import { grownCapacity, grow } from '../util/grow.js';

/** Event lists of the last step; the arrays are reused and replaced only when they grow. */
export interface ContactEventsView {
  /** Pairs that started touching this step: handles beginA[k], beginB[k] for k < beginCount. */
  readonly beginCount: number;
  readonly beginA: Readonly<Float64Array>;
  readonly beginB: Readonly<Float64Array>;
  /** Pairs that stopped touching (or whose body was destroyed). */
  readonly endCount: number;
  readonly endA: Readonly<Float64Array>;
  readonly endB: Readonly<Float64Array>;
  /** Collisions at or above the world's hitEventThreshold, with their approach speed. */
  readonly hitCount: number;
  readonly hitA: Readonly<Float64Array>;
  readonly hitB: Readonly<Float64Array>;
  readonly hitSpeed: Readonly<Float64Array>;
  /**
   * Collisions of a body with a static segment at or above the threshold: body handle
   * segmentHitBody[k], segment handle segmentHitSegment[k] (createSegment's), approach speed
   * segmentHitSpeed[k], for k < segmentHitCount.
   */
  readonly segmentHitCount: number;
  readonly segmentHitBody: Readonly<Float64Array>;
  readonly segmentHitSegment: Readonly<Float64Array>;
  readonly segmentHitSpeed: Readonly<Float64Array>;
}

/**
 * Begin and end touch events come from comparing this step's contacts with the last step's. Both
 * lists are in canonical (lo, hi) slot order, so one merge finds the differences in linear time
 * with no hashing. A pair whose slot was reused by a new body in between has a different handle,
 * and counts as one end and one begin.
 */
export class ContactEvents implements ContactEventsView {
  beginCount = 0;
  beginA = new Float64Array(16);
  beginB = new Float64Array(16);
  endCount = 0;
  endA = new Float64Array(16);
  endB = new Float64Array(16);
  hitCount = 0;
  hitA = new Float64Array(16);
  hitB = new Float64Array(16);
  hitSpeed = new Float64Array(16);
  segmentHitCount = 0;
  segmentHitBody = new Float64Array(16);
  segmentHitSegment = new Float64Array(16);
  segmentHitSpeed = new Float64Array(16);

  private prevCount = 0;
  private prevLo = new Int32Array(16);
  private prevHi = new Int32Array(16);
  private prevHandleLo = new Float64Array(16);
  private prevHandleHi = new Float64Array(16);

  clear(): void {
    this.beginCount = 0;
    this.endCount = 0;
    this.hitCount = 0;
    this.segmentHitCount = 0;
  }

  recordHit(bodies: BodyStore, i: number, j: number, speed: number): void {
    if (this.hitCount === this.hitA.length) {
      const capacity = grownCapacity(this.hitA.length, this.hitCount + 1);
      this.hitA = grow(this.hitA, capacity);
      this.hitB = grow(this.hitB, capacity);
      this.hitSpeed = grow(this.hitSpeed, capacity);
    }
    this.hitA[this.hitCount] = bodies.handleOf(i);
    this.hitB[this.hitCount] = bodies.handleOf(j);
    this.hitSpeed[this.hitCount++] = speed;
  }

  /** A hit of the body in slot i on the segment in slot s. */
  recordSegmentHit(bodies: BodyStore, i: number, segments: SegmentStore, s: number, speed: number): void {
    if (this.segmentHitCount === this.segmentHitBody.length) {
      const capacity = grownCapacity(this.segmentHitBody.length, this.segmentHitCount + 1);
      this.segmentHitBody = grow(this.segmentHitBody, capacity);
      this.segmentHitSegment = grow(this.segmentHitSegment, capacity);
      this.segmentHitSpeed = grow(this.segmentHitSpeed, capacity);
    }
    this.segmentHitBody[this.segmentHitCount] = bodies.handleOf(i);
    this.segmentHitSegment[this.segmentHitCount] = segments.handleOf(s);
    this.segmentHitSpeed[this.segmentHitCount++] = speed;
  }

  /** Diffs the step's canonical contacts against the previous step's, then keeps them. */
  update(bodies: BodyStore, contacts: ContactBuffer): void {
    const { lo, hi, count } = contacts;
    const { prevLo, prevHi, prevHandleLo, prevHandleHi, prevCount } = this;
    let p = 0;
    let c = 0;
    while (p < prevCount || c < count) {
      let order: number;
      if (p === prevCount) order = 1;
      else if (c === count) order = -1;
      else order = prevLo[p] !== lo[c] ? prevLo[p] - lo[c] : prevHi[p] - hi[c];
      if (order < 0) {
        this.pushEnd(prevHandleLo[p], prevHandleHi[p]);
        p++;
      } else if (order > 0) {
        this.pushBegin(bodies.handleOf(lo[c]), bodies.handleOf(hi[c]));
        c++;
      } else {
        const a = bodies.handleOf(lo[c]);
        const b = bodies.handleOf(hi[c]);
        if (a !== prevHandleLo[p] || b !== prevHandleHi[p]) {
          this.pushEnd(prevHandleLo[p], prevHandleHi[p]);
          this.pushBegin(a, b);
        }
        p++;
        c++;
      }
    }
    this.keep(bodies, contacts);
  }

  memoryBytes(): number {
    return (this.beginA.byteLength + this.endA.byteLength + this.prevLo.byteLength + this.prevHandleLo.byteLength) * 2 + (this.hitA.byteLength + this.segmentHitBody.byteLength) * 3;
  }

  private keep(bodies: BodyStore, contacts: ContactBuffer): void {
    const n = contacts.count;
    if (this.prevLo.length < n) {
      const capacity = grownCapacity(this.prevLo.length, n);
      this.prevLo = grow(this.prevLo, capacity);
      this.prevHi = grow(this.prevHi, capacity);
      this.prevHandleLo = grow(this.prevHandleLo, capacity);
      this.prevHandleHi = grow(this.prevHandleHi, capacity);
    }
    for (let k = 0; k < n; k++) {
      const i = contacts.lo[k];
      const j = contacts.hi[k];
      this.prevLo[k] = i;
      this.prevHi[k] = j;
      this.prevHandleLo[k] = bodies.handleOf(i);
      this.prevHandleHi[k] = bodies.handleOf(j);
    }
    this.prevCount = n;
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
