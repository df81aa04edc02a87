import type { BodyType } from './store/body-types.js';
import { BODY_TYPES, TypeCode } from './store/body-types.js';
import type { BroadPhaseName } from './broadphase/registry.js';
import { BROADPHASE_NAMES } from './broadphase/registry.js';
import type { IntegratorName } from './integrate/integrator.js';
import { INTEGRATOR_NAMES } from './integrate/integrator.js';
import type { NewBody } from './store/body-store.js';
import type { NewSegment } from './store/segment-store.js';
import type { StepSettings } from './step/pipeline.js';
import type { ShapeRouteSettings } from './step/shape-route.js';
import {
  MAX_MAGNITUDE,
  MAX_RESTITUTION,
  boundedNonNegative,
  boundedNumber,
  boundedPositive,
  finiteNumber,
  knownKeys,
  nonNegativeNumber,
  oneOf,
  plainObject,
  positiveNumber,
  describeValue,
} from './util/validate.js';

/** A point or a direction in world units. */
export interface Vector {
  x: number;
  y: number;
}

/** What the World constructor takes; every option has a default, so `new World()` is a valid, empty, unbounded world. */
export interface WorldOptions {
  /** An axis-aligned box from (0, 0) to (width, height) that contains every body. Default: none. */
  bounds?: { width: number; height: number } | null | undefined;
  /** Acceleration applied to dynamic bodies, in length units per second squared. Default (0, 0). */
  gravity?: Vector | undefined;
  /** Restitution of the box walls and default restitution of new bodies. Default 1 (elastic). */
  restitution?: number | undefined;
  /**
   * Friction of the box walls and default friction of new shapes, as `restitution` is. Default 0,
   * the report's frictionless circles; Box2D's default is 0.6. A pair's friction is the geometric
   * mean of its two. Above 0 the world takes the shape route (docs/engine.md, "The shape route").
   */
  friction?: number | undefined;
  /**
   * The contact solver of a world with shapes: 'soft', Box2D v3's soft step with sub-steps, which
   * holds stacks and piles; 'elastic', the report's single pass of exact impulses, which keeps the
   * kinetic energy of frictionless elastic collisions but cannot hold a stack; or 'auto' (the
   * default): the report's circle engine while the world holds only frictionless circles; once it
   * has any other shape, friction or a body made with createBody, the elastic pass while it is an
   * elastic gas (no gravity, no joints, nothing that takes contacts with friction, rolling
   * resistance or restitution below 1, its own friction 0 and restitution at least 1) and the soft
   * step otherwise, decided at every step.
   */
  solver?: 'auto' | 'elastic' | 'soft' | undefined;
  /** Sub-steps of the soft step. Default 4, as Box2D v3. An integer in [1, 64]. */
  substeps?: number | undefined;
  /**
   * Length units per meter, as Box2D's b2SetLengthUnitsPerMeter and Rapier's length_unit: the
   * soft step's tolerances (linear slop 0.005 m, speculative distance 0.02 m, push-out speed
   * 3 m/s, restitution threshold 1 m/s, sleep speed 0.05 m/s, top speed 400 m/s, at most 1e100)
   * are scaled by it. Within [1e-100, 1e100]; default 1 (meters). The lab's pixel scenes use 50.
   */
  lengthUnit?: number | undefined;
  /** Stiffness of the soft step's contacts, as a frequency in hertz. Default 30 (Box2D). */
  contactHertz?: number | undefined;
  /** Damping ratio of the soft step's contacts. Default 10 (Box2D). */
  contactDampingRatio?: number | undefined;
  /**
   * How hard a rigid joint pulls back to its constraint in the soft step, as a frequency in hertz
   * (at most twice the contacts'), and its damping ratio. Defaults 60 and 2 (Box2D v3's jointHertz
   * and jointDampingRatio).
   */
  jointHertz?: number | undefined;
  jointDampingRatio?: number | undefined;
  /** The fastest a dynamic body moves, length units per second: every step caps the velocity it moves a body with, and the speeds it leaves, at it (the soft step kinematic bodies too, as Box2D). Default: with shapes 400 x lengthUnit (Box2D's maximumLinearSpeed); the circle engine 1e100, which only keeps numbers finite. At most 1e100. */
  maxLinearSpeed?: number | undefined;
  /**
   * Collisions approaching slower than this are inelastic, as Box2D's restitution threshold:
   * lets bodies come to rest (and sleep) under gravity. Default 0 on the circle route and in the
   * elastic pass, so elastic scenes stay exact; 1 x lengthUnit in the soft step, as Box2D.
   */
  restitutionThreshold?: number | undefined;
  /**
   * Fraction of each contact's overlap (beyond `contactSlop`) that separation removes in a step.
   * Default 1: the report's mass-weighted separation, which removes it all at once. In piles under
   * gravity that pushes bodies through each other and the pile boils; 0.2, Box2D's Baumgarte factor,
   * with a small `contactSlop` lets it rest (docs/engine.md, "Piles"). In (0, 1].
   */
  positionCorrection?: number | undefined;
  /**
   * Overlap, in length units, that separation leaves in place, so that resting contacts persist
   * from step to step and their impulses carry the load. Default 0. About 1 % of a radius suits piles.
   */
  contactSlop?: number | undefined;
  /**
   * Passes of the contact solve. Default 1: the report's single pass of impulses and separation.
   * More switch to sequential impulses with warm starting and the box walls as contacts (Box2D
   * v2's solver), which hold piles up; see docs/engine.md, "Piles". An integer in [1, 64].
   */
  solverIterations?: number | undefined;
  /** Default 'auto'. */
  broadphase?: BroadPhaseName | undefined;
  /**
   * Default 'semi-implicit-euler'; 'explicit-euler' is the report's exact method; 'rk4' (classical
   * Runge-Kutta) integrates force-driven springs and takes the shape route (docs/engine.md, Integrators).
   */
  integrator?: IntegratorName | undefined;
  /**
   * Let dynamic bodies that stay slower than `sleepSpeed` for `sleepTime` seconds fall asleep.
   * Default false: the report's scenes are all motion, and sleeping changes results.
   */
  sleeping?: boolean | undefined;
  /**
   * Speed below which a body counts as still, in length units per second. Default 1 on the circle
   * route, where one pass of impulses leaves resting bodies about |g| dt fast (keep it above that);
   * 0.05 x lengthUnit in the soft step, as Box2D. A turning body counts its rim's speed too.
   */
  sleepSpeed?: number | undefined;
  /** Seconds a body must stay still before it sleeps. Default 0.5. */
  sleepTime?: number | undefined;
  /**
   * Sweep dynamic bodies that move more than their radius in a step against static circles and
   * segments, so that none tunnels through them. Default true; the lab turns it off to match the
   * report's discrete Unity settings.
   */
  continuous?: boolean | undefined;
  /** Record begin and end touch events each step (see `world.contactEvents()`). Default false. */
  contactEvents?: boolean | undefined;
  /**
   * Record a hit event for each collision of two bodies, of a body and a segment, or of a body and
   * a box wall, whose approach speed is at least this (swept impacts included). Default: none.
   */
  hitEventThreshold?: number | undefined;
}

/** What createCircle takes: the report's circle body, with optional spin, friction and layers. */
export interface CircleOptions {
  x: number;
  y: number;
  vx?: number | undefined;
  vy?: number | undefined;
  radius: number;
  /** Default 'dynamic'. */
  type?: BodyType | undefined;
  /** Default: the world's `restitution`. */
  restitution?: number | undefined;
  /** Default density * pi * radius^2. Give `mass` or `density`, not both. */
  mass?: number | undefined;
  /** Mass per unit area when `mass` is not given. Default 1. */
  density?: number | undefined;
  /** Collision layers this body belongs to, a 32-bit set. Default 1. */
  category?: number | undefined;
  /** Layers this body collides with, a 32-bit set. Default 0xffffffff (all). */
  mask?: number | undefined;
  /** Multiplies the world's gravity for this body. Default 1. */
  gravityScale?: number | undefined;
  /** Velocity decays as v / (1 + h * linearDamping) over each solver step h, as in Box2D v3: the step's dt on the circle route, each of its sub-steps (dt / substeps) on the shape route. Default 0. */
  linearDamping?: number | undefined;
  /** Coulomb friction. Default: the world's `friction`. Above 0 the world takes the shape route. */
  friction?: number | undefined;
  /** Default 0. See MaterialOptions.rollingResistance. */
  rollingResistance?: number | undefined;
  /** Reports overlaps and never collides. Default false. */
  sensor?: boolean | undefined;
  /** Radians, in the sense documented in docs/engine.md. Default 0. */
  angle?: number | undefined;
  /** Radians per second. Default 0. */
  angularVelocity?: number | undefined;
  /** Angular velocity decays likewise (see linearDamping). Default 0. */
  angularDamping?: number | undefined;
  /** Default false. */
  fixedRotation?: boolean | undefined;
  /** Default false. See BodyOptions.bullet. */
  bullet?: boolean | undefined;
}

export interface ResolvedWorldOptions {
  bounds: { width: number; height: number } | null;
  gravity: Vector;
  restitution: number;
  friction: number;
  solver: 'auto' | 'elastic' | 'soft';
  substeps: number;
  lengthUnit: number;
  contactHertz: number;
  contactDampingRatio: number;
  jointHertz: number;
  jointDampingRatio: number;
  maxLinearSpeed: number | null;
  /** null: the route's default. */
  restitutionThresholdGiven: number | null;
  sleepSpeedGiven: number | null;
  restitutionThreshold: number;
  positionCorrection: number;
  contactSlop: number;
  solverIterations: number;
  broadphase: BroadPhaseName;
  integrator: IntegratorName;
  sleeping: boolean;
  sleepSpeed: number;
  sleepTime: number;
  contactEvents: boolean;
  hitEventThreshold: number;
  continuous: boolean;
}

/** What createSegment takes: a static wall from (x1, y1) to (x2, y2), which bodies collide with but never move. */
export interface SegmentOptions {
  x1: number;
  y1: number;
  x2: number;
  y2: number;
  /** Half the wall's width: the segment acts as a capsule of this radius. Default 0. */
  thickness?: number | undefined;
  /** Default: the world's `restitution`. */
  restitution?: number | undefined;
  /** Default: the world's `friction`. A segment with friction puts the world on the shape route (docs/engine.md). */
  friction?: number | undefined;
  category?: number | undefined;
  mask?: number | undefined;
}

/**
 * What createChain takes: static segments from each point to the next (and from the last back to
 * the first with `loop`), joined smoothly (docs/engine.md, "Chains"); the material and layers as
 * createSegment's, for every link.
 */
export interface ChainOptions {
  points: { x: number; y: number }[];
  loop?: boolean | undefined;
  thickness?: number | undefined;
  restitution?: number | undefined;
  friction?: number | undefined;
  category?: number | undefined;
  mask?: number | undefined;
}

const WORLD_KEYS = [
  'bounds',
  'gravity',
  'restitution',
  'friction',
  'solver',
  'substeps',
  'lengthUnit',
  'contactHertz',
  'contactDampingRatio',
  'jointHertz',
  'jointDampingRatio',
  'maxLinearSpeed',
  'restitutionThreshold',
  'positionCorrection',
  'contactSlop',
  'solverIterations',
  'broadphase',
  'integrator',
  'sleeping',
  'sleepSpeed',
  'sleepTime',
  'contactEvents',
  'hitEventThreshold',
  'continuous',
];
const CIRCLE_KEYS = [
  'x',
  'y',
  'vx',
  'vy',
  'radius',
  'type',
  'restitution',
  'mass',
  'density',
  'category',
  'mask',
  'gravityScale',
  'linearDamping',
  'friction',
  'rollingResistance',
  'sensor',
  'angle',
  'angularVelocity',
  'angularDamping',
  'fixedRotation',
  'bullet',
];

export function resolveWorldOptions(input: unknown): ResolvedWorldOptions {
  const options = plainObject('World options', input === undefined ? {} : input);
  knownKeys('World options', options, WORLD_KEYS);
  let bounds: ResolvedWorldOptions['bounds'] = null;
  if (options.bounds !== undefined && options.bounds !== null) {
    const b = plainObject('bounds', options.bounds);
    knownKeys('bounds', b, ['width', 'height']);
    bounds = { width: boundedPositive('bounds.width', b.width), height: boundedPositive('bounds.height', b.height) };
  }
  return {
    bounds,
    gravity: options.gravity === undefined ? { x: 0, y: 0 } : vector('gravity', options.gravity),
    restitution: options.restitution === undefined ? 1 : restitutionNumber('restitution', options.restitution),
    friction: options.friction === undefined ? 0 : boundedNonNegative('friction', options.friction),
    solver: options.solver === undefined ? 'auto' : oneOf('solver', options.solver, ['auto', 'elastic', 'soft'] as const),
    substeps: options.substeps === undefined ? 4 : iterationCount('substeps', options.substeps),
    lengthUnit: options.lengthUnit === undefined ? 1 : boundedPositive('lengthUnit', options.lengthUnit),
    contactHertz: options.contactHertz === undefined ? 30 : positiveNumber('contactHertz', options.contactHertz),
    contactDampingRatio: options.contactDampingRatio === undefined ? 10 : boundedNonNegative('contactDampingRatio', options.contactDampingRatio),
    jointHertz: options.jointHertz === undefined ? 60 : boundedPositive('jointHertz', options.jointHertz),
    jointDampingRatio: options.jointDampingRatio === undefined ? 2 : boundedNonNegative('jointDampingRatio', options.jointDampingRatio),
    maxLinearSpeed: options.maxLinearSpeed === undefined ? null : boundedPositive('maxLinearSpeed', options.maxLinearSpeed),
    restitutionThresholdGiven: options.restitutionThreshold === undefined ? null : nonNegativeNumber('restitutionThreshold', options.restitutionThreshold),
    sleepSpeedGiven: options.sleepSpeed === undefined ? null : nonNegativeNumber('sleepSpeed', options.sleepSpeed),
    restitutionThreshold:
      options.restitutionThreshold === undefined ? 0 : nonNegativeNumber('restitutionThreshold', options.restitutionThreshold),
    positionCorrection: options.positionCorrection === undefined ? 1 : fraction('positionCorrection', options.positionCorrection),
    contactSlop: options.contactSlop === undefined ? 0 : nonNegativeNumber('contactSlop', options.contactSlop),
    solverIterations: options.solverIterations === undefined ? 1 : iterationCount('solverIterations', options.solverIterations),
    broadphase: options.broadphase === undefined ? 'auto' : broadphaseName(options.broadphase),
    integrator: options.integrator === undefined ? 'semi-implicit-euler' : integratorName(options.integrator),
    sleeping: options.sleeping === undefined ? false : flag('sleeping', options.sleeping),
    sleepSpeed: options.sleepSpeed === undefined ? 1 : nonNegativeNumber('sleepSpeed', options.sleepSpeed),
    sleepTime: options.sleepTime === undefined ? 0.5 : nonNegativeNumber('sleepTime', options.sleepTime),
    contactEvents: options.contactEvents === undefined ? false : flag('contactEvents', options.contactEvents),
    hitEventThreshold:
      options.hitEventThreshold === undefined ? Infinity : nonNegativeNumber('hitEventThreshold', options.hitEventThreshold),
    continuous: options.continuous === undefined ? true : flag('continuous', options.continuous),
  };
}

export const MAX_SOLVER_ITERATIONS = 64;

function iterationCount(field: string, value: unknown): number {
  const n = finiteNumber(field, value);
  if (!Number.isInteger(n) || n < 1 || n > MAX_SOLVER_ITERATIONS) {
    throw new RangeError(`${field} must be an integer in [1, ${MAX_SOLVER_ITERATIONS}], got ${describeValue(value)}`);
  }
  return n;
}

/** A number in (0, 1]. */
function fraction(field: string, value: unknown): number {
  const n = finiteNumber(field, value);
  if (!(n > 0 && n <= 1)) throw new RangeError(`${field} must be in (0, 1], got ${describeValue(value)}`);
  return n;
}

export function flag(field: string, value: unknown): boolean {
  if (typeof value !== 'boolean') throw new TypeError(`${field} must be true or false, got ${describeValue(value)}`);
  return value;
}

/** A 32-bit layer set: an integer in [0, 2^32). */
/**
 * A 32-bit collision layer set, as an unsigned integer. A signed 32-bit one is taken as its bits,
 * since JavaScript's bitwise operators give those: `~PLAYER` (negative) means every layer but
 * PLAYER's, as `(~PLAYER) >>> 0` does.
 */
export function layerBits(field: string, value: unknown): number {
  const n = finiteNumber(field, value);
  if (!Number.isInteger(n) || n < -0x80000000 || n > 0xffffffff) {
    throw new RangeError(`${field} must be a 32-bit integer, in [0, 0xffffffff] or (as ~ and | give) in [-0x80000000, -1], got ${describeValue(value)}`);
  }
  return n >>> 0;
}

export function vector(field: string, input: unknown): Vector {
  const v = plainObject(field, input);
  knownKeys(field, v, ['x', 'y']);
  return { x: boundedNumber(`${field}.x`, v.x), y: boundedNumber(`${field}.y`, v.y) };
}

export function broadphaseName(value: unknown): BroadPhaseName {
  return oneOf('broadphase', value, BROADPHASE_NAMES);
}

export function integratorName(value: unknown): IntegratorName {
  return oneOf('integrator', value, INTEGRATOR_NAMES);
}

export function bodyType(value: unknown): BodyType {
  return oneOf('type', value, BODY_TYPES);
}

/** Validates circle options into a store record; the containment check is the world's. */
export function resolveCircle(input: unknown, defaultRestitution: number): NewBody {
  const o = plainObject('circle options', input);
  knownKeys('circle options', o, CIRCLE_KEYS);
  const radius = boundedPositive('radius', o.radius);
  let mass: number;
  if (o.mass !== undefined) {
    if (o.density !== undefined) throw new TypeError(`give mass or density, not both (mass ${String(o.mass)}, density ${String(o.density)})`);
    mass = boundedPositive('mass', o.mass);
  } else {
    const density = o.density === undefined ? 1 : positiveNumber('density', o.density);
    mass = density * Math.PI * radius * radius;
    if (!(mass <= MAX_MAGNITUDE && mass >= 1 / MAX_MAGNITUDE)) {
      throw new RangeError(`mass from density ${density} and radius ${radius} is ${mass}, outside [${1 / MAX_MAGNITUDE}, ${MAX_MAGNITUDE}] (so that no step can overflow)`);
    }
  }
  const type = TypeCode[o.type === undefined ? 'dynamic' : bodyType(o.type)];
  return {
    x: boundedNumber('x', o.x),
    y: boundedNumber('y', o.y),
    vx: o.vx === undefined ? 0 : type === TypeCode.static ? staticVelocity('vx', o.vx) : boundedNumber('vx', o.vx),
    vy: o.vy === undefined ? 0 : type === TypeCode.static ? staticVelocity('vy', o.vy) : boundedNumber('vy', o.vy),
    radius,
    mass,
    restitution: o.restitution === undefined ? defaultRestitution : restitutionNumber('restitution', o.restitution),
    type,
    category: o.category === undefined ? 1 : layerBits('category', o.category),
    mask: o.mask === undefined ? 0xffffffff : layerBits('mask', o.mask),
    gravityScale: o.gravityScale === undefined ? 1 : boundedNumber('gravityScale', o.gravityScale),
    linearDamping: o.linearDamping === undefined ? 0 : nonNegativeNumber('linearDamping', o.linearDamping),
  };
}

/** A static body takes no velocity: 0 is accepted, anything else refused by name. */
export function staticVelocity(field: string, value: unknown): number {
  const v = finiteNumber(field, value);
  if (v !== 0) throw new RangeError(`${field} of a static body must be 0, got ${v}; make it kinematic to move it`);
  return 0;
}

/** A restitution: >= 0, at most MAX_RESTITUTION (above 1 a bounce adds energy, and speeds are capped at the world's top speed). */
export function restitutionNumber(field: string, value: unknown): number {
  const n = nonNegativeNumber(field, value);
  if (!(n <= MAX_RESTITUTION)) throw new RangeError(`${field} must be at most ${MAX_RESTITUTION}, got ${describeValue(value)}`);
  return n;
}

export function resolveSegment(input: unknown, defaultRestitution: number, defaultFriction: number): NewSegment {
  const o = plainObject('segment options', input);
  knownKeys('segment options', o, ['x1', 'y1', 'x2', 'y2', 'thickness', 'restitution', 'friction', 'category', 'mask']);
  const segment = {
    ax: boundedNumber('x1', o.x1),
    ay: boundedNumber('y1', o.y1),
    bx: boundedNumber('x2', o.x2),
    by: boundedNumber('y2', o.y2),
    thickness: o.thickness === undefined ? 0 : boundedNonNegative('thickness', o.thickness),
    restitution: o.restitution === undefined ? defaultRestitution : restitutionNumber('restitution', o.restitution),
    friction: o.friction === undefined ? defaultFriction : boundedNonNegative('friction', o.friction),
    category: o.category === undefined ? 1 : layerBits('category', o.category),
    mask: o.mask === undefined ? 0xffffffff : layerBits('mask', o.mask),
  };
  if (segment.ax === segment.bx && segment.ay === segment.by && segment.thickness === 0) {
    throw new RangeError(`a segment from (${segment.ax}, ${segment.ay}) to itself needs a thickness > 0`);
  }
  return segment;
}

/**
 * A chain's links, each with its neighbours' far points (see NewSegment), from createChain's
 * options; every point and option checked, and a link of no length refused, before any is made.
 */
export function resolveChain(input: unknown, defaultRestitution: number, defaultFriction: number): NewSegment[] {
  const o = plainObject('chain options', input);
  knownKeys('chain options', o, ['points', 'loop', 'thickness', 'restitution', 'friction', 'category', 'mask']);
  if (!Array.isArray(o.points)) throw new TypeError(`points must be an array of { x, y }, got ${describeValue(o.points)}`);
  const loop = o.loop === undefined ? false : o.loop;
  if (typeof loop !== 'boolean') throw new TypeError(`loop must be a boolean, got ${describeValue(loop)}`);
  const least = loop ? 3 : 2;
  if (o.points.length < least) throw new RangeError(`a ${loop ? 'loop' : 'chain'} needs at least ${least} points, got ${o.points.length}`);
  const points = o.points.map((p: unknown, k: number) => {
    const q = plainObject(`points[${k}]`, p);
    knownKeys(`points[${k}]`, q, ['x', 'y']);
    return { x: boundedNumber(`points[${k}].x`, q.x), y: boundedNumber(`points[${k}].y`, q.y) };
  });
  const n = points.length;
  const links = loop ? n : n - 1;
  const material = { thickness: o.thickness, restitution: o.restitution, friction: o.friction, category: o.category, mask: o.mask };
  const out: NewSegment[] = [];
  for (let k = 0; k < links; k++) {
    const a = points[k];
    const b = points[(k + 1) % n];
    if (a.x === b.x && a.y === b.y) throw new RangeError(`points[${k}] and points[${(k + 1) % n}] are the same point (${a.x}, ${a.y}): a chain's links need a length`);
    const segment = resolveSegment({ x1: a.x, y1: a.y, x2: b.x, y2: b.y, ...material }, defaultRestitution, defaultFriction);
    segment.prev = loop || k > 0 ? points[(k + n - 1) % n] : null;
    segment.next = loop || k + 2 < n ? points[(k + 2) % n] : null;
    out.push(segment);
  }
  return out;
}

/** The step's settings from the world's validated options. */
export function stepSettings(resolved: ResolvedWorldOptions): StepSettings {
  return {
    gravity: resolved.gravity,
    box: resolved.bounds,
    wallRestitution: resolved.restitution,
    solver: {
      restitutionThreshold: resolved.restitutionThreshold,
      hitThreshold: resolved.hitEventThreshold,
      positionCorrection: resolved.positionCorrection,
      contactSlop: resolved.contactSlop,
      iterations: resolved.solverIterations,
      wakeSpeed: resolved.sleepSpeed,
    },
    sleeping: { enabled: resolved.sleeping, speed: resolved.sleepSpeed, time: resolved.sleepTime },
    continuous: resolved.continuous,
  };
}

/** The shape route's settings from the world's validated options (Box2D's defaults scaled by lengthUnit). */
export function shapeRouteSettings(resolved: ResolvedWorldOptions, gravity: Vector): ShapeRouteSettings {
  const unit = resolved.lengthUnit;
  const slop = 0.005 * unit;
  return {
    gravity,
    box: resolved.bounds,
    // With 'auto', World.step sets this before every step (see World.shapeSolver).
    solver: resolved.solver === 'elastic' ? 'elastic' : 'soft',
    integrator: resolved.integrator,
    soft: {
      substeps: resolved.substeps,
      contactHertz: resolved.contactHertz,
      contactDampingRatio: resolved.contactDampingRatio,
      contactPushSpeed: 3 * unit,
      // A thousandth of the slop: far below any gap a body is meant to close, far above the
      // hair (about 1e-10 m) that the speculative branch leaves.
      touchingGap: 1e-3 * slop,
      restitutionThreshold: resolved.restitutionThresholdGiven ?? 1 * unit,
      // Within the speeds a step keeps finite, however large the unit.
      maxLinearSpeed: resolved.maxLinearSpeed ?? Math.min(400 * unit, MAX_MAGNITUDE),
    },
    elastic: {
      restitutionThreshold: resolved.restitutionThresholdGiven ?? 0,
      positionCorrection: resolved.positionCorrection,
      contactSlop: resolved.contactSlop,
    },
    // The elastic pass works on overlaps alone, so its bodies need no speculative reach: a margin
    // would only widen every bounding circle and send more pairs to the narrow-phase. 'auto' keeps
    // the soft step's reach even while it takes the elastic pass, since it can move to the soft
    // step at any step and the bounding radii are set when shapes are made.
    margin: resolved.solver === 'elastic' ? 0 : 4 * slop,
    slop,
    wallFriction: resolved.friction,
    wallRestitution: resolved.restitution,
    sleeping: { enabled: resolved.sleeping, speed: resolved.sleepSpeedGiven ?? 0.05 * unit, time: resolved.sleepTime },
    continuous: resolved.continuous,
  };
}
