import { TypeCode, ShapeCode } from './body-types.js';
import { grownCapacity, grow, type Column } from '../util/grow.js';
import { BodyKernel } from './body-kernel.js';
import { JOINT_HANDLES, MAX_GENERATION, SEGMENT_HANDLES, SHAPE_HANDLES, SLOT_SPACE } from './handles.js';
import { BodyFlag, RigidColumns } from './rigid-columns.js';
import { MAX_MAGNITUDE } from '../util/validate.js';

export { SLOT_SPACE, MAX_GENERATION, SEGMENT_HANDLES } from './handles.js';
/** A mask with every collision layer. */
const ALL_LAYERS = 0xffffffff;

export interface NewBody {
  x: number;
  y: number;
  vx: number;
  vy: number;
  radius: number;
  mass: number;
  restitution: number;
  type: number;
  category: number;
  mask: number;
  gravityScale: number;
  linearDamping: number;
}

/** Every column, widest elements first so that each starts aligned in a kernel's memory. */
const COLUMN_NAMES = [
  'x', 'y', 'vx', 'vy', 'radius', 'mass', 'invMass', 'restitution', 'gravityScale', 'linearDamping', 'forceX', 'forceY',
  'generation', 'category', 'mask', 'sleepTime',
  'type', 'shape', 'asleep',
] as const;
type ColumnName = (typeof COLUMN_NAMES)[number];

/**
 * Structure-of-arrays body storage indexed by slot. Slots are the engine's canonical body order:
 * they never move while a body lives, so anything ordered by slot is independent of how a
 * broad-phase happened to find it. Destroyed slots stay in place as holes (type FREE) and are
 * reused last-freed-first, which is deterministic.
 *
 * Float64 everywhere on the hot state: the engine promises energy conservation to round-off and
 * bit-identical results, and Float32 would spend that on 8 bytes per column.
 *
 * The columns live in one WebAssembly memory where the runtime has it (see BodyKernel), shared
 * when a parallel step is attached, so that the plain stages can run there; they are ordinary
 * typed arrays to everything else.
 */
export class BodyStore {
  capacity = 0;
  /** One past the highest slot ever used: stages loop over [0, slotCount) and skip FREE. */
  slotCount = 0;
  liveCount = 0;

  x = new Float64Array(0);
  y = new Float64Array(0);
  vx = new Float64Array(0);
  vy = new Float64Array(0);
  radius = new Float64Array(0);
  mass = new Float64Array(0);
  /** 1/mass for dynamic bodies, 0 for static and kinematic ones (infinitely massive). */
  invMass = new Float64Array(0);
  restitution = new Float64Array(0);
  type = new Uint8Array(0);
  shape = new Uint8Array(0);
  generation = new Uint32Array(0);

  // Colder columns: read by the general integrator, the narrow-phase filter and the sleep stage.
  /** Collision layers: a pair collides only if each body's category is in the other's mask. */
  category = new Uint32Array(0);
  mask = new Uint32Array(0);
  gravityScale = new Float64Array(0);
  linearDamping = new Float64Array(0);
  /** Forces accumulated by applyForce until the next step, which applies and clears them. */
  forceX = new Float64Array(0);
  forceY = new Float64Array(0);
  /** Seconds a dynamic body has been slower than the sleep speed. */
  sleepTime = new Float32Array(0);
  /** 1 while a dynamic body sleeps: it is not integrated and pairs of sleepers are skipped. */
  asleep = new Uint8Array(0);

  /** Bodies whose gravity scale or damping differ from the defaults: they need the general integrator. */
  customMotionCount = 0;
  /** Bodies currently asleep. */
  sleepingCount = 0;
  /** Static bodies: continuous collision sweeps fast bodies against them. */
  staticCount = 0;
  /** Kinematic bodies: with static ones and sleepers, pairs the narrow-phase may drop (everyPairCollides). */
  kinematicCount = 0;
  /** Bodies whose collision filter can refuse a pair: a mask without every bit, or no category bit. */
  selectiveFilterCount = 0;
  /** True between applyForce and the next step. */
  forcesPending = false;
  /**
   * The circle route's speed limit for this step's motion, where the world was given one
   * (maxLinearSpeed) and a body may pass it within the step (see World.limitMotion): the motion
   * then takes the general loop, which moves no dynamic body faster (see moveVelocity).
   * MAX_MAGNITUDE for none; the shape route passes its own limit to its integration.
   */
  speedCap = MAX_MAGNITUDE;
  /**
   * The world's box, when it has one: from the boundary stage on, every live centre lies inside
   * it, so grids can be laid over it without measuring the bodies' extent.
   */
  box: { width: number; height: number } | null = null;
  /** Bumped whenever the set of live bodies changes, for structures that persist between steps. */
  membershipVersion = 0;
  /** Bumped whenever a live body becomes static or stops being static (membershipVersion covers the rest). */
  staticFlips = 0;
  /** Bumped whenever the columns are reallocated: worker threads then need the new buffers. */
  layoutVersion = 0;
  /** Columns live on SharedArrayBuffers (a parallel step is attached). */
  shared = false;
  /**
   * The columns' WebAssembly memory and the stages' kernel over it, or null: columns then are
   * plain (or shared) typed arrays and every stage runs its TypeScript loop.
   */
  kernel: BodyKernel | null = null;
  /**
   * Orientation, angular velocity, inertia and shape lists, allocated once a body turns or has
   * shapes (see RigidColumns); null in a world of the report's circles.
   */
  rigid: RigidColumns | null = null;
  /**
   * Static bodies are kept out of the broad-phase and found through the static index instead
   * (set once a world has shapes): then `proxyCount` and the radius range count moving bodies only.
   */
  staticsApart = false;

  private freeSlots = new Int32Array(0);
  private freeCount = 0;

  /** Radius range of live bodies, kept incrementally and recomputed lazily after removals. */
  private cachedMaxRadius = 0;
  private cachedMinRadius = Infinity;
  private radiusRangeStale = false;

  constructor(initialCapacity = 0) {
    if (initialCapacity > 0) this.grow(initialCapacity);
  }

  /** Writes slot's handle into out[at] (see SlotOwner: a handle passed through memory is never boxed). */
  writeHandle(slot: number, out: Float64Array, at: number): void {
    out[at] = this.handleOf(slot);
  }

  /** Whether slot's handle is handles[at] (see SlotOwner). */
  holdsHandle(slot: number, handles: Float64Array, at: number): boolean {
    return this.handleOf(slot) === handles[at];
  }

  handleOf(slot: number): number {
    return this.generation[slot] * SLOT_SPACE + slot;
  }

  /** The slot of a live body's handle, or -1 for an unknown or stale one. */
  slotOf(handle: number): number {
    if (!Number.isSafeInteger(handle) || handle < 0) return -1;
    const slot = handle % SLOT_SPACE;
    const gen = (handle - slot) / SLOT_SPACE;
    if (slot >= this.slotCount || this.type[slot] === TypeCode.free || this.generation[slot] !== gen) return -1;
    return slot;
  }

  /** Explains why `slotOf` refused a handle, for error messages. */
  describeMissing(handle: number): string {
    if (!Number.isSafeInteger(handle) || handle < 0) return 'is not a body handle';
    if (handle >= JOINT_HANDLES) return 'is a joint handle, not a body handle';
    if (handle >= SHAPE_HANDLES) return 'is a shape handle, not a body handle';
    if (handle >= SEGMENT_HANDLES) return 'is a segment handle, not a body handle';
    const slot = handle % SLOT_SPACE;
    const gen = (handle - slot) / SLOT_SPACE;
    if (slot >= this.slotCount || gen > this.generation[slot]) return 'is unknown to this world';
    return 'is stale: its body was destroyed';
  }

  /** Whether `add` has a slot to give: a free one, or one below SLOT_SPACE. */
  hasRoom(): boolean {
    return this.freeCount > 0 || this.slotCount < SLOT_SPACE;
  }

  add(body: NewBody): number {
    let slot: number;
    if (this.freeCount > 0) {
      slot = this.freeSlots[--this.freeCount];
    } else {
      if (this.slotCount === this.capacity) this.grow(this.slotCount + 1);
      slot = this.slotCount++;
    }
    this.x[slot] = body.x;
    this.y[slot] = body.y;
    this.vx[slot] = body.vx;
    this.vy[slot] = body.vy;
    this.radius[slot] = body.radius;
    this.mass[slot] = body.mass;
    this.restitution[slot] = body.restitution;
    this.shape[slot] = ShapeCode.circle;
    // Open first (a fresh slot holds zeros), so that setFilter counts this body from nothing.
    this.category[slot] = 1;
    this.mask[slot] = ALL_LAYERS;
    this.setFilter(slot, body.category, body.mask);
    this.gravityScale[slot] = body.gravityScale;
    this.linearDamping[slot] = body.linearDamping;
    this.forceX[slot] = 0;
    this.forceY[slot] = 0;
    this.sleepTime[slot] = 0;
    this.asleep[slot] = 0;
    if (body.gravityScale !== 1 || body.linearDamping !== 0) this.customMotionCount++;
    this.setTypeCode(slot, body.type);
    this.rigid?.clear(slot);
    this.liveCount++;
    this.membershipVersion++;
    if (this.isProxyType(body.type)) {
      if (body.radius > this.cachedMaxRadius) this.cachedMaxRadius = body.radius;
      if (body.radius < this.cachedMinRadius) this.cachedMinRadius = body.radius;
    }
    return slot;
  }

  remove(slot: number): void {
    if (this.hasCustomMotion(slot)) this.customMotionCount--;
    this.wake(slot);
    // Out of the counts: a freed slot keeps an open filter, which add() then counts from.
    this.setFilter(slot, 1, ALL_LAYERS);
    this.countType(this.type[slot], -1);
    this.type[slot] = TypeCode.free;
    this.vx[slot] = 0;
    this.vy[slot] = 0;
    this.invMass[slot] = 0;
    this.liveCount--;
    this.membershipVersion++;
    const r = this.radius[slot];
    if (r === this.cachedMaxRadius || r === this.cachedMinRadius) this.radiusRangeStale = true;
    const nextGeneration = this.generation[slot] + 1;
    // A slot whose generation would overflow the handle encoding is retired rather than reused.
    if (nextGeneration < MAX_GENERATION) {
      this.generation[slot] = nextGeneration;
      if (this.freeCount === this.freeSlots.length) {
        this.freeSlots = grow(this.freeSlots, grownCapacity(this.freeSlots.length, this.freeCount + 1));
      }
      this.freeSlots[this.freeCount++] = slot;
    }
  }

  setMotion(slot: number, gravityScale: number, linearDamping: number): void {
    const wasCustom = this.hasCustomMotion(slot);
    this.gravityScale[slot] = gravityScale;
    this.linearDamping[slot] = linearDamping;
    this.customMotionCount += Number(this.hasCustomMotion(slot)) - Number(wasCustom);
  }

  /** Sets a body's angular damping (rotation columns in use), keeping customMotionCount. */
  setAngularDamping(slot: number, damping: number): void {
    const wasCustom = this.hasCustomMotion(slot);
    this.rigid!.angularDamping[slot] = damping;
    this.customMotionCount += Number(this.hasCustomMotion(slot)) - Number(wasCustom);
  }

  /** Whether the body's motion is more than velocity plus the world's gravity (see customMotionCount). */
  private hasCustomMotion(slot: number): boolean {
    return this.gravityScale[slot] !== 1 || this.linearDamping[slot] !== 0 || (this.rigid !== null && this.rigid.angularDamping[slot] !== 0);
  }

  /** Wakes a body, and with it every body of the island it fell asleep with (see RigidColumns.islandNext). */
  wake(slot: number): void {
    this.sleepTime[slot] = 0;
    if (this.asleep[slot]) {
      this.asleep[slot] = 0;
      this.sleepingCount--;
    }
    const rigid = this.rigid;
    if (rigid === null || rigid.islandNext[slot] < 0) return;
    let s = rigid.islandNext[slot];
    rigid.islandNext[slot] = -1;
    while (s !== slot && s >= 0) {
      const next = rigid.islandNext[s];
      rigid.islandNext[s] = -1;
      this.sleepTime[s] = 0;
      if (this.asleep[s]) {
        this.asleep[s] = 0;
        this.sleepingCount--;
      }
      s = next;
    }
  }

  fallAsleep(slot: number): void {
    if (this.asleep[slot]) return;
    this.asleep[slot] = 1;
    this.sleepingCount++;
    this.vx[slot] = 0;
    this.vy[slot] = 0;
    if (this.rigid) this.rigid.angularVelocity[slot] = 0;
  }

  setTypeCode(slot: number, code: number): void {
    this.wake(slot);
    const previous = this.type[slot];
    this.countType(previous, -1);
    this.countType(code, 1);
    this.type[slot] = code;
    this.invMass[slot] = code === TypeCode.dynamic ? 1 / this.mass[slot] : 0;
    if (code === TypeCode.static) {
      this.vx[slot] = 0;
      this.vy[slot] = 0;
    }
    const rigid = this.rigid;
    if (rigid) {
      rigid.invInertia[slot] = code === TypeCode.dynamic ? inverseInertia(rigid, slot) : 0;
      if (code === TypeCode.static) rigid.angularVelocity[slot] = 0;
    }
    if (previous !== TypeCode.free && (previous === TypeCode.static) !== (code === TypeCode.static)) this.staticFlips++;
    if (this.staticsApart && previous !== TypeCode.free && (previous === TypeCode.static) !== (code === TypeCode.static)) {
      this.membershipVersion++;
      this.radiusRangeStale = true;
    }
  }

  /** Sets a body's mass and rotational inertia (from its shapes), and their inverses for its type. */
  setMass(slot: number, mass: number, inertia: number): void {
    this.mass[slot] = mass;
    this.invMass[slot] = this.type[slot] === TypeCode.dynamic ? 1 / mass : 0;
    const rigid = this.rigid;
    if (!rigid) return;
    rigid.inertia[slot] = inertia;
    rigid.invInertia[slot] = this.type[slot] === TypeCode.dynamic ? inverseInertia(rigid, slot) : 0;
  }

  private countType(code: number, change: number): void {
    if (code === TypeCode.static) this.staticCount += change;
    else if (code === TypeCode.kinematic) this.kinematicCount += change;
  }

  /** Sets a live body's collision layers (see World.setCollisionFilter), keeping selectiveFilterCount. */
  setFilter(slot: number, category: number, mask: number): void {
    const wasSelective = this.mask[slot] !== ALL_LAYERS || this.category[slot] === 0;
    const isSelective = mask !== ALL_LAYERS || category === 0;
    this.selectiveFilterCount += Number(isSelective) - Number(wasSelective);
    this.category[slot] = category;
    this.mask[slot] = mask;
  }

  /**
   * True when the narrow-phase would pass every pair of live bodies to the circle test alone: every
   * body dynamic and awake, and every filter open (each body has a category bit, and every mask
   * has every bit). Only circles exist today; polygons will add their shape count here.
   */
  get everyPairCollides(): boolean {
    return this.staticCount === 0 && this.kinematicCount === 0 && this.sleepingCount === 0 && this.selectiveFilterCount === 0;
  }

  /** Bodies the broad-phase covers: every live body, or every non-static one when statics are apart. */
  get proxyCount(): number {
    return this.staticsApart ? this.liveCount - this.staticCount : this.liveCount;
  }

  /** Whether a body of this type code is in the broad-phase (see staticsApart). */
  isProxyType(code: number): boolean {
    return code !== TypeCode.free && !(this.staticsApart && code === TypeCode.static);
  }

  /** Allocates the rotational columns (identity rotation, no spin) if they are not yet there. */
  useRigid(): RigidColumns {
    if (this.rigid) return this.rigid;
    const rigid = new RigidColumns();
    rigid.reserve(this.capacity);
    this.rigid = rigid;
    return rigid;
  }

  /** Changes a live body's broad-phase radius (its shapes changed). */
  setRadius(slot: number, r: number): void {
    this.radius[slot] = r;
    this.radiusRangeStale = true;
    this.membershipVersion++;
  }

  /** Keeps static bodies out of the broad-phase from now on (see staticsApart). */
  setStaticsApart(): void {
    if (this.staticsApart) return;
    this.staticsApart = true;
    this.radiusRangeStale = true;
    this.membershipVersion++;
  }

  minRadius(): number {
    this.refreshRadiusRange();
    return this.cachedMinRadius;
  }

  maxRadius(): number {
    this.refreshRadiusRange();
    return this.cachedMaxRadius;
  }

  /** Radii change only with a body's shapes (setRadius), so removals and those make the cached range stale. */
  private refreshRadiusRange(): void {
    if (!this.radiusRangeStale) return;
    let max = 0;
    let min = Infinity;
    const { radius, type } = this;
    for (let i = 0; i < this.slotCount; i++) {
      if (!this.isProxyType(type[i])) continue;
      if (radius[i] > max) max = radius[i];
      if (radius[i] < min) min = radius[i];
    }
    this.cachedMaxRadius = max;
    this.cachedMinRadius = min;
    this.radiusRangeStale = false;
  }

  memoryBytes(): number {
    if (this.kernel) return this.kernel.memoryBytes() + this.freeSlots.byteLength;
    return (
      this.x.byteLength * 12 +
      this.type.byteLength * 3 +
      this.generation.byteLength * 3 +
      this.sleepTime.byteLength +
      this.freeSlots.byteLength
    );
  }

  /** Makes room for `needed` slots up front, so that adding them never reallocates. */
  reserve(needed: number): void {
    if (needed > this.capacity) this.grow(needed);
  }

  /**
   * Moves every column onto shared memory (or back), for the threads of a parallel step. Views
   * taken earlier (World.views) go stale, as after any growth.
   */
  setShared(shared: boolean): void {
    if (shared === this.shared) return;
    this.shared = shared;
    this.reallocate(this.capacity);
  }

  private grow(needed: number): void {
    this.reallocate(grownCapacity(this.capacity, needed));
  }

  private reallocate(capacity: number): void {
    const shared = this.shared;
    const columns = this as unknown as Record<ColumnName, Column>;
    const bytesPerBody = COLUMN_NAMES.reduce((sum, name) => sum + columns[name].BYTES_PER_ELEMENT, 0);
    const kernel = BodyKernel.create(capacity, bytesPerBody, COLUMN_NAMES.length, shared);
    for (const name of COLUMN_NAMES) {
      columns[name] = kernel ? kernel.place(columns[name], capacity) : grow(columns[name], capacity, shared);
    }
    kernel?.bind(this);
    this.kernel = kernel;
    this.rigid?.reserve(capacity);
    this.capacity = capacity;
    this.layoutVersion++;
  }
}

/** 1 / inertia for a dynamic body free to turn; 0 for one with fixed rotation or no inertia. */
function inverseInertia(rigid: RigidColumns, slot: number): number {
  const inertia = rigid.inertia[slot];
  // An inertia rounded to a subnormal (a dense shape 1e-100 across) has no finite inverse: such a
  // body does not turn, as one whose inertia rounded to 0.
  const inverse = 1 / inertia;
  return inertia > 0 && inverse < Infinity && (rigid.flags[slot] & BodyFlag.fixedRotation) === 0 ? inverse : 0;
}
