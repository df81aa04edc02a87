import { allocateLike, grownCapacity, grow, type Column } from '../util/grow.js';
import type { Manifold } from './manifold.js';

/** `bodyB` of a contact with a world shape (a segment or a wall of the box) rather than a body. */
export const WORLD = -1;

/**
 * The step's contacts between shapes. Each contact lives in a slot that it keeps for as long as
 * its two shapes touch, step after step (Box2D's persistent contacts); `order` lists this step's
 * slots in the canonical order: by (body A slot, body B slot), a contact with a world shape after
 * every contact of its body with bodies, then by shape pair in the bodies' shape order. Stages
 * walk `order`, so results depend on that order alone, never on which slot a contact got.
 *
 * Each slot holds its manifold (normal, one or two points with anchors relative to each body's
 * centre of mass: a manifold without points is never listed, which the soft step's kernel relies
 * on) and what the solver accumulated on it. A contact whose manifold is kept
 * (see ShapeNarrowPhase.recycle) is updated where it lies, a few fields, instead of
 * being copied into a new list: piles at rest keep nearly all their contacts, and copying a
 * contact's forty-odd fields was a third of a 5,050-box pyramid's narrow-phase. A recomputed one
 * (`rewrite`) inherits its impulses point by point where the same features touch again (warm
 * starting); a new one (`add`) starts from none. Where the slots of a list lie scattered against
 * its order, the next step begins by moving them into it, once (see compact).
 *
 * Keys: body slots, and shape handles (ShapeStore's, with generation; for a world shape its
 * segment handle or wall code), so that a reused slot never passes its impulses to a newcomer.
 */
/**
 * A contact point's record (ContactList.points): its anchors from each centre of mass, its
 * separation, the impulses the solver kept on it, the largest normal impulse of the step (whether
 * it really collided: restitution, events), the approach speed before the solve (positive when
 * approaching, for hit events), its world position, and its separation when the manifold was
 * computed (for recycling).
 */
export const ContactPoint = {
  anchorAX: 0,
  anchorAY: 1,
  anchorBX: 2,
  anchorBY: 3,
  separation: 4,
  normalImpulse: 5,
  tangentImpulse: 6,
  totalNormalImpulse: 7,
  approachSpeed: 8,
  x: 9,
  y: 10,
  baseSeparation: 11,
} as const;
export const POINT_STRIDE = 12;

// The fields as this module's own constants, which V8 folds into the code (see joint-layout.ts).
const { anchorAX: AAX, anchorAY: AAY, anchorBX: ABX, anchorBY: ABY, separation: SEPARATION, normalImpulse: NORMAL_IMPULSE, tangentImpulse: TANGENT_IMPULSE, totalNormalImpulse: TOTAL_NORMAL_IMPULSE, approachSpeed: APPROACH_SPEED, x: PX, y: PY, baseSeparation: BASE_SEPARATION } = ContactPoint;

/** A contact's recycling record (ContactList.recycle): A's and B's rotations, and B's centre and rotation in A's frame. */
export const Recycle = { ac: 0, as: 1, bc: 2, bs: 3, x: 4, y: 5, c: 6, s: 7 } as const;
export const RECYCLE = 8;

/**
 * Where the narrow-phase leaves a pair's poses and material for `add`, `rewrite` and `cache`
 * (ContactList.pose): in a typed array rather than as arguments, since V8 boxes each number passed
 * to a call it does not inline, an allocation apiece, per pair and step.
 */
export const Pose = { ax: 0, ay: 1, ac: 2, as: 3, bx: 4, by: 5, bc: 6, bs: 7, friction: 8, restitution: 9, rolling: 10, keyA: 11, keyB: 12 } as const;

/** Where compact considers moving the contacts: every this many steps at most, lists of at least this many. */
const COMPACT_EVERY = 8;
const COMPACT_MIN = 64;

let compacting = true;
/** Whether contact lists move scattered contacts into their order (see ContactList.compact): for tests that compare the bits with and without. */
export function setContactCompaction(on: boolean): void {
  compacting = on;
}

/** Every per-slot column, with its doubles (or integers) per slot: what grow sizes and compact moves. */
const COLUMNS = [
  ['bodyA', 1],
  ['bodyB', 1],
  ['shapeA', 1],
  ['shapeB', 1],
  ['keyA', 1],
  ['keyB', 1],
  ['pointCount', 1],
  ['normalX', 1],
  ['normalY', 1],
  ['friction', 1],
  ['restitution', 1],
  ['rollingResistance', 1],
  ['rollingImpulse', 1],
  ['points', 2 * POINT_STRIDE],
  ['id', 2],
  ['recycle', RECYCLE],
  ['kept', 1],
  ['listed', 1],
] as const;
type ColumnName = (typeof COLUMNS)[number][0];

export class ContactList {
  /** The pair's poses, A's then B's (x, y, cosine, sine), its friction, restitution and rolling resistance, and its shapes' keys: see Pose. */
  readonly pose = new Float64Array(13);
  /** Contacts this step: order[0, count). */
  count = 0;
  /** This step's contact slots, in canonical order. */
  order = new Int32Array(0);
  /** Last step's, while the narrow-phase builds this one (see begin). */
  previousOrder = new Int32Array(0);
  previousCount = 0;
  bodyA = new Int32Array(0);
  bodyB = new Int32Array(0);
  shapeA = new Int32Array(0);
  /** ShapeStore slot, or for a world contact the world-shape entry id. */
  shapeB = new Int32Array(0);
  keyA = new Float64Array(0);
  keyB = new Float64Array(0);
  pointCount = new Uint8Array(0);
  normalX = new Float64Array(0);
  normalY = new Float64Array(0);
  friction = new Float64Array(0);
  restitution = new Float64Array(0);
  rollingResistance = new Float64Array(0);
  rollingImpulse = new Float64Array(0);
  /**
   * Two points per contact, point p of contact k at 2k + p: its fields (CONTACT_POINT, see
   * ContactPoint) in one record of POINT_STRIDE doubles, since the solver's preparation and
   * recycling read most of a point's fields at once; and its feature id.
   */
  points = new Float64Array(0);
  id = new Int32Array(0);
  /**
   * For recycling (see ShapeNarrowPhase): per contact, RECYCLE doubles (see Recycle), the two
   * bodies' rotations when the manifold was last computed and B's centre and rotation relative
   * to A then, in one run of memory, since recycling reads them all of a contact at once.
   */
  recycle = new Float64Array(0);
  /**
   * Per contact, 1 where this step's list kept its manifold from last step's (see keep): its
   * normal, anchors, material and point count are those the solver last prepared it with.
   */
  kept = new Uint8Array(0);
  private capacity = 0;
  /** Slots handed out so far; those below it not in use are on the free list. */
  private slotCount = 0;
  private freeSlots = new Int32Array(0);
  private freeCount = 0;
  /** The step a slot was last listed in (see begin), so that finish frees the rest. */
  private listed = new Uint32Array(0);
  private epoch = 0;
  /** How many steps' lists this list has begun (see begin): a solver that keeps what it made of a list checks that it saw the one before. */
  get steps(): number {
    return this.epoch;
  }
  /**
   * Whether this step's list is last step's: the same contacts in the same slots (set by finish).
   * The soft step then keeps its colouring, which depends on nothing else but the awake bodies.
   */
  unchanged = false;
  /** Contacts added since begin, and whether begin moved the slots (compact). */
  private added = 0;
  private moved = false;
  /** How many times compact has moved the contacts. */
  compactions = 0;
  /** The step of the last compact, and the columns it swapped out, reused by the next. */
  private compactedAt = 0;
  private readonly spare: Partial<Record<ColumnName, Column>> = {};

  /**
   * Starts a step's list: this step's order becomes last step's, and the new one is empty. Where
   * last step's slots lie scattered (see compact), they are first moved into its order.
   */
  begin(): void {
    this.added = 0;
    this.moved = false;
    if (compacting && this.epoch - this.compactedAt >= COMPACT_EVERY && this.scattered()) this.compact();
    const last = this.order;
    this.order = this.previousOrder;
    this.previousOrder = last;
    this.previousCount = this.count;
    this.count = 0;
    this.epoch++;
    if (this.order.length < this.previousOrder.length) this.order = new Int32Array(this.previousOrder.length);
  }

  /** Whether more than a quarter of the listed contacts do not follow the one before them in memory. */
  private scattered(): boolean {
    const { order, count } = this;
    if (count < COMPACT_MIN) return false;
    let breaks = 0;
    for (let n = 1; n < count; n++) if (order[n] !== order[n - 1] + 1) breaks++;
    return 4 * breaks > count;
  }

  /**
   * Moves the listed contacts into slots 0..count-1 in their canonical order, every column at once,
   * and frees the rest. Slots keep a contact for as long as it lasts, so a pile that formed as
   * bodies fell holds its contacts in the order they began, scattered against the canonical order
   * in which every stage walks them (recycling, the solver's preparation, storing its impulses):
   * each contact a cache miss. Only the order matters to the results, never the slot, so the bits
   * stay the same. 4,000 boxes settled into a pile: a contact followed the one before it in memory
   * for 1 % of the pile's 10,000, and for 82 % with the moves, as contacts come and go between
   * them (docs/engine.md, "Performance with shapes").
   */
  private compact(): void {
    const { order, count } = this;
    this.compactedAt = this.epoch;
    this.compactions++;
    this.moved = true;
    const self = this as unknown as Record<ColumnName, Column>;
    for (let c = 0; c < COLUMNS.length; c++) {
      const name = COLUMNS[c][0];
      const stride = COLUMNS[c][1];
      const from = self[name];
      let into = this.spare[name];
      if (into === undefined || into.length !== from.length) into = allocateLike(from, from.length);
      for (let n = 0; n < count; n++) {
        const source = order[n] * stride;
        const target = n * stride;
        for (let f = 0; f < stride; f++) into[target + f] = from[source + f];
      }
      this.spare[name] = from;
      self[name] = into;
    }
    for (let n = 0; n < count; n++) order[n] = n;
    this.slotCount = count;
    this.freeCount = 0;
  }

  /** Frees the slots of last step's contacts that this step did not list. */
  finish(): void {
    const { previousOrder, listed, epoch } = this;
    const count = this.previousCount;
    // Nothing added, nothing moved and as many as last step: last step's contacts, every one, in
    // the same slots and so in the same order.
    this.unchanged = this.added === 0 && !this.moved && this.count === count;
    // Before the loop, so that nothing follows it (see ShapeNarrowPhase.collidePairs).
    this.previousCount = 0;
    for (let n = 0; n < count; n++) {
      const k = previousOrder[n];
      if (listed[k] !== epoch) this.freeSlots[this.freeCount++] = k;
    }
  }

  /** Drops every contact (a world whose contacts no longer mean anything, say after a reset). */
  clear(): void {
    this.unchanged = false;
    this.count = 0;
    this.previousCount = 0;
    this.slotCount = 0;
    this.freeCount = 0;
  }

  /**
   * A new contact with its manifold, listed next; points get their anchors from the two centres
   * of mass in `pose`, with its material and keys, and start with no impulse. Returns its slot.
   */
  add(bodyA: number, bodyB: number, shapeA: number, shapeB: number, m: Manifold): number {
    const pose = this.pose;
    const keyA = pose[Pose.keyA];
    const keyB = pose[Pose.keyB];
    let k: number;
    this.added++;
    if (this.freeCount > 0) k = this.freeSlots[--this.freeCount];
    else {
      if (this.slotCount === this.capacity) this.grow(this.slotCount + 1);
      k = this.slotCount++;
    }
    this.bodyA[k] = bodyA;
    this.bodyB[k] = bodyB;
    this.shapeA[k] = shapeA;
    this.shapeB[k] = shapeB;
    this.keyA[k] = keyA;
    this.keyB[k] = keyB;
    this.friction[k] = pose[Pose.friction];
    this.restitution[k] = pose[Pose.restitution];
    this.rollingResistance[k] = pose[Pose.rolling];
    this.rollingImpulse[k] = 0;
    this.write(k, m);
    for (let p = 0; p < m.pointCount; p++) {
      const o = (2 * k + p) * POINT_STRIDE;
      this.points[o + NORMAL_IMPULSE] = 0;
      this.points[o + TANGENT_IMPULSE] = 0;
    }
    this.list(k);
    return k;
  }

  /**
   * Contact k, listed last step, with a manifold computed anew, listed next: each new point takes
   * the impulses of the old point with the same feature id, others start from none; so does the
   * rolling impulse.
   */
  rewrite(k: number, m: Manifold): void {
    const oldCount = this.pointCount[k];
    const id0 = this.id[2 * k];
    const id1 = this.id[2 * k + 1];
    const pt = this.points;
    const o0 = 2 * k * POINT_STRIDE;
    const normal0 = pt[o0 + NORMAL_IMPULSE];
    const normal1 = pt[o0 + POINT_STRIDE + NORMAL_IMPULSE];
    const tangent0 = pt[o0 + TANGENT_IMPULSE];
    const tangent1 = pt[o0 + POINT_STRIDE + TANGENT_IMPULSE];
    this.write(k, m);
    for (let p = 0; p < m.pointCount; p++) {
      const o = (2 * k + p) * POINT_STRIDE;
      const id = m.id[p];
      if (oldCount > 0 && id0 === id) {
        pt[o + NORMAL_IMPULSE] = normal0;
        pt[o + TANGENT_IMPULSE] = tangent0;
      } else if (oldCount > 1 && id1 === id) {
        pt[o + NORMAL_IMPULSE] = normal1;
        pt[o + TANGENT_IMPULSE] = tangent1;
      } else {
        pt[o + NORMAL_IMPULSE] = 0;
        pt[o + TANGENT_IMPULSE] = 0;
      }
    }
    this.list(k);
  }

  /** Lists contact k, listed last step, with its manifold kept (see ShapeNarrowPhase.recycle). */
  keep(k: number): void {
    this.list(k);
    this.kept[k] = 1;
  }

  /** Lists contact k in this step's order, with a manifold computed this step. */
  private list(k: number): void {
    if (this.count === this.order.length) this.order = grow(this.order, grownCapacity(this.order.length, this.count + 1));
    this.order[this.count++] = k;
    this.listed[k] = this.epoch;
    this.kept[k] = 0;
  }

  /** Slot k's manifold: normal, points, anchors from the centres (ax, ay), (bx, by), separations, ids. */
  private write(k: number, m: Manifold): void {
    const pose = this.pose;
    const ax = pose[Pose.ax];
    const ay = pose[Pose.ay];
    const bx = pose[Pose.bx];
    const by = pose[Pose.by];
    const n = m.pointCount;
    this.pointCount[k] = n;
    this.normalX[k] = m.normalX;
    this.normalY[k] = m.normalY;
    const pt = this.points;
    for (let p = 0; p < n; p++) {
      const at = 2 * k + p;
      const o = at * POINT_STRIDE;
      const px = m.x[p];
      const py = m.y[p];
      pt[o + PX] = px;
      pt[o + PY] = py;
      pt[o + AAX] = px - ax;
      pt[o + AAY] = py - ay;
      pt[o + ABX] = px - bx;
      pt[o + ABY] = py - by;
      pt[o + SEPARATION] = m.separation[p];
      pt[o + BASE_SEPARATION] = m.separation[p];
      this.id[at] = m.id[p];
      pt[o + TOTAL_NORMAL_IMPULSE] = 0;
      pt[o + APPROACH_SPEED] = 0;
    }
  }

  /** Notes the poses the manifold of contact k was computed at (centres and rotations of A and B, in `pose`). */
  cache(k: number): void {
    const pose = this.pose;
    const ax = pose[Pose.ax];
    const ay = pose[Pose.ay];
    const ac = pose[Pose.ac];
    const as = pose[Pose.as];
    const bx = pose[Pose.bx];
    const by = pose[Pose.by];
    const bc = pose[Pose.bc];
    const bs = pose[Pose.bs];
    const r = this.recycle;
    const o = k * RECYCLE;
    r[o + Recycle.ac] = ac;
    r[o + Recycle.as] = as;
    r[o + Recycle.bc] = bc;
    r[o + Recycle.bs] = bs;
    const dx = bx - ax;
    const dy = by - ay;
    // B's centre and rotation in A's frame.
    r[o + Recycle.x] = ac * dx + as * dy;
    r[o + Recycle.y] = -as * dx + ac * dy;
    r[o + Recycle.c] = ac * bc + as * bs;
    r[o + Recycle.s] = ac * bs - as * bc;
  }

  memoryBytes(): number {
    let spare = 0;
    for (const [name] of COLUMNS) spare += this.spare[name]?.byteLength ?? 0;
    return this.capacity * (4 * 4 + 8 * 2 + 1 + 8 * 14 + 4 + 4 + 1) + 2 * this.capacity * (8 * POINT_STRIDE + 4) + this.order.byteLength + this.previousOrder.byteLength + spare;
  }

  private grow(needed: number): void {
    const c = grownCapacity(this.capacity, needed);
    const self = this as unknown as Record<ColumnName, Column>;
    for (let k = 0; k < COLUMNS.length; k++) self[COLUMNS[k][0]] = grow(self[COLUMNS[k][0]], COLUMNS[k][1] * c);
    this.freeSlots = grow(this.freeSlots, c);
    this.capacity = c;
  }

}
