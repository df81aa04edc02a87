import type { BodyStore } from '../store/body-store.js';
import type { PairConsumer } from '../store/pair-sink.js';
import type { SegmentStore } from '../store/segment-store.js';
import { SHAPE_STRIDE, ShapeField, type ShapeStore } from '../store/shape-store.js';
import { ContactBuffer } from '../store/contact-buffer.js';
import { TypeCode } from '../store/body-types.js';
import { BodyFlag } from '../store/rigid-columns.js';
import { boxesApart, ORIENTED_BOX } from './oriented-boxes.js';
import { grownCapacity, grow } from '../util/grow.js';
import type { StaticTree } from '../broadphase/static-tree.js';
import { ContactList, ContactPoint, Pose, POINT_STRIDE, RECYCLE, Recycle, WORLD } from './contact-list.js';
import { Manifold } from './manifold.js';
import { WorldShape } from './world-shape.js';
import { collide } from './dispatch.js';
import { smoothSegment } from './smooth-segment.js';
import type { JointStore } from '../joints/joint-store.js';
import { SlotList, type Queries } from '../query/queries.js';
import { shapeBounds } from '../shapes/bounds.js';

/** Candidate pairs readAhead loads at a time: their records and poses (some 160 KB) stay in a core's L2 until the pairs are tested. */
const READ_AHEAD = 256;
/** Doubles in a 64-byte cache line. */
const LINE = 8;
/** Where readAhead leaves its sums, so that V8 keeps the loads. */
const readAheadSink = new Float64Array(READ_AHEAD);

/**
 * Loads the memory that candidate pairs lo/hi[from..to) are about to read: both bodies' poses and
 * shape counts, and each body's first shape's oriented box and record, every cache line of it. Its iterations
 * are independent short runs of loads, which the core keeps many of in flight at once; in the
 * pair loop each pair's misses wait behind the work of the pair before it. JavaScript has no
 * prefetch, so the loads are summed into readAheadSink. Reading a few pairs ahead inside the
 * pair loop instead is slower: there the sum waits on its loads among the pair's own work. What
 * this gains, and where it loses, is in docs/engine.md, "Performance with shapes".
 */
function readAhead(bodies: BodyStore, shapes: ShapeStore, lo: Int32Array, hi: Int32Array, from: number, to: number): void {
  const { x, y } = bodies;
  const { c, s, firstShape, shapeCount } = bodies.rigid!;
  const { record, box } = shapes;
  for (let k = from; k < to; k++) {
    const i = lo[k];
    const j = hi[k];
    let sum = x[i] + y[i] + c[i] + s[i] + x[j] + y[j] + c[j] + s[j] + shapeCount[i] + shapeCount[j];
    const sa = firstShape[i];
    const sb = firstShape[j];
    if (sa >= 0) {
      const r = sa * SHAPE_STRIDE;
      sum += box[sa * ORIENTED_BOX] + record[r + SHAPE_STRIDE - 1];
      for (let o = 0; o < SHAPE_STRIDE; o += LINE) sum += record[r + o];
    }
    if (sb >= 0) {
      const r = sb * SHAPE_STRIDE;
      sum += box[sb * ORIENTED_BOX] + record[r + SHAPE_STRIDE - 1];
      for (let o = 0; o < SHAPE_STRIDE; o += LINE) sum += record[r + o];
    }
    readAheadSink[k - from] = sum;
  }
}

/** Kept manifolds: each body turned less than acos(0.98), about 11 degrees, since (Box2D's B2_CONTACT_RECYCLE_COS_ANGLE). */
const RECYCLE_COS = 0.98;

/** Static tree entry ids: a static body's shape by its shape slot; segments and walls above. */
export const SEGMENT_ENTRY = 2 ** 24;
export const WALL_ENTRY = 2 ** 25;

/** What world shapes the narrow-phase can meet besides bodies: the segments, and the box. */
export interface WorldShapes {
  segments: SegmentStore;
  /** The box's walls as four rectangles (see boxWall), or null without a box. */
  box: { width: number; height: number } | null;
  /** How thick the walls are, outside the box. */
  wallThickness: number;
}

const wallBounds = new Float64Array(4);

/** Fills `out` with wall w (BoxWall numbering: x = 0, x = width, y = 0, y = height) of the box. */
export function boxWall(world: WorldShapes, w: number, out: WorldShape): WorldShape {
  const { width, height } = world.box!;
  const t = world.wallThickness;
  const b = wallBounds;
  b[0] = w === 1 ? width : -t;
  b[1] = w === 3 ? height : -t;
  b[2] = w === 0 ? 0 : width + t;
  b[3] = w === 2 ? 0 : height + t;
  return out.rectangle(b);
}

/**
 * The narrow-phase of worlds with shapes, in two passes.
 *
 * `consume` (the broad-phase's consumer) keeps the candidate body pairs that could touch: at
 * least one awake moving body and one dynamic, collision layers open at body level, and bounding
 * circles (which include the speculative margin) overlapping, a test that depends on the pair
 * alone, so every broad-phase hands on the same pairs. `gatherStatic` adds each awake dynamic
 * body's pairs with static things from the static tree: static bodies as body pairs, segments and
 * walls as world pairs.
 *
 * `build` then sorts the body pairs canonically and runs the shape pairs of each through the
 * dispatch table, in order, into the step's ContactList, each contact inheriting its impulses
 * from last step's list. A sleeping body touched by an awake one is noted in `wake`: the route
 * wakes its island and collides again before the solve (see ShapeRoute.run), so that it wakes
 * whole, with its own contacts.
 */
export class ShapeNarrowPhase implements PairConsumer {
  readonly candidates = new ContactBuffer();
  /** The step's contacts (persistent: see ContactList). */
  readonly current = new ContactList();
  /** Pairs dropped by collision layers (body level in consume, shape level in build). */
  filtered = 0;
  /** Shape pairs run through a pair function in the last build. */
  shapePairs = 0;
  /** Sensor overlaps found this step: (sensor shape slot, visitor shape slot). */
  sensorSlots = new Int32Array(16);
  visitorSlots = new Int32Array(16);
  sensorCount = 0;
  /** The world's joints, once it has any: bodies a joint holds apart make no pair (see JointStore.joined). */
  joints: JointStore | null = null;
  /** Sleepers an awake body touched this step: their islands wake before the solve (see ShapeRoute.run). */
  wake = new Int32Array(16);
  wakeCount = 0;
  private worldBody = new Int32Array(16);
  private worldEntry = new Int32Array(16);
  private worldCount = 0;
  private stamp = new Int32Array(0);
  private epoch = 0;
  private readonly shapeA = new WorldShape();
  private readonly shapeB = new WorldShape();
  private readonly manifold = new Manifold();
  private wakeSpeed = 0;
  private recycleDistance = 0;
  private margin = 0;
  /**
   * The step's margin as boxesApart reads it, and the walls' material. These, the margin and the
   * slop (in `manifold`) are read from memory by the pair loop and what it calls rather than
   * passed down: V8 inlines the loop into its callers as it sees fit, and a double computed in the
   * frame that makes a call it does not inline is boxed at every call, once per pair.
   */
  private readonly boxReach = new Float64Array(1);
  private wallFriction = 0;
  private wallRestitution = 0;
  private dt = 0;
  /** Contacts whose manifold the last build kept from the step before (see recycle). */
  recycled = 0;
  /** Per body slot, 1 where its contacts are recomputed whatever they did (see noteFastBodies). */
  private fastBody = new Uint8Array(0);
  /** Bodies whose contacts the next build recomputes (see forget). */
  private forgotten = new Int32Array(8);
  private forgottenCount = 0;

  constructor(private readonly bodies: BodyStore) {}

  /**
   * Has the next build recompute body `slot`'s contacts rather than keep them: its centre of mass
   * moved (a shape added or removed, its type changed), and a kept manifold's anchors, relative to
   * that centre, would no longer lie on its shapes; the move, smaller than the recycle distance,
   * would pass for motion, and the body would rest sunk into its support or above it.
   */
  forget(slot: number): void {
    if (this.forgottenCount === this.forgotten.length) this.forgotten = grow(this.forgotten, 2 * this.forgotten.length);
    this.forgotten[this.forgottenCount++] = slot;
  }

  begin(): void {
    this.filtered = 0;
    this.candidates.clear();
    this.worldCount = 0;
    this.wakeCount = 0;
    this.sensorCount = 0;
  }

  accept(pairs: Int32Array, from: number, to: number): void {
    // Only reached with PairSink.contactsDirect, which the shape route leaves off.
    for (let p = from; p < to; p += 2) this.consume1(pairs[p], pairs[p + 1]);
  }

  consume(a: Int32Array, b: Int32Array, count: number): void {
    for (let k = 0; k < count; k++) this.consume1(a[k], b[k]);
  }

  private consume1(i: number, j: number): void {
    const { type, asleep, category, mask, x, y, radius } = this.bodies;
    const movingI = type[i] === TypeCode.kinematic || (type[i] === TypeCode.dynamic && asleep[i] === 0);
    const movingJ = type[j] === TypeCode.kinematic || (type[j] === TypeCode.dynamic && asleep[j] === 0);
    if (!(movingI || movingJ)) return;
    if (type[i] !== TypeCode.dynamic && type[j] !== TypeCode.dynamic) return;
    if ((category[i] & mask[j]) === 0 || (category[j] & mask[i]) === 0) {
      this.filtered++;
      return;
    }
    const joints = this.joints;
    if (joints !== null && joints.nonColliding > 0 && joints.joined(i, j)) {
      this.filtered++;
      return;
    }
    const dx = x[j] - x[i];
    const dy = y[j] - y[i];
    const reach = radius[i] + radius[j];
    if (dx * dx + dy * dy >= reach * reach) return;
    if (i < j) this.candidates.push(i, j);
    else this.candidates.push(j, i);
  }

  /**
   * Pairs of each awake dynamic body with the static tree's entries its bounding box overlaps
   * (static bodies as body pairs, segments within reach as world pairs), and with each wall of the
   * box its bounding circle reaches (the walls lie outside the box, so past a side is overlap).
   * `recycleDistance` is build's: how far a kept manifold's bodies may have drifted.
   */
  gatherStatic(tree: StaticTree, shapes: ShapeStore, world: WorldShapes, recycleDistance: number): void {
    const bodies = this.bodies;
    const { type, asleep, x, y, radius, category, mask, slotCount } = bodies;
    const segments = world.segments;
    const box = world.box;
    const width = box ? box.width : 0;
    const height = box ? box.height : 0;
    const searchTree = tree.count > 0;
    if (this.stamp.length < slotCount) this.stamp = new Int32Array(grownCapacity(this.stamp.length, slotCount));
    for (let i = 0; i < slotCount; i++) {
      if (type[i] !== TypeCode.dynamic || asleep[i]) continue;
      const px = x[i];
      const py = y[i];
      const r = radius[i];
      let found = 0;
      if (searchTree) {
        const box = tree.box;
        box[0] = px - r;
        box[1] = py - r;
        box[2] = px + r;
        box[3] = py + r;
        found = tree.queryBox();
      }
      if (found > 0) {
        const stamp = ++this.epoch;
        for (let f = 0; f < found; f++) {
          const entry = tree.found[f];
          if (entry < SEGMENT_ENTRY) {
            const s = shapes.body[entry];
            if (this.stamp[s] === stamp) continue;
            this.stamp[s] = stamp;
            if ((category[i] & mask[s]) === 0 || (category[s] & mask[i]) === 0) {
              this.filtered++;
              continue;
            }
            const joints = this.joints;
            if (joints !== null && joints.nonColliding > 0 && joints.joined(i, s)) {
              this.filtered++;
              continue;
            }
            if (i < s) this.candidates.push(i, s);
            else this.candidates.push(s, i);
          } else {
            const g = entry - SEGMENT_ENTRY;
            if ((category[i] & segments.mask[g]) === 0 || (segments.category[g] & mask[i]) === 0) {
              this.filtered++;
              continue;
            }
            if (this.beyondSegment(segments, g, px, py, r, recycleDistance)) continue;
            this.pushWorld(i, entry);
          }
        }
      }
      if (box !== null) {
        if (px - r <= 0) this.pushWorld(i, WALL_ENTRY);
        if (px + r >= width) this.pushWorld(i, WALL_ENTRY + 1);
        if (py - r <= 0) this.pushWorld(i, WALL_ENTRY + 2);
        if (py + r >= height) this.pushWorld(i, WALL_ENTRY + 3);
      }
    }
  }

  /**
   * Builds the step's contact list in canonical order, inheriting impulses from the last step's.
   * `margin` is the speculative distance (0: touching only), `slop` the solver's linear slop.
   */
  build(shapes: ShapeStore, world: WorldShapes, margin: number, slop: number, wallFriction: number, wallRestitution: number, wakeSpeed: number, recycleDistance: number, dt: number): void {
    this.wakeSpeed = wakeSpeed;
    this.recycleDistance = recycleDistance;
    this.margin = margin;
    this.boxReach[0] = margin;
    this.manifold.margin = margin;
    this.manifold.slop = slop;
    this.wallFriction = wallFriction;
    this.wallRestitution = wallRestitution;
    this.dt = dt;
    this.recycled = 0;
    if (recycleDistance > 0) this.noteFastBodies();
    this.forgottenCount = 0;
    const list = this.current;
    list.begin();
    const bodies = this.bodies;
    this.candidates.sortCanonical(bodies.slotCount);
    this.shapePairs = 0;
    this.collidePairs(shapes, world);
    list.finish();
  }

  /**
   * build's loop: the candidate body pairs in canonical order, each body's world pairs after its
   * body pairs. Its own function, with nothing after the loop: V8 compiles a loop this long on
   * the first step (on-stack replacement) before anything after it has run, and a property read
   * there without feedback then left that code at every step of the 5,050-box pyramid.
   */
  private collidePairs(shapes: ShapeStore, world: WorldShapes): void {
    const { lo, hi, count } = this.candidates;
    let w = 0;
    let p = 0;
    // Where no manifold is kept every pair reads its shapes' records; where they are kept most
    // pairs read none, and reading ahead only adds loads (see readAhead).
    const ahead = this.recycleDistance === 0;
    let readTo = 0;
    for (let k = 0; k <= count; k++) {
      if (ahead && k === readTo && k < count) {
        readTo = Math.min(k + READ_AHEAD, count);
        readAhead(this.bodies, shapes, lo, hi, k, readTo);
      }
      const i = k < count ? lo[k] : Infinity;
      // World pairs of bodies below i come first, after those bodies' body pairs.
      while (w < this.worldCount && this.worldBody[w] < i) {
        p = this.collideWorld(this.worldBody[w], this.worldEntry[w], shapes, world, p);
        w++;
      }
      if (k === count) break;
      p = this.collideBodies(i, hi[k], shapes, p);
    }
  }

  memoryBytes(): number {
    return this.candidates.memoryBytes() + this.current.memoryBytes() + this.worldBody.byteLength * 2 + this.stamp.byteLength + this.wake.byteLength;
  }

  /**
   * Whether a body whose bounding circle (speculative margin included) is at (px, py) with radius
   * r lies too far from segment g for any contact, new or kept: farther than r, the segment's
   * thickness and the distance a kept manifold may drift (see recycle), widened by a millionth
   * against rounding. A long diagonal segment's bounding box holds many bodies nowhere near it,
   * and each would otherwise be a pair function's call.
   */
  private beyondSegment(segments: SegmentStore, g: number, px: number, py: number, r: number, recycleDistance: number): boolean {
    const ax = segments.ax[g];
    const ay = segments.ay[g];
    const ex = segments.bx[g] - ax;
    const ey = segments.by[g] - ay;
    const length2 = ex * ex + ey * ey;
    let t = length2 > 0 ? ((px - ax) * ex + (py - ay) * ey) / length2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    const dx = px - (ax + t * ex);
    const dy = py - (ay + t * ey);
    const reach = (r + segments.thickness[g] + recycleDistance) * (1 + 1e-6) + 1e-9;
    return dx * dx + dy * dy > reach * reach;
  }

  private pushWorld(i: number, entry: number): void {
    if (this.worldCount === this.worldBody.length) {
      const capacity = grownCapacity(this.worldBody.length, this.worldCount + 1);
      this.worldBody = grow(this.worldBody, capacity);
      this.worldEntry = grow(this.worldEntry, capacity);
    }
    this.worldBody[this.worldCount] = i;
    this.worldEntry[this.worldCount++] = entry;
  }

  /**
   * The step's sensor overlaps, where the bodies ended it (Box2D v3 runs its sensors after the
   * solve, so an overlap begins in the step it appears, not the next): each live sensor shape's
   * box is looked up among the bodies (`queries`, built for `version`, the positions the step
   * leaves), and each shape there of a dynamic body other than the sensor's own, that the
   * filters let through and no joint keeps apart, is tested for overlap (a point closer than 0).
   * A sensor reports the shapes of dynamic bodies alone, not other sensors; a visitor asleep
   * inside stays inside, as Box2D keeps it. The order found does not matter: the events sort the
   * pairs.
   */
  sense(shapes: ShapeStore, queries: Queries, version: number, slop: number): void {
    this.sensorCount = 0;
    if (shapes.sensors === 0) return;
    const bodies = this.bodies;
    const { type, x, y } = bodies;
    const { c, s, firstShape } = bodies.rigid!;
    const pose = this.senseScratch;
    const found = this.senseFound;
    const m = this.manifold;
    // Overlap alone: no speculative points (the next build sets the step's margin again).
    m.margin = 0;
    m.slop = slop;
    for (let sa = 0; sa < shapes.slotCount; sa++) {
      if (shapes.live[sa] !== 1 || shapes.sensor[sa] !== 1) continue;
      const i = shapes.body[sa];
      pose[0] = x[i];
      pose[1] = y[i];
      pose[2] = c[i];
      pose[3] = s[i];
      const box = shapeBounds(shapes, sa, pose, this.senseBox);
      queries.slotsInBox(version, box, found);
      const a = this.shapeA.fromPose(shapes, sa, pose, 0);
      for (let f = 0; f < found.count; f++) {
        const j = found.slots[f];
        if (j === i || type[j] !== TypeCode.dynamic) continue;
        const joints = this.joints;
        if (joints !== null && joints.nonColliding > 0 && joints.joined(i, j)) continue;
        pose[4] = x[j];
        pose[5] = y[j];
        pose[6] = c[j];
        pose[7] = s[j];
        for (let sb = firstShape[j]; sb >= 0; sb = shapes.next[sb]) {
          if (shapes.sensor[sb] === 1) continue;
          if ((shapes.category[sa] & shapes.mask[sb]) === 0 || (shapes.category[sb] & shapes.mask[sa]) === 0) continue;
          const b = this.shapeB.fromPose(shapes, sb, pose, 4);
          collide(a, b, m);
          if (m.pointCount > 0 && (m.separation[0] < 0 || (m.pointCount === 2 && m.separation[1] < 0))) this.noteSensor(sa, sb);
        }
      }
    }
  }

  private readonly senseScratch = new Float64Array(8);
  private readonly senseBox = new Float64Array(4);
  private readonly senseFound = new SlotList();

  private noteSensor(sensor: number, visitor: number): void {
    if (this.sensorCount === this.sensorSlots.length) {
      this.sensorSlots = grow(this.sensorSlots, 2 * this.sensorSlots.length);
      this.visitorSlots = grow(this.visitorSlots, 2 * this.visitorSlots.length);
    }
    this.sensorSlots[this.sensorCount] = sensor;
    this.visitorSlots[this.sensorCount++] = visitor;
  }

  private noteWake(slot: number): void {
    if (this.wakeCount === this.wake.length) this.wake = grow(this.wake, 2 * this.wake.length);
    this.wake[this.wakeCount++] = slot;
  }

  /** Whether the awake body in `slot` wakes a sleeper it touches: kinematic, or faster than the sleep speed (rim included). */
  private wakes(slot: number): boolean {
    const bodies = this.bodies;
    const t = bodies.type[slot];
    // A kinematic body at rest holds what it supports as a static one does (see IslandSleep).
    if (t === TypeCode.kinematic) return bodies.vx[slot] !== 0 || bodies.vy[slot] !== 0 || bodies.rigid!.angularVelocity[slot] !== 0;
    if (t !== TypeCode.dynamic) return false;
    const v = Math.sqrt(bodies.vx[slot] * bodies.vx[slot] + bodies.vy[slot] * bodies.vy[slot]) + bodies.radius[slot] * Math.abs(bodies.rigid!.angularVelocity[slot]);
    return v > this.wakeSpeed;
  }

  private collideBodies(i: number, j: number, shapes: ShapeStore, p: number): number {
    const bodies = this.bodies;
    const rigid = bodies.rigid!;
    const { x, y } = bodies;
    const { c, s, firstShape, shapeCount } = rigid;
    const compound = shapeCount[i] > 1 || shapeCount[j] > 1;
    const list = this.current;
    p = this.seek(i, j, p);
    // 1: kept; 0: tried, not kept (the loop below need not try again); -1: not tried.
    const lone = !compound && this.recycleDistance > 0 ? this.recycledLone(i, j, shapes, p) : -1;
    if (lone === 1) return this.afterTouch(i, j, p);
    let touching = false;
    // Each shape's header in its record: one run of memory per shape (see ShapeStore.record).
    const record = shapes.record;
    for (let sa = firstShape[i]; sa >= 0; sa = record[sa * SHAPE_STRIDE + ShapeField.next]) {
      const ra = sa * SHAPE_STRIDE;
      for (let sb = firstShape[j]; sb >= 0; sb = record[sb * SHAPE_STRIDE + ShapeField.next]) {
        const rb = sb * SHAPE_STRIDE;
        if ((record[ra + ShapeField.category] & record[rb + ShapeField.mask]) === 0 || (record[rb + ShapeField.category] & record[ra + ShapeField.mask]) === 0) {
          this.filtered++;
          continue;
        }
        // A sensor takes no contact: its overlaps are found at the step's end (see sense).
        if (record[ra + ShapeField.sensor] === 1 || record[rb + ShapeField.sensor] === 1) continue;
        if (compound) {
          const ax = x[i] + c[i] * shapes.centroidX[sa] - s[i] * shapes.centroidY[sa];
          const ay = y[i] + s[i] * shapes.centroidX[sa] + c[i] * shapes.centroidY[sa];
          const bx = x[j] + c[j] * shapes.centroidX[sb] - s[j] * shapes.centroidY[sb];
          const by = y[j] + s[j] * shapes.centroidX[sb] + c[j] * shapes.centroidY[sb];
          const reach = shapes.extent[sa] + shapes.extent[sb] + this.margin;
          if ((bx - ax) * (bx - ax) + (by - ay) * (by - ay) >= reach * reach) continue;
        }
        // The shapes' keys, through `pose` (see Pose): handles are doubles, boxed when passed to a call.
        const pose = list.pose;
        pose[Pose.keyA] = record[ra + ShapeField.handle];
        pose[Pose.keyB] = record[rb + ShapeField.handle];
        const q = this.find(p, i, j);
        if (q >= 0 && this.recycleDistance > 0 && lone !== 0 && this.recycle(q, i, j)) {
          touching = true;
          continue;
        }
        // The boxes apart: the pair function would find no point (nor a sensor an overlap).
        if (boxesApart(x, y, c, s, i, shapes.box, sa * ORIENTED_BOX, j, shapes.box, sb * ORIENTED_BOX, this.boxReach)) continue;
        this.shapePairs++;
        pose[Pose.ax] = x[i];
        pose[Pose.ay] = y[i];
        pose[Pose.ac] = c[i];
        pose[Pose.as] = s[i];
        pose[Pose.bx] = x[j];
        pose[Pose.by] = y[j];
        pose[Pose.bc] = c[j];
        pose[Pose.bs] = s[j];
        const a = this.shapeA.fromPose(shapes, sa, pose, Pose.ax);
        const b = this.shapeB.fromPose(shapes, sb, pose, Pose.bx);
        const m = this.manifold;
        collide(a, b, m);
        if (m.pointCount === 0) continue;
        touching = true;
        const friction = Math.sqrt(shapes.friction[sa] * shapes.friction[sb]);
        const restitution = Math.max(shapes.restitution[sa], shapes.restitution[sb]);
        // Box2D's rule: the larger coefficient times the larger radius, a lever arm for the torque.
        const resistance = Math.max(shapes.rollingResistance[sa], shapes.rollingResistance[sb]);
        const rolling = resistance > 0 ? resistance * Math.max(record[ra + ShapeField.radius], record[rb + ShapeField.radius]) : 0;
        let k = q;
        pose[Pose.friction] = friction;
        pose[Pose.restitution] = restitution;
        pose[Pose.rolling] = rolling;
        if (q >= 0) list.rewrite(q, m);
        else k = list.add(i, j, sa, sb, m);
        list.cache(k);
      }
    }
    return touching ? this.afterTouch(i, j, p) : p;
  }

  /** A sleeper touched by an awake body is noted to wake; returns p. */
  private afterTouch(i: number, j: number, p: number): number {
    const asleep = this.bodies.asleep;
    if (asleep[i] && !asleep[j] && this.wakes(j)) this.noteWake(i);
    else if (asleep[j] && !asleep[i] && this.wakes(i)) this.noteWake(j);
    return p;
  }

  /**
   * Whether the pair of two bodies of one shape each kept last step's manifold (see recycle): 1
   * if it did, 0 if not, -1 where this path does not apply. It reads no shape record, which the
   * general loop reads for each shape's filter, sensor flag and key: the pair's bodies passed the
   * body-level filter (consume, gatherStatic), which for a lone shape is the shape's own; a pair
   * with a sensor has no manifold to keep; the key is the shape's handle.
   * Most pairs of a pile at rest end here, and the records they skip are the pair loop's cache
   * misses once the solver's constraints have pushed them out (see docs/engine.md, "Performance
   * with shapes"). The general loop computes what was not kept.
   */
  private recycledLone(i: number, j: number, shapes: ShapeStore, p: number): number {
    const rigid = this.bodies.rigid!;
    const sa = rigid.firstShape[i];
    const sb = rigid.firstShape[j];
    if (sa < 0 || sb < 0) return -1;
    // find's loop with the keys in locals rather than through the pose array: 1.46-1.51 -> 1.40-1.44
    // ms for the resting pyramid's narrow-phase (four alternations of builds).
    const keyA = shapes.handleOf(sa);
    const keyB = shapes.handleOf(sb);
    const list = this.current;
    const { previousOrder, previousCount, bodyA, bodyB } = list;
    for (let n = p; n < previousCount; n++) {
      const k = previousOrder[n];
      if (bodyA[k] !== i || bodyB[k] !== j) break;
      if (list.keyA[k] === keyA && list.keyB[k] === keyB) return this.recycle(k, i, j) ? 1 : 0;
    }
    return 0;
  }

  private collideWorld(i: number, entry: number, shapes: ShapeStore, world: WorldShapes, p: number): number {
    const bodies = this.bodies;
    const rigid = bodies.rigid!;
    const { x, y } = bodies;
    const { c, s, firstShape } = rigid;
    const list = this.current;
    const segments = world.segments;
    const isWall = entry >= WALL_ENTRY;
    const g = isWall ? entry - WALL_ENTRY : entry - SEGMENT_ENTRY;
    const b = isWall
      ? boxWall(world, g, this.shapeB)
      : this.shapeB.segment(segments, g);
    const keyB = isWall ? -1 - g : segments.handleOf(g);
    const otherFriction = isWall ? this.wallFriction : segments.friction[g];
    const otherRestitution = isWall ? this.wallRestitution : segments.restitution[g];
    const otherCategory = isWall ? 0xffffffff : segments.category[g];
    const otherMask = isWall ? 0xffffffff : segments.mask[g];
    p = this.seekEntry(i, entry, this.seek(i, WORLD, p));
    for (let sa = firstShape[i]; sa >= 0; sa = shapes.next[sa]) {
      if ((shapes.category[sa] & otherMask) === 0 || (otherCategory & shapes.mask[sa]) === 0) continue;
      if (shapes.sensor[sa]) continue;
      const pose = list.pose;
      pose[Pose.keyA] = shapes.record[sa * SHAPE_STRIDE + ShapeField.handle];
      pose[Pose.keyB] = keyB;
      const q = this.findWorld(p, i, entry);
      if (q >= 0 && this.recycleDistance > 0 && this.recycle(q, i, WORLD)) continue;
      this.shapePairs++;
      pose[Pose.ax] = x[i];
      pose[Pose.ay] = y[i];
      pose[Pose.ac] = c[i];
      pose[Pose.as] = s[i];
      pose[Pose.bx] = 0;
      pose[Pose.by] = 0;
      pose[Pose.bc] = 1;
      pose[Pose.bs] = 0;
      const a = this.shapeA.fromPose(shapes, sa, pose, Pose.ax);
      const m = this.manifold;
      collide(a, b, m);
      if (!isWall && segments.smooth[g] !== 0) smoothSegment(a, segments, g, m);
      if (m.pointCount === 0) continue;
      const friction = Math.sqrt(shapes.friction[sa] * otherFriction);
      const restitution = Math.max(shapes.restitution[sa], otherRestitution);
      const rolling = shapes.rollingResistance[sa] * Math.max(shapes.radius[sa], b.radius);
      let k = q;
      pose[Pose.friction] = friction;
      pose[Pose.restitution] = restitution;
      pose[Pose.rolling] = rolling;
      if (q >= 0) list.rewrite(q, m);
      else k = list.add(i, WORLD, sa, entry, m);
      list.cache(k);
    }
    return p;
  }

  /** Advances p in last step's order to the first contact of pair (i, j) or beyond it. */
  private seek(i: number, j: number, p: number): number {
    const list = this.current;
    const { previousOrder, previousCount, bodyA, bodyB } = list;
    const jKey = j === WORLD ? Infinity : j;
    while (p < previousCount) {
      const k = previousOrder[p];
      const pi = bodyA[k];
      const pj = bodyB[k] === WORLD ? Infinity : bodyB[k];
      if (pi > i || (pi === i && pj >= jKey)) break;
      p++;
    }
    return p;
  }

  /**
   * Advances p, at body i's first world contact of last step's order or beyond, past those with
   * world entries below `entry`. A body's world pairs come in ascending entry order, in both steps'
   * lists (gatherStatic lists the tree's entries ascending, then the walls), so each of its world
   * pairs looks only at its own entry's contacts: a plank lying across 4,000 segments scanned all
   * of its contacts for each, 50 ms a step.
   */
  private seekEntry(i: number, entry: number, p: number): number {
    const list = this.current;
    const { previousOrder, previousCount, bodyA, bodyB, shapeB } = list;
    while (p < previousCount) {
      const k = previousOrder[p];
      if (bodyA[k] !== i || bodyB[k] !== WORLD || shapeB[k] >= entry) break;
      p++;
    }
    return p;
  }

  /** find for body i's world pair with `entry`: the contacts of that entry alone, from p on (see seekEntry). */
  private findWorld(p: number, i: number, entry: number): number {
    const list = this.current;
    const keyA = list.pose[Pose.keyA];
    const keyB = list.pose[Pose.keyB];
    const { previousOrder, previousCount, bodyA, bodyB, shapeB } = list;
    for (let n = p; n < previousCount; n++) {
      const k = previousOrder[n];
      if (bodyA[k] !== i || bodyB[k] !== WORLD || shapeB[k] !== entry) break;
      if (list.keyA[k] === keyA && list.keyB[k] === keyB) return k;
    }
    return -1;
  }

  /** The slot of last step's contact of the same two shapes (from p on in its order), or -1. */
  private find(p: number, i: number, j: number): number {
    const list = this.current;
    const keyA = list.pose[Pose.keyA];
    const keyB = list.pose[Pose.keyB];
    const { previousOrder, previousCount, bodyA, bodyB } = list;
    for (let n = p; n < previousCount; n++) {
      const k = previousOrder[n];
      if (bodyA[k] !== i || bodyB[k] !== j) break;
      if (list.keyA[k] === keyA && list.keyB[k] === keyB) return k;
    }
    return -1;
  }

  /**
   * Keeps last step's manifold for contact q where it still holds, and says whether it did: Box2D
   * v3's contact recycling. It holds where neither body moved fast, each turned less than about 11
   * degrees since the manifold was computed, and B moved relative to A (its centre, and its
   * farthest point through the turn) less than the recycle distance. Kept manifolds keep their
   * anchors and take their separations from how the anchors moved, as the sub-steps do: resting
   * contacts then do not jitter with each new computation of their points (a stack of 15 boxes
   * leaned 0.23 m without it, Box2D's 0.001), and piles at rest skip the pair functions. The test and the keeping share one reading of the poses and the cache.
   */
  private recycle(q: number, i: number, j: number): boolean {
    const list = this.current;
    const bodies = this.bodies;
    const { x, y, radius, type } = bodies;
    const rigid = bodies.rigid!;
    const { c, s } = rigid;
    const world = j === WORLD;
    if (this.fastBody[i] === 1 || (!world && this.fastBody[j] === 1)) return false;
    const ac = c[i];
    const as = s[i];
    const bc = world ? 1 : c[j];
    const bs = world ? 0 : s[j];
    const r = list.recycle;
    const o = q * RECYCLE;
    const cachedAc = r[o + Recycle.ac];
    const cachedAs = r[o + Recycle.as];
    const cachedBc = r[o + Recycle.bc];
    const cachedBs = r[o + Recycle.bs];
    // Each body's turn since the cache, q q0^-1: its cosines first, for the test.
    const dac = ac * cachedAc + as * cachedAs;
    const dbc = bc * cachedBc + bs * cachedBs;
    if (!(Math.min(dac, dbc) > RECYCLE_COS)) return false;
    const ax = x[i];
    const ay = y[i];
    const bx = world ? 0 : x[j];
    const by = world ? 0 : y[j];
    const dx = bx - ax;
    const dy = by - ay;
    const rx = ac * dx + as * dy;
    const ry = -as * dx + ac * dy;
    const rc = ac * bc + as * bs;
    const rs = ac * bs - as * bc;
    // The relative rotation's change since the cache: sin of the angle between rs/rc and the cached one.
    const turn = rs * r[o + Recycle.c] - rc * r[o + Recycle.s];
    const extentA = type[i] === TypeCode.static ? 0 : radius[i] - this.margin;
    const extentB = world || type[j] === TypeCode.static ? 0 : radius[j] - this.margin;
    const ex = rx - r[o + Recycle.x];
    const ey = ry - r[o + Recycle.y];
    const moved = Math.sqrt(ex * ex + ey * ey);
    if (!(moved + Math.max(extentA, extentB) * Math.abs(turn) < this.recycleDistance)) return false;
    // Kept: listed again with its separations brought up to date, each anchor turned as its body
    // turned since, (dac, das) and (dbc, dbs). Here rather than in a ContactList method, which V8
    // did not inline: the call and the pose passed through memory took the resting pyramid's
    // narrow-phase from 1.37-1.42 to 1.52-1.54 ms.
    const das = as * cachedAc - ac * cachedAs;
    const dbs = bs * cachedBc - bc * cachedBs;
    const n = list.pointCount[q];
    const nx = list.normalX[q];
    const ny = list.normalY[q];
    const pt = list.points;
    for (let p = 0; p < n; p++) {
      const at = (2 * q + p) * POINT_STRIDE;
      const rAx0 = pt[at + ContactPoint.anchorAX];
      const rAy0 = pt[at + ContactPoint.anchorAY];
      const rBx0 = pt[at + ContactPoint.anchorBX];
      const rBy0 = pt[at + ContactPoint.anchorBY];
      const rAx = dac * rAx0 - das * rAy0;
      const rAy = das * rAx0 + dac * rAy0;
      const rBx = dbc * rBx0 - dbs * rBy0;
      const rBy = dbs * rBx0 + dbc * rBy0;
      pt[at + ContactPoint.separation] = pt[at + ContactPoint.baseSeparation] + (dx + rBx - rAx) * nx + (dy + rBy - rAy) * ny;
      pt[at + ContactPoint.x] = ax + rAx;
      pt[at + ContactPoint.y] = ay + rAy;
      pt[at + ContactPoint.totalNormalImpulse] = 0;
      pt[at + ContactPoint.approachSpeed] = 0;
    }
    list.keep(q);
    this.recycled++;
    return true;
  }

  /**
   * Notes the bodies whose contacts are always recomputed (fastBody): those that move more than
   * half their smallest extent in a step, and bullets.
   */
  private noteFastBodies(): void {
    const bodies = this.bodies;
    const { vx, vy, radius, type, slotCount } = bodies;
    const rigid = bodies.rigid!;
    const { angularVelocity, flags, minExtent } = rigid;
    if (this.fastBody.length < slotCount) this.fastBody = new Uint8Array(grownCapacity(this.fastBody.length, slotCount));
    const fastBody = this.fastBody;
    for (let i = 0; i < slotCount; i++) {
      if (type[i] === TypeCode.static || type[i] === TypeCode.free) {
        fastBody[i] = 0;
        continue;
      }
      const v = Math.sqrt(vx[i] * vx[i] + vy[i] * vy[i]) + (radius[i] - this.margin) * Math.abs(angularVelocity[i]);
      fastBody[i] = (flags[i] & BodyFlag.bullet) !== 0 || v * this.dt > 0.5 * minExtent[i] ? 1 : 0;
    }
    for (let k = 0; k < this.forgottenCount; k++) {
      const slot = this.forgotten[k];
      if (slot < slotCount) fastBody[slot] = 1;
    }
  }
}
