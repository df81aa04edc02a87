import { J } from '../../joints/joint-layout.js';
import { makeSoft, DPX, DPY, DQC, DQS, VX, VY, W } from '../solver-body.js';
import { jointAngle, limitTotal, type JointKernel } from './joint-kernel.js';

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
    if (r[o + J.hertz] > 0) makeSoft(r[o + J.hertz], r[o + J.dampingRatio], h, r, o + J.springBias);
    else r[o + J.springImpulseSum] = 0;
    if (r[o + J.enableLimit] === 0) {
      r[o + J.lowerImpulse] = 0;
      r[o + J.upperImpulse] = 0;
    }
    if (r[o + J.enableMotor] === 0) r[o + J.motorImpulse] = 0;
  },

  warmStart(r, o, states) {
    const sa = r[o + J.stateA];
    const sb = r[o + J.stateB];
    const mA = r[o + J.invMassA];
    const mB = r[o + J.invMassB];
    const iA = r[o + J.invInertiaA];
    const iB = r[o + J.invInertiaB];
    const rAx = states[sa + DQC] * r[o + J.rAX] - states[sa + DQS] * r[o + J.rAY];
    const rAy = states[sa + DQS] * r[o + J.rAX] + states[sa + DQC] * r[o + J.rAY];
    const rBx = states[sb + DQC] * r[o + J.rBX] - states[sb + DQS] * r[o + J.rBY];
    const rBy = states[sb + DQS] * r[o + J.rBX] + states[sb + DQC] * r[o + J.rBY];
    const axial = r[o + J.springImpulseSum] + r[o + J.motorImpulse] + r[o + J.lowerImpulse] - r[o + J.upperImpulse];
    const px = r[o + J.linearImpulseX];
    const py = r[o + J.linearImpulseY];
    states[sa + VX] -= mA * px;
    states[sa + VY] -= mA * py;
    states[sa + W] -= iA * (rAx * py - rAy * px + axial);
    states[sb + VX] += mB * px;
    states[sb + VY] += mB * py;
    states[sb + W] += iB * (rBx * py - rBy * px + axial);
  },

  solve(r, o, states, step, useBias) {
    const sa = r[o + J.stateA];
    const sb = r[o + J.stateB];
    const mA = r[o + J.invMassA];
    const mB = r[o + J.invMassB];
    const iA = r[o + J.invInertiaA];
    const iB = r[o + J.invInertiaB];
    let vAx = states[sa + VX];
    let vAy = states[sa + VY];
    let wA = states[sa + W];
    let vBx = states[sb + VX];
    let vBy = states[sb + VY];
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
    let massScale = 1;
    let impulseScale = 0;
    if (useBias) {
      const bias = step.soft[0];
      cx += bias * (states[sb + DPX] - states[sa + DPX] + r[o + J.deltaCenterX] + rBx - rAx);
      cy += bias * (states[sb + DPY] - states[sa + DPY] + r[o + J.deltaCenterY] + rBy - rAy);
      massScale = step.soft[1];
      impulseScale = step.soft[2];
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
    vAx -= mA * px;
    vAy -= mA * py;
    wA -= iA * (rAx * py - rAy * px);
    vBx += mB * px;
    vBy += mB * py;
    wB += iB * (rBx * py - rBy * px);
    states[sa + VX] = vAx;
    states[sa + VY] = vAy;
    states[sa + W] = wA;
    states[sb + VX] = vBx;
    states[sb + VY] = vBy;
    states[sb + W] = wB;
  },

  reaction(r, o, inverseH) {
    r[o + J.forceX] = r[o + J.linearImpulseX] * inverseH;
    r[o + J.forceY] = r[o + J.linearImpulseY] * inverseH;
    r[o + J.torque] = (r[o + J.springImpulseSum] + r[o + J.motorImpulse] + r[o + J.lowerImpulse] - r[o + J.upperImpulse]) * inverseH;
  },
};
