import { atan2Into } from '../../math/trig.js';
import { J } from '../../joints/joint-layout.js';
import { DPX, DPY, DQC, DQS, DYNAMIC, VX, VY, W, holdState } from '../solver-body.js';
import { softSpring, Spring } from '../spring-frequency.js';

// The record's fields as this module's own constants, which V8 folds into the code (see J).
const { angle: ANGLE, angularImpulse: ANGULAR_IMPULSE, dampingRatio: DAMPING_RATIO, deltaAngle: DELTA_ANGLE, deltaCenterX: DELTA_CENTER_X, deltaCenterY: DELTA_CENTER_Y, enableLimit: ENABLE_LIMIT, enableMotor: ENABLE_MOTOR, hertz: HERTZ, invInertiaA: INV_INERTIA_A, invInertiaB: INV_INERTIA_B, invMassA: INV_MASS_A, invMassB: INV_MASS_B, linearImpulseX: LINEAR_IMPULSE_X, linearImpulseY: LINEAR_IMPULSE_Y, lowerImpulse: LOWER_IMPULSE, motorImpulse: MOTOR_IMPULSE, rAX: R_AX, rAY: R_AY, rBX: R_BX, rBY: R_BY, springBias: SPRING_BIAS, springImpulseSum: SPRING_IMPULSE_SUM, stateA: STATE_A, stateB: STATE_B, upperImpulse: UPPER_IMPULSE } = J;

/** What every joint's solve reads besides its record: the sub-step and the joints' softness. */
export interface JointStepContext {
  h: number;
  inverseH: number;
  /** Bias rate, mass scale and impulse scale of a rigid joint's push back to its constraint. */
  soft: Float64Array;
  /** The same of the target joint's spin damping (see target-joint.ts). */
  spinSoft: Float64Array;
}

/**
 * One joint kind's part of the soft step (see JointSolver), each over the joint's record `r` at
 * offset `o` (joint-layout.ts) and the bodies' solver states:
 *
 *   prepare    once per step, after the common fields (anchors, masses, delta centre) are set
 *   warmStart  per sub-step, applies the impulses the joint kept
 *   solve      per sub-step, twice: with the soft push back (useBias) and in the relax pass without
 *   reaction   after the step, the force and torque the joint put on body B
 *   refresh    optional, before each sub-step's warm start and relax pass of a joint with far
 *              arms (see JointSolver): the effective masses again, from the frame now, where
 *              the bodies' travel within the step lengthens the arms (the sliding kinds)
 */
export interface JointKernel {
  /** Whether the solve reads the joint angle (measureAngle), so that preparation measures its value at the step's start: an arc tangent a joint that does not read it is spared. */
  readsAngle(r: Float64Array, o: number): boolean;
  prepare(r: Float64Array, o: number, step: JointStepContext): void;
  warmStart(r: Float64Array, o: number, states: Float64Array): void;
  solve(r: Float64Array, o: number, states: Float64Array, step: JointStepContext, useBias: boolean): void;
  reaction(r: Float64Array, o: number, inverseH: number, states: Float64Array): void;
  refresh?(r: Float64Array, o: number, states: Float64Array): void;
}

const angleIO = new Float64Array(3);

/**
 * The joint angle now into r[o + ANGLE]: its angle at the step's start plus B's turn less A's
 * since. (Numbers go through the record and scratch arrays here and below, not as arguments or
 * results: V8 boxes those where it does not inline a call, an allocation per joint per pass.)
 */
export function measureAngle(r: Float64Array, o: number, states: Float64Array): void {
  const sa = r[o + STATE_A];
  const sb = r[o + STATE_B];
  const ac = states[sa + DQC];
  const as = states[sa + DQS];
  const bc = states[sb + DQC];
  const bs = states[sb + DQS];
  angleIO[0] = bs * ac - bc * as;
  angleIO[1] = bc * ac + bs * as;
  atan2Into(angleIO, 0);
  r[o + ANGLE] = r[o + DELTA_ANGLE] + angleIO[2];
}

/**
 * The soft constraint of a spring of r[o + hertzField] hertz and damping ratio r[o + DAMPING_RATIO]
 * (softSpring: solved at the frequency that keeps it, with the same damping), its bias rate, mass
 * scale and impulse scale into r[o + at..at + 2].
 */
export function softFromRecord(r: Float64Array, o: number, hertzField: number, at: number, step: JointStepContext): void {
  const io = springIO;
  io[Spring.hertz] = r[o + hertzField];
  io[Spring.zeta] = r[o + DAMPING_RATIO];
  io[Spring.h] = step.h;
  softSpring(io);
  r[o + at] = io[Spring.bias];
  r[o + at + 1] = io[Spring.massScale];
  r[o + at + 2] = io[Spring.impulseScale];
}

const springIO = new Float64Array(8);

/** A limit's gap, speed and effective mass (limitIO[0], limitIO[1], limitIO[3]) in, the change of its impulse (limitIO[2]) out: see applyLimit. */
export const limitIO = new Float64Array(4);

/**
 * Whether the joint being solved has far arms (JointSolver sets it per joint: 1 or 0), the
 * linear speed limit, and the spins its bodies A and B are held within. A far-arm joint's solve pushes its bodies in stages (point,
 * limits, block) whose moments cancel in exact arithmetic and leave some 1e-16 x impulse x arm
 * of spin in doubles; the next stage reads that spin and, through an arm of many radii of
 * gyration, can carry it past the largest double within one solve. Such a joint's pushes hold
 * their bodies within the limits after each stage (holdPushed), not only after the solve.
 */
export const holdIO = new Float64Array(4);

/** After a stage's push: holds both bodies within the speed limits where holdIO says the joint has far arms. */
export function holdPushed(states: Float64Array, sa: number, sb: number): void {
  if (holdIO[0] !== 1) return;
  if (states[sa + DYNAMIC] === 1) holdState(states, sa, holdIO[1], holdIO[2]);
  if (states[sb + DYNAMIC] === 1) holdState(states, sb, holdIO[1], holdIO[3]);
}

/**
 * The new total impulse of a one-sided limit C >= 0, into r[o + field], with C and its speed
 * along it in limitIO[0..1] and its effective mass in limitIO[3]: apart (C > 0) it lets the
 * gap close within the sub-step and no more (speculative, as contacts do); past it, the soft push
 * back in the biased solve, none in the relax pass. The impulse's change goes to limitIO[2].
 */
export function applyLimit(r: Float64Array, o: number, field: number, step: JointStepContext, useBias: boolean): void {
  const C = limitIO[0];
  let bias = 0;
  let massScale = 1;
  let impulseScale = 0;
  if (C > 0) bias = C * step.inverseH;
  else if (useBias) {
    bias = step.soft[0] * C;
    massScale = step.soft[1];
    impulseScale = step.soft[2];
  }
  const accumulated = r[o + field];
  const impulse = -massScale * limitIO[3] * (limitIO[1] + bias) - impulseScale * accumulated;
  const total = Math.max(accumulated + impulse, 0);
  r[o + field] = total;
  limitIO[2] = total - accumulated;
}

/**
 * What every kind with a spring, limits or a motor prepares alike: the spring's softness (or its
 * impulse cleared when it has none), and the impulses of a limit or motor that is off cleared.
 */
export function prepareSpringLimitMotor(r: Float64Array, o: number, step: JointStepContext): void {
  if (r[o + HERTZ] > 0) softFromRecord(r, o, HERTZ, SPRING_BIAS, step);
  else r[o + SPRING_IMPULSE_SUM] = 0;
  if (r[o + ENABLE_LIMIT] === 0) {
    r[o + LOWER_IMPULSE] = 0;
    r[o + UPPER_IMPULSE] = 0;
  }
  if (r[o + ENABLE_MOTOR] === 0) r[o + MOTOR_IMPULSE] = 0;
}

/**
 * Applies the joint's linear impulse at the anchors (where they are now): the point's alone. The
 * angular impulse of a revolute joint's spring, motor and limits, or of a weld's angle, is applied
 * apart, as a turn about the anchors (warmStartTurn in pinned-turn.ts).
 */
export function warmStartPoint(r: Float64Array, o: number, states: Float64Array): void {
  // Added to each moment below, 0 leaves a moment of -0 at +0, whose spin then keeps its sign of 0 and the hashes theirs.
  const angular = 0;
  const sa = r[o + STATE_A];
  const sb = r[o + STATE_B];
  const rAx = states[sa + DQC] * r[o + R_AX] - states[sa + DQS] * r[o + R_AY];
  const rAy = states[sa + DQS] * r[o + R_AX] + states[sa + DQC] * r[o + R_AY];
  const rBx = states[sb + DQC] * r[o + R_BX] - states[sb + DQS] * r[o + R_BY];
  const rBy = states[sb + DQS] * r[o + R_BX] + states[sb + DQC] * r[o + R_BY];
  const px = r[o + LINEAR_IMPULSE_X];
  const py = r[o + LINEAR_IMPULSE_Y];
  const mA = r[o + INV_MASS_A];
  const mB = r[o + INV_MASS_B];
  // A body that does not turn (static, kinematic, fixed rotation) takes no moment: its inverse
  // inertia of 0 times a moment that overflowed (a stiff spring's impulse at a far arm) is NaN.
  const iA = r[o + INV_INERTIA_A];
  const iB = r[o + INV_INERTIA_B];
  states[sa + VX] -= mA * px;
  states[sa + VY] -= mA * py;
  if (iA !== 0) states[sa + W] -= iA * (rAx * py - rAy * px + angular);
  states[sb + VX] += mB * px;
  states[sb + VY] += mB * py;
  if (iB !== 0) states[sb + W] += iB * (rBx * py - rBy * px + angular);
}

/** The softness of a rigid velocity constraint: no bias, full mass, no impulse decay (the relax pass). */
export const RIGID = new Float64Array([0, 1, 0]);

/**
 * The 2x2 point constraint that keeps the two anchors together (revolute, weld): the relative
 * speed of the anchors, plus a bias rate times their separation where it is > 0, driven to 0
 * through the block's effective mass, softened: the bias rate, mass scale and impulse scale are
 * soft[at..at + 2] (the joints' softness, a spring's in a record, or RIGID).
 */
export function solvePoint(r: Float64Array, o: number, states: Float64Array, soft: Float64Array, at: number): void {
  const biasRate = soft[at];
  const massScale = soft[at + 1];
  const impulseScale = soft[at + 2];
  const sa = r[o + STATE_A];
  const sb = r[o + STATE_B];
  const mA = r[o + INV_MASS_A];
  const mB = r[o + INV_MASS_B];
  const iA = r[o + INV_INERTIA_A];
  const iB = r[o + INV_INERTIA_B];
  const vAx = states[sa + VX];
  const vAy = states[sa + VY];
  const wA = states[sa + W];
  const vBx = states[sb + VX];
  const vBy = states[sb + VY];
  const wB = states[sb + W];
  const qAc = states[sa + DQC];
  const qAs = states[sa + DQS];
  const qBc = states[sb + DQC];
  const qBs = states[sb + DQS];
  const rAx = qAc * r[o + R_AX] - qAs * r[o + R_AY];
  const rAy = qAs * r[o + R_AX] + qAc * r[o + R_AY];
  const rBx = qBc * r[o + R_BX] - qBs * r[o + R_BY];
  const rBy = qBs * r[o + R_BX] + qBc * r[o + R_BY];
  let cx = vBx - wB * rBy - (vAx - wA * rAy);
  let cy = vBy + wB * rBx - (vAy + wA * rAx);
  if (biasRate > 0) {
    cx += biasRate * (states[sb + DPX] - states[sa + DPX] + r[o + DELTA_CENTER_X] + rBx - rAx);
    cy += biasRate * (states[sb + DPY] - states[sa + DPY] + r[o + DELTA_CENTER_Y] + rBy - rAy);
  }
  const k11 = mA + mB + rAy * rAy * iA + rBy * rBy * iB;
  const k12 = -rAy * rAx * iA - rBy * rBx * iB;
  const k22 = mA + mB + rAx * rAx * iA + rBx * rBx * iB;
  let det = k11 * k22 - k12 * k12;
  let bx = 0;
  let by = 0;
  let plainFinite = false;
  if (det > WELL_POSED * k11 * k22) {
    det = 1 / det;
    bx = det * (k22 * cx - k12 * cy);
    by = det * (k11 * cy - k12 * cx);
    plainFinite = Number.isFinite(bx) && Number.isFinite(by);
  }
  if (!plainFinite) {
    const block = solvePointBlock(mA + mB, iA, rAx, rAy, iB, rBx, rBy, cx, cy);
    bx = block[0];
    by = block[1];
  }
  const px = -massScale * bx - impulseScale * r[o + LINEAR_IMPULSE_X];
  const py = -massScale * by - impulseScale * r[o + LINEAR_IMPULSE_Y];
  r[o + LINEAR_IMPULSE_X] += px;
  r[o + LINEAR_IMPULSE_Y] += py;
  states[sa + VX] = vAx - mA * px;
  states[sa + VY] = vAy - mA * py;
  states[sa + W] = iA === 0 ? wA : wA - iA * (rAx * py - rAy * px);
  states[sb + VX] = vBx + mB * px;
  states[sb + VY] = vBy + mB * py;
  states[sb + W] = iB === 0 ? wB : wB + iB * (rBx * py - rBy * px);
  holdPushed(states, sa, sb);
}

/**
 * How far above zero a 2x2 block's determinant, k11 k22 - k12^2, must lie, relative to k11 k22, for
 * its plain arithmetic to be trusted: below, the two products agree in more digits than that
 * leaves, and the difference is their rounding (a lever arm some 2e4 times its body's radius of
 * gyration makes the block this close to rank one: a 1 cm disc pinned 100 m away).
 */
export const WELL_POSED = 1e-8;

const pointBlock = new Float64Array(2);

/**
 * The solution b of K b = c for a point constraint's block K = m I + iA rA' rA'^T + iB rB' rB'^T
 * (rA', rB' the arms turned a quarter), where the plain arithmetic fails: far arms make the
 * determinant of the entries cancel to its rounding, and products of huge entries and speeds pass
 * the largest double although the solution does not. The determinant comes from its terms here,
 * each positive, m (m + iA |rA|^2 + iB |rB|^2) + iA iB (rA x rB)^2, with the block scaled by its
 * largest entry. A block past the largest double, or an answer that is, gives no impulse. Into a
 * reused array: b = (out[0], out[1]).
 */
export function solvePointBlock(m: number, iA: number, rAx: number, rAy: number, iB: number, rBx: number, rBy: number, c1: number, c2: number): Float64Array {
  const k11 = m + iA * rAy * rAy + iB * rBy * rBy;
  const k12 = -iA * rAy * rAx - iB * rBy * rBx;
  const k22 = m + iA * rAx * rAx + iB * rBx * rBx;
  const scale = Math.max(k11, k22);
  pointBlock[0] = 0;
  pointBlock[1] = 0;
  if (!(scale > 0 && scale < Infinity)) return pointBlock;
  const a = k11 / scale;
  const b = k12 / scale;
  const d = k22 / scale;
  const mass = m / scale;
  const arms = (iA * (rAx * rAx + rAy * rAy) + iB * (rBx * rBx + rBy * rBy)) / scale;
  const sA = Math.sqrt(iA);
  const sB = Math.sqrt(iB);
  const cross = ((sA * rAx) * (sB * rBy) - (sA * rAy) * (sB * rBx)) / scale;
  const det = mass * (mass + arms) + cross * cross;
  if (!(det > 0)) return pointBlock;
  const inverse = 1 / (det * scale);
  const b1 = inverse * (d * c1 - b * c2);
  const b2 = inverse * (a * c2 - b * c1);
  if (Number.isFinite(b1) && Number.isFinite(b2)) {
    pointBlock[0] = b1;
    pointBlock[1] = b2;
  }
  return pointBlock;
}

/** Where a frame keeps the anchors from each centre of mass, in the world now. */
export interface TurnedAnchors {
  rAx: number;
  rAy: number;
  rBx: number;
  rBy: number;
}

/** The prepared anchors turned by each body's rotation since the step began, into f. */
export function turnAnchors(r: Float64Array, o: number, states: Float64Array, sa: number, sb: number, f: TurnedAnchors): void {
  const qAc = states[sa + DQC];
  const qAs = states[sa + DQS];
  const qBc = states[sb + DQC];
  const qBs = states[sb + DQS];
  f.rAx = qAc * r[o + R_AX] - qAs * r[o + R_AY];
  f.rAy = qAs * r[o + R_AX] + qAc * r[o + R_AY];
  f.rBx = qBc * r[o + R_BX] - qBs * r[o + R_BY];
  f.rBy = qBs * r[o + R_BX] + qBc * r[o + R_BY];
}
