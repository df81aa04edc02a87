import type { BodyStore } from '../store/body-store.js';
import { TypeCode } from '../store/body-types.js';
import { J, JOINT_KIND_NAMES, JOINT_STRIDE, JointKind, type JointKindName } from '../joints/joint-layout.js';
import { ForceSprings } from './force-springs.js';
import { GasPressure } from './gas-pressure.js';
import type { IntegratorName } from '../integrate/integrator.js';
import type { JointStore } from '../joints/joint-store.js';
import { BODY, DYNAMIC, FAR_ARM, holdState, makeSoft } from './solver-body.js';
import { holdIO, type JointKernel, type JointStepContext } from './joints/joint-kernel.js';
import { distanceJoint } from './joints/distance-joint.js';
import { isPointDistanceJoint, PointDistanceJoints } from './joints/point-distance-joints.js';
import type { SoftStepKernel } from './soft-step-kernel.js';
import { revoluteJoint } from './joints/revolute-joint.js';
import { pinnedIO, pinnedTurnAtStart, TURN_MASS, turnIO } from './joints/pinned-turn.js';
import { prismaticJoint } from './joints/prismatic-joint.js';
import { weldJoint } from './joints/weld-joint.js';
import { wheelJoint } from './joints/wheel-joint.js';
import { SPIN_DAMPING, SPIN_HERTZ, targetJoint } from './joints/target-joint.js';
import { atan2Into, TWO_PI } from '../math/trig.js';
import { grownCapacity } from '../util/grow.js';

// The record's fields as this module's own constants, which V8 folds into the code (see J).
const { active: ACTIVE, anchorAX: ANCHOR_AX, anchorAY: ANCHOR_AY, anchorBX: ANCHOR_BX, anchorBY: ANCHOR_BY, angularImpulse: ANGULAR_IMPULSE, axialImpulse: AXIAL_IMPULSE, axisX: AXIS_X, axisY: AXIS_Y, deltaAngle: DELTA_ANGLE, deltaCenterX: DELTA_CENTER_X, deltaCenterY: DELTA_CENTER_Y, enableLimit: ENABLE_LIMIT, enableMotor: ENABLE_MOTOR, hertz: HERTZ, forceX: FORCE_X, forceY: FORCE_Y, invInertiaA: INV_INERTIA_A, invInertiaB: INV_INERTIA_B, invMassA: INV_MASS_A, invMassB: INV_MASS_B, linearImpulseX: LINEAR_IMPULSE_X, linearImpulseY: LINEAR_IMPULSE_Y, lowerImpulse: LOWER_IMPULSE, motorImpulse: MOTOR_IMPULSE, rAX: R_AX, rAY: R_AY, rBX: R_BX, rBY: R_BY, referenceAngle: REFERENCE_ANGLE, springImpulseSum: SPRING_IMPULSE_SUM, stateA: STATE_A, stateB: STATE_B, targetX: TARGET_X, targetY: TARGET_Y, torque: TORQUE, upperImpulse: UPPER_IMPULSE, worldAxisX: WORLD_AXIS_X, worldAxisY: WORLD_AXIS_Y } = J;

const angleIO = new Float64Array(3);

/** Each constraint kind's solver: one line per kind. Springs and gas pressure are forces, applied apart (ForceSprings, GasPressure). */
const KERNEL_OF: Record<Exclude<JointKindName, 'spring' | 'pressure'>, JointKernel> = {
  distance: distanceJoint,
  revolute: revoluteJoint,
  prismatic: prismaticJoint,
  weld: weldJoint,
  wheel: wheelJoint,
  target: targetJoint,
};
/** The same, indexed by JointKind. */
const JOINT_KERNELS: readonly JointKernel[] = JOINT_KIND_NAMES.map((name) => (name === 'spring' || name === 'pressure' ? null! : KERNEL_OF[name]));

/** The accumulated impulses of a joint, and whether each is angular (a torque's) rather than linear. */
const IMPULSES: readonly number[] = [LINEAR_IMPULSE_X, LINEAR_IMPULSE_Y, ANGULAR_IMPULSE, SPRING_IMPULSE_SUM, MOTOR_IMPULSE, LOWER_IMPULSE, UPPER_IMPULSE, AXIAL_IMPULSE];
const ANGULAR: Record<number, readonly number[]> = {
  [JointKind.distance]: [],
  [JointKind.revolute]: [SPRING_IMPULSE_SUM, MOTOR_IMPULSE, LOWER_IMPULSE, UPPER_IMPULSE],
  [JointKind.prismatic]: [ANGULAR_IMPULSE],
  [JointKind.weld]: [ANGULAR_IMPULSE],
  [JointKind.wheel]: [MOTOR_IMPULSE],
  [JointKind.target]: [ANGULAR_IMPULSE],
};

/**
 * Keeps a joint's kept impulses within what could change its bodies' relative speed by twice the
 * speed limits in one sub-step. A joint that cannot be met (made far from its constraint, or
 * against another joint) takes more impulse every sub-step; warm-started from it, the next
 * sub-step's velocities would grow without bound, to infinity and NaN. Met joints never come near.
 * The bounds, linear and angular, go to bounds[at] and bounds[at + 1] for holdImpulses.
 */
function boundImpulses(r: Float64Array, o: number, kind: number, limits: Float64Array, bounds: Float64Array, at: number): void {
  const maxSpeed = limits[0];
  const maxAngular = limits[1];
  const inverseMass = r[o + INV_MASS_A] + r[o + INV_MASS_B];
  const inverseInertia = r[o + INV_INERTIA_A] + r[o + INV_INERTIA_B];
  const linear = inverseMass > 0 ? (2 * maxSpeed) / inverseMass : 0;
  let angular = inverseInertia > 0 ? (2 * maxAngular) / inverseInertia : 0;
  // A revolute joint's spring, motor and limits, and a weld's angle, turn the bodies about the
  // anchors, with that turn's mass.
  if ((kind === JointKind.revolute || kind === JointKind.weld) && inverseInertia > 0) {
    pinnedTurnAtStart(r, o);
    angular = 2 * maxAngular * turnIO[TURN_MASS];
  }
  bounds[at] = linear;
  bounds[at + 1] = angular;
  clampImpulses(r, o, kind, bounds, at);
}

/** Per joint kind, bit k set where IMPULSES[k] is angular (see ANGULAR): holdImpulses runs per joint and sub-step. */
const ANGULAR_BITS = (() => {
  const bits = new Uint8Array(JOINT_KIND_NAMES.length);
  for (const [kind, fields] of Object.entries(ANGULAR)) {
    for (const field of fields) bits[Number(kind)] |= 1 << IMPULSES.indexOf(field);
  }
  return bits;
})();

/**
 * Each of joint o's kept impulses within bounds[at] (a force's) or bounds[at + 1] (a torque's).
 * The bounds are read from the array: doubles passed to a call V8 does not inline are boxed.
 */
function clampImpulses(r: Float64Array, o: number, kind: number, bounds: Float64Array, at: number): void {
  const linear = bounds[at];
  const angular = bounds[at + 1];
  const bits = ANGULAR_BITS[kind];
  for (let k = 0; k < IMPULSES.length; k++) {
    const most = ((bits >> k) & 1) === 1 ? angular : linear;
    const at = o + IMPULSES[k];
    const value = r[at];
    if (value > most) r[at] = most;
    else if (value < -most) r[at] = -most;
  }
}

/**
 * Whether joint o's lever arms on either body (`reach`: jointArm's bound in arm[0], plus the most
 * the two bodies can part within the step at the speed limit, limits[2]) reach more than FAR_ARM of that body's
 * radii of gyration, sqrt(I / m). The
 * effective masses are prepared once per step, from the arms at its start; an arm that a turn or
 * that travel makes many times longer within the step leaves the stale mass answering a velocity
 * error with an impulse that multiplies it: from a unit box anchored 1e45 out, or from bodies
 * 1e-10 wide that part at 1000 m/s on a wheel joint, past the largest double within one step.
 * Those joints' bodies are held within the speed limits after each of their impulses
 * (holdWithinLimits); no joint between bodies larger than about 1e-5 of the length unit comes near.
 */
function farArms(r: Float64Array, o: number, arm: Float64Array, limits: Float64Array): boolean {
  const reach = arm[0] + limits[2];
  const arm2 = reach * reach;
  const far2 = FAR_ARM * FAR_ARM;
  return arm2 * r[o + INV_INERTIA_A] > far2 * r[o + INV_MASS_A] || arm2 * r[o + INV_INERTIA_B] > far2 * r[o + INV_MASS_B];
}

/**
 * The bound on every lever arm joint o's kind forms, its anchors' and its centres' distances,
 * into out[0]: a double returned from, or passed to, a call V8 does not inline is boxed, once a
 * joint a step.
 */
function jointArm(r: Float64Array, o: number, out: Float64Array): void {
  out[0] = Math.sqrt(r[o + R_AX] * r[o + R_AX] + r[o + R_AY] * r[o + R_AY]) + Math.sqrt(r[o + R_BX] * r[o + R_BX] + r[o + R_BY] * r[o + R_BY]) + Math.sqrt(r[o + DELTA_CENTER_X] * r[o + DELTA_CENTER_X] + r[o + DELTA_CENTER_Y] * r[o + DELTA_CENTER_Y]);
}

/**
 * How far out in its radii of gyration an anchor may lie, as i |r|^2 / m, before a joint that
 * turns its bodies about the anchors (a weld's angle; a revolute joint's spring, motor and
 * limits: see pinned-turn.ts) is held as far arms are. The turn moves the body's centre along
 * the tangent to its arm, which a sub-step's turn carries off the arm's circle by the arm times
 * half the turn squared, and what the pin pulls back of that through such a lever grew at every
 * sub-step: a 0.1 m square welded 17 m out (8e4) under 374 m/s^2 in steps of 0.5 s, and a capsule
 * of radius 5 mm welded 24 m out (6e5) under 7,000 m/s^2, reached NaN. A 5 cm disc welded 1 m out
 * is at 800, 5 m out at 20,000.
 */
const TURN_HOLD = 1e4;

/**
 * Whether an idle joint (no body awake and moving) holds a sleeping body, and so keeps reading the
 * force it carried as it fell asleep, as Box2D keeps a sleeping joint's impulses: a rope holding a
 * sleeping weight still reads its weight. One between static or kinematic bodies does nothing, and
 * reads 0. Apart from listJoints, whose loop V8 then keeps small enough to inline what it calls.
 */
function holdsSleeper(bodies: BodyStore, a: number, b: number): boolean {
  return (a >= 0 && bodies.asleep[a] === 1 && bodies.type[a] === TypeCode.dynamic) || (bodies.asleep[b] === 1 && bodies.type[b] === TypeCode.dynamic);
}

/** Whether joints of `kind` hold their bodies as constraints (see JointSolver's loneJoints). */
function holds(kind: number): boolean {
  return kind !== JointKind.spring && kind !== JointKind.pressure && kind !== JointKind.target;
}

/** Whether joint o (of `kind`) turns its bodies about anchors lying past TURN_HOLD (see there). */
function turnsFarOut(r: Float64Array, o: number, kind: number): boolean {
  if (kind !== JointKind.weld && !(kind === JointKind.revolute && (r[o + HERTZ] > 0 || r[o + ENABLE_MOTOR] === 1 || r[o + ENABLE_LIMIT] === 1))) return false;
  const m = r[o + INV_MASS_A] + r[o + INV_MASS_B];
  const a = r[o + INV_INERTIA_A] * (r[o + R_AX] * r[o + R_AX] + r[o + R_AY] * r[o + R_AY]);
  const b = r[o + INV_INERTIA_B] * (r[o + R_BX] * r[o + R_BX] + r[o + R_BY] * r[o + R_BY]);
  return a > TURN_HOLD * m || b > TURN_HOLD * m;
}

/**
 * How many times the linear speed limit a far-armed joint's anchor may move at through its
 * body's spin (see spinCaps): a met joint's anchors move together, each within about twice
 * the limit.
 */
const ANCHOR_SPEEDS = 4;

/**
 * The spins, into caps[at] (A) and caps[at + 1] (B), past which joint o's far arms would move an
 * anchor faster than ANCHOR_SPEEDS times the linear speed limit, or the angular limit where that
 * is lower. The angular limit alone, pi / 4 a step, bounds no anchor: at a step of 1e-100 s it
 * is 8e99 rad/s, which an arm of 1e99 turns into 1e199 m/s, and the products of such speeds
 * pass the largest double (a prismatic joint between a box 1e30 tall and a body 1e99 away
 * reached NaN in two steps). The arm of each spin is the one the joint's impulses turn it by: a
 * sliding joint's (prismatic, wheel) reaches from A's centre to B's anchor, and lengthens by
 * how far the bodies part within the step (`travel`); every other kind's is the anchor's own.
 * A body's spin about its own anchor (a disc on a long rope) is not bounded here.
 */
function spinCaps(r: Float64Array, o: number, kind: number, limits: Float64Array, caps: Float64Array, at: number): void {
  const reach = ANCHOR_SPEEDS * limits[0];
  let armA: number;
  if (kind === JointKind.prismatic || kind === JointKind.wheel) {
    const dx = r[o + DELTA_CENTER_X] + r[o + R_BX];
    const dy = r[o + DELTA_CENTER_Y] + r[o + R_BY];
    armA = Math.sqrt(dx * dx + dy * dy) + limits[2];
  } else {
    armA = Math.sqrt(r[o + R_AX] * r[o + R_AX] + r[o + R_AY] * r[o + R_AY]);
  }
  const armB = Math.sqrt(r[o + R_BX] * r[o + R_BX] + r[o + R_BY] * r[o + R_BY]);
  caps[at] = armA * limits[1] > reach ? reach / armA : limits[1];
  caps[at + 1] = armB * limits[1] > reach ? reach / armB : limits[1];
}

/** Caps joint o's dynamic bodies at the linear speed limit and the spins of spinCaps (caps[at], caps[at + 1]): see farArms. */
function holdWithinLimits(states: Float64Array, r: Float64Array, o: number, maxSpeed: number, caps: Float64Array, at: number): void {
  const sa = r[o + STATE_A];
  const sb = r[o + STATE_B];
  if (states[sa + DYNAMIC] === 1) holdState(states, sa, maxSpeed, caps[at]);
  if (states[sb + DYNAMIC] === 1) holdState(states, sb, maxSpeed, caps[at + 1]);
}

/** Wakes every sleeping body of a ring of which some body moves. */
function wakeRing(bodies: BodyStore, ring: Int32Array): void {
  const { type, asleep } = bodies;
  let moving = false;
  for (let k = 0; k < ring.length && !moving; k++) moving = type[ring[k]] === TypeCode.kinematic || (type[ring[k]] === TypeCode.dynamic && asleep[ring[k]] === 0);
  if (!moving) return;
  for (let k = 0; k < ring.length; k++) if (asleep[ring[k]] === 1) bodies.wake(ring[k]);
}

/** How stiff and damped a rigid joint's push back is: Box2D v3's joint softness (jointHertz, jointDampingRatio). */
export interface JointSettings {
  hertz: number;
  dampingRatio: number;
}

/** Where listJoints counts the joints it lists: general, point distance, spring and pressure joints. */
const Listed = { active: 0, points: 1, springs: 2, pressure: 3, farArms: 4 } as const;

/**
 * The joints' part of the soft step (SoftStep calls each stage where Box2D v3 does: joints before
 * contacts in the warm start, the solve and the relax pass, so that contacts have the last word).
 * Joints are solved one after another in slot order, then the point distance joints colour by
 * colour (PointDistanceJoints); both orders depend on the calls that made the joints alone: the
 * same bits with every broad-phase and thread count. A joint whose bodies both stand still this
 * step (static or asleep) is skipped and keeps its impulses.
 */
export class JointSolver {
  /** Per joint slot, the bounds boundImpulses found for its kept impulses this step: linear, angular. */
  private bounds = new Float64Array(0);
  private readonly step: JointStepContext = { h: 0, inverseH: 0, soft: new Float64Array(3), spinSoft: new Float64Array(3) };
  /** Live joints some body of which moves this step, in slot order. */
  private active = new Int32Array(0);
  /** Per active joint, 1 where its lever arms are far (see farArms). */
  private farArms = new Uint8Array(0);
  /** Per joint slot, 1 where the joint is the only one on each of its moving bodies (see loneJoints). */
  private lone = new Uint8Array(0);
  /** Per body slot, how many constraint joints hold it (loneJoints' count, left at 0 after). */
  private jointsOf = new Int32Array(0);
  /** Per active joint with far arms, the spins its bodies are held within (see spinCaps): A's at 2k, B's at 2k + 1. */
  private spinCaps = new Float64Array(0);
  private activeCount = 0;
  /** The point distance joints (ropes, jellies, blobs), solved apart in colours; their slots, in slot order. */
  private readonly points = new PointDistanceJoints();
  private pointSlots = new Int32Array(0);
  private pointA = new Int32Array(0);
  private pointB = new Int32Array(0);
  /** Live force-driven springs some body of which moves, in slot order. */
  private springSlots = new Int32Array(0);
  /** Live pressure joints, in slot order. */
  private pressureSlots = new Int32Array(0);
  private readonly gas = new GasPressure();
  private readonly springs = new ForceSprings();
  /** The speed limits (linear, angular) for boundImpulses and holdWithinLimits, how far two bodies can part in the step at them (see farArms), and the step. */
  private readonly limits = new Float64Array(4);
  /** The lever-arm bound (jointArm) of the joint listJoints is listing. */
  private readonly arm = new Float64Array(1);
  /** How many joints listJoints listed of each kind of solve (see Listed). */
  private readonly listed = new Int32Array(5);
  /** How the springs are integrated: the world's integrator. */
  integrator: IntegratorName = 'semi-implicit-euler';

  constructor(readonly store: JointStore, readonly settings: JointSettings) {}

  /** Wakes each sleeping body joined to a moving one, so that no joint pulls on a body the solve holds fixed. */
  wakeJoined(bodies: BodyStore): void {
    if (bodies.sleepingCount === 0) return;
    const { store } = this;
    const { type, asleep } = bodies;
    for (let j = 0; j < store.slotCount; j++) {
      if (store.live[j] === 0) continue;
      const a = store.bodyA[j];
      const b = store.bodyB[j];
      if (a < 0) continue;
      if (store.kind[j] === JointKind.pressure) {
        wakeRing(bodies, store.ring(j));
        continue;
      }
      const movingA = type[a] === TypeCode.kinematic || (type[a] === TypeCode.dynamic && asleep[a] === 0);
      const movingB = type[b] === TypeCode.kinematic || (type[b] === TypeCode.dynamic && asleep[b] === 0);
      if (movingA && asleep[b] === 1) bodies.wake(b);
      else if (movingB && asleep[a] === 1) bodies.wake(a);
    }
  }

  /**
   * Once per step, after the bodies are gathered: `index` maps a body slot to its solver state (0:
   * fixed); `contactHertz` is the contacts' stiffness this step, which a rigid joint's is twice at most.
   */
  prepare(bodies: BodyStore, index: Int32Array, slotOfState: Int32Array, stateCount: number, h: number, dt: number, contactHertz: number, gx: number, gy: number, maxSpeed: number, maxAngular: number, kernel: SoftStepKernel | null): void {
    const { store, step } = this;
    step.h = h;
    step.inverseH = 1 / h;
    makeSoft(Math.min(this.settings.hertz, 2 * contactHertz), this.settings.dampingRatio, h, step.soft);
    makeSoft(SPIN_HERTZ, SPIN_DAMPING, h, step.spinSoft);
    if (this.active.length < store.slotCount) {
      this.active = new Int32Array(Math.max(store.slotCount, 2 * this.active.length));
      this.farArms = new Uint8Array(this.active.length);
      this.spinCaps = new Float64Array(2 * this.active.length);
      this.springSlots = new Int32Array(this.active.length);
      this.pressureSlots = new Int32Array(this.active.length);
      this.pointSlots = new Int32Array(this.active.length);
      this.pointA = new Int32Array(this.active.length);
      this.pointB = new Int32Array(this.active.length);
      this.bounds = new Float64Array(2 * this.active.length);
      this.lone = new Uint8Array(this.active.length);
    }
    this.limits[0] = maxSpeed;
    this.limits[1] = maxAngular;
    this.limits[2] = 2 * maxSpeed * dt;
    this.limits[3] = dt;
    this.loneJoints(bodies);
    // The bounds on kept impulses take every turn about the anchors, whose mass is the larger (a
    // looser bound), lone or not.
    pinnedIO[0] = 1;
    this.listJoints(bodies, index);
    const listed = this.listed;
    this.activeCount = listed[Listed.active];
    this.points.prepare(store, bodies, this.pointSlots, this.pointA, this.pointB, listed[Listed.points], stateCount, h, step.soft, maxSpeed, kernel);
    this.springs.prepare(store, this.springSlots, listed[Listed.springs], stateCount, bodies, slotOfState, gx, gy);
    this.gas.prepare(store, this.pressureSlots, listed[Listed.pressure], bodies, index);
  }

  /**
   * Notes in `lone` the joints that are the only joint holding each of their dynamic bodies, whose
   * turns are then taken about their anchors (see pinned-turn.ts); static and kinematic bodies and
   * the world, which no impulse moves, do not count. Force-driven springs and pressure push, and a
   * target joint (a drag) pulls within its force: they hold nothing.
   */
  private loneJoints(bodies: BodyStore): void {
    const { store, lone } = this;
    const type = bodies.type;
    if (this.jointsOf.length < bodies.slotCount) this.jointsOf = new Int32Array(grownCapacity(this.jointsOf.length, bodies.slotCount));
    const jointsOf = this.jointsOf;
    for (let j = 0; j < store.slotCount; j++) {
      if (store.live[j] === 0 || !holds(store.kind[j])) continue;
      const a = store.bodyA[j];
      if (a >= 0 && type[a] === TypeCode.dynamic) jointsOf[a]++;
      if (type[store.bodyB[j]] === TypeCode.dynamic) jointsOf[store.bodyB[j]]++;
    }
    for (let j = 0; j < store.slotCount; j++) {
      if (store.live[j] === 0 || !holds(store.kind[j])) continue;
      const a = store.bodyA[j];
      const b = store.bodyB[j];
      lone[j] = (a < 0 || type[a] !== TypeCode.dynamic || jointsOf[a] === 1) && (type[b] !== TypeCode.dynamic || jointsOf[b] === 1) ? 1 : 0;
    }
    for (let j = 0; j < store.slotCount; j++) {
      if (store.live[j] === 0) continue;
      const a = store.bodyA[j];
      if (a >= 0) jointsOf[a] = 0;
      jointsOf[store.bodyB[j]] = 0;
    }
  }

  /**
   * prepare's pass over the joints: clears the active ones' forces, notes which are active, and lists them by
   * how they are solved (counts in `listed`), preparing the general ones. Its own function with
   * nothing after its loop, the counts kept in `listed` as it goes: V8 compiles a loop this long
   * during the first step (on-stack replacement), before the code after it has run, and an
   * operation there without feedback then left that code at every step.
   */
  private listJoints(bodies: BodyStore, index: Int32Array): void {
    const store = this.store;
    const r = store.record;
    const listed = this.listed;
    listed.fill(0);
    for (let j = 0; j < store.slotCount; j++) {
      if (store.live[j] === 0) continue;
      const o = j * JOINT_STRIDE;
      const a = store.bodyA[j];
      const b = store.bodyB[j];
      const ia = a < 0 ? 0 : index[a];
      const ib = index[b];
      if (ia !== 0 || ib !== 0 || !holdsSleeper(bodies, a, b)) {
        r[o + FORCE_X] = 0;
        r[o + FORCE_Y] = 0;
        r[o + TORQUE] = 0;
      }
      if (store.kind[j] === JointKind.pressure) {
        // The whole ring wakes together (wakeJoined), so its first two bodies speak for it.
        r[o + ACTIVE] = ia === 0 && ib === 0 ? 0 : 1;
        if (ia !== 0 || ib !== 0) this.pressureSlots[listed[Listed.pressure]++] = j;
        continue;
      }
      if (ia === 0 && ib === 0) {
        r[o + ACTIVE] = 0;
        continue;
      }
      r[o + ACTIVE] = 1;
      if (store.kind[j] === JointKind.distance && isPointDistanceJoint(r, o, bodies, a, b)) {
        const points = listed[Listed.points]++;
        this.pointSlots[points] = j;
        this.pointA[points] = ia;
        this.pointB[points] = ib;
        continue;
      }
      this.prepareJoint(bodies, j, o, ia, ib);
      if (store.kind[j] === JointKind.spring) this.springSlots[listed[Listed.springs]++] = j;
      else {
        jointArm(r, o, this.arm);
        const far = farArms(r, o, this.arm, this.limits) || this.staleArms(bodies, a, b, o) || turnsFarOut(r, o, store.kind[j]);
        this.farArms[listed[Listed.active]] = far ? 1 : 0;
        if (far) {
          listed[Listed.farArms]++;
          spinCaps(r, o, store.kind[j], this.limits, this.spinCaps, 2 * listed[Listed.active]);
        }
        this.active[listed[Listed.active]++] = j;
      }
    }
  }

  /**
   * Whether joint o's effective masses, prepared from its arms at the step's start (this.arm,
   * jointArm's bound), could be more than twice what they will be before the step ends: its
   * bodies (slots a, b; a < 0 for none) part, at their relative speed as the step starts (within
   * twice the speed limit) times the step, by enough to lengthen its lever arms past halving the
   * masses. A Gauss-Seidel pass with more than twice the mass a constraint has overshoots it, and
   * each pass grows the error: bodies 3 m apart on a wheel joint, one 100,000 times lighter than the other, thrown
   * about a box at 400 m/s in steps of 0.5 s, spun to 1e173 rad/s within a step and gave NaN.
   * Like far arms (see farArms), such a joint's bodies are then held within the speed limits after
   * each of its impulses and a sliding joint's masses taken again before each pass. Bodies that
   * move together (a ragdoll falling) part little; spins, within the angular limit, turn the arms
   * but do not lengthen them.
   */
  private staleArms(bodies: BodyStore, a: number, b: number, o: number): boolean {
    const r = this.store.record;
    const arm = this.arm[0];
    const { vx, vy } = bodies;
    let dvx = 0;
    let dvy = 0;
    if (a >= 0 && r[o + STATE_A] !== 0) {
      dvx -= vx[a];
      dvy -= vy[a];
    }
    if (r[o + STATE_B] !== 0) {
      dvx += vx[b];
      dvy += vy[b];
    }
    const dt = this.limits[3];
    const speedSq = dvx * dvx + dvy * dvy;
    // The masses halve only once the arms grow by sqrt(2) - 1 of themselves at least: most joints,
    // whose bodies part by less, are settled here without a square root.
    if (speedSq * dt * dt <= 0.17 * arm * arm) return false;
    const parting = Math.min(Math.sqrt(speedSq), 2 * this.limits[0]) * dt;
    const turning = r[o + INV_INERTIA_A] + r[o + INV_INERTIA_B];
    const start = r[o + INV_MASS_A] + r[o + INV_MASS_B] + turning * arm * arm;
    const end = arm + parting;
    return turning * end * end > start + start;
  }

  /**
   * The common fields of joint j (record offset o; its bodies' solver states ia, ib), then its
   * kind's. Apart from prepare's loop so that each compiles quickly: a step that ran this in
   * the interpreter would box every number it computes.
   */
  private prepareJoint(bodies: BodyStore, j: number, o: number, ia: number, ib: number): void {
    const { store, step } = this;
    const r = store.record;
    const a = store.bodyA[j];
    const b = store.bodyB[j];
    const { invMass, x, y } = bodies;
    const { c, s, invInertia, localCenterX, localCenterY } = bodies.rigid!;
    r[o + STATE_A] = ia * BODY;
    r[o + STATE_B] = ib * BODY;
    r[o + INV_MASS_A] = ia === 0 ? 0 : invMass[a];
    r[o + INV_INERTIA_A] = ia === 0 ? 0 : invInertia[a];
    r[o + INV_MASS_B] = ib === 0 ? 0 : invMass[b];
    r[o + INV_INERTIA_B] = ib === 0 ? 0 : invInertia[b];
    const ca = a < 0 ? 1 : c[a];
    const sa = a < 0 ? 0 : s[a];
    const cb = c[b];
    const sb = s[b];
    const lax = a < 0 ? 0 : r[o + ANCHOR_AX] - localCenterX[a];
    const lay = a < 0 ? 0 : r[o + ANCHOR_AY] - localCenterY[a];
    const lbx = r[o + ANCHOR_BX] - localCenterX[b];
    const lby = r[o + ANCHOR_BY] - localCenterY[b];
    r[o + R_AX] = ca * lax - sa * lay;
    r[o + R_AY] = sa * lax + ca * lay;
    r[o + R_BX] = cb * lbx - sb * lby;
    r[o + R_BY] = sb * lbx + cb * lby;
    r[o + DELTA_CENTER_X] = x[b] - (a < 0 ? r[o + TARGET_X] : x[a]);
    r[o + DELTA_CENTER_Y] = y[b] - (a < 0 ? r[o + TARGET_Y] : y[a]);
    r[o + WORLD_AXIS_X] = ca * r[o + AXIS_X] - sa * r[o + AXIS_Y];
    r[o + WORLD_AXIS_Y] = sa * r[o + AXIS_X] + ca * r[o + AXIS_Y];
    const kind = store.kind[j];
    // The arc tangent is most of a pin's preparation, and only some joints read the angle.
    if (kind !== JointKind.spring && JOINT_KERNELS[kind].readsAngle(r, o)) {
      angleIO[0] = sb * ca - cb * sa;
      angleIO[1] = cb * ca + sb * sa;
      atan2Into(angleIO, 0);
      let angle = angleIO[2] - r[o + REFERENCE_ANGLE];
      if (kind === JointKind.revolute && r[o + ENABLE_LIMIT] === 1) {
        // Limits are followed across ±pi from the angle the last step started at (the bodies turn
        // less than pi a step): wrapped, an angle pushed past a limit near ±pi reads as lying
        // beyond the other limit, which then drives it on the wrong way round. (nearestTurn, written
        // out: V8 boxes a number a call it does not inline returns.)
        angle += TWO_PI * Math.round((r[o + DELTA_ANGLE] - angle) / TWO_PI);
      } else if (angle > Math.PI) angle -= TWO_PI;
      else if (angle < -Math.PI) angle += TWO_PI;
      r[o + DELTA_ANGLE] = angle;
    }
    if (store.kind[j] !== JointKind.spring) {
      boundImpulses(r, o, store.kind[j], this.limits, this.bounds, 2 * j);
      JOINT_KERNELS[store.kind[j]].prepare(r, o, step);
    }
  }

  /**
   * Each sub-step, before its velocity update: the springs' forces, as the integrator says, and
   * the gas's. Under Runge-Kutta the gas's impulse comes first, so that the stages start from the
   * velocities it gives and carry its motion through the springs: applied after them, it acted
   * outside the stages, and a spinning ring of 16 bodies on force springs around a gas lost 0.4 %
   * of its angular momentum in 10 s, which uniform pressure does not change (2e-5 this way).
   */
  springsBefore(states: Float64Array): void {
    const rk4 = this.integrator === 'rk4';
    if (rk4) this.gas.apply(this.store.record, states, this.step);
    this.springs.before(this.store.record, states, this.step, this.integrator, this.limits);
    if (!rk4) this.gas.apply(this.store.record, states, this.step);
  }

  /** Each sub-step, once the bodies moved. */
  springsAfter(states: Float64Array): void {
    this.springs.after(states, this.integrator, this.limits);
  }

  /** Each sub-step: the other joints in slot order, then the point distance joints colour by colour. */
  warmStart(states: Float64Array): void {
    const { store, active, activeCount, limits, farArms, spinCaps } = this;
    const r = store.record;
    for (let k = 0; k < activeCount; k++) {
      const j = active[k];
      const o = j * JOINT_STRIDE;
      const joint = JOINT_KERNELS[store.kind[j]];
      if (farArms[k] === 1 && joint.refresh !== undefined) joint.refresh(r, o, states);
      pinnedIO[0] = this.lone[j];
      joint.warmStart(r, o, states);
      if (farArms[k] === 1) holdWithinLimits(states, r, o, limits[0], spinCaps, 2 * k);
    }
    this.points.warmStart(states);
  }

  solve(states: Float64Array, useBias: boolean): void {
    const { store, active, activeCount, step, limits, farArms, spinCaps } = this;
    const r = store.record;
    holdIO[1] = limits[0];
    for (let k = 0; k < activeCount; k++) {
      const j = active[k];
      const o = j * JOINT_STRIDE;
      const joint = JOINT_KERNELS[store.kind[j]];
      // The relax pass follows the sub-step's move (the solve with the bias shares the warm start's positions).
      if (!useBias && farArms[k] === 1 && joint.refresh !== undefined) joint.refresh(r, o, states);
      holdIO[0] = farArms[k];
      if (farArms[k] === 1) {
        holdIO[2] = spinCaps[2 * k];
        holdIO[3] = spinCaps[2 * k + 1];
      }
      pinnedIO[0] = this.lone[j];
      joint.solve(r, o, states, step, useBias);
      if (farArms[k] === 1) holdWithinLimits(states, r, o, limits[0], spinCaps, 2 * k);
    }
    holdIO[0] = 0;
    this.points.solve(states, useBias);
  }

  /**
   * After each sub-step: the kept impulses within their bounds again (see boundImpulses), of the
   * joints with far arms (see farArms), and of every joint where a body ended the sub-step past
   * the speed limits (`held`). A joint that cannot be met takes more impulse every sub-step, and
   * at 64 sub-steps of a long step, or at a step of 1e-100 s between bodies 1e100 apart, its warm
   * start outgrew the largest double before the next step's prepare bounded it. Met joints never
   * come near the bounds, and a scene without far arms whose bodies keep to the limits skips this.
   */
  holdImpulses(held: boolean): void {
    const { store, active, activeCount, bounds, farArms } = this;
    if (!held && this.listed[Listed.farArms] === 0) return;
    const r = store.record;
    for (let k = 0; k < activeCount; k++) {
      if (!held && farArms[k] === 0) continue;
      const j = active[k];
      clampImpulses(r, j * JOINT_STRIDE, store.kind[j], bounds, 2 * j);
    }
  }

  /** After the sub-steps: each joint's force and torque on body B over the last sub-step. */
  finish(states: Float64Array): void {
    const { store, active, activeCount, step, points } = this;
    const r = store.record;
    points.finish(r, step.inverseH);
    this.springs.finish(r, states);
    for (let k = 0; k < activeCount; k++) {
      const j = active[k];
      pinnedIO[0] = this.lone[j];
      JOINT_KERNELS[store.kind[j]].reaction(r, j * JOINT_STRIDE, step.inverseH, states);
    }
  }

  get count(): number {
    return this.store.count;
  }

  memoryBytes(): number {
    return this.active.byteLength + this.farArms.byteLength + this.lone.byteLength + this.jointsOf.byteLength + this.spinCaps.byteLength + this.bounds.byteLength + 3 * this.pointSlots.byteLength + this.points.memoryBytes() + this.springSlots.byteLength + this.pressureSlots.byteLength + this.springs.memoryBytes() + this.gas.memoryBytes();
  }
}
