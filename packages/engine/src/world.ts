import { BodyStore, SLOT_SPACE } from './store/body-store.js';
import { SegmentStore } from './store/segment-store.js';
import type { BodyType } from './store/body-types.js';
import { TypeCode, typeName } from './store/body-types.js';
import type { BroadPhaseName } from './broadphase/registry.js';
import { BROADPHASES } from './broadphase/registry.js';
import { MaxGridBroadPhase, type GridGeometry } from './broadphase/maxgrid.js';
import { AutoBroadPhase } from './broadphase/auto.js';
import { ContactEvents, type ContactEventsView } from './store/contact-events.js';
import { Queries, type RayHit } from './query/queries.js';
import { Disturbances } from './solver/disturbances.js';
import { NO_QUERY_OPTIONS, queryMask, queryOutput, rayArguments, rayHitOutput, rayHitsOutput } from './query/query-args.js';
import type { CircleState, BodyViews, QueryOptions } from './world-types.js';
import * as analytics from './analytics.js';
import { StepPipeline } from './step/pipeline.js';
import { checkWorkerCount, DEFAULT_MIN_BODIES, ParallelStep } from './parallel/parallel-step.js';
import type { StepStats } from './step/stats.js';
import type { IntegratorName } from './integrate/integrator.js';
import { describeValue, finiteNumber, knownKeys, nonNegativeInteger, nonNegativeNumber, plainObject } from './util/validate.js';
import {
  bodyType,
  broadphaseName,
  layerBits,
  integratorName,
  resolveCircle,
  resolveWorldOptions,
  resolveSegment,
  stepSettings,
  type SegmentOptions,
  vector,
  type CircleOptions,
  type Vector,
  type WorldOptions,
} from './options.js';

/**
 * A 2D world of circles. A step is a fixed sequence of stages, each in its own module:
 * integrate, boundary (box walls), broad-phase, narrow-phase, solve (canonical order, impulses,
 * separation), correct (keep separated circles in the box). See `stats` for each stage's time.
 */
export class World {
  private readonly bodies = new BodyStore();
  private readonly segments = new SegmentStore();
  private readonly pipeline: StepPipeline;
  private readonly bounds: { width: number; height: number } | null;
  private readonly defaultRestitution: number;
  private readonly queries = new Queries(this.bodies);
  private readonly disturbances = new Disturbances();
  /** Bumped whenever positions or the body set change, so cached query grids know to rebuild. */
  private geometryVersion = 0;
  /** Bumped by stopWorkers, so that workers still starting know they were cancelled. */
  private workerStarts = 0;
  private readonly viewsRecord = {
    slotCount: 0,
    liveCount: 0,
    x: new Float64Array(0),
    y: new Float64Array(0),
    vx: new Float64Array(0),
    vy: new Float64Array(0),
    radius: new Float64Array(0),
    mass: new Float64Array(0),
    type: new Uint8Array(0),
    asleep: new Uint8Array(0),
  };

  constructor(options: WorldOptions = {}) {
    const resolved = resolveWorldOptions(options);
    this.bounds = resolved.bounds;
    this.bodies.box = resolved.bounds;
    this.defaultRestitution = resolved.restitution;
    const events = resolved.contactEvents || resolved.hitEventThreshold < Infinity ? new ContactEvents() : null;
    this.pipeline = new StepPipeline(this.bodies, this.segments, BROADPHASES[resolved.broadphase](), resolved.integrator, stepSettings(resolved), events);
  }

  get bodyCount(): number {
    return this.bodies.liveCount;
  }

  get broadphase(): BroadPhaseName {
    return this.pipeline.broadPhase.name as BroadPhaseName;
  }

  get integrator(): IntegratorName {
    return this.pipeline.integrator;
  }

  get gravity(): Vector {
    const g = this.pipeline.settings.gravity;
    return { x: g.x, y: g.y };
  }

  get restitution(): number {
    return this.defaultRestitution;
  }

  get box(): { width: number; height: number } | null {
    return this.bounds ? { ...this.bounds } : null;
  }

  /** Statistics of the last step; the same object is updated in place by every step. */
  get stats(): Readonly<StepStats> {
    return this.pipeline.stats;
  }

  createCircle(options: CircleOptions): number {
    const body = resolveCircle(options, this.defaultRestitution);
    this.assertInBox(body.x, body.y, body.radius);
    if (!this.bodies.hasRoom()) throw new RangeError(`a world holds at most ${SLOT_SPACE} bodies at once (handles encode the slot in 24 bits)`);
    this.geometryVersion++;
    return this.bodies.handleOf(this.bodies.add(body));
  }

  destroyBody(handle: number): void {
    const s = this.slot(handle);
    this.disturbances.note(this.bodies, s);
    this.bodies.remove(s);
    this.geometryVersion++;
  }

  /** A static wall from (x1, y1) to (x2, y2), at any angle, optionally thick. Segment handles are their own space. */
  createSegment(options: SegmentOptions): number {
    const segment = resolveSegment(options, this.defaultRestitution);
    if (!this.segments.hasRoom()) throw new RangeError(`a world holds at most ${SLOT_SPACE} segments at once (handles encode the slot in 24 bits)`);
    return this.segments.add(segment);
  }

  destroySegment(handle: number): void {
    this.segments.remove(this.segmentSlot(handle));
  }

  getSegment(handle: number): Required<SegmentOptions> {
    const s = this.segmentSlot(handle);
    const g = this.segments;
    return { x1: g.ax[s], y1: g.ay[s], x2: g.bx[s], y2: g.by[s], thickness: g.thickness[s], restitution: g.restitution[s], category: g.category[s], mask: g.mask[s] };
  }

  get segmentCount(): number {
    return this.segments.count;
  }

  hasBody(handle: number): boolean {
    return this.bodies.slotOf(handle) >= 0;
  }

  getCircle(handle: number): CircleState {
    const s = this.slot(handle);
    const b = this.bodies;
    return {
      x: b.x[s],
      y: b.y[s],
      vx: b.vx[s],
      vy: b.vy[s],
      radius: b.radius[s],
      mass: b.mass[s],
      type: typeName(b.type[s]),
      restitution: b.restitution[s],
      category: b.category[s],
      mask: b.mask[s],
      gravityScale: b.gravityScale[s],
      linearDamping: b.linearDamping[s],
      awake: b.asleep[s] === 0,
    };
  }

  /** Handles of all live bodies, in slot order. Allocates: not for per-frame use. */
  handles(): number[] {
    const out: number[] = [];
    const b = this.bodies;
    for (let s = 0; s < b.slotCount; s++) if (b.type[s] !== TypeCode.free) out.push(b.handleOf(s));
    return out;
  }

  /** The slot of a live body in the bulk views, or -1 for a stale or unknown handle. */
  slotOfHandle(handle: number): number {
    return this.bodies.slotOf(handle);
  }

  /** The handle of the body in a slot of the bulk views, or -1 for a free slot. */
  handleAtSlot(slot: number): number {
    const b = this.bodies;
    if (!Number.isInteger(slot) || slot < 0 || slot >= b.slotCount || b.type[slot] === TypeCode.free) return -1;
    return b.handleOf(slot);
  }

  setVelocity(handle: number, vx: number, vy: number): void {
    const s = this.slot(handle);
    finiteNumber('vx', vx);
    finiteNumber('vy', vy);
    if (this.bodies.type[s] === TypeCode.static) {
      throw new RangeError(`body ${handle} is static and cannot be given a velocity (${vx}, ${vy}); make it kinematic or dynamic first`);
    }
    this.bodies.vx[s] = vx;
    this.bodies.vy[s] = vy;
    this.bodies.wake(s);
  }

  setPosition(handle: number, x: number, y: number): void {
    const s = this.slot(handle);
    finiteNumber('x', x);
    finiteNumber('y', y);
    this.assertInBox(x, y, this.bodies.radius[s]);
    this.disturbances.note(this.bodies, s);
    this.bodies.x[s] = x;
    this.bodies.y[s] = y;
    this.disturbances.note(this.bodies, s);
    this.bodies.wake(s);
    this.geometryVersion++;
  }

  /** Adds a force (mass x length / s^2) to a dynamic body for the next step only; wakes it. */
  applyForce(handle: number, fx: number, fy: number): void {
    const s = this.dynamicSlot(handle, 'a force', fx, fy);
    const b = this.bodies;
    const totalX = b.forceX[s] + fx;
    const totalY = b.forceY[s] + fy;
    // Finite inputs can still sum, or divide by a small mass, past the largest double; the step would then spread infinities.
    if (!Number.isFinite(totalX * b.invMass[s]) || !Number.isFinite(totalY * b.invMass[s])) {
      throw new RangeError(`a force (${fx}, ${fy}) on body ${handle} would make its acceleration non-finite (pending force (${totalX}, ${totalY}), mass ${b.mass[s]})`);
    }
    b.forceX[s] = totalX;
    b.forceY[s] = totalY;
    this.bodies.forcesPending = true;
    this.bodies.wake(s);
  }

  /** Changes a dynamic body's velocity by impulse / mass at once; wakes it. */
  applyImpulse(handle: number, ix: number, iy: number): void {
    const s = this.dynamicSlot(handle, 'an impulse', ix, iy);
    const b = this.bodies;
    const vx = b.vx[s] + ix * b.invMass[s];
    const vy = b.vy[s] + iy * b.invMass[s];
    if (!Number.isFinite(vx) || !Number.isFinite(vy)) {
      throw new RangeError(`an impulse (${ix}, ${iy}) on body ${handle} would make its velocity (${vx}, ${vy}) non-finite (mass ${b.mass[s]})`);
    }
    b.vx[s] = vx;
    b.vy[s] = vy;
    this.bodies.wake(s);
  }

  setGravityScale(handle: number, scale: number): void {
    const s = this.slot(handle);
    this.bodies.setMotion(s, finiteNumber('gravityScale', scale), this.bodies.linearDamping[s]);
    this.bodies.wake(s);
  }

  setLinearDamping(handle: number, damping: number): void {
    const s = this.slot(handle);
    this.bodies.setMotion(s, this.bodies.gravityScale[s], nonNegativeNumber('linearDamping', damping));
    this.bodies.wake(s);
  }

  /** Collision layers: bodies a and b collide only if (a.category & b.mask) and (b.category & a.mask). */
  setCollisionFilter(handle: number, category: number, mask: number): void {
    const s = this.slot(handle);
    const c = layerBits('category', category);
    const m = layerBits('mask', mask);
    this.disturbances.note(this.bodies, s);
    this.bodies.setFilter(s, c, m);
    this.bodies.wake(s);
  }

  isAwake(handle: number): boolean {
    return this.bodies.asleep[this.slot(handle)] === 0;
  }

  /** Wakes a body, or puts a dynamic body to sleep at once (its velocity becomes zero). */
  setAwake(handle: number, awake: boolean): void {
    const s = this.slot(handle);
    if (typeof awake !== 'boolean') throw new TypeError(`awake must be true or false, got ${describeValue(awake)}`);
    if (awake) this.bodies.wake(s);
    else if (this.bodies.type[s] === TypeCode.dynamic) this.bodies.fallAsleep(s);
  }

  /** Changes a body's motion type at run time (the report's mutable object types, 3.2). */
  setType(handle: number, type: BodyType): void {
    const s = this.slot(handle);
    const code = TypeCode[bodyType(type)];
    this.disturbances.note(this.bodies, s);
    this.bodies.setTypeCode(s, code);
    this.geometryVersion++;
  }

  setBroadphase(name: BroadPhaseName): void {
    const checked = broadphaseName(name);
    if (checked !== this.pipeline.broadPhase.name) this.pipeline.broadPhase = BROADPHASES[checked]();
  }

  setIntegrator(name: IntegratorName): void {
    this.pipeline.integrator = integratorName(name);
  }

  setGravity(x: number, y: number): void {
    const g = vector('gravity', { x, y });
    this.pipeline.settings.gravity.x = g.x;
    this.pipeline.settings.gravity.y = g.y;
  }

  /** Pre-sizes body storage for `count` bodies, so that creating them never reallocates. */
  reserve(count: number): void {
    nonNegativeInteger('reserve count', count);
    if (count > SLOT_SPACE) throw new RangeError(`reserve count must be at most ${SLOT_SPACE} (the bodies a world can hold), got ${count}`);
    this.bodies.reserve(count);
  }

  /**
   * Runs the step on `workerCount` threads: this one and `workerCount - 1` worker threads
   * (worker_threads in Node, module Web Workers in browsers, which need a cross-origin isolated
   * page for SharedArrayBuffer). Resolves once they are running; until then steps run on this
   * thread. Motion, the Max Grid broad-phase with the narrow-phase, the solver and correct run in
   * parallel. The result is the same bits for any worker count, and as without workers.
   * `views()` must be taken again afterwards: the columns move to shared memory.
   */
  async startWorkers(workerCount: number, options: { minBodies?: number } = {}): Promise<void> {
    checkWorkerCount(workerCount);
    knownKeys('startWorkers options', plainObject('startWorkers options', options), ['minBodies']);
    const minBodies = options.minBodies === undefined ? DEFAULT_MIN_BODIES : nonNegativeInteger('minBodies', options.minBodies);
    this.stopWorkers();
    const started = this.workerStarts;
    const parallel = await ParallelStep.start(workerCount, this.bodies, this.pipeline.contacts);
    if (started !== this.workerStarts) {
      // stopWorkers (or another startWorkers) was called while these were starting: it wins.
      parallel.stop();
      return;
    }
    parallel.minBodies = minBodies;
    this.pipeline.parallel = parallel;
  }

  /** Stops the worker threads; later steps run on this thread alone. */
  stopWorkers(): void {
    this.workerStarts++;
    this.pipeline.parallel?.stop();
    this.pipeline.parallel = null;
  }

  /** Threads working on each step: 1 without workers. */
  get workerCount(): number {
    return this.pipeline.parallel?.threads ?? 1;
  }

  /** Advances the world by `dt` seconds. Allocates nothing once buffers have grown to the scene. */
  step(dt: number): void {
    finiteNumber('dt', dt);
    if (dt < 0) throw new RangeError(`dt must be >= 0, got ${dt}`);
    this.disturbances.wakeTouching(this.bodies, this.queries, this.geometryVersion, this.pipeline.settings.solver.contactSlop);
    this.pipeline.run(dt);
    this.geometryVersion++;
  }

  kineticEnergy(): number {
    return analytics.kineticEnergy(this.bodies);
  }

  potentialEnergy(): number {
    const g = this.pipeline.settings.gravity;
    return analytics.potentialEnergy(this.bodies, g.x, g.y);
  }

  momentum(): Vector {
    return analytics.momentum(this.bodies);
  }

  /** 16 hex digits identifying the exact bits of every body's state; equal across runtimes. */
  stateHash(): string {
    return analytics.stateHash(this.bodies);
  }

  /**
   * Touch events of the last step, when the world was created with `contactEvents: true` (begin
   * and end) or a `hitEventThreshold` (hits). The object and its arrays are reused by every step.
   */
  contactEvents(): ContactEventsView {
    const events = this.pipeline.events;
    if (!events) throw new RangeError('contact events are off: create the World with contactEvents: true or a hitEventThreshold');
    return events;
  }

  /**
   * Handles of the circles containing the point (boundary included), ascending. Pass `out` to
   * reuse an array: it is emptied, filled and returned.
   */
  queryPoint(x: number, y: number, options: QueryOptions = NO_QUERY_OPTIONS, out?: number[]): number[] {
    const mask = queryMask(options);
    finiteNumber('x', x);
    finiteNumber('y', y);
    return this.queries.point(this.geometryVersion, x, y, mask, queryOutput(out));
  }

  /** Handles of the circles overlapping the box (touching included), ascending; `out` as in queryPoint. */
  queryAABB(minX: number, minY: number, maxX: number, maxY: number, options: QueryOptions = NO_QUERY_OPTIONS, out?: number[]): number[] {
    const mask = queryMask(options);
    finiteNumber('minX', minX);
    finiteNumber('minY', minY);
    finiteNumber('maxX', maxX);
    finiteNumber('maxY', maxY);
    if (minX > maxX || minY > maxY) throw new RangeError(`queryAABB needs min <= max, got (${minX}, ${minY})..(${maxX}, ${maxY})`);
    return this.queries.box(this.geometryVersion, minX, minY, maxX, maxY, mask, queryOutput(out));
  }

  /**
   * The first circle the segment from (x1, y1) to (x2, y2) enters, or null. Circles containing
   * (x1, y1) are ignored. Pass `out` to reuse a hit object: it is filled and returned.
   */
  rayCast(x1: number, y1: number, x2: number, y2: number, options: QueryOptions = NO_QUERY_OPTIONS, out?: RayHit): RayHit | null {
    const mask = queryMask(options);
    rayArguments(x1, y1, x2, y2);
    return this.queries.rayFirst(this.geometryVersion, x1, y1, x2, y2, mask, rayHitOutput(out));
  }

  /**
   * Every circle the segment enters, nearest first. Pass `out` to reuse an array: the hit objects
   * it holds are overwritten in place, it is cut to the number of hits and returned.
   */
  rayCastAll(x1: number, y1: number, x2: number, y2: number, options: QueryOptions = NO_QUERY_OPTIONS, out?: RayHit[]): RayHit[] {
    const mask = queryMask(options);
    rayArguments(x1, y1, x2, y2);
    return this.queries.rayAll(this.geometryVersion, x1, y1, x2, y2, mask, rayHitsOutput(out));
  }

  views(): BodyViews {
    const v = this.viewsRecord;
    const b = this.bodies;
    v.slotCount = b.slotCount;
    v.liveCount = b.liveCount;
    v.x = b.x;
    v.y = b.y;
    v.vx = b.vx;
    v.vy = b.vy;
    v.radius = b.radius;
    v.mass = b.mass;
    v.type = b.type;
    v.asleep = b.asleep;
    return v;
  }

  /** The Max Grid of the last step (for drawing it), or null with another broad-phase. */
  gridGeometry(): GridGeometry | null {
    const broad = this.pipeline.broadPhase;
    const used = broad instanceof AutoBroadPhase ? broad.current : broad;
    // Before its first build (no step yet, or too few bodies to grid) a Max Grid has no cells.
    return used instanceof MaxGridBroadPhase && used.geometry.columns > 0 ? used.geometry : null;
  }

  /**
   * Bytes held by the engine's typed arrays and WebAssembly memories (whole 64 KiB pages): body
   * columns, broad-phase and contact scratch.
   */
  memoryBytes(): number {
    return this.bodies.memoryBytes() + this.segments.memoryBytes() + this.pipeline.memoryBytes();
  }

  /** Capacities of internal buffers, for tests that check nothing grows after warm-up. */
  internalCapacities(): Record<string, number> {
    return {
      bodies: this.bodies.capacity,
      contacts: this.pipeline.contacts.lo.length,
      broadphaseBytes: this.pipeline.broadPhase.memoryBytes(),
    };
  }

  private dynamicSlot(handle: number, what: string, ax: number, ay: number): number {
    const s = this.slot(handle);
    finiteNumber('x component', ax);
    finiteNumber('y component', ay);
    if (this.bodies.type[s] !== TypeCode.dynamic) {
      throw new RangeError(`body ${handle} is ${typeName(this.bodies.type[s])}: only dynamic bodies take ${what}, got (${ax}, ${ay})`);
    }
    return s;
  }

  private segmentSlot(handle: number): number {
    finiteNumber('segment handle', handle);
    const s = this.segments.slotOf(handle);
    if (s < 0) throw new RangeError(`segment handle ${describeValue(handle)} ${this.segments.describeMissing(handle)}`);
    return s;
  }

  private slot(handle: number): number {
    finiteNumber('handle', handle);
    const s = this.bodies.slotOf(handle);
    if (s < 0) throw new RangeError(`handle ${describeValue(handle)} ${this.bodies.describeMissing(handle)}`);
    return s;
  }

  private assertInBox(x: number, y: number, r: number): void {
    const box = this.bounds;
    if (!box) return;
    if (x - r < 0 || x + r > box.width || y - r < 0 || y + r > box.height) {
      throw new RangeError(
        `circle at (${x}, ${y}) with radius ${r} is outside the box 0..${box.width} x 0..${box.height}`,
      );
    }
  }
}
