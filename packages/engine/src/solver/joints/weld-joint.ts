import { J } from '../../joints/joint-layout.js';
import { makeSoft, DPX, DPY, DQC, DQS, VX, VY, W } from '../solver-body.js';
import { jointAngle, type JointKernel } from './joint-kernel.js';

/**
 * A weld joint: B keeps its pose in A's frame, the angle first, then the anchors together.
 * Rigid by default (the joints' soft push back in the biased pass); a linear or angular frequency
 * makes that part a spring of its own, acting in both passes (Box2D v3's weld joint).
 */
export const weldJoint: JointKernel = {
  prepare(r, o, h) {
    const k = r[o + J.invInertiaA] + r[o + J.invInertiaB];
    r[o + J.axialMass] = k > 0 ? 1 / k : 0;
    if (r[o + J.linearHertz] > 0) makeSoft(r[o + J.linearHertz], r[o + J.dampingRatio], h, r, o + J.springBias);
    if (r[o + J.angularHertz] > 0) makeSoft(r[o + J.angularHertz], r[o + J.dampingRatio], h, r, o + J.softBias);
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
    const px = r[o + J.linearImpulseX];
    const py = r[o + J.linearImpulseY];
    const angular = r[o + J.angularImpulse];
    states[sa + VX] -= mA * px;
    states[sa + VY] -= mA * py;
    states[sa + W] -= iA * (rAx * py - rAy * px + angular);
    states[sb + VX] += mB * px;
    states[sb + VY] += mB * py;
    states[sb + W] += iB * (rBx * py - rBy * px + angular);
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
    {
      const springy = r[o + J.angularHertz] > 0;
      let bias = 0;
      let massScale = 1;
      let impulseScale = 0;
      if (springy || useBias) {
        const C = jointAngle(states, sa, sb, r[o + J.deltaAngle]);
        bias = (springy ? r[o + J.softBias] : step.soft[0]) * C;
        massScale = springy ? r[o + J.softMass] : step.soft[1];
        impulseScale = springy ? r[o + J.softImpulse] : step.soft[2];
      }
      const accumulated = r[o + J.angularImpulse];
      const impulse = -r[o + J.axialMass] * massScale * (wB - wA + bias) - impulseScale * accumulated;
      r[o + J.angularImpulse] = accumulated + impulse;
      wA -= iA * impulse;
      wB += iB * impulse;
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
    const springy = r[o + J.linearHertz] > 0;
    let massScale = 1;
    let impulseScale = 0;
    if (springy || useBias) {
      const bias = springy ? r[o + J.springBias] : step.soft[0];
      cx += bias * (states[sb + DPX] - states[sa + DPX] + r[o + J.deltaCenterX] + rBx - rAx);
      cy += bias * (states[sb + DPY] - states[sa + DPY] + r[o + J.deltaCenterY] + rBy - rAy);
      massScale = springy ? r[o + J.springMass] : step.soft[1];
      impulseScale = springy ? r[o + J.springImpulse] : step.soft[2];
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
    r[o + J.torque] = r[o + J.angularImpulse] * inverseH;
  },
};
