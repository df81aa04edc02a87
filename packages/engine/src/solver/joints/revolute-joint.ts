import { J } from '../../joints/joint-layout.js';
import { W } from '../solver-body.js';
import { applyLimit, limitIO, measureAngle, prepareSpringLimitMotor, RIGID, solvePoint, warmStartPoint, type JointKernel } from './joint-kernel.js';

// The record's fields as this module's own constants, which V8 folds into the code (see J).
const { angle: ANGLE, axialMass: AXIAL_MASS, enableLimit: ENABLE_LIMIT, enableMotor: ENABLE_MOTOR, forceX: FORCE_X, forceY: FORCE_Y, hertz: HERTZ, invInertiaA: INV_INERTIA_A, invInertiaB: INV_INERTIA_B, linearImpulseX: LINEAR_IMPULSE_X, linearImpulseY: LINEAR_IMPULSE_Y, lower: LOWER, lowerImpulse: LOWER_IMPULSE, maxMotor: MAX_MOTOR, motorImpulse: MOTOR_IMPULSE, motorSpeed: MOTOR_SPEED, springBias: SPRING_BIAS, springImpulse: SPRING_IMPULSE, springImpulseSum: SPRING_IMPULSE_SUM, springMass: SPRING_MASS, stateA: STATE_A, stateB: STATE_B, torque: TORQUE, upper: UPPER, upperImpulse: UPPER_IMPULSE } = J;

/**
 * A revolute joint (a pin): the two anchors kept together by a 2x2 point constraint, with an
 * optional angular spring towards the reference angle, a motor of bounded torque, and angle
 * limits, solved in that order so that the point constraint, the stiffest, has the last word
 * (Box2D v3's revolute joint, Catto's "Solver2D" soft step).
 */
export const revoluteJoint: JointKernel = {
  // Only its spring and its limits hold an angle.
  readsAngle(r, o) {
    return r[o + HERTZ] > 0 || r[o + ENABLE_LIMIT] === 1;
  },

  prepare(r, o, step) {
    const k = r[o + INV_INERTIA_A] + r[o + INV_INERTIA_B];
    r[o + AXIAL_MASS] = k > 0 ? 1 / k : 0;
    prepareSpringLimitMotor(r, o, step);
  },

  warmStart(r, o, states) {
    warmStartPoint(r, o, states, true);
  },

  solve(r, o, states, step, useBias) {
    const sa = r[o + STATE_A];
    const sb = r[o + STATE_B];
    const iA = r[o + INV_INERTIA_A];
    const iB = r[o + INV_INERTIA_B];
    let wA = states[sa + W];
    let wB = states[sb + W];
    const turns = iA + iB > 0;
    const axialMass = r[o + AXIAL_MASS];
    if (turns && r[o + HERTZ] > 0) {
      measureAngle(r, o, states);
      const C = r[o + ANGLE];
      const accumulated = r[o + SPRING_IMPULSE_SUM];
      const impulse = -r[o + SPRING_MASS] * axialMass * (wB - wA + r[o + SPRING_BIAS] * C) - r[o + SPRING_IMPULSE] * accumulated;
      r[o + SPRING_IMPULSE_SUM] = accumulated + impulse;
      wA -= iA * impulse;
      wB += iB * impulse;
    }
    if (turns && r[o + ENABLE_MOTOR] === 1) {
      const accumulated = r[o + MOTOR_IMPULSE];
      const most = r[o + MAX_MOTOR] * step.h;
      let total = accumulated - axialMass * (wB - wA - r[o + MOTOR_SPEED]);
      total = total < -most ? -most : total > most ? most : total;
      r[o + MOTOR_IMPULSE] = total;
      wA -= iA * (total - accumulated);
      wB += iB * (total - accumulated);
    }
    if (turns && r[o + ENABLE_LIMIT] === 1) {
      measureAngle(r, o, states);
      const angle = r[o + ANGLE];
      limitIO[0] = angle - r[o + LOWER];
      limitIO[1] = wB - wA;
      applyLimit(r, o, LOWER_IMPULSE, step, useBias);
      wA -= iA * limitIO[2];
      wB += iB * limitIO[2];
      limitIO[0] = r[o + UPPER] - angle;
      limitIO[1] = wA - wB;
      applyLimit(r, o, UPPER_IMPULSE, step, useBias);
      wA += iA * limitIO[2];
      wB -= iB * limitIO[2];
    }
    states[sa + W] = wA;
    states[sb + W] = wB;
    solvePoint(r, o, states, useBias ? step.soft : RIGID, 0);
  },

  reaction(r, o, inverseH) {
    r[o + FORCE_X] = r[o + LINEAR_IMPULSE_X] * inverseH;
    r[o + FORCE_Y] = r[o + LINEAR_IMPULSE_Y] * inverseH;
    r[o + TORQUE] = (r[o + SPRING_IMPULSE_SUM] + r[o + MOTOR_IMPULSE] + r[o + LOWER_IMPULSE] - r[o + UPPER_IMPULSE]) * inverseH;
  },
};
