import { J } from '../../joints/joint-layout.js';
import { W } from '../solver-body.js';
import { measureAngle, RIGID, softFromRecord, solvePoint, warmStartPoint, type JointKernel } from './joint-kernel.js';

// The record's fields as this module's own constants, which V8 folds into the code (see J).
const { angle: ANGLE, angularHertz: ANGULAR_HERTZ, angularImpulse: ANGULAR_IMPULSE, axialMass: AXIAL_MASS, forceX: FORCE_X, forceY: FORCE_Y, invInertiaA: INV_INERTIA_A, invInertiaB: INV_INERTIA_B, linearHertz: LINEAR_HERTZ, linearImpulseX: LINEAR_IMPULSE_X, linearImpulseY: LINEAR_IMPULSE_Y, softBias: SOFT_BIAS, softImpulse: SOFT_IMPULSE, softMass: SOFT_MASS, springBias: SPRING_BIAS, stateA: STATE_A, stateB: STATE_B, torque: TORQUE } = J;

/**
 * A weld joint: B keeps its pose in A's frame, the angle first, then the anchors together.
 * Rigid by default (the joints' soft push back in the biased pass); a linear or angular frequency
 * makes that part a spring of its own, acting in both passes (Box2D v3's weld joint).
 */
export const weldJoint: JointKernel = {
  readsAngle() {
    return true;
  },

  prepare(r, o, step) {
    const k = r[o + INV_INERTIA_A] + r[o + INV_INERTIA_B];
    r[o + AXIAL_MASS] = k > 0 ? 1 / k : 0;
    if (r[o + LINEAR_HERTZ] > 0) softFromRecord(r, o, LINEAR_HERTZ, SPRING_BIAS, step);
    if (r[o + ANGULAR_HERTZ] > 0) softFromRecord(r, o, ANGULAR_HERTZ, SOFT_BIAS, step);
  },

  warmStart(r, o, states) {
    warmStartPoint(r, o, states, false);
  },

  solve(r, o, states, step, useBias) {
    const sa = r[o + STATE_A];
    const sb = r[o + STATE_B];
    const wA = states[sa + W];
    const wB = states[sb + W];
    const springyAngle = r[o + ANGULAR_HERTZ] > 0;
    let bias = 0;
    let massScale = 1;
    let impulseScale = 0;
    if (springyAngle || useBias) {
      measureAngle(r, o, states);
      const C = r[o + ANGLE];
      bias = (springyAngle ? r[o + SOFT_BIAS] : step.soft[0]) * C;
      massScale = springyAngle ? r[o + SOFT_MASS] : step.soft[1];
      impulseScale = springyAngle ? r[o + SOFT_IMPULSE] : step.soft[2];
    }
    const accumulated = r[o + ANGULAR_IMPULSE];
    const impulse = -r[o + AXIAL_MASS] * massScale * (wB - wA + bias) - impulseScale * accumulated;
    r[o + ANGULAR_IMPULSE] = accumulated + impulse;
    states[sa + W] = wA - r[o + INV_INERTIA_A] * impulse;
    states[sb + W] = wB + r[o + INV_INERTIA_B] * impulse;
    if (r[o + LINEAR_HERTZ] > 0) solvePoint(r, o, states, r, o + SPRING_BIAS);
    else solvePoint(r, o, states, useBias ? step.soft : RIGID, 0);
  },

  reaction(r, o, inverseH) {
    r[o + FORCE_X] = r[o + LINEAR_IMPULSE_X] * inverseH;
    r[o + FORCE_Y] = r[o + LINEAR_IMPULSE_Y] * inverseH;
    r[o + TORQUE] = r[o + ANGULAR_IMPULSE] * inverseH;
  },
};
