import { J } from '../../joints/joint-layout.js';
import { W } from '../solver-body.js';
import { applyLimit, limitIO, measureAngle, prepareSpringLimitMotor, RIGID, solvePoint, warmStartPoint, type JointKernel } from './joint-kernel.js';
import { applyTurn, pinnedTurn, turnIO, turnLinear, TURN_IMPULSE, TURN_MASS, TURN_X, TURN_Y, warmStartTurn } from './pinned-turn.js';

// The record's fields as this module's own constants, which V8 folds into the code (see J).
const { angle: ANGLE, invMassA: INV_MASS_A, invMassB: INV_MASS_B, rAX: R_AX, rAY: R_AY, rBX: R_BX, rBY: R_BY, enableLimit: ENABLE_LIMIT, enableMotor: ENABLE_MOTOR, forceX: FORCE_X, forceY: FORCE_Y, hertz: HERTZ, invInertiaA: INV_INERTIA_A, invInertiaB: INV_INERTIA_B, linearImpulseX: LINEAR_IMPULSE_X, linearImpulseY: LINEAR_IMPULSE_Y, lower: LOWER, lowerImpulse: LOWER_IMPULSE, maxMotor: MAX_MOTOR, motorImpulse: MOTOR_IMPULSE, motorSpeed: MOTOR_SPEED, springBias: SPRING_BIAS, springImpulse: SPRING_IMPULSE, springImpulseSum: SPRING_IMPULSE_SUM, springMass: SPRING_MASS, stateA: STATE_A, stateB: STATE_B, torque: TORQUE, upper: UPPER, upperImpulse: UPPER_IMPULSE } = J;

/**
 * A revolute joint (a pin): the two anchors kept together by a 2x2 point constraint, with an
 * optional angular spring towards the reference angle, a motor of bounded torque, and angle
 * limits (Box2D v3's revolute joint, Catto's "Solver2D" soft step). The spring and motor come
 * first, then the point constraint, then the limits, so that they have the last word on the
 * joint's turn; all three turn the bodies about the pin (pinnedTurn), leaving the anchors'
 * relative speed as they found it.
 */
export const revoluteJoint: JointKernel = {
  // Only its spring and its limits hold an angle.
  readsAngle(r, o) {
    return r[o + HERTZ] > 0 || r[o + ENABLE_LIMIT] === 1;
  },

  prepare(r, o, step) {
    prepareSpringLimitMotor(r, o, step);
  },

  warmStart(r, o, states) {
    warmStartPoint(r, o, states);
    const turn = r[o + SPRING_IMPULSE_SUM] + r[o + MOTOR_IMPULSE] + r[o + LOWER_IMPULSE] - r[o + UPPER_IMPULSE];
    // A pin without spring, motor or limits (a grid of 19,794) has no turn to warm-start.
    if (turn === 0) return;
    turnIO[TURN_IMPULSE] = turn;
    warmStartTurn(r, o, states);
  },

  solve(r, o, states, step, useBias) {
    const sa = r[o + STATE_A];
    const sb = r[o + STATE_B];
    const sprung = r[o + HERTZ] > 0;
    const driven = r[o + ENABLE_MOTOR] === 1;
    const limited = r[o + ENABLE_LIMIT] === 1;
    if (r[o + INV_INERTIA_A] + r[o + INV_INERTIA_B] === 0 || !(sprung || driven || limited)) {
      solvePoint(r, o, states, useBias ? step.soft : RIGID, 0);
      return;
    }
    pinnedTurn(r, o, states);
    const mass = turnIO[TURN_MASS];
    if (sprung) {
      measureAngle(r, o, states);
      const accumulated = r[o + SPRING_IMPULSE_SUM];
      const impulse = -r[o + SPRING_MASS] * mass * (states[sb + W] - states[sa + W] + r[o + SPRING_BIAS] * r[o + ANGLE]) - r[o + SPRING_IMPULSE] * accumulated;
      r[o + SPRING_IMPULSE_SUM] = accumulated + impulse;
      turnIO[TURN_IMPULSE] = impulse;
      applyTurn(r, o, states);
    }
    if (driven) {
      const accumulated = r[o + MOTOR_IMPULSE];
      const most = r[o + MAX_MOTOR] * step.h;
      let total = accumulated - mass * (states[sb + W] - states[sa + W] - r[o + MOTOR_SPEED]);
      total = total < -most ? -most : total > most ? most : total;
      r[o + MOTOR_IMPULSE] = total;
      turnIO[TURN_IMPULSE] = total - accumulated;
      applyTurn(r, o, states);
    }
    // The turns' linear parts stay theirs (applyTurn keeps them apart): the pin's soft solve decays
    // its own kept impulse alone, and the warm start takes those parts again from the arms.
    solvePoint(r, o, states, useBias ? step.soft : RIGID, 0);
    if (!limited) return;
    measureAngle(r, o, states);
    const angle = r[o + ANGLE];
    limitIO[0] = angle - r[o + LOWER];
    limitIO[1] = states[sb + W] - states[sa + W];
    limitIO[3] = mass;
    applyLimit(r, o, LOWER_IMPULSE, step, useBias);
    turnIO[TURN_IMPULSE] = limitIO[2];
    applyTurn(r, o, states);
    limitIO[0] = r[o + UPPER] - angle;
    limitIO[1] = states[sa + W] - states[sb + W];
    limitIO[3] = mass;
    applyLimit(r, o, UPPER_IMPULSE, step, useBias);
    turnIO[TURN_IMPULSE] = -limitIO[2];
    applyTurn(r, o, states);
  },

  reaction(r, o, inverseH, states) {
    // The force holds the anchors together: the pin's impulse and the turns' linear parts.
    const turn = r[o + SPRING_IMPULSE_SUM] + r[o + MOTOR_IMPULSE] + r[o + LOWER_IMPULSE] - r[o + UPPER_IMPULSE];
    turnIO[TURN_IMPULSE] = turn;
    turnLinear(r, o, states);
    r[o + FORCE_X] = (r[o + LINEAR_IMPULSE_X] + turnIO[TURN_X]) * inverseH;
    r[o + FORCE_Y] = (r[o + LINEAR_IMPULSE_Y] + turnIO[TURN_Y]) * inverseH;
    r[o + TORQUE] = turn * inverseH;
  },
};
