import { BodyStore, SLOT_SPACE } from './store/body-store.js';
import { SegmentStore } from './store/segment-store.js';
import type { BodyType } from './store/body-types.js';
import { TypeCode, typeName } from './store/body-types.js';
import type { BroadPhaseName } from './broadphase/registry.js';
import { BROADPHASES } from './broadphase/registry.js';
import { MaxGridBroadPhase, type GridGeometry } from './broadphase/maxgrid.js';
import { AutoBroadPhase } from './broadphase/auto.js';
import { HierarchicalGridBroadPhase } from './broadphase/hgrid.js';
import { PersistentSapBroadPhase } from './broadphase/sap-persistent.js';
import { webAssembly } from './util/wasm.js';
import { gridKernelUse, bodyKernelUse, softStepKernelUse, type WorldBackend } from './backend.js';
import { ContactEvents, type ContactEventsView } from './store/contact-events.js';
import { ContactPoint, POINT_STRIDE } from './narrowphase/contact-list.js';
import { Queries, type RayHit } from './query/queries.js';
import { Disturbances } from './solver/disturbances.js';
import { anyFaster, limitSpeeds } from './solver/speed-limit.js';
import { contactsOutput, NO_QUERY_OPTIONS, queryMask, queryOutput, rayArguments, rayHitOutput, rayHitsOutput } from './query/query-args.js';
import { BodyContacts, type BodyContact, type ContactSources } from './query/body-contacts.js';
import type { CircleState, BodyViews, BodyState, ContactPointViews, QueryOptions, ShapeState, ShapeViews } from './world-types.js';
import { grow, grownCapacity } from './util/grow.js';
import { BodyShapes } from './shapes/body-shapes.js';
import { ShapeRoute } from './step/shape-route.js';
import { turnCircles } from './integrate/rigid-motion.js';
import { clearForces } from './integrate/motion.js';
import { atan2, cosSin, nearestTurn } from './math/trig.js';
import { BodyFlag } from './store/rigid-columns.js';
import { SHAPE_STRIDE, SHAPE_VERTICES, VERTEX, type NewShape } from './store/shape-store.js';
import { Geometry, SHAPE_KIND_NAMES, areaProperties, emptyAreaProperties } from './shapes/geometry.js';
import { bodyBounds, poseOf } from './shapes/bounds.js';
import {
  applyMassOption,
  BODY_KEYS,
  MATERIAL_KEYS,
  OFFSET_KEYS,
  resolveBody,
  resolveGeometry,
  checkReach,
  resolveMaterial,
  type BodyOptions,
  type BoxOptions,
  type CapsuleOptions,
  type PolygonOptions,
  type ResolvedBody,
  type ShapeOptions,
} from './shapes/shape-options.js';
import * as analytics from './analytics.js';
import { DEBUG_COLORS, DebugDraw, type DebugRenderBuffers, type DebugRenderOptions } from './debug-draw.js';
import { JointStore } from './joints/joint-store.js';
import { J, JOINT_KIND_NAMES, JOINT_STRIDE, JointKind } from './joints/joint-layout.js';
import { resolveJoint, type JointOptions, type JointWorld } from './joints/joint-options.js';
import { JointSolver } from './solver/joint-solver.js';
import type { JointEventsView, JointState, JointViews } from './world-types.js';
import { StepPipeline } from './step/pipeline.js';
import { checkWorkerCount, DEFAULT_MIN_BODIES, ParallelStep } from './parallel/parallel-step.js';
import type { StepStats } from './step/stats.js';
import { INTEGRATOR_NAMES, type CircleIntegratorName, type IntegratorName } from './integrate/integrator.js';
import { MAX_DT, MIN_DT, MAX_MAGNITUDE, MAX_SHAPE_REACH, boundedNumber, describeValue, finiteNumber, knownKeys, nonNegativeInteger, nonNegativeNumber, plainObject } from './util/validate.js';
import { flag } from './options.js';
import { copyOptions, field, firstDifference, holdsObject, numberField, readSnapshot, writeOnto, writeSnapshot } from './snapshot/world-snapshot.js';
import { transientFields } from './snapshot/state-graph.js';
import {
  bodyType,
  broadphaseName,
  layerBits,
  integratorName,
  resolveCircle,
  resolveWorldOptions,
  resolveChain,
  resolveSegment,
  shapeRouteSettings,
  stepSettings,
  type ResolvedWorldOptions,
  type SegmentOptions,
  type ChainOptions,
  vector,
  type CircleOptions,
  type Vector,
  type WorldOptions,
} from './options.js';

const rotation = new Float64Array(2);

/** The circle route's integrator for a world's choice ('rk4' worlds take the shape route, so any serves). */
function circleIntegrator(name: IntegratorName): CircleIntegratorName {
  return name === 'rk4' ? 'semi-implicit-euler' : name;
}

/** Settings a public setter (or the step itself) changes, which a restored world need not share with its options. */
const SETTER_PATHS = new Set(['settings.step.gravity', 'settings.shapes.gravity', 'settings.shapes.integrator', 'settings.shapes.solver', 'settings.resolved.gravity']);
const box4 = new Float64Array(4);
const pose4 = new Float64Array(4);
// Scratch outside the world, so that a call refused after using it leaves the snapshot's bytes as they were.
const massScratch = emptyAreaProperties();
const scratchGeometry = new Geometry();
const EMPTY = new Float64Array(0);
/** Mass and inertia after a change of shapes (see checkLoadsAfter). */
const loads = new Float64Array(2);

/**
 * A 2D world of bodies. A step is a fixed list of stages over the stores, on one of two routes
 * chosen at one place (`step`): the report's circle engine, for worlds of frictionless circles
 * (integrate, boundary, broad-phase, narrow-phase, solve, correct, report), or the shape route
 * (step/shape-route.ts) once the world holds any other shape. See `stats` for each stage's time.
 */
export class World {
  private readonly bodies = new BodyStore();
  private readonly segments = new SegmentStore();
  private readonly pipeline: StepPipeline;
  private readonly bounds: { width: number; height: number } | null;
  private readonly defaultRestitution: number;
  private readonly defaultFriction: number;
  private readonly resolved: ResolvedWorldOptions;
  /** The options as given, for World.restore to build a world of the same configuration. */
  private readonly creation: Record<string, unknown>;
  private readonly queries = new Queries(this.bodies, this.segments);
  /** bodyContacts' search, and what it reads. */
  private readonly contactIndex = new BodyContacts();
  private readonly contactSources: ContactSources = { bodies: this.bodies, segments: this.segments, queries: this.queries, version: 0, shapes: null, world: null, joints: null, margin: 0, slop: 0, box: null, contactSlop: 0 };
  private readonly disturbances = new Disturbances();
  private readonly shapes = new BodyShapes(this.bodies);
  private shapeRoute: ShapeRoute | null = null;
  /** The integrator asked for; the circle route, which has no 'rk4', never runs once it is. */
  private integratorChoice: IntegratorName;
  /** The joints and their solver, made with the first joint. */
  private joints: JointSolver | null = null;
  /** Joints destroyed with a body since the last step began: reported with the next step's events. */
  private pendingJointEvents: { joint: number; reason: 'broken' | 'bodyDestroyed'; bodyA: number | null; bodyB: number }[] = [];
  private readonly jointEventsRecord: JointEventsView = { count: 0, joint: [], reason: [], bodyA: [], bodyB: [] };
  private readonly jointViewsRecord: JointViews = {
    count: 0,
    handle: new Float64Array(0),
    kind: new Uint8Array(0),
    anchorAX: new Float64Array(0),
    anchorAY: new Float64Array(0),
    anchorBX: new Float64Array(0),
    anchorBY: new Float64Array(0),
  };
  /** Bumped whenever static bodies, their shapes or the segments change, so the static tree rebuilds. */
  private staticVersion = 0;
  /** Some body was given a spin or torque: the circle route then advances rotations. */
  private turning = false;
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
    c: EMPTY,
    s: EMPTY,
    angularVelocity: EMPTY,
    shapes: null as ShapeViews | null,
  };
  private readonly contactPointsRecord = {
    count: 0,
    x: new Float64Array(0),
    y: new Float64Array(0),
    nx: new Float64Array(0),
    ny: new Float64Array(0),
    separation: new Float64Array(0),
  };
  private readonly shapeViewsRecord = {
    slotCount: 0,
    stride: SHAPE_STRIDE,
    vertexStart: SHAPE_VERTICES,
    live: new Uint8Array(0),
    body: new Int32Array(0),
    kind: new Uint8Array(0),
    vertexCount: new Uint8Array(0),
    radius: new Float64Array(0),
    sensor: new Uint8Array(0),
    vertices: new Float64Array(0),
  };

  /** An empty world; options left out take the defaults WorldOptions lists (no box, no gravity, elastic, frictionless). */
  constructor(options: WorldOptions = {}) {
    // Read once, into a copy that is both checked and kept.
    const input = plainObject('World options', options);
    const resolved = resolveWorldOptions(input);
    this.creation = input;
    this.resolved = resolved;
    this.bounds = resolved.bounds;
    this.bodies.box = resolved.bounds;
    // Static bodies are paired with moving ones through the static index, never in the broad-phase.
    this.bodies.setStaticsApart();
    this.defaultRestitution = resolved.restitution;
    this.defaultFriction = resolved.friction;
    const events = resolved.contactEvents || resolved.hitEventThreshold < Infinity ? new ContactEvents() : null;
    this.integratorChoice = resolved.integrator;
    this.pipeline = new StepPipeline(this.bodies, this.segments, BROADPHASES[resolved.broadphase](), circleIntegrator(resolved.integrator), stepSettings(resolved), events);
    if (resolved.solver === 'soft' || resolved.friction > 0 || resolved.integrator === 'rk4') this.engage();
  }

  /** Live bodies: circles and bodies with shapes, of every motion type. */
  get bodyCount(): number {
    return this.bodies.liveCount;
  }

  /** The broad-phase the next step uses (WorldOptions.broadphase, setBroadphase). */
  get broadphase(): BroadPhaseName {
    return this.pipeline.broadPhase.name as BroadPhaseName;
  }

  /** The integrator the next step uses (WorldOptions.integrator, setIntegrator). */
  get integrator(): IntegratorName {
    return this.integratorChoice;
  }

  /** The route the next step takes: 'circles' (the report's engine) or 'shapes', and with it the solver. */
  get route(): { route: 'circles' | 'shapes'; solver: 'elastic' | 'soft' } {
    if (!this.shapes.engaged) return { route: 'circles', solver: 'elastic' };
    return { route: 'shapes', solver: this.shapeSolver() };
  }

  /**
   * The solver the shape route's next step uses: the one asked for, or with 'auto' the elastic
   * pass while the world is an elastic gas (no gravity, no joints, the world's friction 0 and
   * restitution at least 1, and so its walls and defaults, and every shape and segment that takes
   * contacts frictionless, without rolling resistance, at restitution 1 or more: the report's
   * scenes with shapes, whose energy that pass keeps), the soft step otherwise. A function of the
   * world as it stands, checked at every step, so a restored snapshot makes the same choice.
   */
  private shapeSolver(): 'elastic' | 'soft' {
    const asked = this.resolved.solver;
    if (asked !== 'auto') return asked;
    const g = this.pipeline.settings.gravity;
    const material = this.defaultFriction === 0 && this.defaultRestitution >= 1;
    const gas = g.x === 0 && g.y === 0 && material && (this.joints === null || this.joints.count === 0) && this.shapes.store.inelastic === 0 && this.segments.inelastic === 0;
    return gas ? 'elastic' : 'soft';
  }

  /**
   * What steps this world: its route, its threads, and whether each WebAssembly kernel runs, with
   * why or why not (no WebAssembly in the runtime, a kernel switched off, a broad-phase without a
   * grid). The kernels change speed only, never a result: the TypeScript loops give the same bits.
   */
  get backend(): WorldBackend {
    const route = this.route;
    const broad = this.pipeline.broadPhase;
    const grid = broad instanceof AutoBroadPhase ? !(broad.current instanceof PersistentSapBroadPhase) : broad instanceof MaxGridBroadPhase || broad instanceof HierarchicalGridBroadPhase;
    const name = broad instanceof AutoBroadPhase ? `auto (now ${broad.current.name})` : broad.name;
    return {
      route: route.route,
      threads: this.workerCount,
      lastStepThreads: this.pipeline.stats.threads,
      webAssembly: webAssembly() !== null,
      gridKernel: gridKernelUse(name, grid),
      bodyKernel: bodyKernelUse(this.bodies.kernel !== null, this.bodies.slotCount),
      softStepKernel: softStepKernelUse(route.route, route.solver, route.route === 'shapes' && route.solver === 'soft' && this.shapeRoute!.soft.usesKernel),
    };
  }

  /** A copy of the world's gravity: changing it changes nothing; setGravity does. */
  get gravity(): Vector {
    const g = this.pipeline.settings.gravity;
    return { x: g.x, y: g.y };
  }

  /** The box walls' restitution, and the default of new bodies and segments. */
  get restitution(): number {
    return this.defaultRestitution;
  }

  /** The box walls' friction, and the default of new shapes and segments. */
  get friction(): number {
    return this.defaultFriction;
  }

  /** A copy of the box from (0, 0) to (width, height) that contains every body, or null without one. */
  get box(): { width: number; height: number } | null {
    return this.bounds ? { ...this.bounds } : null;
  }

  /** Statistics of the last step; the same object is updated in place by every step. */
  get stats(): Readonly<StepStats> {
    return this.pipeline.stats;
  }

  /**
   * The world's whole state as bytes: bodies, shapes, segments, joints, contacts with their
   * warm-start impulses, sleep timers, pending forces and events, free handles, options. A world
   * restored from them (World.restore, or restore in place) steps to exactly the same bits as
   * this one from here on, in any runtime. Worker threads are not part of it. Allocates: take one
   * when the game needs one, not every frame of a large world.
   */
  snapshot(): Uint8Array {
    return writeSnapshot(this);
  }

  /**
   * A new world from `snapshot()`'s bytes, stepping to the same bits as the world they came from
   * (without worker threads: start them again). A corrupt, cut, or future-format snapshot, or one
   * an engine with another state layout wrote, is a RangeError saying so; nothing is built. So is
   * one whose hash holds but whose gravity or bodies hold a value no step reaches (a NaN or
   * infinite coordinate, velocity, mass or force, a negative mass, a rotation that is not a unit
   * vector), whose options are refused, or whose settings are not what its options give.
   */
  static restore(snapshot: Uint8Array): World {
    const read = readSnapshot(snapshot);
    let world: World;
    try {
      world = new World(read.options as WorldOptions);
    } catch (error) {
      // Options that were accepted when the world was made, rewritten under a consistent hash.
      throw new RangeError(`snapshot is corrupt: its options are refused (${(error as Error).message})`);
    }
    const state = read.state;
    if (holdsObject(field(state, 'bodies', 'rigid'))) world.useRigid();
    if (holdsObject(field(state, 'shapeRoute'))) world.engage();
    if (holdsObject(field(state, 'joints'))) world.useJoints();
    if (holdsObject(field(state, 'pipeline', 'events'))) world.useEvents();
    const broadphase = field(state, 'pipeline', 'broadPhase', 'name');
    if (broadphase?.t === 'value' && typeof broadphase.v === 'string' && broadphase.v !== world.broadphase) world.setBroadphase(broadphase.v as BroadPhaseName);
    const capacity = numberField(field(state, 'bodies', 'capacity'));
    if (capacity > 0) world.bodies.reserve(capacity);
    // What the options give, before the snapshot's state is written over it.
    const settings = copyOptions(world.settingsTree());
    writeOnto(world, read);
    world.checkRestoredState(settings);
    // Columns a parallel step had moved onto shared memory come back to this thread's own.
    if (world.bodies.shared) world.bodies.setShared(false);
    if (world.pipeline.contacts.shared) world.pipeline.contacts.setShared(false);
    return world;
  }

  /**
   * Turns this world into the one `snapshot` was taken of, keeping this object: handles held
   * from before are as valid as they were when the snapshot was taken. Stops worker threads;
   * views(), stats and other objects read before must be read again. A snapshot that is refused
   * (see World.restore) leaves this world unchanged.
   */
  restore(snapshot: Uint8Array): void {
    const restored = World.restore(snapshot);
    this.stopWorkers();
    const starts = this.workerStarts;
    const self = this as unknown as Record<string, unknown>;
    for (const [key, value] of Object.entries(restored)) {
      // Callbacks that read this world's fields stay this world's: the restored fields move here.
      // (An empty object or array is a field, not callbacks: the creation options of a world made
      // with none, the joint events pending when none were.)
      if (value !== null && typeof value === 'object' && isCallbacks(value)) continue;
      self[key] = value;
    }
    this.workerStarts = starts + 1;
  }

  /**
   * Adds a circle body and returns its handle. A world of frictionless circles steps on the
   * report's circle engine; a circle with friction, rolling resistance, a sensor or `bullet` moves
   * the world to the shape route.
   */
  createCircle(options: CircleOptions): number {
    // Read once: every check below reads the copy.
    const o = plainObject('circle options', options);
    const body = resolveCircle(o, this.defaultRestitution);
    const spin = resolveBody({ x: body.x, y: body.y, angle: o.angle, angularVelocity: o.angularVelocity, fixedRotation: o.fixedRotation, bullet: o.bullet, angularDamping: o.angularDamping, type: o.type });
    const material = resolveMaterial(o, this.materialDefaults(), scratchGeometry.setCircle(0, 0, body.radius));
    material.restitution = body.restitution;
    this.checkGravityScale(body.gravityScale);
    this.assertInBox(body.x, body.y, body.radius);
    if (!this.bodies.hasRoom()) throw new RangeError(`a world holds at most ${SLOT_SPACE} bodies at once (handles encode the slot in 24 bits)`);
    const shaped = this.shapes.engaged || material.friction > 0 || material.rollingResistance > 0 || material.sensor || (spin.flags & BodyFlag.bullet) !== 0;
    if (shaped) checkReach('circle', o, scratchGeometry.setCircle(0, 0, body.radius));
    if (!this.shapes.engaged && shaped) this.engage();
    if (this.shapes.engaged) {
      material.density = body.mass / (Math.PI * body.radius * body.radius);
      return this.createShaped({ ...spin, vx: body.vx, vy: body.vy, gravityScale: body.gravityScale, linearDamping: body.linearDamping }, material);
    }
    this.geometryVersion++;
    const slot = this.bodies.add(body);
    if (body.type === TypeCode.static) this.staticVersion++;
    if (this.bodies.rigid || spin.c !== 1 || spin.s !== 0 || spin.angularVelocity !== 0 || spin.flags !== 0 || spin.angularDamping !== 0) {
      const rigid = this.useRigid();
      rigid.c[slot] = spin.c;
      rigid.s[slot] = spin.s;
      rigid.angularVelocity[slot] = spin.angularVelocity;
      rigid.flags[slot] = spin.flags;
      this.bodies.setAngularDamping(slot, spin.angularDamping);
      this.bodies.setMass(slot, body.mass, (body.mass * body.radius * body.radius) / 2);
      if (spin.angularVelocity !== 0) this.turning = true;
    }
    // A sleeper it overlaps wakes at the next step (nothing else would wake one under a static circle).
    this.disturbances.note(this.bodies, slot);
    return this.bodies.handleOf(slot);
  }

  /**
   * A body with no shapes yet, at (x, y) with `angle`: add them with addShape. A dynamic body
   * without shapes has mass 1 and does not turn until it gets some. In a world with `bounds`, the
   * box holds such a body by its origin: (x, y) must lie in it, and the body stops at a side it
   * reaches.
   */
  createBody(options: BodyOptions): number {
    const o = plainObject('body options', options);
    knownKeys('body options', o, BODY_KEYS);
    const body = resolveBody(o);
    this.checkGravityScale(body.gravityScale);
    this.assertPointInBox(body.x, body.y);
    if (!this.bodies.hasRoom()) throw new RangeError(`a world holds at most ${SLOT_SPACE} bodies at once (handles encode the slot in 24 bits)`);
    this.engage();
    return this.createShaped(body, null);
  }

  /** A body holding one box: `width` x `height` centred on its origin. See BoxOptions. */
  createBox(options: BoxOptions): number {
    return this.createWithShape('box', 'box options', options, ['width', 'height', 'radius', 'mass']);
  }

  /** A body holding one convex polygon, vertices in its own frame. See PolygonOptions. */
  createPolygon(options: PolygonOptions): number {
    return this.createWithShape('polygon', 'polygon options', options, ['vertices', 'radius', 'mass']);
  }

  /** A body holding one capsule along its x axis. See CapsuleOptions. */
  createCapsule(options: CapsuleOptions): number {
    return this.createWithShape('capsule', 'capsule options', options, ['length', 'radius', 'mass']);
  }

  /**
   * Adds a shape to a body, placed by offsetX/offsetY/offsetAngle in the body's frame; the body's
   * mass, centre of mass and inertia follow from all its shapes (its origin stays put). Returns
   * the shape's handle.
   */
  addShape(handle: number, options: ShapeOptions): number {
    const slot = this.slot(handle);
    const membership = this.bodies.membershipVersion;
    const o = plainObject('shape options', options);
    const kind = o.kind;
    if (typeof kind !== 'string' || !['circle', 'box', 'polygon', 'capsule'].includes(kind)) {
      throw new RangeError(`kind must be one of 'circle', 'box', 'polygon', 'capsule', got ${describeValue(kind)}`);
    }
    const geometryKeys = kind === 'circle' ? ['radius', 'offsetX', 'offsetY'] : kind === 'box' ? ['width', 'height', 'radius', ...OFFSET_KEYS] : kind === 'polygon' ? ['vertices', 'radius', ...OFFSET_KEYS] : ['length', 'radius', ...OFFSET_KEYS];
    knownKeys(`${kind} shape options`, o, ['kind', ...geometryKeys, ...MATERIAL_KEYS]);
    const geometry = resolveGeometry(kind, o, new Geometry());
    const shape = resolveMaterial(o, this.materialDefaults(), geometry);
    this.assertBodiesKept(membership, 'shape options');
    if (!this.shapes.store.hasRoom()) throw new RangeError(`a world holds at most ${SLOT_SPACE} shapes at once`);
    // Everything checked before the world takes the shape route, so that a refused shape leaves
    // it as it was. Until then the body is a circle centred on its origin, which becomes its
    // first shape with the mass it has (BodyShapes.engage).
    const b = this.bodies;
    const rigid = b.rigid;
    const engaged = this.shapes.engaged;
    const mass = this.shapes.massWith(slot, shape) + (engaged ? 0 : b.mass[slot]);
    this.checkMass(handle, mass, b.type[slot] !== TypeCode.dynamic);
    this.checkLoadsAfter(handle, slot, shape, -1, 'adding this shape');
    const c = rigid ? rigid.c[slot] : 1;
    const sn = rigid ? rigid.s[slot] : 0;
    const lx = rigid && engaged ? rigid.localCenterX[slot] : 0;
    const ly = rigid && engaged ? rigid.localCenterY[slot] : 0;
    this.assertShapeInBox(shape.geometry, b.x[slot], b.y[slot], c, sn, lx, ly);
    this.engage();
    const s = this.shapes.add(slot, shape);
    if (shape.sensor) this.useEvents();
    this.shapesChanged(slot);
    this.noteShape(s);
    return this.shapes.store.handleOf(s);
  }

  /**
   * Refuses options whose reading (a getter) created or destroyed bodies since `membership` was
   * read: a handle checked before may no longer name the body it did, and its slot may be free or
   * another body's.
   */
  private assertBodiesKept(membership: number, what: string): void {
    if (this.bodies.membershipVersion !== membership) {
      throw new TypeError(`${what}: reading them created or destroyed bodies (a getter with side effects?), so the handles they name may no longer be the bodies they were; pass plain values`);
    }
  }

  /** Removes a shape from its body, whose mass and centre follow; the body stays, with its other shapes. */
  destroyShape(shapeHandle: number): void {
    const s = this.shapeSlot(shapeHandle);
    const slot = this.shapes.store.body[s];
    const rigid = this.bodies.rigid!;
    // The shapes left must give a mass addShape would accept (the last one leaves a shapeless body of mass 1).
    const handle = this.bodies.handleOf(slot);
    if (rigid.shapeCount[slot] > 1) this.checkMass(handle, this.shapes.massWithout(slot, s), this.bodies.type[slot] !== TypeCode.dynamic);
    else {
      // The body becomes shapeless, and the box then holds it by its origin (see createBody).
      const b = this.bodies;
      const lx = rigid.localCenterX[slot];
      const ly = rigid.localCenterY[slot];
      const ox = b.x[slot] - (rigid.c[slot] * lx - rigid.s[slot] * ly);
      const oy = b.y[slot] - (rigid.s[slot] * lx + rigid.c[slot] * ly);
      const box = this.bounds;
      if (box && !(ox >= 0 && ox <= box.width && oy >= 0 && oy <= box.height)) {
        throw new RangeError(`destroying shape ${shapeHandle}, the last of body ${handle}, would leave a body without shapes with its origin at (${ox}, ${oy}), outside the box 0..${box.width} x 0..${box.height}; move the body first (setTransform) or destroy it`);
      }
    }
    this.checkLoadsAfter(handle, slot, null, s, 'destroying this shape');
    this.disturbances.note(this.bodies, slot);
    this.shapes.remove(s);
    this.shapesChanged(slot);
  }

  /** A shape's geometry (in its body's frame, from the origin), material and filter. */
  getShape(shapeHandle: number): ShapeState {
    const s = this.shapeSlot(shapeHandle);
    const store = this.shapes.store;
    const slot = store.body[s];
    const rigid = this.bodies.rigid!;
    const cx = rigid.localCenterX[slot];
    const cy = rigid.localCenterY[slot];
    const vertices: { x: number; y: number }[] = [];
    for (let i = 0, at = s * SHAPE_STRIDE + SHAPE_VERTICES; i < store.vertexCount[s]; i++, at += VERTEX) vertices.push({ x: store.record[at] + cx, y: store.record[at + 1] + cy });
    return {
      kind: SHAPE_KIND_NAMES[store.kind[s]],
      body: this.bodies.handleOf(slot),
      radius: store.radius[s],
      vertices,
      density: store.density[s],
      friction: store.friction[s],
      restitution: store.restitution[s],
      rollingResistance: store.rollingResistance[s],
      category: store.category[s],
      mask: store.mask[s],
      sensor: store.sensor[s] === 1,
    };
  }

  /**
   * Destroys a body with its shapes and its joints; each joint goes with a 'bodyDestroyed' event,
   * reported in jointEvents() after the next step.
   */
  destroyBody(handle: number): void {
    const s = this.slot(handle);
    if (this.joints !== null) this.destroyJointsOf(s);
    this.disturbances.note(this.bodies, s);
    if (this.bodies.type[s] === TypeCode.static) this.staticVersion++;
    if (this.shapeRoute && this.bodies.rigid!.flags[s] & BodyFlag.bullet) this.shapeRoute.bullets--;
    this.shapes.removeAll(s);
    this.bodies.remove(s);
    this.geometryVersion++;
  }

  /** A static wall from (x1, y1) to (x2, y2), at any angle, optionally thick. Segment handles are their own space. */
  createSegment(options: SegmentOptions): number {
    const segment = resolveSegment(options, this.defaultRestitution, this.defaultFriction);
    if (!this.segments.hasRoom()) throw new RangeError(`a world holds at most ${SLOT_SPACE} segments at once (handles encode the slot in 24 bits)`);
    if (segment.friction > 0) this.engage();
    this.staticVersion++;
    const handle = this.segments.add(segment);
    this.noteSegment(this.segmentSlot(handle));
    return handle;
  }

  /**
   * Static segments from each point to the next (and back to the first with `loop`), joined
   * smoothly: a shape sliding or rolling across a join meets no seam there, as on Box2D's chain
   * shapes (docs/engine.md, "Chains"). Returns the links' handles, in order; each is a segment
   * (getSegment, destroySegment, queries, events). Every point and option is checked before any
   * link is made.
   */
  createChain(options: ChainOptions): number[] {
    const links = resolveChain(options, this.defaultRestitution, this.defaultFriction);
    if (!this.segments.hasRoom(links.length)) throw new RangeError(`a world holds at most ${SLOT_SPACE} segments at once (handles encode the slot in 24 bits)`);
    if (links.some((link) => link.friction > 0)) this.engage();
    this.staticVersion++;
    const handles: number[] = [];
    for (const link of links) {
      const handle = this.segments.add(link);
      this.noteSegment(this.segmentSlot(handle));
      handles.push(handle);
    }
    return handles;
  }

  /** Removes a static segment; a stale or unknown handle throws a RangeError. */
  destroySegment(handle: number): void {
    const slot = this.segmentSlot(handle);
    this.noteSegment(slot);
    this.segments.remove(slot);
    this.staticVersion++;
  }

  /**
   * Notes segment `slot` for the next step's wakeTouching, as circles along it each about the
   * size of the widest body (at most 64): a sleeper it now crosses, or that rested on it, wakes,
   * and one asleep elsewhere along a long floor does not.
   */
  private noteSegment(slot: number): void {
    const b = this.bodies;
    if (b.sleepingCount === 0) return;
    const g = this.segments;
    const ax = g.ax[slot];
    const ay = g.ay[slot];
    const dx = g.bx[slot] - ax;
    const dy = g.by[slot] - ay;
    const length = Math.sqrt(dx * dx + dy * dy);
    const pieces = Math.min(64, Math.max(1, Math.ceil(length / (2 * (g.thickness[slot] + b.maxRadius())))));
    const reach = length / (2 * pieces) + g.thickness[slot];
    for (let k = 0; k < pieces; k++) {
      const t = (k + 0.5) / pieces;
      this.disturbances.noteCircle(b, ax + t * dx, ay + t * dy, reach);
    }
  }

  /** A segment as created, with every default filled in. */
  getSegment(handle: number): Required<SegmentOptions> {
    const s = this.segmentSlot(handle);
    const g = this.segments;
    return {
      x1: g.ax[s],
      y1: g.ay[s],
      x2: g.bx[s],
      y2: g.by[s],
      thickness: g.thickness[s],
      restitution: g.restitution[s],
      friction: g.friction[s],
      category: g.category[s],
      mask: g.mask[s],
    };
  }

  /** Live static segments. */
  get segmentCount(): number {
    return this.segments.count;
  }

  /** Shapes on bodies (0 in a world of circles only, whose circles are not listed as shapes). */
  get shapeCount(): number {
    return this.shapes.store.count;
  }

  /** Whether a handle names a live body: false once it is destroyed, even if its slot is reused; a TypeError for what is not a finite number. */
  hasBody(handle: number): boolean {
    finiteNumber('handle', handle);
    return this.bodies.slotOf(handle) >= 0;
  }

  /** A circle body's state (see CircleState); a body that is not a single circle throws: use getBody and getShape. */
  getCircle(handle: number): CircleState {
    const s = this.slot(handle);
    const b = this.bodies;
    let radius = b.radius[s];
    if (this.shapes.engaged) {
      const first = b.rigid!.firstShape[s];
      const store = this.shapes.store;
      if (first < 0 || store.kind[first] !== 0 || b.rigid!.shapeCount[s] !== 1) {
        throw new RangeError(`body ${handle} is not a single circle (it has ${b.rigid!.shapeCount[s]} shapes); use getBody and getShape`);
      }
      radius = store.radius[first];
    }
    return {
      x: b.x[s],
      y: b.y[s],
      vx: b.vx[s],
      vy: b.vy[s],
      radius,
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

  /** A body's pose, velocity and mass (see BodyState). */
  getBody(handle: number): BodyState {
    const s = this.slot(handle);
    const b = this.bodies;
    const rigid = b.rigid;
    const c = rigid ? rigid.c[s] : 1;
    const sn = rigid ? rigid.s[s] : 0;
    const lx = rigid ? rigid.localCenterX[s] : 0;
    const ly = rigid ? rigid.localCenterY[s] : 0;
    const shapes: number[] = [];
    if (rigid && this.shapes.engaged) for (let k = rigid.firstShape[s]; k >= 0; k = this.shapes.store.next[k]) shapes.push(this.shapes.store.handleOf(k));
    const flags = rigid ? rigid.flags[s] : 0;
    return {
      x: b.x[s] - (c * lx - sn * ly),
      y: b.y[s] - (sn * lx + c * ly),
      angle: atan2(sn, c),
      vx: b.vx[s],
      vy: b.vy[s],
      angularVelocity: rigid ? rigid.angularVelocity[s] : 0,
      mass: b.mass[s],
      inertia: (flags & BodyFlag.fixedRotation) !== 0 ? 0 : rigid ? rigid.inertia[s] : (b.mass[s] * b.radius[s] * b.radius[s]) / 2,
      centerX: b.x[s],
      centerY: b.y[s],
      type: typeName(b.type[s]),
      awake: b.asleep[s] === 0,
      fixedRotation: (flags & BodyFlag.fixedRotation) !== 0,
      bullet: (flags & BodyFlag.bullet) !== 0,
      gravityScale: b.gravityScale[s],
      linearDamping: b.linearDamping[s],
      angularDamping: rigid ? rigid.angularDamping[s] : 0,
      shapes,
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
    finiteNumber('handle', handle);
    return this.bodies.slotOf(handle);
  }

  /** The handle of the body in a slot of the bulk views, or -1 for a free slot. */
  handleAtSlot(slot: number): number {
    finiteNumber('slot', slot);
    const b = this.bodies;
    if (!Number.isInteger(slot) || slot < 0 || slot >= b.slotCount || b.type[slot] === TypeCode.free) return -1;
    return b.handleOf(slot);
  }

  /** The handle of the shape in a slot of the shape views, or -1. */
  shapeHandleAtSlot(slot: number): number {
    finiteNumber('slot', slot);
    const store = this.shapes.store;
    if (!Number.isInteger(slot) || slot < 0 || slot >= store.slotCount || store.live[slot] !== 1) return -1;
    return store.handleOf(slot);
  }

  /** Sets a body's linear velocity and wakes it; a static body throws. */
  setVelocity(handle: number, vx: number, vy: number): void {
    const s = this.slot(handle);
    boundedNumber('vx', vx);
    boundedNumber('vy', vy);
    if (this.bodies.type[s] === TypeCode.static) {
      throw new RangeError(`body ${handle} is static and cannot be given a velocity (${vx}, ${vy}); make it kinematic or dynamic first`);
    }
    this.bodies.vx[s] = vx;
    this.bodies.vy[s] = vy;
    this.bodies.wake(s);
  }

  /** Sets a body's angular velocity, radians per second (see BodyState.angle for the sense); wakes it. */
  setAngularVelocity(handle: number, angularVelocity: number): void {
    const s = this.slot(handle);
    boundedNumber('angularVelocity', angularVelocity);
    if (this.bodies.type[s] === TypeCode.static && angularVelocity !== 0) {
      throw new RangeError(`body ${handle} is static and cannot be given an angular velocity (${angularVelocity}); make it kinematic or dynamic first`);
    }
    this.useRigid().angularVelocity[s] = angularVelocity;
    if (angularVelocity !== 0) this.turning = true;
    this.bodies.wake(s);
  }

  /** Moves a body's origin to (x, y): its centre follows. */
  setPosition(handle: number, x: number, y: number): void {
    const s = this.slot(handle);
    boundedNumber('x', x);
    boundedNumber('y', y);
    const rigid = this.bodies.rigid;
    this.placeBody(s, x, y, rigid ? rigid.c[s] : 1, rigid ? rigid.s[s] : 0);
  }

  /** Moves a body's origin to (x, y) and turns it to `angle` radians; wakes it. */
  setTransform(handle: number, x: number, y: number, angle: number): void {
    const s = this.slot(handle);
    boundedNumber('x', x);
    boundedNumber('y', y);
    finiteNumber('angle', angle);
    cosSin(angle, rotation);
    this.placeBody(s, x, y, rotation[0], rotation[1]);
  }

  /**
   * Sets a body's velocities so that, moving at them, it reaches the origin (x, y) turned to
   * `angle` radians after `dt` seconds, the shorter way round: a moving platform, a door or an
   * animated body driven by poses, which carries what rests on it by friction where setTransform
   * would jump it there (Box2D v3's b2Body_SetTargetTransform). Call it before each step with that
   * step's dt; the elastic pass lands on the pose to rounding, the soft step's sub-steps turn a
   * body close to it, within maxLinearSpeed and an eighth of a turn a step, the limits Box2D
   * holds every awake body to. Meant for kinematic bodies; a dynamic one takes the velocities as
   * a start, and a static one throws. Wakes it.
   */
  setTargetTransform(handle: number, x: number, y: number, angle: number, dt: number): void {
    const s = this.slot(handle);
    boundedNumber('x', x);
    boundedNumber('y', y);
    finiteNumber('angle', angle);
    finiteNumber('dt', dt);
    if (!(dt > 0)) throw new RangeError(`dt must be > 0, got ${dt}`);
    const b = this.bodies;
    if (b.type[s] === TypeCode.static) {
      throw new RangeError(`body ${handle} is static and cannot be given a velocity towards (${x}, ${y}, ${angle}); make it kinematic or dynamic first`);
    }
    cosSin(angle, rotation);
    const c = rotation[0];
    const sn = rotation[1];
    const rigid = b.rigid;
    const lx = rigid ? rigid.localCenterX[s] : 0;
    const ly = rigid ? rigid.localCenterY[s] : 0;
    const vx = (x + (c * lx - sn * ly) - b.x[s]) / dt;
    const vy = (y + (sn * lx + c * ly) - b.y[s]) / dt;
    const c0 = rigid ? rigid.c[s] : 1;
    const s0 = rigid ? rigid.s[s] : 0;
    const w = atan2(c0 * sn - s0 * c, c0 * c + s0 * sn) / dt;
    if (!(Math.abs(vx) <= MAX_MAGNITUDE && Math.abs(vy) <= MAX_MAGNITUDE && Math.abs(w) <= MAX_MAGNITUDE)) {
      throw new RangeError(`reaching (${x}, ${y}, ${angle}) in dt ${dt} takes a velocity (${vx}, ${vy}) and spin ${w} beyond ${MAX_MAGNITUDE}`);
    }
    b.vx[s] = vx;
    b.vy[s] = vy;
    if (w !== 0 || rigid) {
      this.useRigid().angularVelocity[s] = w;
      if (w !== 0) this.turning = true;
    }
    b.wake(s);
  }

  /** Adds a force (mass x length / s^2) to a dynamic body for the next step only; wakes it. */
  applyForce(handle: number, fx: number, fy: number): void {
    const s = this.dynamicSlot(handle, 'a force', 'fx', fx, 'fy', fy);
    const b = this.bodies;
    const totalX = b.forceX[s] + fx;
    const totalY = b.forceY[s] + fy;
    // Finite inputs can still sum, or divide by a small mass, past what a step can take; it would then spread infinities.
    if (!(Math.abs(totalX * b.invMass[s]) <= MAX_MAGNITUDE && Math.abs(totalY * b.invMass[s]) <= MAX_MAGNITUDE)) {
      throw new RangeError(`a force (${fx}, ${fy}) on body ${handle} would make its acceleration exceed ${MAX_MAGNITUDE} (pending force (${totalX}, ${totalY}), mass ${b.mass[s]})`);
    }
    b.forceX[s] = totalX;
    b.forceY[s] = totalY;
    this.bodies.forcesPending = true;
    this.bodies.wake(s);
  }

  /** Adds a torque (mass x length^2 / s^2) to a dynamic body for the next step only; wakes it. */
  applyTorque(handle: number, torque: number): void {
    const s = this.dynamicSlot(handle, 'a torque', 'torque', torque, null, 0);
    const total = (this.bodies.rigid?.torque[s] ?? 0) + torque;
    if (!(Math.abs(total * this.inverseInertia(s)) <= MAX_MAGNITUDE)) {
      throw new RangeError(`a torque ${torque} on body ${handle} would make its angular acceleration exceed ${MAX_MAGNITUDE} (pending torque ${total}, inertia ${this.inertiaOf(s)})`);
    }
    const rigid = this.useRigid();
    rigid.torque[s] = total;
    this.bodies.forcesPending = true;
    this.turning = true;
    this.bodies.wake(s);
  }

  /** Changes a dynamic body's velocity by impulse / mass at once; wakes it. */
  applyImpulse(handle: number, ix: number, iy: number): void {
    const s = this.dynamicSlot(handle, 'an impulse', 'ix', ix, 'iy', iy);
    const b = this.bodies;
    const vx = b.vx[s] + ix * b.invMass[s];
    const vy = b.vy[s] + iy * b.invMass[s];
    if (!(Math.abs(vx) <= MAX_MAGNITUDE && Math.abs(vy) <= MAX_MAGNITUDE)) {
      throw new RangeError(`an impulse (${ix}, ${iy}) on body ${handle} would make its velocity (${vx}, ${vy}) exceed ${MAX_MAGNITUDE} (mass ${b.mass[s]})`);
    }
    b.vx[s] = vx;
    b.vy[s] = vy;
    this.bodies.wake(s);
  }

  /** Changes a dynamic body's angular velocity by impulse / inertia at once; wakes it. */
  applyAngularImpulse(handle: number, impulse: number): void {
    const s = this.dynamicSlot(handle, 'an angular impulse', 'impulse', impulse, null, 0);
    const w = (this.bodies.rigid?.angularVelocity[s] ?? 0) + impulse * this.inverseInertia(s);
    if (!(Math.abs(w) <= MAX_MAGNITUDE)) throw new RangeError(`an angular impulse ${impulse} on body ${handle} would make its angular velocity ${w} exceed ${MAX_MAGNITUDE} (inertia ${this.inertiaOf(s)})`);
    this.useRigid().angularVelocity[s] = w;
    if (w !== 0) this.turning = true;
    this.bodies.wake(s);
  }

  /**
   * Adds a force (mass x length / s^2) acting at the world point (x, y) to a dynamic body for the
   * next step only: the force at its centre of mass and the torque (x - cx) fy - (y - cy) fx about
   * it (Box2D's b2Body_ApplyForce). Wakes it. Refused whole (nothing added) where either part would
   * exceed what a step can take.
   */
  applyForceAtPoint(handle: number, fx: number, fy: number, x: number, y: number): void {
    const s = this.dynamicSlot(handle, 'a force', 'fx', fx, 'fy', fy);
    finiteNumber('x', x);
    finiteNumber('y', y);
    const b = this.bodies;
    const torque = (x - b.x[s]) * fy - (y - b.y[s]) * fx;
    const totalX = b.forceX[s] + fx;
    const totalY = b.forceY[s] + fy;
    const totalTorque = (b.rigid?.torque[s] ?? 0) + torque;
    if (!(Math.abs(totalX * b.invMass[s]) <= MAX_MAGNITUDE && Math.abs(totalY * b.invMass[s]) <= MAX_MAGNITUDE)) {
      throw new RangeError(`a force (${fx}, ${fy}) on body ${handle} would make its acceleration exceed ${MAX_MAGNITUDE} (pending force (${totalX}, ${totalY}), mass ${b.mass[s]})`);
    }
    if (!(Math.abs(totalTorque * this.inverseInertia(s)) <= MAX_MAGNITUDE)) {
      throw new RangeError(`a force (${fx}, ${fy}) at (${x}, ${y}) on body ${handle} would make its angular acceleration exceed ${MAX_MAGNITUDE} (pending torque ${totalTorque}, inertia ${this.inertiaOf(s)})`);
    }
    b.forceX[s] = totalX;
    b.forceY[s] = totalY;
    if (torque !== 0) {
      this.useRigid().torque[s] = totalTorque;
      this.turning = true;
    }
    b.forcesPending = true;
    b.wake(s);
  }

  /**
   * Changes a dynamic body's velocity by impulse / mass and its angular velocity by the impulse's
   * moment about its centre of mass, ((x - cx) iy - (y - cy) ix) / inertia, at once: an impulse at
   * the world point (x, y) (Box2D's b2Body_ApplyLinearImpulse). Wakes it; refused whole where either
   * speed would exceed what a step can take.
   */
  applyImpulseAtPoint(handle: number, ix: number, iy: number, x: number, y: number): void {
    const s = this.dynamicSlot(handle, 'an impulse', 'ix', ix, 'iy', iy);
    finiteNumber('x', x);
    finiteNumber('y', y);
    const b = this.bodies;
    const vx = b.vx[s] + ix * b.invMass[s];
    const vy = b.vy[s] + iy * b.invMass[s];
    const moment = (x - b.x[s]) * iy - (y - b.y[s]) * ix;
    const w = (b.rigid?.angularVelocity[s] ?? 0) + moment * this.inverseInertia(s);
    if (!(Math.abs(vx) <= MAX_MAGNITUDE && Math.abs(vy) <= MAX_MAGNITUDE)) {
      throw new RangeError(`an impulse (${ix}, ${iy}) on body ${handle} would make its velocity (${vx}, ${vy}) exceed ${MAX_MAGNITUDE} (mass ${b.mass[s]})`);
    }
    if (!(Math.abs(w) <= MAX_MAGNITUDE)) {
      throw new RangeError(`an impulse (${ix}, ${iy}) at (${x}, ${y}) on body ${handle} would make its angular velocity ${w} exceed ${MAX_MAGNITUDE} (inertia ${this.inertiaOf(s)})`);
    }
    b.vx[s] = vx;
    b.vy[s] = vy;
    if (moment !== 0) {
      this.useRigid().angularVelocity[s] = w;
      if (w !== 0) this.turning = true;
    }
    b.wake(s);
  }

  /** Sets the factor on the world's gravity for one body (CircleOptions.gravityScale); wakes it. */
  setGravityScale(handle: number, scale: number): void {
    const s = this.slot(handle);
    this.checkGravityScale(boundedNumber('gravityScale', scale));
    this.bodies.setMotion(s, scale, this.bodies.linearDamping[s]);
    this.bodies.wake(s);
  }

  /** Sets a body's linear damping (CircleOptions.linearDamping), at least 0; wakes it. */
  setLinearDamping(handle: number, damping: number): void {
    const s = this.slot(handle);
    this.bodies.setMotion(s, this.bodies.gravityScale[s], nonNegativeNumber('linearDamping', damping));
    this.bodies.wake(s);
  }

  /** Sets a body's angular damping, at least 0, as linearDamping does for velocity; wakes it. */
  setAngularDamping(handle: number, damping: number): void {
    const s = this.slot(handle);
    const value = nonNegativeNumber('angularDamping', damping);
    this.useRigid();
    this.bodies.setAngularDamping(s, value);
    this.bodies.wake(s);
  }

  /** Fixes or frees a body's rotation (a fixed one has no rotational inertia and stops turning). */
  setFixedRotation(handle: number, fixed: boolean): void {
    const s = this.slot(handle);
    flag('fixedRotation', fixed);
    if (!fixed && this.bodies.type[s] === TypeCode.dynamic) this.checkTorque(handle, s, this.inertiaOf(s), 'freeing its rotation');
    const rigid = this.useRigid();
    rigid.flags[s] = fixed ? rigid.flags[s] | BodyFlag.fixedRotation : rigid.flags[s] & ~BodyFlag.fixedRotation;
    if (fixed) rigid.angularVelocity[s] = 0;
    this.bodies.setMass(s, this.bodies.mass[s], rigid.inertia[s]);
    this.bodies.wake(s);
  }

  /** Collision layers: bodies a and b collide only if (a.category & b.mask) and (b.category & a.mask). With shapes, every shape of the body takes them. */
  setCollisionFilter(handle: number, category: number, mask: number): void {
    const s = this.slot(handle);
    const c = layerBits('category', category);
    const m = layerBits('mask', mask);
    this.disturbances.note(this.bodies, s);
    if (this.shapes.engaged) {
      const store = this.shapes.store;
      for (let k = this.bodies.rigid!.firstShape[s]; k >= 0; k = store.next[k]) store.setFilter(k, c, m);
    }
    this.bodies.setFilter(s, c, m);
    this.bodies.wake(s);
    if (this.bodies.type[s] === TypeCode.static) this.staticVersion++;
  }

  /** Whether a body is awake; a sleeping body does not move until something wakes it (setAwake, a setter, a touch). */
  isAwake(handle: number): boolean {
    return this.bodies.asleep[this.slot(handle)] === 0;
  }

  /** Wakes a body (with the island it sleeps in), or puts a dynamic body to sleep at once (its velocity becomes zero). */
  setAwake(handle: number, awake: boolean): void {
    const s = this.slot(handle);
    if (typeof awake !== 'boolean') throw new TypeError(`awake must be true or false, got ${describeValue(awake)}`);
    if (awake) this.bodies.wake(s);
    else if (this.bodies.type[s] === TypeCode.dynamic) this.bodies.fallAsleep(s);
  }

  /**
   * Changes a body's motion type at run time (the report's mutable object types, 3.2). Its joints
   * stay: one whose bodies are then both static or kinematic does nothing (createJoint refuses
   * such a pair) until one of them is dynamic again.
   */
  setType(handle: number, type: BodyType): void {
    const s = this.slot(handle);
    const code = TypeCode[bodyType(type)];
    const rigid = this.bodies.rigid;
    if (code === TypeCode.dynamic && this.shapes.engaged && rigid!.shapeCount[s] > 0) this.checkMass(handle, this.shapes.massWith(s, null));
    this.disturbances.note(this.bodies, s);
    if (this.bodies.type[s] === TypeCode.static || code === TypeCode.static) this.staticVersion++;
    this.bodies.setTypeCode(s, code);
    if (this.shapes.engaged) {
      this.shapes.update(s);
      this.shapeRoute?.narrow.forget(s);
    }
    if (code === TypeCode.static && rigid) rigid.angularVelocity[s] = 0;
    this.geometryVersion++;
  }

  /** Switches the broad-phase from the next step; every broad-phase gives the same bits, at its own speed. */
  setBroadphase(name: BroadPhaseName): void {
    const checked = broadphaseName(name);
    if (checked !== this.pipeline.broadPhase.name) this.pipeline.broadPhase = BROADPHASES[checked]();
  }

  /** Switches the integrator; 'rk4' moves the world to the shape route (see IntegratorName). */
  setIntegrator(name: IntegratorName): void {
    const checked = integratorName(name);
    if (checked === 'rk4') this.engage();
    this.integratorChoice = checked;
    this.pipeline.integrator = circleIntegrator(checked);
    if (this.shapeRoute) this.shapeRoute.settings.integrator = checked;
    if (this.joints) this.joints.integrator = checked;
  }

  /** Sets the world's gravity, in length units per second squared. */
  setGravity(x: number, y: number): void {
    const g = vector('gravity', { x, y });
    // Every body's gravity scale times the new gravity must stay a bounded acceleration.
    const { gravityScale, type, slotCount } = this.bodies;
    let most = 0;
    for (let k = 0; k < slotCount; k++) if (type[k] === TypeCode.dynamic && Math.abs(gravityScale[k]) > most) most = Math.abs(gravityScale[k]);
    this.checkGravityScale(most, g.x, g.y, 'gravity');
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
   * A world with shapes steps on this thread alone (same bits); the workers serve circle worlds.
   * `views()` must be taken again afterwards: the columns move to shared memory.
   *
   * Options: `minBodies` (below it a step runs on this thread alone), and `adaptive` (default
   * true): each step is timed, and now and then one runs the other way, on this thread alone or
   * on the threads, so that a machine whose cores are busy with other work steps on one thread
   * rather than wait for workers the scheduler does not run (`stats.threads` says which ran).
   * `adaptive: false` always uses the threads, for measuring them.
   *
   * `workerUrl` (a URL or a string) names the worker script, for builds that do not emit the
   * engine's own: Vite 8 and webpack 5 do by themselves (Vite 7's dev server with
   * `optimizeDeps.exclude` of the engine); with esbuild, build
   * `@maxgrid/engine/worker` as an entry point of its own and pass the URL it is served at.
   */
  async startWorkers(
    workerCount: number,
    options: { minBodies?: number | undefined; adaptive?: boolean | undefined; workerUrl?: string | { readonly href: string } | undefined } = {},
  ): Promise<void> {
    checkWorkerCount(workerCount);
    options = plainObject('startWorkers options', options);
    knownKeys('startWorkers options', options, ['minBodies', 'adaptive', 'workerUrl']);
    const minBodies = options.minBodies === undefined ? DEFAULT_MIN_BODIES : nonNegativeInteger('minBodies', options.minBodies);
    if (options.adaptive !== undefined && typeof options.adaptive !== 'boolean') throw new TypeError(`startWorkers option adaptive must be a boolean, got ${String(options.adaptive)}`);
    const script: unknown = options.workerUrl;
    if (script !== undefined && !(typeof script === 'string' ? script !== '' : typeof (script as { href?: unknown } | null)?.href === 'string')) {
      throw new TypeError(`startWorkers option workerUrl must be a URL or a non-empty string, got ${script === '' ? '""' : String(script)}`);
    }
    this.stopWorkers();
    const started = this.workerStarts;
    const parallel = await ParallelStep.start(workerCount, this.bodies, this.pipeline.contacts, options.workerUrl);
    if (started !== this.workerStarts) {
      // stopWorkers (or another startWorkers) was called while these were starting: it wins.
      parallel.stop();
      return;
    }
    parallel.minBodies = minBodies;
    if (options.adaptive === false) parallel.governor = null;
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

  /**
   * Advances the world by `dt` seconds: 0, or within [1e-100, 1e6] (a RangeError otherwise).
   * Allocates nothing once buffers have grown to the scene.
   */
  step(dt: number): void {
    finiteNumber('dt', dt);
    if (dt < 0) throw new RangeError(`dt must be >= 0, got ${dt}`);
    if (dt > MAX_DT) throw new RangeError(`dt must be at most ${MAX_DT} s (so that a step cannot overflow), got ${dt}`);
    if (dt > 0 && dt < MIN_DT) throw new RangeError(`dt must be 0 or at least ${MIN_DT} s (so that a step cannot overflow), got ${dt}`);
    this.disturbances.wakeTouching(this.bodies, this.queries, this.geometryVersion, this.pipeline.settings.solver.contactSlop);
    if (this.shapeRoute) {
      const solver = this.shapeSolver();
      // Kept manifolds and impulses belong to the solver that made them (the elastic pass keeps
      // none, and its impulses are whole collisions): the other starts from fresh contacts.
      if (solver !== this.shapeRoute.settings.solver) {
        this.shapeRoute.settings.solver = solver;
        this.shapeRoute.narrow.current.clear();
      }
      if (this.joints !== null) this.beginJointEvents();
      this.shapeRoute.run(dt, this.pipeline.broadPhase, this.staticVersion, this.pipeline.stats, this.queries, this.geometryVersion, this.pipeline.events, this.pipeline.settings.solver.hitThreshold);
      limitSpeeds(this.bodies, this.shapeRoute.settings.soft.maxLinearSpeed, MAX_MAGNITUDE);
      if (this.joints !== null && this.joints.store.breakable > 0 && dt > 0) this.breakJoints();
    } else {
      this.limitMotion(dt);
      this.pipeline.run(dt, this.staticVersion);
      if (this.turning) turnCircles(this.bodies, dt);
      // After the turn, which reads the torques: the forces acted in the pipeline's motion.
      if (dt > 0) clearForces(this.bodies);
      limitSpeeds(this.bodies, this.resolved.maxLinearSpeed ?? MAX_MAGNITUDE, MAX_MAGNITUDE);
    }
    // Events kept for hits or sensors list no touches unless asked to.
    if (!this.resolved.contactEvents) this.pipeline.events?.dropTouches();
    this.geometryVersion++;
  }


  /**
   * The circle route's speed limit, where one was given, for this step's motion (BodyStore.speedCap,
   * which sends it to the general loop): only where a body may pass it within the step, one faster
   * than the limit less what gravity adds in a step, or where forces, damping or gravity scales
   * act. Elsewhere the plain loop (the body kernel's) moves every body within the limit as it is.
   */
  private limitMotion(dt: number): void {
    const cap = this.resolved.maxLinearSpeed;
    if (cap === null) return;
    const b = this.bodies;
    const g = this.pipeline.settings.gravity;
    const general = b.customMotionCount > 0 || b.forcesPending || b.sleepingCount > 0;
    b.speedCap = general || anyFaster(b, cap - Math.sqrt(g.x * g.x + g.y * g.y) * dt) ? cap : MAX_MAGNITUDE;
  }

  /**
   * Joins two bodies (see JointOptions for each kind: 'distance', 'revolute', 'prismatic', 'weld',
   * 'wheel', 'target', 'spring', 'pressure'); returns the joint's handle. Anchors are in each body's own frame, from its
   * origin, as shapes are. The world moves to the soft step (joints need it: a world made with
   * solver 'elastic' refuses them). Both bodies wake. Joined bodies do not collide unless
   * collideConnected is set; they sleep and wake as one island.
   */
  createJoint(options: JointOptions): number {
    if (this.resolved.solver === 'elastic') throw new RangeError("joints need the soft step: this world was made with solver 'elastic'; use 'auto' or 'soft'");
    const membership = this.bodies.membershipVersion;
    // Read once (the copy), and refused before any handle in it is looked up where that reading
    // created or destroyed bodies.
    const copy = plainObject('joint options', options);
    this.assertBodiesKept(membership, 'joint options');
    const resolved = resolveJoint(copy, this.jointWorld);
    const store = this.joints?.store;
    if (store !== undefined && !store.hasRoom()) throw new RangeError(`a world holds at most ${SLOT_SPACE} joints at once`);
    this.engage();
    const joints = this.useJoints();
    const slot = joints.store.add(resolved.kind, resolved.bodyA, resolved.bodyB, resolved.collide, resolved.definition, resolved.ring);
    if (resolved.bodyA >= 0) this.bodies.wake(resolved.bodyA);
    this.bodies.wake(resolved.bodyB);
    if (resolved.ring) for (const body of resolved.ring) this.bodies.wake(body);
    return joints.store.handleOf(slot);
  }

  /** Destroys a joint; its bodies wake. */
  destroyJoint(handle: number): void {
    const j = this.jointSlot(handle);
    const store = this.joints!.store;
    if (store.bodyA[j] >= 0) this.bodies.wake(store.bodyA[j]);
    this.bodies.wake(store.bodyB[j]);
    store.remove(j);
  }

  /** Whether a handle names a live joint: false once it is destroyed, breaks, or goes with one of its bodies. */
  hasJoint(handle: number): boolean {
    finiteNumber('handle', handle);
    return this.joints !== null && this.joints.store.slotOf(handle) >= 0;
  }

  /** Live joints. */
  get jointCount(): number {
    return this.joints?.store.count ?? 0;
  }

  /** Handles of the live joints, in slot order (the order they are solved in). Allocates. */
  jointHandles(): number[] {
    const out: number[] = [];
    const store = this.joints?.store;
    if (store) for (let j = 0; j < store.slotCount; j++) if (store.live[j] === 1) out.push(store.handleOf(j));
    return out;
  }

  /** Handles of the joints on a body. Allocates. */
  jointsOf(handle: number): number[] {
    const s = this.slot(handle);
    const out: number[] = [];
    const store = this.joints?.store;
    if (!store) return out;
    if (s < store.firstEdge.length) for (let e = store.firstEdge[s]; e >= 0; e = store.edgeNext[e]) out.push(store.handleOf(e >> 1));
    for (const j of store.ringsOf(s)) if (!out.includes(store.handleOf(j))) out.push(store.handleOf(j));
    return out.sort((a, b) => a - b);
  }

  /** A joint's kind, bodies, anchors in the world, and the force and torque it put on body B in the last step. */
  getJoint(handle: number): JointState {
    const j = this.jointSlot(handle);
    const store = this.joints!.store;
    const r = store.record;
    const o = j * JOINT_STRIDE;
    const a = store.bodyA[j];
    const b = store.bodyB[j];
    const pa = new Float64Array(2);
    const pb = new Float64Array(2);
    if (a >= 0) this.jointWorld.worldPoint(a, r[o + J.anchorAX], r[o + J.anchorAY], pa);
    else {
      pa[0] = r[o + J.targetX];
      pa[1] = r[o + J.targetY];
    }
    this.jointWorld.worldPoint(b, r[o + J.anchorBX], r[o + J.anchorBY], pb);
    const rigid = this.bodies.rigid!;
    const ca = a >= 0 ? rigid.c[a] : 1;
    const sa = a >= 0 ? rigid.s[a] : 0;
    const cb = rigid.c[b];
    const sb = rigid.s[b];
    let angle = atan2(sb * ca - cb * sa, cb * ca + sb * sa) - r[o + J.referenceAngle];
    const kind = store.kind[j];
    // A limited revolute joint's angle is the one its limits act on, followed across ±pi (J.deltaAngle).
    if (kind === JointKind.revolute && r[o + J.enableLimit] === 1) angle = nearestTurn(angle, r[o + J.deltaAngle]);
    else if (angle > Math.PI) angle -= 2 * Math.PI;
    else if (angle < -Math.PI) angle += 2 * Math.PI;
    const dx = pb[0] - pa[0];
    const dy = pb[1] - pa[1];
    const slides = kind === JointKind.prismatic || kind === JointKind.wheel;
    const axisX = ca * r[o + J.axisX] - sa * r[o + J.axisY];
    const axisY = sa * r[o + J.axisX] + ca * r[o + J.axisY];
    return {
      kind: JOINT_KIND_NAMES[kind],
      bodyA: a >= 0 ? this.bodies.handleOf(a) : null,
      bodyB: this.bodies.handleOf(b),
      anchorA: { x: pa[0], y: pa[1] },
      anchorB: { x: pb[0], y: pb[1] },
      force: { x: r[o + J.forceX], y: r[o + J.forceY] },
      torque: r[o + J.torque],
      length: Math.sqrt(dx * dx + dy * dy),
      angle: kind === JointKind.target || kind === JointKind.distance || kind === JointKind.spring ? 0 : angle,
      translation: slides ? dx * axisX + dy * axisY : 0,
      collideConnected: store.collide[j] === 1,
      ring: kind === JointKind.pressure ? Array.from(store.ring(j), (body) => this.bodies.handleOf(body)) : [],
      area: kind === JointKind.pressure ? this.ringArea(store.ring(j)) : 0,
    };
  }

  /** The area of the polygon through a ring's bodies' centres of mass. */
  private ringArea(ring: Int32Array): number {
    const { x, y } = this.bodies;
    let twice = 0;
    for (let k = 0; k < ring.length; k++) {
      const p = ring[k];
      const q = ring[(k + 1) % ring.length];
      twice += x[p] * y[q] - x[q] * y[p];
    }
    return Math.abs(0.5 * twice);
  }

  /**
   * Whether the polygon through a ring's bodies' centres crosses itself (a bow-tie), and where:
   * two edges that are not neighbours meet, crossing or touching (an edge through another's end,
   * as a figure eight's lobes meet at a body), by the signs of four orientations and, where one
   * is 0, whether that end lies within the other edge. Every pair of edges: the ring is made once.
   */
  private ringCrossing(ring: Int32Array, out: Int32Array): boolean {
    const { x, y } = this.bodies;
    const n = ring.length;
    const side = (a: number, b: number, c: number): number => Math.sign((x[b] - x[a]) * (y[c] - y[a]) - (y[b] - y[a]) * (x[c] - x[a]));
    // c on the line through a and b: whether it lies between them.
    const within = (a: number, b: number, c: number): boolean =>
      Math.min(x[a], x[b]) <= x[c] && x[c] <= Math.max(x[a], x[b]) && Math.min(y[a], y[b]) <= y[c] && y[c] <= Math.max(y[a], y[b]);
    for (let i = 0; i < n; i++) {
      const a = ring[i];
      const b = ring[(i + 1) % n];
      for (let j = i + 2; j < n; j++) {
        if (i === 0 && j === n - 1) continue;
        const c = ring[j];
        const d = ring[(j + 1) % n];
        const abc = side(a, b, c);
        const abd = side(a, b, d);
        const cda = side(c, d, a);
        const cdb = side(c, d, b);
        const crosses = abc * abd < 0 && cda * cdb < 0;
        const touches = (abc === 0 && within(a, b, c)) || (abd === 0 && within(a, b, d)) || (cda === 0 && within(c, d, a)) || (cdb === 0 && within(c, d, b));
        if (crosses || touches) {
          out[0] = i;
          out[1] = j;
          return true;
        }
      }
    }
    return false;
  }

  /** Moves a target joint's target; its body wakes. */
  setJointTarget(handle: number, x: number, y: number): void {
    const j = this.jointSlot(handle);
    const store = this.joints!.store;
    if (store.kind[j] !== JointKind.target) throw new RangeError(`joint ${handle} is a ${JOINT_KIND_NAMES[store.kind[j]]} joint: only target joints have a target`);
    boundedNumber('x', x);
    boundedNumber('y', y);
    store.record[j * JOINT_STRIDE + J.targetX] = x;
    store.record[j * JOINT_STRIDE + J.targetY] = y;
    this.bodies.wake(store.bodyB[j]);
  }

  /**
   * Sets the motor of a revolute, prismatic or wheel joint: its speed, and its largest torque (a
   * force for a prismatic joint), 0 switching it off. Its bodies wake.
   */
  setJointMotor(handle: number, speed: number, maxForceOrTorque: number): void {
    const j = this.jointSlot(handle);
    const store = this.joints!.store;
    const kind = store.kind[j];
    if (kind !== JointKind.revolute && kind !== JointKind.prismatic && kind !== JointKind.wheel) {
      throw new RangeError(`joint ${handle} is a ${JOINT_KIND_NAMES[kind]} joint: only revolute, prismatic and wheel joints have a motor`);
    }
    boundedNumber('speed', speed);
    const most = nonNegativeNumber('maxForceOrTorque', maxForceOrTorque);
    if (!(most <= MAX_MAGNITUDE)) throw new RangeError(`maxForceOrTorque must be at most ${MAX_MAGNITUDE}, got ${most}`);
    const o = j * JOINT_STRIDE;
    store.record[o + J.motorSpeed] = speed;
    store.record[o + J.maxMotor] = most;
    store.record[o + J.enableMotor] = most > 0 ? 1 : 0;
    if (most === 0) store.record[o + J.motorImpulse] = 0;
    if (store.bodyA[j] >= 0) this.bodies.wake(store.bodyA[j]);
    this.bodies.wake(store.bodyB[j]);
  }

  /**
   * Joints that went in the last step: those that broke in it, and those destroyed with a body
   * since the step before it. The object and its arrays are reused by every step.
   */
  jointEvents(): JointEventsView {
    return this.jointEventsRecord;
  }

  /** Every live joint's anchors in the world, in slot order, for drawing. The object and its arrays are reused. */
  jointViews(): JointViews {
    const v = this.jointViewsRecord;
    const store = this.joints?.store;
    v.count = 0;
    if (!store) return v;
    if (v.handle.length < store.count) {
      const capacity = grownCapacity(v.handle.length, store.count);
      v.handle = new Float64Array(capacity);
      v.kind = new Uint8Array(capacity);
      v.anchorAX = new Float64Array(capacity);
      v.anchorAY = new Float64Array(capacity);
      v.anchorBX = new Float64Array(capacity);
      v.anchorBY = new Float64Array(capacity);
    }
    const r = store.record;
    let n = 0;
    for (let j = 0; j < store.slotCount; j++) {
      if (store.live[j] === 0 || store.kind[j] === JointKind.pressure) continue;
      const o = j * JOINT_STRIDE;
      const a = store.bodyA[j];
      if (a >= 0) {
        this.jointWorld.worldPoint(a, r[o + J.anchorAX], r[o + J.anchorAY], rotation);
        v.anchorAX[n] = rotation[0];
        v.anchorAY[n] = rotation[1];
      } else {
        v.anchorAX[n] = r[o + J.targetX];
        v.anchorAY[n] = r[o + J.targetY];
      }
      this.jointWorld.worldPoint(store.bodyB[j], r[o + J.anchorBX], r[o + J.anchorBY], rotation);
      v.anchorBX[n] = rotation[0];
      v.anchorBY[n] = rotation[1];
      v.handle[n] = store.handleOf(j);
      v.kind[n] = store.kind[j];
      n++;
    }
    v.count = n;
    return v;
  }

  /** Linear plus rotational kinetic energy of the dynamic bodies. */
  kineticEnergy(): number {
    return analytics.kineticEnergy(this.bodies);
  }

  /** Gravity's potential energy of the dynamic bodies, plus the elastic energy of force-driven springs (kind 'spring'). */
  potentialEnergy(): number {
    const g = this.pipeline.settings.gravity;
    let energy = analytics.potentialEnergy(this.bodies, g.x, g.y);
    const store = this.joints?.store;
    if (!store) return energy;
    const r = store.record;
    for (let j = 0; j < store.slotCount; j++) {
      if (store.live[j] === 0 || store.kind[j] !== JointKind.spring) continue;
      const o = j * JOINT_STRIDE;
      this.jointWorld.worldPoint(store.bodyA[j], r[o + J.anchorAX], r[o + J.anchorAY], rotation);
      const ax = rotation[0];
      const ay = rotation[1];
      this.jointWorld.worldPoint(store.bodyB[j], r[o + J.anchorBX], r[o + J.anchorBY], rotation);
      const dx = rotation[0] - ax;
      const dy = rotation[1] - ay;
      const stretch = Math.sqrt(dx * dx + dy * dy) - r[o + J.length];
      energy += 0.5 * r[o + J.stiffness] * stretch * stretch;
    }
    return energy;
  }

  /** Linear momentum of the dynamic bodies (sum of m v). */
  momentum(): Vector {
    return analytics.momentum(this.bodies);
  }

  /** Angular momentum of the dynamic bodies about the origin: orbital (r x m v) plus spin (I w). */
  angularMomentum(): number {
    return analytics.angularMomentum(this.bodies);
  }

  /**
   * 16 hex digits identifying the exact bits of every body's motion: its slot, type, position,
   * velocity, rotation and angular velocity; equal across runtimes. Not what no step changes (mass,
   * shapes, materials, flags, joints): worlds built differently can hash alike, and `snapshot()`'s
   * bytes compare whole worlds.
   */
  stateHash(): string {
    return analytics.stateHash(this.bodies);
  }

  /**
   * The contact points of the last step (see ContactPointViews): every manifold point of a world
   * with shapes; for circles, one point per touching pair, midway between the surfaces.
   */
  contactPoints(): ContactPointViews {
    const out = this.contactPointsRecord;
    let n = 0;
    const put = (x: number, y: number, nx: number, ny: number, separation: number) => {
      if (n === out.x.length) {
        const capacity = grownCapacity(out.x.length, n + 1);
        out.x = grow(out.x, capacity);
        out.y = grow(out.y, capacity);
        out.nx = grow(out.nx, capacity);
        out.ny = grow(out.ny, capacity);
        out.separation = grow(out.separation, capacity);
      }
      out.x[n] = x;
      out.y[n] = y;
      out.nx[n] = nx;
      out.ny[n] = ny;
      out.separation[n++] = separation;
    };
    if (this.shapeRoute) {
      const c = this.shapeRoute.narrow.current;
      for (let listed = 0; listed < c.count; listed++) {
        const k = c.order[listed];
        for (let p = 0; p < c.pointCount[k]; p++) {
          const o = (2 * k + p) * POINT_STRIDE;
          put(c.points[o + ContactPoint.x], c.points[o + ContactPoint.y], c.normalX[k], c.normalY[k], c.points[o + ContactPoint.separation]);
        }
      }
    } else {
      const { x, y, radius } = this.bodies;
      const { lo, hi, count } = this.pipeline.contacts;
      for (let k = 0; k < count; k++) {
        const i = lo[k];
        const j = hi[k];
        const dx = x[j] - x[i];
        const dy = y[j] - y[i];
        const d = Math.sqrt(dx * dx + dy * dy);
        const nx = d > 0 ? dx / d : 1;
        const ny = d > 0 ? dy / d : 0;
        const gap = d - radius[i] - radius[j];
        const along = radius[i] + gap / 2;
        put(x[i] + nx * along, y[i] + ny * along, nx, ny, gap);
      }
    }
    out.count = n;
    return out;
  }

  /**
   * The contacts of body `handle` where it lies (see BodyContact): with other bodies, static
   * segments and the box's walls, each with its normal from this body and its points, as Box2D
   * v3's b2Body_GetContactData gives them. A body at rest on the ground has a contact there whose
   * normal points down (+y). Found as the narrow-phase finds them, at the bodies' current poses:
   * on the shape route each shape pair that may collide, within the soft step's speculative margin
   * (0 under the elastic pass); in a world of circles, the circles, segments and walls it overlaps
   * or touches (within `contactSlop`, or the rounding of touching). A sleeping body has its contacts. Pass `out` to reuse an array and its contact
   * objects: it is filled, cut to the number of contacts and returned. Costs a box search and the
   * pair functions of the shapes near the body.
   */
  bodyContacts(handle: number, out?: BodyContact[]): BodyContact[] {
    const s = this.slot(handle);
    const into = contactsOutput(out);
    const from = this.contactSources;
    from.version = this.geometryVersion;
    const route = this.shapeRoute;
    if (route !== null) {
      from.shapes = this.shapes.store;
      from.world = route.world;
      from.joints = this.joints !== null ? this.joints.store : null;
      from.margin = this.shapeSolver() === 'elastic' ? 0 : route.settings.margin;
      from.slop = route.settings.slop;
    } else {
      from.shapes = null;
      from.world = null;
      from.joints = null;
    }
    from.box = this.bodies.box;
    from.contactSlop = this.pipeline.settings.solver.contactSlop;
    return this.contactIndex.read(s, from, into);
  }

  /**
   * Touch events of the last step, when the world was created with `contactEvents: true` (begin
   * and end) or a `hitEventThreshold` (hits), or holds a sensor (whose overlaps are reported here).
   * The object and its arrays are reused by every step.
   */
  contactEvents(): ContactEventsView {
    const events = this.pipeline.events;
    if (!events) throw new RangeError('contact events are off: create the World with contactEvents: true or a hitEventThreshold');
    return events;
  }

  /**
   * Handles of the bodies with a shape (or circle) containing the point, and of the static
   * segments that do, boundary included, ascending (a segment's handle is above every body's:
   * `hasBody` tells them apart). Pass `out` to reuse an array: it is emptied, filled and returned.
   */
  queryPoint(x: number, y: number, options: QueryOptions = NO_QUERY_OPTIONS, out?: number[]): number[] {
    const mask = queryMask(options);
    finiteNumber('x', x);
    finiteNumber('y', y);
    return this.queries.point(this.geometryVersion, x, y, mask, queryOutput(out));
  }

  /** Handles of the bodies with a shape (or circle) overlapping the box, and of the static segments that do, touching included, ascending; `out` as in queryPoint. */
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
   * The first body (by its shapes, or circle) or static segment that the segment from (x1, y1) to
   * (x2, y2) enters, or null. Shapes and segments containing (x1, y1) are ignored. Pass `out` to
   * reuse a hit object: it is filled and returned.
   */
  rayCast(x1: number, y1: number, x2: number, y2: number, options: QueryOptions = NO_QUERY_OPTIONS, out?: RayHit): RayHit | null {
    const mask = queryMask(options);
    rayArguments(x1, y1, x2, y2);
    return this.queries.rayFirst(this.geometryVersion, x1, y1, x2, y2, mask, rayHitOutput(out));
  }

  /**
   * Every body (by its shapes, or circle) and static segment the segment enters, nearest first. Pass `out` to reuse an array: the hit objects
   * it holds are overwritten in place, it is cut to the number of hits and returned.
   */
  rayCastAll(x1: number, y1: number, x2: number, y2: number, options: QueryOptions = NO_QUERY_OPTIONS, out?: RayHit[]): RayHit[] {
    const mask = queryMask(options);
    rayArguments(x1, y1, x2, y2);
    return this.queries.rayAll(this.geometryVersion, x1, y1, x2, y2, mask, rayHitsOutput(out));
  }

  /** Zero-copy views of the body columns for renderers (see BodyViews); take them again after adding bodies. */
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
    const rigid = b.rigid;
    v.c = rigid ? rigid.c : EMPTY;
    v.s = rigid ? rigid.s : EMPTY;
    v.angularVelocity = rigid ? rigid.angularVelocity : EMPTY;
    if (this.shapes.engaged) {
      const store = this.shapes.store;
      const sv = this.shapeViewsRecord;
      sv.slotCount = store.slotCount;
      sv.live = store.live;
      sv.body = store.body;
      sv.kind = store.kind;
      sv.vertexCount = store.vertexCount;
      sv.radius = store.radius;
      sv.sensor = store.sensor;
      sv.vertices = store.record;
      v.shapes = sv;
    } else {
      v.shapes = null;
    }
    return v;
  }

  /**
   * The world as coloured line segments any renderer can draw (see DebugRenderBuffers): shape
   * outlines coloured by body state, static segments and the box, joints, and contact normals,
   * each part on unless `options` turns it off. The buffers are reused by every call.
   */
  debugRender(options: DebugRenderOptions = {}): DebugRenderBuffers {
    const o = plainObject('debugRender options', options);
    knownKeys('debugRender options', o, ['shapes', 'statics', 'joints', 'contacts', 'contactLength']);
    const on = (field: string) => (o[field] === undefined ? true : flag(field, o[field]));
    const shapes = on('shapes');
    const statics = on('statics');
    const joints = on('joints');
    const contacts = on('contacts');
    const contactLength = o.contactLength === undefined ? 0.2 * this.resolved.lengthUnit : nonNegativeNumber('contactLength', o.contactLength);
    const draw = this.debugDraw;
    draw.begin();
    if (shapes) draw.bodies(this.bodies, this.shapes.engaged ? this.shapes.store : null);
    if (statics) draw.statics(this.segments, this.bounds);
    if (joints) {
      const v = this.jointViews();
      for (let k = 0; k < v.count; k++) draw.line(v.anchorAX[k], v.anchorAY[k], v.anchorBX[k], v.anchorBY[k], DEBUG_COLORS.joint);
    }
    if (contacts) {
      const c = this.contactPoints();
      for (let k = 0; k < c.count; k++) draw.line(c.x[k], c.y[k], c.x[k] + contactLength * c.nx[k], c.y[k] + contactLength * c.ny[k], DEBUG_COLORS.contact);
    }
    return draw.out;
  }

  private readonly debugDraw = new DebugDraw();

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
    return (
      this.bodies.memoryBytes() +
      (this.bodies.rigid?.memoryBytes() ?? 0) +
      this.segments.memoryBytes() +
      this.pipeline.memoryBytes() +
      (this.shapes.engaged ? this.shapes.store.memoryBytes() : 0) +
      (this.shapeRoute?.memoryBytes() ?? 0)
    );
  }

  /** Capacities of internal buffers, for tests that check nothing grows after warm-up. */
  internalCapacities(): Record<string, number> {
    return {
      bodies: this.bodies.capacity,
      contacts: this.pipeline.contacts.lo.length,
      broadphaseBytes: this.pipeline.broadPhase.memoryBytes(),
      shapeRouteBytes: this.shapeRoute?.memoryBytes() ?? 0,
    };
  }


  /** What resolveJoint reads of the bodies. */
  private readonly jointWorld: JointWorld = {
    bodySlot: (field, handle) => {
      if (typeof handle !== 'number' || !Number.isFinite(handle)) throw new TypeError(`${field} must be a body handle, got ${describeValue(handle)}`);
      const s = this.bodies.slotOf(handle);
      if (s < 0) throw new RangeError(`${field} ${describeValue(handle)} ${this.bodies.describeMissing(handle)}`);
      return s;
    },
    localCenter: (slot, out) => {
      const rigid = this.bodies.rigid;
      out[0] = rigid ? rigid.localCenterX[slot] : 0;
      out[1] = rigid ? rigid.localCenterY[slot] : 0;
    },
    worldPoint: (slot, px, py, out) => {
      const b = this.bodies;
      const rigid = b.rigid;
      const c = rigid ? rigid.c[slot] : 1;
      const sn = rigid ? rigid.s[slot] : 0;
      const lx = px - (rigid ? rigid.localCenterX[slot] : 0);
      const ly = py - (rigid ? rigid.localCenterY[slot] : 0);
      out[0] = b.x[slot] + c * lx - sn * ly;
      out[1] = b.y[slot] + sn * lx + c * ly;
    },
    localPoint: (slot, wx, wy, out) => {
      const b = this.bodies;
      const rigid = b.rigid;
      const c = rigid ? rigid.c[slot] : 1;
      const sn = rigid ? rigid.s[slot] : 0;
      const dx = wx - b.x[slot];
      const dy = wy - b.y[slot];
      out[0] = c * dx + sn * dy + (rigid ? rigid.localCenterX[slot] : 0);
      out[1] = -sn * dx + c * dy + (rigid ? rigid.localCenterY[slot] : 0);
    },
    angle: (slot) => {
      const rigid = this.bodies.rigid;
      return rigid ? atan2(rigid.s[slot], rigid.c[slot]) : 0;
    },
    isDynamic: (slot) => this.bodies.type[slot] === TypeCode.dynamic,
    ringArea: (ring) => this.ringArea(ring),
    ringCrossing: (ring, out) => this.ringCrossing(ring, out),
    mass: (slot) => this.bodies.mass[slot],
    gravity: () => {
      const g = this.pipeline.settings.gravity;
      return Math.sqrt(g.x * g.x + g.y * g.y);
    },
  };

  private useJoints(): JointSolver {
    if (this.joints) return this.joints;
    const store = new JointStore();
    this.joints = new JointSolver(store, { hertz: this.resolved.jointHertz, dampingRatio: this.resolved.jointDampingRatio });
    this.joints.integrator = this.integratorChoice;
    this.shapeRoute!.joints = this.joints;
    this.shapeRoute!.narrow.joints = store;
    return this.joints;
  }

  private jointSlot(handle: number): number {
    finiteNumber('joint handle', handle);
    const store = this.joints?.store;
    const j = store ? store.slotOf(handle) : -1;
    if (j < 0) throw new RangeError(`joint handle ${describeValue(handle)} ${store ? store.describeMissing(handle) : 'is unknown to this world (it has no joints)'}`);
    return j;
  }

  /** Body `slot`'s joints go with it, each noted for the next step's joint events; their other bodies wake. */
  private destroyJointsOf(slot: number): void {
    const store = this.joints!.store;
    while (slot < store.firstEdge.length && store.firstEdge[slot] >= 0) {
      const j = store.firstEdge[slot] >> 1;
      const a = store.bodyA[j];
      const b = store.bodyB[j];
      this.pendingJointEvents.push({ joint: store.handleOf(j), reason: 'bodyDestroyed', bodyA: a >= 0 ? this.bodies.handleOf(a) : null, bodyB: this.bodies.handleOf(b) });
      if (a >= 0 && a !== slot) this.bodies.wake(a);
      if (b !== slot) this.bodies.wake(b);
      store.remove(j);
    }
    // Rings hold bodies beyond their first two, which have no edges.
    for (const j of store.ringsOf(slot)) {
      this.pendingJointEvents.push({ joint: store.handleOf(j), reason: 'bodyDestroyed', bodyA: this.bodies.handleOf(store.bodyA[j]), bodyB: this.bodies.handleOf(store.bodyB[j]) });
      for (const body of store.ring(j)) if (body !== slot) this.bodies.wake(body);
      store.remove(j);
    }
  }

  /** The step's joint events start with the joints destroyed with bodies since the last one. */
  private beginJointEvents(): void {
    const v = this.jointEventsRecord;
    v.count = 0;
    v.joint.length = 0;
    v.reason.length = 0;
    v.bodyA.length = 0;
    v.bodyB.length = 0;
    for (const e of this.pendingJointEvents) this.noteJointEvent(e.joint, e.reason, e.bodyA, e.bodyB);
    this.pendingJointEvents.length = 0;
  }

  private noteJointEvent(joint: number, reason: 'broken' | 'bodyDestroyed', bodyA: number | null, bodyB: number): void {
    const v = this.jointEventsRecord;
    v.joint.push(joint);
    v.reason.push(reason);
    v.bodyA.push(bodyA);
    v.bodyB.push(bodyB);
    v.count++;
  }

  /** Joints whose force or torque passed their threshold in this step break, in slot order. */
  private breakJoints(): void {
    const store = this.joints!.store;
    const r = store.record;
    for (let j = 0; j < store.slotCount; j++) {
      if (store.live[j] === 0) continue;
      const o = j * JOINT_STRIDE;
      if (r[o + J.active] === 0) continue;
      const fx = r[o + J.forceX];
      const fy = r[o + J.forceY];
      const force = r[o + J.breakForce];
      const torque = r[o + J.breakTorque];
      if (!(fx * fx + fy * fy > force * force || Math.abs(r[o + J.torque]) > torque)) continue;
      const a = store.bodyA[j];
      const b = store.bodyB[j];
      this.noteJointEvent(store.handleOf(j), 'broken', a >= 0 ? this.bodies.handleOf(a) : null, this.bodies.handleOf(b));
      if (a >= 0) this.bodies.wake(a);
      this.bodies.wake(b);
      store.remove(j);
    }
  }

  /** Lists every body's shapes and moves the world to the shape route (see BodyShapes.engage). */
  private engage(): void {
    if (this.shapeRoute) return;
    // Every circle becomes a shape; one too large for a shape would get an infinite inertia. The
    // caller has changed nothing yet, so refusing here leaves the world as it was.
    const b = this.bodies;
    for (let slot = 0; slot < b.slotCount; slot++) {
      if (b.type[slot] === TypeCode.free || b.radius[slot] <= MAX_SHAPE_REACH) continue;
      throw new RangeError(`body ${b.handleOf(slot)}, a circle of radius ${b.radius[slot]}, would become a shape reaching beyond ${MAX_SHAPE_REACH} (so that its rotational inertia stays finite): a world holding it cannot take shapes, friction, joints, rk4 or the soft solver; make it smaller or destroy it first`);
    }
    const settings = shapeRouteSettings(this.resolved, this.pipeline.settings.gravity);
    settings.integrator = this.integratorChoice;
    this.shapes.engage(settings.margin);
    // The shape route's integration takes its own limit (ShapeRouteSettings.soft).
    this.bodies.speedCap = MAX_MAGNITUDE;
    this.queries.shapes = this.shapes.store;
    this.shapeRoute = new ShapeRoute(this.bodies, this.shapes.store, this.segments, settings);
    this.staticVersion++;
    this.geometryVersion++;
  }

  /** Sensors report through the events, which a world with a sensor keeps whatever its options. */
  private useEvents(): void {
    if (!this.pipeline.events) this.pipeline.events = new ContactEvents();
  }

  /** A body's rotational inertia, before the rotation columns exist too (see circleInertia). */
  private inertiaOf(slot: number): number {
    return this.bodies.rigid ? this.bodies.rigid.inertia[slot] : this.circleInertia(slot);
  }

  /** A circle of the circle route's: a uniform disc's m r^2 / 2, which it gets when the rotation columns are made. */
  private circleInertia(slot: number): number {
    const b = this.bodies;
    return (b.mass[slot] * b.radius[slot] * b.radius[slot]) / 2;
  }

  private inverseInertia(slot: number): number {
    if (this.bodies.rigid) return this.bodies.rigid.invInertia[slot];
    const inertia = this.inertiaOf(slot);
    return inertia > 0 ? 1 / inertia : 0;
  }

  /** The rotational columns, with each circle made so far given a disc's inertia. */
  private useRigid() {
    if (this.bodies.rigid) return this.bodies.rigid;
    const b = this.bodies;
    const rigid = b.useRigid();
    for (let s = 0; s < b.slotCount; s++) if (b.type[s] !== TypeCode.free) b.setMass(s, b.mass[s], this.circleInertia(s));
    return rigid;
  }

  private materialDefaults(): { friction: number; restitution: number } {
    return { friction: this.defaultFriction, restitution: this.defaultRestitution };
  }

  /** createBox, createPolygon, createCapsule: a body and its one shape, everything checked first. */
  private createWithShape(kind: string, field: string, options: unknown, geometryKeys: string[]): number {
    const o = plainObject(field, options);
    knownKeys(field, o, [...BODY_KEYS, ...MATERIAL_KEYS, ...geometryKeys]);
    const body = resolveBody(o);
    const geometry = resolveGeometry(kind, o, new Geometry());
    const shape = resolveMaterial(o, this.materialDefaults(), geometry);
    applyMassOption(o, shape);
    // A mass given is checked as given: the density it becomes, times the area again, can round
    // a mass at a bound (1e100 on a 3 x 3 box) one unit past it.
    const mass = o.mass !== undefined ? (o.mass as number) : shape.density * areaProperties(geometry, massScratch).area;
    this.checkMass(-1, mass, body.type !== TypeCode.dynamic);
    this.checkGravityScale(body.gravityScale);
    this.assertShapeInBox(geometry, body.x, body.y, body.c, body.s, 0, 0);
    if (!this.bodies.hasRoom()) throw new RangeError(`a world holds at most ${SLOT_SPACE} bodies at once (handles encode the slot in 24 bits)`);
    if (!this.shapes.store.hasRoom()) throw new RangeError(`a world holds at most ${SLOT_SPACE} shapes at once`);
    this.engage();
    return this.createShaped(body, shape);
  }

  /** Adds a body (origin at body.x, body.y) with an optional first shape; returns its handle. */
  private createShaped(body: ResolvedBody, shape: NewShape | null): number {
    const b = this.bodies;
    const slot = b.add({
      x: body.x,
      y: body.y,
      vx: body.vx,
      vy: body.vy,
      radius: this.shapes.margin,
      mass: 1,
      restitution: this.defaultRestitution,
      type: body.type,
      category: 0,
      mask: 0,
      gravityScale: body.gravityScale,
      linearDamping: body.linearDamping,
    });
    const rigid = b.rigid!;
    rigid.c[slot] = body.c;
    rigid.s[slot] = body.s;
    rigid.angularVelocity[slot] = body.angularVelocity;
    rigid.flags[slot] = body.flags;
    b.setAngularDamping(slot, body.angularDamping);
    if (shape) this.shapes.add(slot, shape);
    else this.shapes.update(slot);
    if (shape?.sensor) this.useEvents();
    if (body.flags & BodyFlag.bullet) this.shapeRoute!.bullets++;
    this.shapesChanged(slot);
    if (shape) this.disturbances.note(b, slot);
    return b.handleOf(slot);
  }

  /** After a body's shapes changed: static tree, query grid and sleepers near it. */
  private shapesChanged(slot: number): void {
    if (this.bodies.type[slot] === TypeCode.static) this.staticVersion++;
    this.geometryVersion++;
    this.bodies.wake(slot);
    this.shapeRoute?.narrow.forget(slot);
  }

  /**
   * Notes shape s's bounding circle for the next step's wakeTouching: a static or kinematic body
   * never moves into a sleeper, so nothing else would wake one that a new shape now overlaps or
   * supports. The shape's own circle, not its body's: a post added to a long ground wakes the
   * pile it touches, not every pile on the ground.
   */
  private noteShape(s: number): void {
    const b = this.bodies;
    if (b.sleepingCount === 0) return;
    const store = this.shapes.store;
    const slot = store.body[s];
    const rigid = b.rigid!;
    // Its centroid and extent about it, as the narrow-phase's compound test reads them.
    const cx = store.centroidX[s];
    const cy = store.centroidY[s];
    const c = rigid.c[slot];
    const sn = rigid.s[slot];
    this.disturbances.noteCircle(b, b.x[slot] + c * cx - sn * cy, b.y[slot] + sn * cx + c * cy, store.extent[s]);
  }

  /**
   * A RangeError where a gravity scale times gravity (the world's, or the one being set) is an
   * acceleration beyond MAX_MAGNITUDE: each is bounded, but 1e100 times 1e100 would reach 1e200,
   * past what a step's products stay finite for, as a force must leave the acceleration within it.
   */
  private checkGravityScale(scale: number, gx = this.pipeline.settings.gravity.x, gy = this.pipeline.settings.gravity.y, field = 'gravityScale'): void {
    const g = Math.max(Math.abs(gx), Math.abs(gy));
    if (!(Math.abs(scale) * g > MAX_MAGNITUDE)) return;
    const which = field === 'gravity' ? `gravity (${gx}, ${gy}) times a body's gravityScale ${scale}` : `gravityScale ${scale} times gravity (${gx}, ${gy})`;
    throw new RangeError(`${which} is an acceleration beyond ${MAX_MAGNITUDE} (so that no step can overflow)`);
  }

  /**
   * Refuses a change of a dynamic body's shapes (`shape` added, shape slot `without` removed)
   * under which the force or torque already applied to it for the next step would give an
   * acceleration beyond MAX_MAGNITUDE: applyForce and applyTorque check the body as it is, and a
   * smaller mass or inertia afterwards would otherwise carry the load past it, to infinity.
   */
  private checkLoadsAfter(handle: number, slot: number, shape: NewShape | null, without: number, change: string): void {
    const b = this.bodies;
    if (b.type[slot] !== TypeCode.dynamic || !b.forcesPending) return;
    const after = this.shapes.massPropertiesAfter(slot, shape, without, loads);
    const mass = after[0];
    const inertia = after[1];
    const fx = b.forceX[slot];
    const fy = b.forceY[slot];
    if (!(Math.abs(fx / mass) <= MAX_MAGNITUDE && Math.abs(fy / mass) <= MAX_MAGNITUDE)) {
      throw new RangeError(`${change} would give body ${handle} mass ${mass}, under which the force (${fx}, ${fy}) applied to it for the next step is an acceleration beyond ${MAX_MAGNITUDE}; step first, or change the shapes before applying the force`);
    }
    const rigid = b.rigid;
    if (rigid && (rigid.flags[slot] & BodyFlag.fixedRotation) === 0) this.checkTorque(handle, slot, inertia, change);
  }

  /** checkLoadsAfter's test of the pending torque against the inertia `inertia` (0: the body does not turn). */
  private checkTorque(handle: number, slot: number, inertia: number, change: string): void {
    const torque = this.bodies.rigid?.torque[slot] ?? 0;
    if (torque === 0 || !(inertia > 0)) return;
    if (!(Math.abs(torque / inertia) <= MAX_MAGNITUDE)) {
      throw new RangeError(`${change} would give body ${handle} inertia ${inertia}, under which the torque ${torque} applied to it for the next step is an angular acceleration beyond ${MAX_MAGNITUDE}; step first, or make the change before applying the torque`);
    }
  }

  /** A dynamic body's mass must be > 0; any body's within [1 / MAX_MAGNITUDE, MAX_MAGNITUDE] where it has one, so that no step overflows. */
  private checkMass(handle: number, mass: number, massless = false): void {
    if (!(mass > 0)) {
      if (!massless) this.requireMass(handle, mass);
      return;
    }
    if (!(mass <= MAX_MAGNITUDE && mass >= 1 / MAX_MAGNITUDE)) {
      const which = handle >= 0 ? `body ${handle}` : 'the body';
      throw new RangeError(`${which}'s shapes would give it mass ${mass}, outside [${1 / MAX_MAGNITUDE}, ${MAX_MAGNITUDE}] (so that no step can overflow); change their size or density`);
    }
  }

  private requireMass(handle: number, mass: number): never {
    const which = handle >= 0 ? `body ${handle}` : 'a dynamic body';
    throw new RangeError(`${which} needs mass: its shapes would give it mass ${mass}; give a shape a density > 0, or make the body static or kinematic`);
  }

  /** Moves body `slot` so that its origin is at (x, y) turned by (c, s), checking it stays in the box. */
  private placeBody(slot: number, x: number, y: number, c: number, s: number): void {
    const b = this.bodies;
    const rigid = b.rigid;
    const lx = rigid ? rigid.localCenterX[slot] : 0;
    const ly = rigid ? rigid.localCenterY[slot] : 0;
    const cx = x + (c * lx - s * ly);
    const cy = y + (s * lx + c * ly);
    if (this.shapes.engaged) {
      if (rigid!.firstShape[slot] < 0) this.assertPointInBox(cx, cy);
      else if (this.bounds) {
        bodyBounds(this.shapes.store, rigid!.firstShape[slot], poseOf(pose4, cx, cy, c, s), box4);
        this.assertBoundsInBox(box4);
      }
    } else {
      this.assertInBox(cx, cy, b.radius[slot]);
    }
    if (!Number.isFinite(cx) || !Number.isFinite(cy)) throw new RangeError(`position (${x}, ${y}) puts the body's centre of mass at (${cx}, ${cy}), beyond the largest double`);
    this.disturbances.note(b, slot);
    b.x[slot] = cx;
    b.y[slot] = cy;
    if (rigid) {
      rigid.c[slot] = c;
      rigid.s[slot] = s;
    } else if (c !== 1 || s !== 0) {
      const r = this.useRigid();
      r.c[slot] = c;
      r.s[slot] = s;
    }
    this.disturbances.note(b, slot);
    b.wake(slot);
    if (b.type[slot] === TypeCode.static) this.staticVersion++;
    this.geometryVersion++;
  }

  /** The slot of a dynamic body taking `what`: the value in `xField` (and `yField`, if any), checked finite by name. */
  private dynamicSlot(handle: number, what: string, xField: string, ax: number, yField: string | null, ay: number): number {
    const s = this.slot(handle);
    finiteNumber(xField, ax);
    if (yField !== null) finiteNumber(yField, ay);
    if (this.bodies.type[s] !== TypeCode.dynamic) {
      throw new RangeError(`body ${handle} is ${typeName(this.bodies.type[s])}: only dynamic bodies take ${what}, got ${yField === null ? ax : `(${ax}, ${ay})`}`);
    }
    return s;
  }

  private segmentSlot(handle: number): number {
    finiteNumber('segment handle', handle);
    const s = this.segments.slotOf(handle);
    if (s < 0) throw new RangeError(`segment handle ${describeValue(handle)} ${this.segments.describeMissing(handle)}`);
    return s;
  }

  private shapeSlot(handle: number): number {
    finiteNumber('shape handle', handle);
    const s = this.shapes.store.slotOf(handle);
    if (s < 0) throw new RangeError(`shape handle ${describeValue(handle)} ${this.shapes.store.describeMissing(handle)}`);
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

  /**
   * The copies of the options a world keeps, which only they fix (see checkRestoredState): the
   * resolved options themselves, what was made from them, and the stages' settings.
   */
  private settingsTree(): Record<string, unknown> {
    const route = this.shapeRoute;
    return {
      resolved: this.resolved,
      bounds: this.bounds,
      box: this.bodies.box,
      defaults: { restitution: this.defaultRestitution, friction: this.defaultFriction },
      step: this.pipeline.settings,
      shapes: route?.settings ?? null,
      walls: route ? { box: route.world.box, thickness: route.world.wallThickness } : null,
      joints: this.joints?.settings ?? null,
    };
  }

  /**
   * The snapshot's hash catches damage, not a payload rewritten with a consistent hash: before a
   * restored world is handed out, its gravity and every live body's state must be ones that steps
   * could reach, so that no NaN or infinity enters a step through a snapshot. Its settings must be
   * what its options give (`settings`, read before the state was written), but for those a setter
   * changes: gravity, within bounds, and the integrator, one of the names; and the shape route's
   * solver, which each step derives again.
   */
  private checkRestoredState(settings: unknown): void {
    const { x: gx, y: gy } = this.pipeline.settings.gravity;
    if (!(Math.abs(gx) <= MAX_MAGNITUDE && Math.abs(gy) <= MAX_MAGNITUDE)) {
      throw new RangeError(`snapshot is corrupt: gravity (${gx}, ${gy}) is beyond ${MAX_MAGNITUDE}, where no step can take it`);
    }
    const choice = this.integratorChoice;
    if (!(INTEGRATOR_NAMES as readonly unknown[]).includes(choice) || this.pipeline.integrator !== circleIntegrator(choice) || (this.shapeRoute !== null && this.shapeRoute.settings.integrator !== choice) || (this.joints !== null && this.joints.integrator !== choice)) {
      throw new RangeError(`snapshot is corrupt: its integrator (${describeValue(choice)}) is not one of ${INTEGRATOR_NAMES.join(', ')}, or its stages disagree on it`);
    }
    const differs = firstDifference(settings, copyOptions(this.settingsTree()), 'settings', SETTER_PATHS);
    if (differs !== null) throw new RangeError(`snapshot is corrupt: ${differs}, not what its options give`);
    const b = this.bodies;
    const rigid = b.rigid;
    const columns: [string, Float64Array][] = [['x', b.x], ['y', b.y], ['vx', b.vx], ['vy', b.vy], ['radius', b.radius], ['mass', b.mass], ['invMass', b.invMass], ['forceX', b.forceX], ['forceY', b.forceY]];
    if (rigid) columns.push(['cos', rigid.c], ['sin', rigid.s], ['angularVelocity', rigid.angularVelocity], ['inertia', rigid.inertia], ['invInertia', rigid.invInertia], ['torque', rigid.torque]);
    for (let slot = 0; slot < b.slotCount; slot++) {
      if (b.type[slot] === TypeCode.free) continue;
      for (const [name, column] of columns) {
        const v = column[slot];
        if (!Number.isFinite(v) || ((name === 'mass' || name === 'invMass' || name === 'radius' || name === 'inertia' || name === 'invInertia') && v < 0)) {
          throw new RangeError(`snapshot is corrupt: body ${b.handleOf(slot)} has ${name} ${v}, which no step reaches`);
        }
      }
      if (rigid && !(Math.abs(rigid.c[slot] * rigid.c[slot] + rigid.s[slot] * rigid.s[slot] - 1) <= 1e-6)) {
        throw new RangeError(`snapshot is corrupt: body ${b.handleOf(slot)}'s rotation (${rigid.c[slot]}, ${rigid.s[slot]}) is not a unit vector`);
      }
    }
  }

  /** A body without shapes: the box holds its origin (see ShapeRoute.containPoint). */
  private assertPointInBox(x: number, y: number): void {
    const box = this.bounds;
    if (box && !(x >= 0 && x <= box.width && y >= 0 && y <= box.height)) {
      throw new RangeError(`a body without shapes at (${x}, ${y}) is outside the box 0..${box.width} x 0..${box.height}`);
    }
  }

  /** A shape given in a body's frame (from its origin), on a body whose centre is at (px, py) turned by (c, s) with its centre at (lx, ly) in that frame. */
  private assertShapeInBox(g: Geometry, px: number, py: number, c: number, s: number, lx: number, ly: number): void {
    if (!this.bounds) return;
    // The origin lies at centre - rotate(local centre); a body not yet made has its centre at its origin.
    const ox = px - (c * lx - s * ly);
    const oy = py - (s * lx + c * ly);
    let minX = Infinity;
    let minY = Infinity;
    let maxX = -Infinity;
    let maxY = -Infinity;
    for (let i = 0; i < g.count; i++) {
      const wx = ox + c * g.x[i] - s * g.y[i];
      const wy = oy + s * g.x[i] + c * g.y[i];
      minX = Math.min(minX, wx);
      minY = Math.min(minY, wy);
      maxX = Math.max(maxX, wx);
      maxY = Math.max(maxY, wy);
    }
    box4[0] = minX - g.radius;
    box4[1] = minY - g.radius;
    box4[2] = maxX + g.radius;
    box4[3] = maxY + g.radius;
    this.assertBoundsInBox(box4);
  }

  private assertBoundsInBox(b: Float64Array): void {
    const box = this.bounds!;
    if (b[0] < 0 || b[1] < 0 || b[2] > box.width || b[3] > box.height) {
      throw new RangeError(`a shape spanning (${b[0]}, ${b[1]})..(${b[2]}, ${b[3]}) is outside the box 0..${box.width} x 0..${box.height}`);
    }
  }
}

// What reading calls fill (views, contact points, joint views, debug lines) is filled again by
// each call, and workerStarts counts this object's thread starts: neither is the world's state,
// and left out of snapshots, reading a world leaves its snapshot's bytes as they were.
transientFields(World, ['viewsRecord', 'shapeViewsRecord', 'contactPointsRecord', 'jointViewsRecord', 'debugDraw', 'workerStarts', 'contactIndex', 'contactSources']);

/** Whether `value` is an object of callbacks alone: at least one, and nothing else. */
function isCallbacks(value: object): boolean {
  const items = Object.values(value);
  return items.length > 0 && items.every((item) => typeof item === 'function');
}
