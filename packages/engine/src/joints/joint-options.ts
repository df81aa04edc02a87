import type { Vector } from '../options.js';
import { flag, vector } from '../options.js';
import { MAX_MAGNITUDE, MAX_SHAPE_REACH, boundedNonNegative, boundedNumber, describeValue, finiteNumber, knownKeys, plainObject } from '../util/validate.js';
import { nearestTurn, wrapAngle } from '../math/trig.js';
import { J, JOINT_KIND_NAMES, JOINT_STRIDE, JointKind, type JointKindName } from './joint-layout.js';

/** What every joint between two bodies takes. Anchors are in each body's own frame, from its origin. */
export interface JointBaseOptions {
  bodyA: number;
  bodyB: number;
  /** Where the joint holds body A, in A's frame. Default: A's centre of mass. */
  anchorA?: Vector | undefined;
  /** Where it holds body B, in B's frame. Default: B's centre of mass. */
  anchorB?: Vector | undefined;
  /** Whether the two bodies still collide with each other. Default false (Box2D's collideConnected). */
  collideConnected?: boolean | undefined;
  /** The joint breaks (is destroyed, with a joint event) once its force exceeds this. Default Infinity: never. */
  breakForce?: number | undefined;
  /** Likewise for its torque. Default Infinity. */
  breakTorque?: number | undefined;
}

/**
 * Keeps the anchors `length` apart: rigidly, unless a range is given (minLength < maxLength), in
 * which the anchors move freely (a rope), or `hertz` > 0, which makes it a spring towards
 * `length` (free of limits unless a range is also given). A range of one length
 * (minLength == maxLength) holds the anchors rigidly that far apart, spring or not.
 */
export interface DistanceJointOptions extends JointBaseOptions {
  kind: 'distance';
  /**
   * Default: the anchors' distance when the joint is made, or the range's length where
   * minLength == maxLength; must be > 0. With minLength == maxLength it must equal them (a
   * RangeError otherwise). Within a wider range only a spring reads it, and may rest outside the
   * range: the spring then presses the anchors against its nearer end.
   */
  length?: number | undefined;
  /** The range's ends; giving either turns the range on, the other then 0 or unbounded. */
  minLength?: number | undefined;
  maxLength?: number | undefined;
  /**
   * Spring frequency in hertz; 0 (the default) for none. An undamped spring oscillates at it up to
   * about an eighth of the sub-step rate (30 Hz at 60 Hz with 4 sub-steps); a stiffer one at
   * about 33 Hz there (see docs/engine.md, Joints).
   */
  hertz?: number | undefined;
  /** The spring's damping ratio (1 critical). Default 0. */
  dampingRatio?: number | undefined;
}

/** A pin: the anchors kept together, the bodies free to turn about them. */
export interface RevoluteJointOptions extends JointBaseOptions {
  kind: 'revolute';
  /** B's angle less A's at which the joint angle is 0, any finite angle (taken as the same turn within [-pi, pi]). Default: as the bodies stand when it is made. */
  referenceAngle?: number | undefined;
  /**
   * Angle limits (radians, within [-pi, pi]); giving either turns limits on, the other then
   * unbounded. With limits on, the joint angle is followed across ±pi (not wrapped), so a limit
   * at pi holds, and with one limit the joint may wind freely the other way.
   */
  lowerAngle?: number | undefined;
  upperAngle?: number | undefined;
  /** Target relative spin of B against A, radians per second, for a motor of maxMotorTorque. Default 0. */
  motorSpeed?: number | undefined;
  /** The motor's largest torque; the motor is on when this is given and > 0. */
  maxMotorTorque?: number | undefined;
  /**
   * An angular spring towards the reference angle; 0 (the default) for none. Undamped, the
   * bodies swing about the pin at this frequency, wherever the anchors lie on them.
   */
  hertz?: number | undefined;
  dampingRatio?: number | undefined;
}

/** A slider: B keeps A's angle and moves only along `axis`, fixed in A. */
export interface PrismaticJointOptions extends JointBaseOptions {
  kind: 'prismatic';
  /** The axis in A's frame (any length but 0). Default (1, 0). */
  axis?: Vector | undefined;
  referenceAngle?: number | undefined;
  /**
   * Limits on the translation, B's anchor's distance from A's along the axis (anchors made apart
   * across the axis are drawn onto it); either turns limits on.
   */
  lowerTranslation?: number | undefined;
  upperTranslation?: number | undefined;
  motorSpeed?: number | undefined;
  /** The motor's largest force; the motor is on when this is given and > 0. */
  maxMotorForce?: number | undefined;
  /** A spring along the axis towards translation 0; 0 (the default) for none. */
  hertz?: number | undefined;
  dampingRatio?: number | undefined;
}

/**
 * Glues B to A in its pose when made. Rigid by default; either frequency makes that part a
 * spring. An anchor left out is the other anchor's point in its own body (both left out: A's
 * centre), so that the bodies stay where they are.
 */
export interface WeldJointOptions extends JointBaseOptions {
  kind: 'weld';
  referenceAngle?: number | undefined;
  linearHertz?: number | undefined;
  angularHertz?: number | undefined;
  dampingRatio?: number | undefined;
}

/** A wheel on a suspension: B's anchor slides along `axis` in A on a spring, B turns freely or by its motor. */
export interface WheelJointOptions extends JointBaseOptions {
  kind: 'wheel';
  /** The suspension's axis in A's frame. Default (0, 1): up and down on the engine's y-down screens. */
  axis?: Vector | undefined;
  /** The suspension spring's frequency. Default 1 Hz (0: no spring, the wheel slides freely along the axis but for limits and the motor, as in Box2D). */
  hertz?: number | undefined;
  /** Default 0.7. */
  dampingRatio?: number | undefined;
  lowerTranslation?: number | undefined;
  upperTranslation?: number | undefined;
  motorSpeed?: number | undefined;
  maxMotorTorque?: number | undefined;
}

/** Pulls one body's anchor towards a point in the world (dragging with the pointer): Box2D's mouse joint. */
export interface TargetJointOptions {
  kind: 'target';
  body: number;
  /** The point, in world coordinates; move it with setJointTarget. */
  target: Vector;
  /** In the body's frame. Default: its centre of mass. */
  anchor?: Vector | undefined;
  /** Default 5. */
  hertz?: number | undefined;
  /** Default 0.7. */
  dampingRatio?: number | undefined;
  /** The largest pull. Default 1000 times the body's mass times the world's gravity, or times 1 where the gravity is weaker (none included). */
  maxForce?: number | undefined;
  breakForce?: number | undefined;
  breakTorque?: number | undefined;
}

/**
 * A force-driven spring between the two bodies' centres of mass: Hooke's law with damping,
 * F = stiffness (length - rest) + damping (speed apart), integrated by the world's integrator
 * ('explicit-euler', 'semi-implicit-euler' or 'rk4'), where a distance joint's `hertz` is a soft
 * constraint of the solver. For particle systems and the report's integrator comparison.
 */
export interface SpringJointOptions {
  kind: 'spring';
  bodyA: number;
  bodyB: number;
  /** The rest length. Default: the centres' distance when the spring is made. */
  length?: number | undefined;
  /** Force per unit of stretch. */
  stiffness: number;
  /** Force per unit of speed apart. Default 0. */
  damping?: number | undefined;
  collideConnected?: boolean | undefined;
  breakForce?: number | undefined;
}

/**
 * Gas in a ring of bodies (a pressure blob, with springs or joints between neighbours to hold it
 * together): the ideal gas law at constant temperature, P = pressure x A0 / A, A the area of the
 * polygon through the bodies' centres (A0 when made), P pushing each edge outwards with P times
 * its length. The bodies collide as before; the joint's bodyA and bodyB are the ring's first two.
 */
export interface PressureJointOptions {
  kind: 'pressure';
  /** At least 3 distinct bodies, in order around the ring (either way round). */
  bodies: number[];
  /** The gas pressure at the ring's area when made: force per length. */
  pressure: number;
}

/** What createJoint takes: one joint of any kind, told apart by `kind`. */
export type JointOptions = PressureJointOptions | SpringJointOptions | DistanceJointOptions | RevoluteJointOptions | PrismaticJointOptions | WeldJointOptions | WheelJointOptions | TargetJointOptions;

const BASE_KEYS = ['kind', 'bodyA', 'bodyB', 'anchorA', 'anchorB', 'collideConnected', 'breakForce', 'breakTorque'];
const SPRING_KEYS = ['hertz', 'dampingRatio'];
const KEYS: Record<JointKindName, string[]> = {
  distance: [...BASE_KEYS, 'length', 'minLength', 'maxLength', ...SPRING_KEYS],
  revolute: [...BASE_KEYS, 'referenceAngle', 'lowerAngle', 'upperAngle', 'motorSpeed', 'maxMotorTorque', ...SPRING_KEYS],
  prismatic: [...BASE_KEYS, 'axis', 'referenceAngle', 'lowerTranslation', 'upperTranslation', 'motorSpeed', 'maxMotorForce', ...SPRING_KEYS],
  weld: [...BASE_KEYS, 'referenceAngle', 'linearHertz', 'angularHertz', 'dampingRatio'],
  wheel: [...BASE_KEYS, 'axis', 'lowerTranslation', 'upperTranslation', 'motorSpeed', 'maxMotorTorque', ...SPRING_KEYS],
  target: ['kind', 'body', 'target', 'anchor', 'hertz', 'dampingRatio', 'maxForce', 'breakForce', 'breakTorque'],
  spring: ['kind', 'bodyA', 'bodyB', 'length', 'stiffness', 'damping', 'collideConnected', 'breakForce'],
  pressure: ['kind', 'bodies', 'pressure'],
};

/** What resolveJoint needs of the world: body slots from handles, and the bodies' poses. */
export interface JointWorld {
  /** The slot of a live body, or a RangeError naming `field`. */
  bodySlot(field: string, handle: unknown): number;
  /** Body `slot`'s centre of mass in its own frame. */
  localCenter(slot: number, out: Float64Array): void;
  /** A point given in body `slot`'s frame, in the world. */
  worldPoint(slot: number, x: number, y: number, out: Float64Array): void;
  /** A point given in the world, in body `slot`'s frame (worldPoint's inverse). */
  localPoint(slot: number, x: number, y: number, out: Float64Array): void;
  /** Body `slot`'s angle (its rotation's, by the engine's own atan2). */
  angle(slot: number): number;
  isDynamic(slot: number): boolean;
  /** The area of the polygon through a ring of bodies' centres of mass. */
  ringArea(ring: Int32Array): number;
  /** The first edge k (from ring[k] to the next) of that polygon that crosses a later edge, with that edge's index, into out; false where none does. */
  ringCrossing(ring: Int32Array, out: Int32Array): boolean;
  mass(slot: number): number;
  gravity(): number;
}

/** A validated joint: its kind, body slots (A -1 for the world), whether they collide, its record's definition, and a pressure joint's ring. */
export interface ResolvedJoint {
  kind: number;
  bodyA: number;
  bodyB: number;
  collide: boolean;
  definition: Float64Array;
  ring: Int32Array | null;
}

const point = new Float64Array(2);
const pointB = new Float64Array(2);

function optionalNumber(field: string, value: unknown, fallback: number): number {
  return value === undefined ? fallback : boundedNumber(field, value);
}

function optionalNonNegative(field: string, value: unknown, fallback: number): number {
  return value === undefined ? fallback : boundedNonNegative(field, value);
}

/** A threshold: a positive number, or Infinity (never). */
function threshold(field: string, value: unknown): number {
  if (value === undefined || value === Infinity) return Infinity;
  const n = finiteNumber(field, value);
  if (!(n > 0)) throw new RangeError(`${field} must be > 0 (or Infinity: never), got ${describeValue(value)}`);
  return n;
}

/**
 * A unit axis from a non-zero vector. One whose squared length underflows to 0 (or overflows) is
 * first divided by its larger component, so that any vector but (0, 0) has a direction.
 */
function unitAxis(field: string, value: unknown, fallback: Vector): Vector {
  let v = value === undefined ? fallback : vector(field, value);
  const largest = Math.max(Math.abs(v.x), Math.abs(v.y));
  if (!(largest > 0)) throw new RangeError(`${field} must be a non-zero vector, got ${describeValue(value)}`);
  let length = Math.sqrt(v.x * v.x + v.y * v.y);
  if (!(length > 0) || !Number.isFinite(length)) {
    v = { x: v.x / largest, y: v.y / largest };
    length = Math.sqrt(v.x * v.x + v.y * v.y);
  }
  return { x: v.x / length, y: v.y / length };
}

/** A range's ends, either given turning it on: [lower, upper], unbounded sides at ±MAX_MAGNITUDE. */
function range(lowerField: string, upperField: string, lower: unknown, upper: unknown, r: Float64Array): void {
  if (lower === undefined && upper === undefined) return;
  const lo = lower === undefined ? -MAX_MAGNITUDE : boundedNumber(lowerField, lower);
  const hi = upper === undefined ? MAX_MAGNITUDE : boundedNumber(upperField, upper);
  if (lo > hi) throw new RangeError(`${lowerField} (${lo}) must not exceed ${upperField} (${hi})`);
  r[J.lower] = lo;
  r[J.upper] = hi;
  r[J.enableLimit] = 1;
}

/** Validates joint options whole (a TypeError or RangeError naming the field, nothing changed) into a record definition. */
export function resolveJoint(options: unknown, world: JointWorld): ResolvedJoint {
  const o = plainObject('joint options', options);
  const kindName = o.kind;
  if (typeof kindName !== 'string' || !(JOINT_KIND_NAMES as string[]).includes(kindName)) {
    throw new RangeError(`kind must be one of ${JOINT_KIND_NAMES.map((k) => `'${k}'`).join(', ')}, got ${describeValue(kindName)}`);
  }
  const kind = kindName as JointKindName;
  knownKeys(`${kind} joint options`, o, KEYS[kind]);
  const r = new Float64Array(JOINT_STRIDE);
  r[J.breakForce] = threshold('breakForce', o.breakForce);
  r[J.breakTorque] = threshold('breakTorque', o.breakTorque);
  r[J.axisX] = 1;
  if (kind === 'pressure') {
    if (!Array.isArray(o.bodies)) throw new TypeError(`bodies must be an array of body handles, got ${describeValue(o.bodies)}`);
    if (o.bodies.length < 3) throw new RangeError(`bodies must hold at least 3 bodies for a ring, got ${o.bodies.length}`);
    const ring = new Int32Array(o.bodies.length);
    let dynamic = false;
    for (let k = 0; k < ring.length; k++) {
      ring[k] = world.bodySlot(`bodies[${k}]`, o.bodies[k]);
      if (ring.indexOf(ring[k]) < k) throw new RangeError(`bodies[${k}] (${describeValue(o.bodies[k])}) is already in the ring: its bodies must be distinct`);
      if (world.isDynamic(ring[k])) dynamic = true;
    }
    if (!dynamic) throw new RangeError('bodies are all static or kinematic: a pressure joint needs a dynamic body to act on');
    const area = world.ringArea(ring);
    if (!(area > 0)) throw new RangeError(`the ring's bodies enclose no area (${area}): a pressure joint needs a ring around a space`);
    const crossing = new Int32Array(2);
    if (world.ringCrossing(ring, crossing)) {
      const [i, j] = crossing;
      const next = (k: number) => (k + 1) % ring.length;
      throw new RangeError(`the ring crosses itself: its edge from bodies[${i}] to bodies[${next(i)}] crosses the one from bodies[${j}] to bodies[${next(j)}]; a pressure joint needs its bodies in order around the ring`);
    }
    if (o.pressure === undefined) throw new TypeError('pressure must be a finite number, got undefined (a pressure joint needs one)');
    r[J.stiffness] = boundedNonNegative('pressure', o.pressure);
    r[J.length] = area;
    return { kind: JointKind.pressure, bodyA: ring[0], bodyB: ring[1], collide: true, definition: r, ring };
  }
  if (kind === 'target') {
    const b = world.bodySlot('body', o.body);
    if (!world.isDynamic(b)) throw new RangeError(`body ${describeValue(o.body)} must be dynamic for a target joint to pull it`);
    const target = vector('target', o.target);
    world.localCenter(b, point);
    const anchor = o.anchor === undefined ? { x: point[0], y: point[1] } : vector('anchor', o.anchor);
    withinReach('anchor', anchor);
    r[J.anchorBX] = anchor.x;
    r[J.anchorBY] = anchor.y;
    r[J.targetX] = target.x;
    r[J.targetY] = target.y;
    r[J.hertz] = optionalNonNegative('hertz', o.hertz, 5);
    if (!(r[J.hertz] > 0)) throw new RangeError(`hertz must be > 0 for a target joint, got ${describeValue(o.hertz)}`);
    r[J.dampingRatio] = optionalNonNegative('dampingRatio', o.dampingRatio, 0.7);
    r[J.maxForce] = o.maxForce === undefined ? 1000 * world.mass(b) * Math.max(world.gravity(), 1) : boundedNonNegative('maxForce', o.maxForce);
    return { kind: JointKind.target, bodyA: -1, bodyB: b, collide: true, definition: r, ring: null };
  }
  const a = world.bodySlot('bodyA', o.bodyA);
  const b = world.bodySlot('bodyB', o.bodyB);
  if (a === b) throw new RangeError(`bodyA and bodyB are the same body (${describeValue(o.bodyA)}): a joint needs two`);
  if (!world.isDynamic(a) && !world.isDynamic(b)) throw new RangeError(`bodyA ${describeValue(o.bodyA)} and bodyB ${describeValue(o.bodyB)} are both static or kinematic: a joint needs a dynamic body to act on`);
  const collide = o.collideConnected === undefined ? false : flag('collideConnected', o.collideConnected);
  if (kind === 'spring') {
    // Between the centres: the anchors are the centres of mass, in each body's frame.
    world.localCenter(a, point);
    r[J.anchorAX] = point[0];
    r[J.anchorAY] = point[1];
    world.localCenter(b, point);
    r[J.anchorBX] = point[0];
    r[J.anchorBY] = point[1];
    world.worldPoint(a, r[J.anchorAX], r[J.anchorAY], point);
    world.worldPoint(b, r[J.anchorBX], r[J.anchorBY], pointB);
    const dx = pointB[0] - point[0];
    const dy = pointB[1] - point[1];
    r[J.length] = o.length === undefined ? Math.sqrt(dx * dx + dy * dy) : boundedNonNegative('length', o.length);
    if (o.stiffness === undefined) throw new TypeError('stiffness must be a finite number, got undefined (a spring needs one)');
    r[J.stiffness] = boundedNonNegative('stiffness', o.stiffness);
    r[J.damping] = optionalNonNegative('damping', o.damping, 0);
    return { kind: JointKind.spring, bodyA: a, bodyB: b, collide, definition: r, ring: null };
  }
  world.localCenter(a, point);
  let anchorA = o.anchorA === undefined ? { x: point[0], y: point[1] } : vector('anchorA', o.anchorA);
  world.localCenter(b, point);
  let anchorB = o.anchorB === undefined ? { x: point[0], y: point[1] } : vector('anchorB', o.anchorB);
  // A weld keeps the pose it is made in: an anchor left out is the other one's point, as it lies
  // in its own body then (both centres would pull the bodies onto each other).
  if (kind === 'weld' && o.anchorB === undefined) {
    world.worldPoint(a, anchorA.x, anchorA.y, pointB);
    world.localPoint(b, pointB[0], pointB[1], point);
    anchorB = { x: point[0], y: point[1] };
  } else if (kind === 'weld' && o.anchorA === undefined) {
    world.worldPoint(b, anchorB.x, anchorB.y, pointB);
    world.localPoint(a, pointB[0], pointB[1], point);
    anchorA = { x: point[0], y: point[1] };
  }
  withinReach(o.anchorA === undefined && kind === 'weld' ? "anchorA (anchorB's point in body A)" : 'anchorA', anchorA);
  withinReach(o.anchorB === undefined && kind === 'weld' ? "anchorB (anchorA's point in body B)" : 'anchorB', anchorB);
  r[J.anchorAX] = anchorA.x;
  r[J.anchorAY] = anchorA.y;
  r[J.anchorBX] = anchorB.x;
  r[J.anchorBY] = anchorB.y;
  const relative = world.angle(b) - world.angle(a);
  if (kind === 'distance') {
    world.worldPoint(a, anchorA.x, anchorA.y, point);
    world.worldPoint(b, anchorB.x, anchorB.y, pointB);
    const dx = pointB[0] - point[0];
    const dy = pointB[1] - point[1];
    const apart = Math.sqrt(dx * dx + dy * dy);
    const given = o.length === undefined ? undefined : boundedNumber('length', o.length);
    if (given !== undefined && !(given > 0)) throw new RangeError(`length must be > 0, got ${describeValue(o.length)}`);
    const hertz = optionalNonNegative('hertz', o.hertz, 0);
    const dampingRatio = optionalNonNegative('dampingRatio', o.dampingRatio, 0);
    const ranged = o.minLength !== undefined || o.maxLength !== undefined;
    const min = ranged ? optionalNonNegative('minLength', o.minLength, 0) : 0;
    const max = ranged && o.maxLength !== undefined ? boundedNonNegative('maxLength', o.maxLength) : Infinity;
    if (min > max) throw new RangeError(`minLength (${min}) must not exceed maxLength (${max})`);
    // A range of one length leaves the anchors no play, so that length is the joint's: holding a
    // different rest length instead would ignore the range, and no spring has room to act in it.
    const fixed = ranged && min === max;
    if (fixed && given !== undefined && given !== min) {
      throw new RangeError(`length (${given}) must equal minLength and maxLength (${min}) where they are equal: that range holds the anchors ${min} apart (leave length out, or widen the range)`);
    }
    const length = given ?? (fixed ? min : apart);
    if (!(length > 0)) {
      throw new RangeError(fixed ? 'minLength and maxLength are both 0: a distance joint cannot hold its anchors together (use a revolute joint)' : `the anchors coincide (distance ${apart}): give a length > 0, or use a revolute joint`);
    }
    const rigid = fixed || (!ranged && hertz === 0);
    r[J.length] = length;
    r[J.hertz] = hertz;
    r[J.dampingRatio] = dampingRatio;
    r[J.minLength] = rigid ? length : min;
    r[J.maxLength] = rigid ? length : max;
    r[J.enableLimit] = rigid ? 0 : 1;
    return { kind: JointKind.distance, bodyA: a, bodyB: b, collide, definition: r, ring: null };
  }
  r[J.referenceAngle] = o.referenceAngle === undefined ? relative : wrapAngle(finiteNumber('referenceAngle', o.referenceAngle));
  if (kind === 'weld') {
    r[J.linearHertz] = optionalNonNegative('linearHertz', o.linearHertz, 0);
    r[J.angularHertz] = optionalNonNegative('angularHertz', o.angularHertz, 0);
    r[J.dampingRatio] = optionalNonNegative('dampingRatio', o.dampingRatio, 0);
    return { kind: JointKind.weld, bodyA: a, bodyB: b, collide, definition: r, ring: null };
  }
  const wheel = kind === 'wheel';
  r[J.hertz] = optionalNonNegative('hertz', o.hertz, wheel ? 1 : 0);
  r[J.dampingRatio] = optionalNonNegative('dampingRatio', o.dampingRatio, wheel ? 0.7 : 0);
  r[J.motorSpeed] = optionalNumber('motorSpeed', o.motorSpeed, 0);
  const motorField = kind === 'prismatic' ? 'maxMotorForce' : 'maxMotorTorque';
  const maxMotor = optionalNonNegative(motorField, o[motorField], 0);
  r[J.maxMotor] = maxMotor;
  r[J.enableMotor] = maxMotor > 0 ? 1 : 0;
  if (kind === 'revolute') {
    if (o.lowerAngle !== undefined && !(Math.abs(finiteNumber('lowerAngle', o.lowerAngle)) <= Math.PI)) throw new RangeError(`lowerAngle must be within [-pi, pi], got ${describeValue(o.lowerAngle)}`);
    if (o.upperAngle !== undefined && !(Math.abs(finiteNumber('upperAngle', o.upperAngle)) <= Math.PI)) throw new RangeError(`upperAngle must be within [-pi, pi], got ${describeValue(o.upperAngle)}`);
    range('lowerAngle', 'upperAngle', o.lowerAngle, o.upperAngle, r);
    if (r[J.enableLimit] === 1) r[J.deltaAngle] = turnNearLimits(relative - r[J.referenceAngle], r[J.lower], r[J.upper]);
    return { kind: JointKind.revolute, bodyA: a, bodyB: b, collide, definition: r, ring: null };
  }
  const axis = unitAxis('axis', o.axis, wheel ? { x: 0, y: 1 } : { x: 1, y: 0 });
  r[J.axisX] = axis.x;
  r[J.axisY] = axis.y;
  range('lowerTranslation', 'upperTranslation', o.lowerTranslation, o.upperTranslation, r);
  return { kind: wheel ? JointKind.wheel : JointKind.prismatic, bodyA: a, bodyB: b, collide, definition: r, ring: null };
}

/**
 * The turn of a joint angle that lies nearest the limits [lower, upper], where the solver starts
 * following a limited revolute joint's angle (see J.deltaAngle): a joint made a little past a
 * limit near ±pi is pushed back the short way, not around the circle to its other limit.
 */
function turnNearLimits(angle: number, lower: number, upper: number): number {
  const within = nearestTurn(angle, 0);
  let best = within;
  let gap = Math.max(lower - within, within - upper, 0);
  for (const turn of [within - 2 * Math.PI, within + 2 * Math.PI]) {
    const g = Math.max(lower - turn, turn - upper, 0);
    if (g < gap) {
      best = turn;
      gap = g;
    }
  }
  return best;
}

/**
 * A RangeError naming the anchor where it lies farther than MAX_SHAPE_REACH from its body's
 * origin, the bound shapes have: a joint's lever arm times a body's inverse inertia then stays
 * far from the largest double in the solve's products.
 */
function withinReach(field: string, anchor: Vector): void {
  const reach = Math.sqrt(anchor.x * anchor.x + anchor.y * anchor.y);
  if (reach <= MAX_SHAPE_REACH) return;
  throw new RangeError(`${field} (${anchor.x}, ${anchor.y}) lies ${reach} from its body's origin, beyond ${MAX_SHAPE_REACH} (as a shape may reach, so that the joint's lever arms stay finite)`);
}
