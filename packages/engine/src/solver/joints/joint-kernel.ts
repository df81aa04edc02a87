import { atan2 } from '../../math/trig.js';
import { J } from '../../joints/joint-layout.js';
import { makeSoft, DPX, DPY, DQC, DQS, VX, VY, W } from '../solver-body.js';

/** What every joint's solve reads besides its record: the sub-step and the joints' softness. */
export interface JointStepContext {
  h: number;
  inverseH: number;
  /** Bias rate, mass scale and impulse scale of a rigid joint's push back to its constraint. */
  soft: Float64Array;
}

/**
 * One joint kind's part of the soft step (see JointSolver), each over the joint's record `r` at
 * offset `o` (joint-layout.ts) and the bodies' solver states:
 *
 *   prepare    once per step, after the common fields (anchors, masses, delta centre) are set
 *   warmStart  per sub-step, applies the impulses the joint kept
 *   solve      per sub-step, twice: with the soft push back (useBias) and in the relax pass without
 *   reaction   after the step, the force and torque the joint put on body B
 */
export interface JointKernel {
  prepare(r: Float64Array, o: number, h: number): void;
  warmStart(r: Float64Array, o: number, states: Float64Array): void;
  solve(r: Float64Array, o: number, states: Float64Array, step: JointStepContext, useBias: boolean): void;
  reaction(r: Float64Array, o: number, inverseH: number): void;
}

/** The joint angle now: its angle at the step's start plus B's turn less A's since. */
export function jointAngle(states: Float64Array, sa: number, sb: number, deltaAngle: number): number {
  const ac = states[sa + DQC];
  const as = states[sa + DQS];
  const bc = states[sb + DQC];
  const bs = states[sb + DQS];
  return deltaAngle + atan2(bs * ac - bc * as, bc * ac + bs * as);
}

/** An angle in [-pi, pi]. */
export function unwind(angle: number): number {
  if (angle > Math.PI) return angle - 2 * Math.PI;
  if (angle < -Math.PI) return angle + 2 * Math.PI;
  return angle;
}

/**
 * The new total impulse of a one-sided limit C >= 0 with speed cdot along it and effective mass
 * `mass`: apart (C > 0) it lets the gap close within the sub-step and no more (speculative, as
 * contacts do); past it, the soft push back in the biased solve, none in the relax pass.
 */
export function limitTotal(C: number, cdot: number, mass: number, accumulated: number, step: JointStepContext, useBias: boolean): number {
  let bias = 0;
  let massScale = 1;
  let impulseScale = 0;
  if (C > 0) bias = C * step.inverseH;
  else if (useBias) {
    bias = step.soft[0] * C;
    massScale = step.soft[1];
    impulseScale = step.soft[2];
  }
  const impulse = -massScale * mass * (cdot + bias) - impulseScale * accumulated;
  return Math.max(accumulated + impulse, 0);
}

/**
 * What every kind with a spring, limits or a motor prepares alike: the spring's softness (or its
 * impulse cleared when it has none), and the impulses of a limit or motor that is off cleared.
 */
export function prepareSpringLimitMotor(r: Float64Array, o: number, h: number): void {
  if (r[o + J.hertz] > 0) makeSoft(r[o + J.hertz], r[o + J.dampingRatio], h, r, o + J.springBias);
  else r[o + J.springImpulseSum] = 0;
  if (r[o + J.enableLimit] === 0) {
    r[o + J.lowerImpulse] = 0;
    r[o + J.upperImpulse] = 0;
  }
  if (r[o + J.enableMotor] === 0) r[o + J.motorImpulse] = 0;
}

/** Applies the joint's linear impulse at the anchors (where they are now), and `angular` about them, to B (A takes the opposite). */
export function warmStartPoint(r: Float64Array, o: number, states: Float64Array, angular: number): void {
  const sa = r[o + J.stateA];
  const sb = r[o + J.stateB];
  const rAx = states[sa + DQC] * r[o + J.rAX] - states[sa + DQS] * r[o + J.rAY];
  const rAy = states[sa + DQS] * r[o + J.rAX] + states[sa + DQC] * r[o + J.rAY];
  const rBx = states[sb + DQC] * r[o + J.rBX] - states[sb + DQS] * r[o + J.rBY];
  const rBy = states[sb + DQS] * r[o + J.rBX] + states[sb + DQC] * r[o + J.rBY];
  const px = r[o + J.linearImpulseX];
  const py = r[o + J.linearImpulseY];
  const mA = r[o + J.invMassA];
  const mB = r[o + J.invMassB];
  states[sa + VX] -= mA * px;
  states[sa + VY] -= mA * py;
  states[sa + W] -= r[o + J.invInertiaA] * (rAx * py - rAy * px + angular);
  states[sb + VX] += mB * px;
  states[sb + VY] += mB * py;
  states[sb + W] += r[o + J.invInertiaB] * (rBx * py - rBy * px + angular);
}

/**
 * The 2x2 point constraint that keeps the two anchors together (revolute, weld): the relative
 * speed of the anchors, plus `biasRate` times their separation when biasRate > 0, driven to 0
 * through the block's effective mass, softened by `massScale` and `impulseScale`.
 */
export function solvePoint(r: Float64Array, o: number, states: Float64Array, biasRate: number, massScale: number, impulseScale: number): void {
  const sa = r[o + J.stateA];
  const sb = r[o + J.stateB];
  const mA = r[o + J.invMassA];
  const mB = r[o + J.invMassB];
  const iA = r[o + J.invInertiaA];
  const iB = r[o + J.invInertiaB];
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
  const rAx = qAc * r[o + J.rAX] - qAs * r[o + J.rAY];
  const rAy = qAs * r[o + J.rAX] + qAc * r[o + J.rAY];
  const rBx = qBc * r[o + J.rBX] - qBs * r[o + J.rBY];
  const rBy = qBs * r[o + J.rBX] + qBc * r[o + J.rBY];
  let cx = vBx - wB * rBy - (vAx - wA * rAy);
  let cy = vBy + wB * rBx - (vAy + wA * rAx);
  if (biasRate > 0) {
    cx += biasRate * (states[sb + DPX] - states[sa + DPX] + r[o + J.deltaCenterX] + rBx - rAx);
    cy += biasRate * (states[sb + DPY] - states[sa + DPY] + r[o + J.deltaCenterY] + rBy - rAy);
  }
  const k11 = mA + mB + rAy * rAy * iA + rBy * rBy * iB;
  const k12 = -rAy * rAx * iA - rBy * rBx * iB;
  const k22 = mA + mB + rAx * rAx * iA + rBx * rBx * iB;
  let det = k11 * k22 - k12 * k12;
  det = det !== 0 ? 1 / det : 0;
  const bx = det * (k22 * cx - k12 * cy);
  const by = det * (k11 * cy - k12 * cx);
  const px = -massScale * bx - impulseScale * r[o + J.linearImpulseX];
  const py = -massScale * by - impulseScale * r[o + J.linearImpulseY];
  r[o + J.linearImpulseX] += px;
  r[o + J.linearImpulseY] += py;
  states[sa + VX] = vAx - mA * px;
  states[sa + VY] = vAy - mA * py;
  states[sa + W] = wA - iA * (rAx * py - rAy * px);
  states[sb + VX] = vBx + mB * px;
  states[sb + VY] = vBy + mB * py;
  states[sb + W] = wB + iB * (rBx * py - rBy * px);
}
