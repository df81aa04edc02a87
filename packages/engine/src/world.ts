import { BodyStore } from './store/body-store.js';
import type { BodyType } from './store/body-types.js';
import { TypeCode, typeName } from './store/body-types.js';
import { ContactBuffer } from './store/contact-buffer.js';
import { PairSink } from './store/pair-sink.js';
import type { BroadPhase } from './broadphase/broadphase.js';
import type { BroadPhaseName } from './broadphase/registry.js';
import { BROADPHASES } from './broadphase/registry.js';
import { MaxGridBroadPhase, type GridGeometry } from './broadphase/maxgrid.js';
import { AutoBroadPhase } from './broadphase/auto.js';
import { NarrowPhase } from './narrowphase/narrowphase.js';
import { INTEGRATORS, type IntegratorName } from './integrate/integrator.js';
import { bounceOffBox, clampIntoBox } from './solver/box-walls.js';
import { solveContacts } from './solver/contact-solver.js';
import { emptyStats, type StepStats } from './step/stats.js';
import * as analytics from './analytics.js';
import { nowMs } from './util/timer.js';
import { finiteNumber } from './util/validate.js';
import {
  bodyType,
  broadphaseName,
  integratorName,
  resolveCircle,
  resolveWorldOptions,
  vector,
  type CircleOptions,
  type Vector,
  type WorldOptions,
} from './options.js';

export interface CircleState {
  x: number;
  y: number;
  vx: number;
  vy: number;
  radius: number;
  mass: number;
  type: BodyType;
  restitution: number;
}

/**
 * Read-only, zero-copy views of the body columns for renderers, indexed by slot. Walk slots
 * [0, slotCount) and skip those whose `type` is `BodyTypeCode.free`. The arrays are replaced when
 * the world grows, so fetch the views again after adding bodies rather than keeping them.
 */
export interface BodyViews {
  readonly slotCount: number;
  readonly liveCount: number;
  readonly x: Readonly<Float64Array>;
  readonly y: Readonly<Float64Array>;
  readonly vx: Readonly<Float64Array>;
  readonly vy: Readonly<Float64Array>;
  readonly radius: Readonly<Float64Array>;
  readonly type: Readonly<Uint8Array>;
}

/**
 * A 2D world of circles. A step is a fixed sequence of stages, each in its own module:
 * integrate, boundary (box walls), broad-phase, narrow-phase, solve (canonical order, impulses,
 * separation), correct (keep separated circles in the box). See `stats` for each stage's time.
 */
export class World {
  private readonly bodies = new BodyStore();
  private readonly contacts = new ContactBuffer();
  private readonly narrowPhase = new NarrowPhase(this.bodies, this.contacts);
  private readonly pairs = new PairSink(this.narrowPhase, nowMs);
  private broad: BroadPhase;
  private integratorName: IntegratorName;
  private readonly bounds: { width: number; height: number } | null;
  private readonly gravityVector: Vector;
  private readonly defaultRestitution: number;
  private readonly statsRecord: StepStats = emptyStats();
  private readonly viewsRecord = {
    slotCount: 0,
    liveCount: 0,
    x: new Float64Array(0),
    y: new Float64Array(0),
    vx: new Float64Array(0),
    vy: new Float64Array(0),
    radius: new Float64Array(0),
    type: new Uint8Array(0),
  };

  constructor(options: WorldOptions = {}) {
    const resolved = resolveWorldOptions(options);
    this.bounds = resolved.bounds;
    this.gravityVector = resolved.gravity;
    this.defaultRestitution = resolved.restitution;
    this.broad = BROADPHASES[resolved.broadphase]();
    this.integratorName = resolved.integrator;
  }

  get bodyCount(): number {
    return this.bodies.liveCount;
  }

  get broadphase(): BroadPhaseName {
    return this.broad.name as BroadPhaseName;
  }

  get integrator(): IntegratorName {
    return this.integratorName;
  }

  get gravity(): Vector {
    return { x: this.gravityVector.x, y: this.gravityVector.y };
  }

  get restitution(): number {
    return this.defaultRestitution;
  }

  get box(): { width: number; height: number } | null {
    return this.bounds ? { ...this.bounds } : null;
  }

  /** Statistics of the last step; the same object is updated in place by every step. */
  get stats(): Readonly<StepStats> {
    return this.statsRecord;
  }

  createCircle(options: CircleOptions): number {
    const body = resolveCircle(options, this.defaultRestitution);
    this.assertInBox(body.x, body.y, body.radius);
    return this.bodies.handleOf(this.bodies.add(body));
  }

  destroyBody(handle: number): void {
    this.bodies.remove(this.slot(handle));
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
    };
  }

  /** Handles of all live bodies, in slot order. Allocates: not for per-frame use. */
  handles(): number[] {
    const out: number[] = [];
    const b = this.bodies;
    for (let s = 0; s < b.slotCount; s++) if (b.type[s] !== TypeCode.free) out.push(b.handleOf(s));
    return out;
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
  }

  setPosition(handle: number, x: number, y: number): void {
    const s = this.slot(handle);
    finiteNumber('x', x);
    finiteNumber('y', y);
    this.assertInBox(x, y, this.bodies.radius[s]);
    this.bodies.x[s] = x;
    this.bodies.y[s] = y;
  }

  /** Changes a body's motion type at run time (the report's mutable object types, 3.2). */
  setType(handle: number, type: BodyType): void {
    const s = this.slot(handle);
    this.bodies.setTypeCode(s, TypeCode[bodyType(type)]);
  }

  setBroadphase(name: BroadPhaseName): void {
    const checked = broadphaseName(name);
    if (checked !== this.broad.name) this.broad = BROADPHASES[checked]();
  }

  setIntegrator(name: IntegratorName): void {
    this.integratorName = integratorName(name);
  }

  setGravity(x: number, y: number): void {
    const g = vector('gravity', { x, y });
    this.gravityVector.x = g.x;
    this.gravityVector.y = g.y;
  }

  /** Pre-sizes body storage for `count` bodies, so that creating them never reallocates. */
  reserve(count: number): void {
    if (!Number.isSafeInteger(count) || count < 0) throw new RangeError(`reserve count must be a non-negative integer, got ${count}`);
    this.bodies.reserve(count);
  }

  /** Advances the world by `dt` seconds. Allocates nothing once buffers have grown to the scene. */
  step(dt: number): void {
    finiteNumber('dt', dt);
    if (dt < 0) throw new RangeError(`dt must be >= 0, got ${dt}`);
    const bodies = this.bodies;
    const stats = this.statsRecord;
    const g = this.gravityVector;
    const box = this.bounds;
    const t0 = nowMs();

    INTEGRATORS[this.integratorName](bodies, g.x, g.y, dt);
    const t1 = nowMs();

    if (box) bounceOffBox(bodies, box.width, box.height, this.defaultRestitution);
    const t2 = nowMs();

    this.contacts.clear();
    this.pairs.begin();
    const pairTests = this.broad.findPairs(bodies, this.pairs);
    this.pairs.flush();
    const t3 = nowMs();

    this.contacts.sortCanonical(bodies.slotCount);
    solveContacts(bodies, this.contacts);
    const t4 = nowMs();

    if (box) clampIntoBox(bodies, box.width, box.height);
    const t5 = nowMs();

    stats.steps++;
    stats.bodies = bodies.liveCount;
    stats.pairTests = pairTests;
    stats.candidatePairs = this.pairs.total;
    stats.contacts = this.contacts.count;
    stats.integrateMs = t1 - t0;
    stats.boundaryMs = t2 - t1;
    stats.narrowphaseMs = this.pairs.consumerMs;
    stats.broadphaseMs = t3 - t2 - this.pairs.consumerMs;
    stats.solveMs = t4 - t3;
    stats.correctMs = t5 - t4;
    stats.totalMs = t5 - t0;
  }

  kineticEnergy(): number {
    return analytics.kineticEnergy(this.bodies);
  }

  potentialEnergy(): number {
    return analytics.potentialEnergy(this.bodies, this.gravityVector.x, this.gravityVector.y);
  }

  momentum(): Vector {
    return analytics.momentum(this.bodies);
  }

  /** 16 hex digits identifying the exact bits of every body's state; equal across runtimes. */
  stateHash(): string {
    return analytics.stateHash(this.bodies);
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
    v.type = b.type;
    return v;
  }

  /** The Max Grid of the last step (for drawing it), or null with another broad-phase. */
  gridGeometry(): GridGeometry | null {
    const used = this.broad instanceof AutoBroadPhase ? this.broad.current : this.broad;
    return used instanceof MaxGridBroadPhase ? used.geometry : null;
  }

  /** Bytes held by the engine's typed arrays: body columns, broad-phase and contact scratch. */
  memoryBytes(): number {
    return this.bodies.memoryBytes() + this.broad.memoryBytes() + this.contacts.memoryBytes() + this.pairs.memoryBytes();
  }

  /** Capacities of internal buffers, for tests that check nothing grows after warm-up. */
  internalCapacities(): Record<string, number> {
    return {
      bodies: this.bodies.capacity,
      contacts: this.contacts.lo.length,
      broadphaseBytes: this.broad.memoryBytes(),
    };
  }

  private slot(handle: number): number {
    const s = this.bodies.slotOf(handle);
    if (s < 0) throw new RangeError(`handle ${String(handle)} ${this.bodies.describeMissing(handle)}`);
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
