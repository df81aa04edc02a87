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

/** Hits of one kind: what hit (a), what it hit (b), both as handles or wall numbers, and the approach speed. */
class HitList {
  count = 0;
  a = new Float64Array(16);
  b = new Float64Array(16);
  speed = new Float64Array(16);

  push(a: number, b: number, speed: number): void {
    if (this.count === this.a.length) {
      const capacity = grownCapacity(this.a.length, this.count + 1);
      this.a = grow(this.a, capacity);
      this.b = grow(this.b, capacity);
      this.speed = grow(this.speed, capacity);
    }
    this.a[this.count] = a;
    this.b[this.count] = b;
    this.speed[this.count++] = speed;
  }

  memoryBytes(): number {
    return this.a.byteLength * 3;
  }
}

/** This step's touching (slot, slot or wall) pairs of one kind, noted in ascending order for PairDiff. */
class TouchList {
  count = 0;
  a = new Int32Array(16);
  b = new Int32Array(16);

  push(a: number, b: number): void {
    if (this.count === this.a.length) {
      const capacity = grownCapacity(this.a.length, this.count + 1);
      this.a = grow(this.a, capacity);
      this.b = grow(this.b, capacity);
    }
    this.a[this.count] = a;
    this.b[this.count++] = b;
  }

  memoryBytes(): number {
    return this.a.byteLength * 2;
  }
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
  private readonly hits = new HitList();
  private readonly segmentHits = new HitList();
  private readonly wallHits = new HitList();
  private readonly touchingSegments = new TouchList();
  private readonly touchingWalls = new TouchList();

  get hitCount(): number {
    return this.hits.count;
  }
  get hitA(): Float64Array {
    return this.hits.a;
  }
  get hitB(): Float64Array {
    return this.hits.b;
  }
  get hitSpeed(): Float64Array {
    return this.hits.speed;
  }
  get segmentHitCount(): number {
    return this.segmentHits.count;
  }
  get segmentHitBody(): Float64Array {
    return this.segmentHits.a;
  }
  get segmentHitSegment(): Float64Array {
    return this.segmentHits.b;
  }
  get segmentHitSpeed(): Float64Array {
    return this.segmentHits.speed;
  }
  get wallHitCount(): number {
    return this.wallHits.count;
  }
  get wallHitBody(): Float64Array {
    return this.wallHits.a;
  }
  get wallHitWall(): Float64Array {
    return this.wallHits.b;
  }
  get wallHitSpeed(): Float64Array {
    return this.wallHits.speed;
  }
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
    this.hits.count = 0;
    this.segmentHits.count = 0;
    this.wallHits.count = 0;
    this.touchingSegments.count = 0;
    this.touchingWalls.count = 0;
  }

  /** The body in slot i touches the segment in slot s (called in ascending (i, s) order). */
  noteSegmentTouch(i: number, s: number): void {
    this.touchingSegments.push(i, s);
  }

  /** The body in slot i touches box wall `wall` (called in ascending (i, wall) order). */
  noteWallTouch(i: number, wall: number): void {
    this.touchingWalls.push(i, wall);
  }

  recordHit(bodies: BodyStore, i: number, j: number, speed: number): void {
    this.hits.push(bodies.handleOf(i), bodies.handleOf(j), speed);
  }

  /** A hit of the body in slot i on the segment in slot s. */
  recordSegmentHit(bodies: BodyStore, i: number, segments: SegmentStore, s: number, speed: number): void {
    this.segmentHits.push(bodies.handleOf(i), segments.handleOf(s), speed);
  }

  /** A hit of the body in slot i on box wall `wall`. */
  recordWallHit(bodies: BodyStore, i: number, wall: number, speed: number): void {
    this.wallHits.push(bodies.handleOf(i), wall, speed);
  }

  /** Diffs the step's canonical contacts, its body-segment and its body-wall touches against the last step's. */
  update(bodies: BodyStore, contacts: ContactBuffer, segments: SegmentStore): void {
    const { touchingSegments: onSegments, touchingWalls: onWalls } = this;
    this.touches.update(contacts.lo, contacts.hi, contacts.count, bodies, bodies);
    this.segmentTouches.update(onSegments.a, onSegments.b, onSegments.count, bodies, segments);
    this.wallTouches.update(onWalls.a, onWalls.b, onWalls.count, bodies, BOX_WALLS);
  }

  memoryBytes(): number {
    return (
      this.touches.memoryBytes() +
      this.segmentTouches.memoryBytes() +
      this.wallTouches.memoryBytes() +
      this.hits.memoryBytes() +
      this.segmentHits.memoryBytes() +
      this.wallHits.memoryBytes() +
      this.touchingSegments.memoryBytes() +
      this.touchingWalls.memoryBytes()
    );
  }
}
