import { atan2 } from '../../math/trig.js';
import { DQC, DQS } from '../solver-body.js';

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
