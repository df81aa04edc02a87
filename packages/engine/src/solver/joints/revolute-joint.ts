import { J } from '../../joints/joint-layout.js';
import { W } from '../solver-body.js';
import { jointAngle, limitTotal, prepareSpringLimitMotor, solvePoint, warmStartPoint, type JointKernel } from './joint-kernel.js';

/**
 * A revolute joint (a pin): the two anchors kept together by a 2x2 point constraint, with an
 * optional angular spring towards the reference angle, a motor of bounded torque, and angle
 * limits, solved in that order so that the point constraint, the stiffest, has the last word
 * (Box2D v3's revolute joint, Catto's "Solver2D" soft step).
 */
export const revoluteJoint: JointKernel = {
  prepare(r, o, h) {
    const k = r[o + J.invInertiaA] + r[o + J.invInertiaB];
    r[o + J.axialMass] = k > 0 ? 1 / k : 0;
    prepareSpringLimitMotor(r, o, h);
  },

  warmStart(r, o, states) {
    warmStartPoint(r, o, states, r[o + J.springImpulseSum] + r[o + J.motorImpulse] + r[o + J.lowerImpulse] - r[o + J.upperImpulse]);
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
      const C = jointAngle(states, sa, sb, r[o + J.deltaAngle]);
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
      const angle = jointAngle(states, sa, sb, r[o + J.deltaAngle]);
      let accumulated = r[o + J.lowerImpulse];
      let total = limitTotal(angle - r[o + J.lower], wB - wA, axialMass, accumulated, step, useBias);
      r[o + J.lowerImpulse] = total;
      wA -= iA * (total - accumulated);
      wB += iB * (total - accumulated);
      accumulated = r[o + J.upperImpulse];
      total = limitTotal(r[o + J.upper] - angle, wA - wB, axialMass, accumulated, step, useBias);
      r[o + J.upperImpulse] = total;
      wA += iA * (total - accumulated);
      wB -= iB * (total - accumulated);
    }
    states[sa + W] = wA;
    states[sb + W] = wB;
    if (useBias) solvePoint(r, o, states, step.soft[0], step.soft[1], step.soft[2]);
    else solvePoint(r, o, states, 0, 1, 0);
  },

  reaction(r, o, inverseH) {
    r[o + J.forceX] = r[o + J.linearImpulseX] * inverseH;
    r[o + J.forceY] = r[o + J.linearImpulseY] * inverseH;
    r[o + J.torque] = (r[o + J.springImpulseSum] + r[o + J.motorImpulse] + r[o + J.lowerImpulse] - r[o + J.upperImpulse]) * inverseH;
  },
};
