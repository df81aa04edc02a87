import { J } from '../../joints/joint-layout.js';
import { W } from '../solver-body.js';
import { applyLimit, limitIO, measureAngle, prepareSpringLimitMotor, RIGID, solvePoint, warmStartPoint, type JointKernel } from './joint-kernel.js';

/**
 * A revolute joint (a pin): the two anchors kept together by a 2x2 point constraint, with an
 * optional angular spring towards the reference angle, a motor of bounded torque, and angle
 * limits, solved in that order so that the point constraint, the stiffest, has the last word
 * (Box2D v3's revolute joint, Catto's "Solver2D" soft step).
 */
export const revoluteJoint: JointKernel = {
  prepare(r, o, step) {
    const k = r[o + J.invInertiaA] + r[o + J.invInertiaB];
    r[o + J.axialMass] = k > 0 ? 1 / k : 0;
    prepareSpringLimitMotor(r, o, step);
  },

  warmStart(r, o, states) {
    warmStartPoint(r, o, states, true);
  },

  solve(r, o, states, step, useBias) {
    const sa = r[o + J.stateA];
    const sb = r[o + J.stateB];
    const iA = r[o + J.invInertiaA];
    const iB = r[o + J.invInertiaB];
    let wA = states[sa + W];
    let wB = states[sb + W];
    const turns = iA + iB > 0;
    const axialMass = r[o + J.axialMass];
    if (turns && r[o + J.hertz] > 0) {
      measureAngle(r, o, states);
      const C = r[o + J.angle];
      const accumulated = r[o + J.springImpulseSum];
      const impulse = -r[o + J.springMass] * axialMass * (wB - wA + r[o + J.springBias] * C) - r[o + J.springImpulse] * accumulated;
      r[o + J.springImpulseSum] = accumulated + impulse;
      wA -= iA * impulse;
      wB += iB * impulse;
    }
    if (turns && r[o + J.enableMotor] === 1) {
      const accumulated = r[o + J.motorImpulse];
      const most = r[o + J.maxMotor] * step.h;
      let total = accumulated - axialMass * (wB - wA - r[o + J.motorSpeed]);
      total = total < -most ? -most : total > most ? most : total;
      r[o + J.motorImpulse] = total;
      wA -= iA * (total - accumulated);
      wB += iB * (total - accumulated);
    }
    if (turns && r[o + J.enableLimit] === 1) {
      measureAngle(r, o, states);
      const angle = r[o + J.angle];
      limitIO[0] = angle - r[o + J.lower];
      limitIO[1] = wB - wA;
      applyLimit(r, o, J.lowerImpulse, step, useBias);
      wA -= iA * limitIO[2];
      wB += iB * limitIO[2];
      limitIO[0] = r[o + J.upper] - angle;
      limitIO[1] = wA - wB;
      applyLimit(r, o, J.upperImpulse, step, useBias);
      wA += iA * limitIO[2];
      wB -= iB * limitIO[2];
    }
    states[sa + W] = wA;
    states[sb + W] = wB;
    solvePoint(r, o, states, useBias ? step.soft : RIGID, 0);
  },

  reaction(r, o, inverseH) {
    r[o + J.forceX] = r[o + J.linearImpulseX] * inverseH;
    r[o + J.forceY] = r[o + J.linearImpulseY] * inverseH;
    r[o + J.torque] = (r[o + J.springImpulseSum] + r[o + J.motorImpulse] + r[o + J.lowerImpulse] - r[o + J.upperImpulse]) * inverseH;
  },
};
