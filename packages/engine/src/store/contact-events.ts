import type { BodyStore } from './body-store.js';
import type { SegmentStore } from './segment-store.js';
import { grownCapacity, grow } from '../util/grow.js';
import { PairDiff, type Dormancy, type SlotOwner } from './pair-diff.js';
import { TypeCode } from './body-types.js';
import type { ShapeStore } from './shape-store.js';
import { ContactBuffer } from './contact-buffer.js';
import { ContactPoint, POINT_STRIDE, WORLD, type ContactList } from '../narrowphase/contact-list.js';
import { SEGMENT_ENTRY, WALL_ENTRY } from '../narrowphase/shape-narrowphase.js';

// The contact point record's fields as this module's own constants, which V8 folds into the code.
const { approachSpeed: PT_APPROACH_SPEED, totalNormalImpulse: PT_TOTAL_NORMAL_IMPULSE } = ContactPoint;

/** The box walls have no handles: events name them by their BoxWall number. */
const BOX_WALLS: SlotOwner = {
  writeHandle: (wall, out, at) => {
    out[at] = wall;
  },
  holdsHandle: (wall, handles, at) => handles[at] === wall,
};

/**
 * Whether the body in `slot` holds still while asleep: a sleeping dynamic body, or a static one.
 * A touch between two such things lasts through their sleep though the step computes no contact
 * for it, as Box2D v3 keeps a sleeping island's contacts: no end when a body falls asleep where
 * it rests, no begin when it wakes there.
 */
function still(bodies: BodyStore, slot: number): boolean {
  const t = bodies.type[slot];
  return t === TypeCode.static || (t === TypeCode.dynamic && bodies.asleep[slot] === 1);
}

/** Touches between two bodies (slots), both still (see still). */
class SleepingBodyPairs implements Dormancy {
  bodies: BodyStore | null = null;
  dormant(a: number, b: number): boolean {
    const bodies = this.bodies!;
    return still(bodies, a) && still(bodies, b);
  }
}

/** Touches between a body and a segment or a wall: the body asleep. */
class SleepingOnStatics implements Dormancy {
  bodies: BodyStore | null = null;
  dormant(a: number): boolean {
    const bodies = this.bodies!;
    return bodies.type[a] === TypeCode.dynamic && bodies.asleep[a] === 1;
  }
}

/** Touches between two live shapes (slots) whose bodies are still (see still). */
class SleepingShapePairs implements Dormancy {
  bodies: BodyStore | null = null;
  shapes: ShapeStore | null = null;
  dormant(a: number, b: number): boolean {
    const bodies = this.bodies!;
    const shapes = this.shapes!;
    return shapes.live[a] === 1 && shapes.live[b] === 1 && still(bodies, shapes.body[a]) && still(bodies, shapes.body[b]);
  }
}

/**
 * The sleeping touches' tests, shared by every world: each update points them at its stores and
 * lets go after (see dormancy), so that no world's state holds them.
 */
const sleepingBodies = new SleepingBodyPairs();
const sleepingOnSegments = new SleepingOnStatics();
const sleepingOnWalls = new SleepingOnStatics();
const sleepingShapes = new SleepingShapePairs();

/** Points the sleeping touches' tests at this step's stores, or (null) lets them go. */
function dormancy(bodies: BodyStore | null, shapes: ShapeStore | null): void {
  sleepingBodies.bodies = bodies;
  sleepingOnSegments.bodies = bodies;
  sleepingOnWalls.bodies = bodies;
  sleepingShapes.bodies = bodies;
  sleepingShapes.shapes = shapes;
}

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
  /**
   * In a world with shapes, the touches between bodies shape by shape: shapeBeginA[k] and
   * shapeBeginB[k] are the handles of two shapes (the lower shape slot first) that started
   * touching this step; a body pair's begin comes with its first shape pair's. A shape's touches
   * with segments and walls are reported per body in the segment and wall lists. Empty in a
   * world of circles only.
   */
  readonly shapeBeginCount: number;
  readonly shapeBeginA: Readonly<Float64Array>;
  readonly shapeBeginB: Readonly<Float64Array>;
  readonly shapeEndCount: number;
  readonly shapeEndA: Readonly<Float64Array>;
  readonly shapeEndB: Readonly<Float64Array>;
  /** Collisions of two shapes at or above the hit threshold, with their approach speed; B is a segment handle when a shape hit a segment. */
  readonly shapeHitCount: number;
  readonly shapeHitA: Readonly<Float64Array>;
  readonly shapeHitB: Readonly<Float64Array>;
  readonly shapeHitSpeed: Readonly<Float64Array>;
  /**
   * Sensors: sensorBeginSensor[k], a sensor shape's handle, started overlapping the shape
   * sensorBeginVisitor[k] this step; sensorEnd* likewise for overlaps that ended (or whose shape
   * was destroyed; a visitor asleep inside stays inside). Sensors do not see other sensors.
   */
  readonly sensorBeginCount: number;
  readonly sensorBeginSensor: Readonly<Float64Array>;
  readonly sensorBeginVisitor: Readonly<Float64Array>;
  readonly sensorEndCount: number;
  readonly sensorEndSensor: Readonly<Float64Array>;
  readonly sensorEndVisitor: Readonly<Float64Array>;
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

  /**
   * A hit between a and b, merged with one already noted this step between the same two (a
   * compound body's shapes each meeting the other), keeping the faster approach. A body's hits
   * are noted together (contacts come in canonical order), so the search stops at another a.
   */
  /** note, for a pair anywhere in the list, not only among the last entries. */
  noteAnywhere(a: number, b: number, speed: number): void {
    for (let k = 0; k < this.count; k++) {
      if (this.a[k] !== a || this.b[k] !== b) continue;
      if (speed > this.speed[k]) this.speed[k] = speed;
      return;
    }
    this.push(a, b, speed);
  }

  note(a: number, b: number, speed: number): void {
    for (let k = this.count - 1; k >= 0 && this.a[k] === a; k--) {
      if (this.b[k] !== b) continue;
      if (speed > this.speed[k]) this.speed[k] = speed;
      return;
    }
    this.push(a, b, speed);
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
  private readonly shapeTouches = new PairDiff();
  private readonly sensorTouches = new PairDiff();
  private readonly shapeHits = new HitList();
  private readonly touchingBodies = new TouchList();
  private readonly touchingShapes = new ContactBuffer();
  private readonly sensing = new ContactBuffer();

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

  get shapeBeginCount(): number {
    return this.shapeTouches.beginCount;
  }
  get shapeBeginA(): Float64Array {
    return this.shapeTouches.beginA;
  }
  get shapeBeginB(): Float64Array {
    return this.shapeTouches.beginB;
  }
  get shapeEndCount(): number {
    return this.shapeTouches.endCount;
  }
  get shapeEndA(): Float64Array {
    return this.shapeTouches.endA;
  }
  get shapeEndB(): Float64Array {
    return this.shapeTouches.endB;
  }
  get shapeHitCount(): number {
    return this.shapeHits.count;
  }
  get shapeHitA(): Float64Array {
    return this.shapeHits.a;
  }
  get shapeHitB(): Float64Array {
    return this.shapeHits.b;
  }
  get shapeHitSpeed(): Float64Array {
    return this.shapeHits.speed;
  }
  get sensorBeginCount(): number {
    return this.sensorTouches.beginCount;
  }
  get sensorBeginSensor(): Float64Array {
    return this.sensorTouches.beginA;
  }
  get sensorBeginVisitor(): Float64Array {
    return this.sensorTouches.beginB;
  }
  get sensorEndCount(): number {
    return this.sensorTouches.endCount;
  }
  get sensorEndSensor(): Float64Array {
    return this.sensorTouches.endA;
  }
  get sensorEndVisitor(): Float64Array {
    return this.sensorTouches.endB;
  }

  clear(): void {
    this.shapeTouches.clear();
    this.sensorTouches.clear();
    this.shapeHits.count = 0;
    this.touches.clear();
    this.segmentTouches.clear();
    this.wallTouches.clear();
    this.hits.count = 0;
    this.segmentHits.count = 0;
    this.wallHits.count = 0;
    this.touchingSegments.count = 0;
    this.touchingWalls.count = 0;
  }

  /**
   * Empties this step's begin and end lists, bodies', shapes', segments' and walls', keeping the
   * touches they were diffed from: for a world that records hits or sensors' overlaps without
   * `contactEvents`, which lists no touches.
   */
  dropTouches(): void {
    this.touches.clear();
    this.segmentTouches.clear();
    this.wallTouches.clear();
    this.shapeTouches.clear();
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

  /**
   * A hit the continuous sweep bounced, between bodies a and b (handles, in slot order) at shapes
   * sa and sb (handles), noted after the step's contact hits: merged into the pair's entry where a
   * contact already gave one (the list is searched, as sweeps are few).
   */
  noteSweptHit(a: number, b: number, sa: number, sb: number, speed: number): void {
    this.hits.noteAnywhere(a, b, speed);
    this.shapeHits.noteAnywhere(sa, sb, speed);
  }

  /** The same for body `body`'s shape `shape` on segment `segment` (handles). */
  noteSweptSegmentHit(body: number, shape: number, segment: number, speed: number): void {
    this.segmentHits.noteAnywhere(body, segment, speed);
    this.shapeHits.noteAnywhere(shape, segment, speed);
  }

  /** A hit of the body in slot i on box wall `wall`. */
  recordWallHit(bodies: BodyStore, i: number, wall: number, speed: number): void {
    this.wallHits.push(bodies.handleOf(i), wall, speed);
  }

  /** Diffs the step's canonical contacts, its body-segment and its body-wall touches against the last step's. */
  update(bodies: BodyStore, contacts: ContactBuffer, segments: SegmentStore): void {
    const { touchingSegments: onSegments, touchingWalls: onWalls } = this;
    dormancy(bodies, null);
    this.touches.update(contacts.lo, contacts.hi, contacts.count, bodies, bodies, sleepingBodies);
    this.segmentTouches.update(onSegments.a, onSegments.b, onSegments.count, bodies, segments, sleepingOnSegments);
    this.wallTouches.update(onWalls.a, onWalls.b, onWalls.count, bodies, BOX_WALLS, sleepingOnWalls);
    dormancy(null, null);
  }

  /**
   * A step of a world with shapes: touches from its contact list (a contact touches while it has a
   * manifold, speculative points included, as in Box2D), per body pair, per shape pair and with
   * segments and walls; hits from the points that took an impulse approaching at `hitThreshold` or
   * faster; and the sensors' overlaps, (sensor slot, visitor slot) pairs.
   */
  updateShapes(
    bodies: BodyStore,
    shapes: ShapeStore,
    segments: SegmentStore,
    contacts: ContactList,
    hitThreshold: number,
    sensorSlots: Int32Array,
    visitorSlots: Int32Array,
    sensorCount: number,
  ): void {
    const { touchingBodies, touchingSegments, touchingWalls, touchingShapes } = this;
    touchingBodies.count = 0;
    touchingSegments.count = 0;
    touchingWalls.count = 0;
    touchingShapes.clear();
    for (let n = 0; n < contacts.count; n++) {
      const k = contacts.order[n];
      const a = contacts.bodyA[k];
      const b = contacts.bodyB[k];
      const sa = contacts.shapeA[k];
      const sb = contacts.shapeB[k];
      if (b === WORLD) {
        if (sb >= WALL_ENTRY) {
          const wall = sb - WALL_ENTRY;
          // Several shapes of a body on one wall make one touch.
          if (!(touchingWalls.count > 0 && touchingWalls.a[touchingWalls.count - 1] === a && touchingWalls.b[touchingWalls.count - 1] === wall)) touchingWalls.push(a, wall);
        } else {
          const g = sb - SEGMENT_ENTRY;
          if (!(touchingSegments.count > 0 && touchingSegments.a[touchingSegments.count - 1] === a && touchingSegments.b[touchingSegments.count - 1] === g)) touchingSegments.push(a, g);
        }
      } else {
        if (!(touchingBodies.count > 0 && touchingBodies.a[touchingBodies.count - 1] === a && touchingBodies.b[touchingBodies.count - 1] === b)) touchingBodies.push(a, b);
        touchingShapes.push(Math.min(sa, sb), Math.max(sa, sb));
      }
      let fastest = 0;
      for (let p = 0; p < contacts.pointCount[k]; p++) {
        const at = 2 * k + p;
        if (contacts.points[at * POINT_STRIDE + PT_TOTAL_NORMAL_IMPULSE] > 0 && contacts.points[at * POINT_STRIDE + PT_APPROACH_SPEED] > fastest) fastest = contacts.points[at * POINT_STRIDE + PT_APPROACH_SPEED];
      }
      if (fastest > 0 && fastest >= hitThreshold) {
        if (b === WORLD) {
          if (sb >= WALL_ENTRY) this.wallHits.note(bodies.handleOf(a), sb - WALL_ENTRY, fastest);
          else {
            this.segmentHits.note(bodies.handleOf(a), segments.handleOf(sb - SEGMENT_ENTRY), fastest);
            this.shapeHits.push(shapes.handleOf(sa), segments.handleOf(sb - SEGMENT_ENTRY), fastest);
          }
        } else {
          this.hits.note(bodies.handleOf(a), bodies.handleOf(b), fastest);
          this.shapeHits.push(shapes.handleOf(sa), shapes.handleOf(sb), fastest);
        }
      }
    }
    // Segment touches diff in (body, segment) order, which the contact list already keeps; shape pairs need sorting.
    touchingShapes.sortCanonical(shapes.slotCount);
    dormancy(bodies, shapes);
    this.touches.update(touchingBodies.a, touchingBodies.b, touchingBodies.count, bodies, bodies, sleepingBodies);
    this.segmentTouches.update(touchingSegments.a, touchingSegments.b, touchingSegments.count, bodies, segments, sleepingOnSegments);
    this.wallTouches.update(touchingWalls.a, touchingWalls.b, touchingWalls.count, bodies, BOX_WALLS, sleepingOnWalls);
    this.shapeTouches.update(touchingShapes.lo, touchingShapes.hi, touchingShapes.count, shapes, shapes, sleepingShapes);
    dormancy(null, null);
    const sensing = this.sensing;
    sensing.clear();
    for (let k = 0; k < sensorCount; k++) sensing.push(sensorSlots[k], visitorSlots[k]);
    sensing.sortCanonical(shapes.slotCount);
    this.sensorTouches.update(sensing.lo, sensing.hi, sensing.count, shapes, shapes);
  }

  memoryBytes(): number {
    return (
      this.shapeTouches.memoryBytes() +
      this.sensorTouches.memoryBytes() +
      this.shapeHits.memoryBytes() +
      this.touchingBodies.memoryBytes() +
      this.touchingShapes.memoryBytes() +
      this.sensing.memoryBytes() +
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
