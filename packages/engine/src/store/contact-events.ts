import type { BodyStore } from './body-store.js';
import type { SegmentStore } from './segment-store.js';
import type { ContactBuffer } from './contact-buffer.js';
import { grownCapacity, grow } from '../util/grow.js';
import { PairDiff, type SlotOwner } from './pair-diff.js';

/** The box walls have no handles: events name them by their BoxWall number. */
const BOX_WALLS: SlotOwner = { handleOf: (wall) => wall };

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
  /**
   * A body and a static segment that started touching this step: body handle
   * segmentBeginBody[k], segment handle segmentBeginSegment[k], for k < segmentBeginCount.
   */
  readonly segmentBeginCount: number;
  readonly segmentBeginBody: Readonly<Float64Array>;
  readonly segmentBeginSegment: Readonly<Float64Array>;
  /** A body and a segment that stopped touching (or one of which was destroyed). */
  readonly segmentEndCount: number;
  readonly segmentEndBody: Readonly<Float64Array>;
  readonly segmentEndSegment: Readonly<Float64Array>;
  /**
   * Collisions of a body with a wall of the world's box at or above the threshold: body handle
   * wallHitBody[k], wall wallHitWall[k] (a BoxWall number), approach speed wallHitSpeed[k], for
   * k < wallHitCount.
   */
  readonly wallHitCount: number;
  readonly wallHitBody: Readonly<Float64Array>;
  readonly wallHitWall: Readonly<Float64Array>;
  readonly wallHitSpeed: Readonly<Float64Array>;
  /** A body and a box wall that started touching this step (body handle, BoxWall number). */
  readonly wallBeginCount: number;
  readonly wallBeginBody: Readonly<Float64Array>;
  readonly wallBeginWall: Readonly<Float64Array>;
  /** A body and a box wall that stopped touching (or whose body was destroyed). */
  readonly wallEndCount: number;
  readonly wallEndBody: Readonly<Float64Array>;
  readonly wallEndWall: Readonly<Float64Array>;
}

/**
 * The step's events. Touches between bodies are the step's canonical contacts diffed against the
 * last step's; touches between bodies and segments, the pairs the segment solve found (body slots
 * ascending, then segment slots) diffed likewise (see PairDiff), and touches with the box walls,
 * the (body, wall) pairs noteWallContacts found. Hits are recorded as the solvers, the walls stage
 * and the continuous sweep meet them.
 */
export class ContactEvents implements ContactEventsView {
  private readonly touches = new PairDiff();
  private readonly segmentTouches = new PairDiff();
  private readonly wallTouches = new PairDiff();
  hitCount = 0;
  hitA = new Float64Array(16);
  hitB = new Float64Array(16);
  hitSpeed = new Float64Array(16);
  segmentHitCount = 0;
  segmentHitBody = new Float64Array(16);
  segmentHitSegment = new Float64Array(16);
  segmentHitSpeed = new Float64Array(16);
  wallHitCount = 0;
  wallHitBody = new Float64Array(16);
  wallHitWall = new Float64Array(16);
  wallHitSpeed = new Float64Array(16);
  /** This step's touching body-segment pairs, in the order the segment solve found them. */
  private touchingBody = new Int32Array(16);
  private touchingSegment = new Int32Array(16);
  private touchingCount = 0;
  private wallTouchBody = new Int32Array(16);
  private wallTouchWall = new Int32Array(16);
  private wallTouchCount = 0;

  get beginCount(): number {
    return this.touches.beginCount;
  }
  get beginA(): Float64Array {
    return this.touches.beginA;
  }
  get beginB(): Float64Array {
    return this.touches.beginB;
  }
  get endCount(): number {
    return this.touches.endCount;
  }
  get endA(): Float64Array {
    return this.touches.endA;
  }
  get endB(): Float64Array {
    return this.touches.endB;
  }
  get segmentBeginCount(): number {
    return this.segmentTouches.beginCount;
  }
  get segmentBeginBody(): Float64Array {
    return this.segmentTouches.beginA;
  }
  get segmentBeginSegment(): Float64Array {
    return this.segmentTouches.beginB;
  }
  get segmentEndCount(): number {
    return this.segmentTouches.endCount;
  }
  get segmentEndBody(): Float64Array {
    return this.segmentTouches.endA;
  }
  get segmentEndSegment(): Float64Array {
    return this.segmentTouches.endB;
  }
  get wallBeginCount(): number {
    return this.wallTouches.beginCount;
  }
  get wallBeginBody(): Float64Array {
    return this.wallTouches.beginA;
  }
  get wallBeginWall(): Float64Array {
    return this.wallTouches.beginB;
  }
  get wallEndCount(): number {
    return this.wallTouches.endCount;
  }
  get wallEndBody(): Float64Array {
    return this.wallTouches.endA;
  }
  get wallEndWall(): Float64Array {
    return this.wallTouches.endB;
  }

  clear(): void {
    this.touches.clear();
    this.segmentTouches.clear();
    this.wallTouches.clear();
    this.hitCount = 0;
    this.segmentHitCount = 0;
    this.wallHitCount = 0;
    this.touchingCount = 0;
    this.wallTouchCount = 0;
  }

  /** The body in slot i touches box wall `wall` (called in ascending (i, wall) order). */
  noteWallTouch(i: number, wall: number): void {
    if (this.wallTouchCount === this.wallTouchBody.length) {
      const capacity = grownCapacity(this.wallTouchBody.length, this.wallTouchCount + 1);
      this.wallTouchBody = grow(this.wallTouchBody, capacity);
      this.wallTouchWall = grow(this.wallTouchWall, capacity);
    }
    this.wallTouchBody[this.wallTouchCount] = i;
    this.wallTouchWall[this.wallTouchCount++] = wall;
  }

  /** The body in slot i touches the segment in slot s (called in ascending (i, s) order). */
  noteSegmentTouch(i: number, s: number): void {
    if (this.touchingCount === this.touchingBody.length) {
      const capacity = grownCapacity(this.touchingBody.length, this.touchingCount + 1);
      this.touchingBody = grow(this.touchingBody, capacity);
      this.touchingSegment = grow(this.touchingSegment, capacity);
    }
    this.touchingBody[this.touchingCount] = i;
    this.touchingSegment[this.touchingCount++] = s;
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

  /** A hit of the body in slot i on box wall `wall`. */
  recordWallHit(bodies: BodyStore, i: number, wall: number, speed: number): void {
    if (this.wallHitCount === this.wallHitBody.length) {
      const capacity = grownCapacity(this.wallHitBody.length, this.wallHitCount + 1);
      this.wallHitBody = grow(this.wallHitBody, capacity);
      this.wallHitWall = grow(this.wallHitWall, capacity);
      this.wallHitSpeed = grow(this.wallHitSpeed, capacity);
    }
    this.wallHitBody[this.wallHitCount] = bodies.handleOf(i);
    this.wallHitWall[this.wallHitCount] = wall;
    this.wallHitSpeed[this.wallHitCount++] = speed;
  }

  /** Diffs the step's canonical contacts, its body-segment and its body-wall touches against the last step's. */
  update(bodies: BodyStore, contacts: ContactBuffer, segments: SegmentStore): void {
    this.touches.update(contacts.lo, contacts.hi, contacts.count, bodies, bodies);
    this.segmentTouches.update(this.touchingBody, this.touchingSegment, this.touchingCount, bodies, segments);
    this.wallTouches.update(this.wallTouchBody, this.wallTouchWall, this.wallTouchCount, bodies, BOX_WALLS);
  }

  memoryBytes(): number {
    return (
      this.touches.memoryBytes() +
      this.segmentTouches.memoryBytes() +
      this.wallTouches.memoryBytes() +
      (this.hitA.byteLength + this.segmentHitBody.byteLength + this.wallHitBody.byteLength) * 3 +
      (this.touchingBody.byteLength + this.wallTouchBody.byteLength) * 2
    );
  }
}
