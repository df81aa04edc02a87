import { J } from '../../joints/joint-layout.js';
import { DPX, DPY, DQC, DQS, VX, VY, W } from '../solver-body.js';
import { softFromRecord, type JointKernel } from './joint-kernel.js';

/** The spin damping of a dragged body, as Box2D's mouse joint has: a weak soft constraint on its spin alone. */
export const SPIN_HERTZ = 0.5;
export const SPIN_DAMPING = 0.1;

/**
 * A target joint (Box2D's mouse joint): a spring of `hertz` pulling one body's anchor towards a
 * point in the world, with at most `maxForce`, the same in both passes; it also damps the body's
 * spin a little, so that a dragged body does not whirl. Body A is the world (state 0).
 */
export const targetJoint: JointKernel = {
  prepare(r, o, step) {
    softFromRecord(r, o, J.hertz, J.springBias, step);
    r[o + J.softBias] = step.spinSoft[0];
    r[o + J.softMass] = step.spinSoft[1];
    r[o + J.softImpulse] = step.spinSoft[2];
  },

  warmStart(r, o, states) {
    const sb = r[o + J.stateB];
    const rBx = states[sb + DQC] * r[o + J.rBX] - states[sb + DQS] * r[o + J.rBY];
    const rBy = states[sb + DQS] * r[o + J.rBX] + states[sb + DQC] * r[o + J.rBY];
    const px = r[o + J.linearImpulseX];
    const py = r[o + J.linearImpulseY];
    states[sb + VX] += r[o + J.invMassB] * px;
    states[sb + VY] += r[o + J.invMassB] * py;
    states[sb + W] += r[o + J.invInertiaB] * (rBx * py - rBy * px + r[o + J.angularImpulse]);
  },

  solve(r, o, states, step) {
    const sb = r[o + J.stateB];
    const mB = r[o + J.invMassB];
    const iB = r[o + J.invInertiaB];
    let vx = states[sb + VX];
    let vy = states[sb + VY];
    let w = states[sb + W];
    {
      const accumulated = r[o + J.angularImpulse];
      const impulse = r[o + J.softMass] * (iB > 0 ? -w / iB : 0) - r[o + J.softImpulse] * accumulated;
      r[o + J.angularImpulse] = accumulated + impulse;
      w += iB * impulse;
    }
    const rBx = states[sb + DQC] * r[o + J.rBX] - states[sb + DQS] * r[o + J.rBY];
    const rBy = states[sb + DQS] * r[o + J.rBX] + states[sb + DQC] * r[o + J.rBY];
    const bias = r[o + J.springBias];
    const cx = vx - w * rBy + bias * (states[sb + DPX] + r[o + J.deltaCenterX] + rBx);
    const cy = vy + w * rBx + bias * (states[sb + DPY] + r[o + J.deltaCenterY] + rBy);
    const k11 = mB + iB * rBy * rBy;
    const k12 = -iB * rBx * rBy;
    const k22 = mB + iB * rBx * rBx;
    let det = k11 * k22 - k12 * k12;
    det = det !== 0 ? 1 / det : 0;
    const massScale = r[o + J.springMass];
    const impulseScale = r[o + J.springImpulse];
    const oldX = r[o + J.linearImpulseX];
    const oldY = r[o + J.linearImpulseY];
    let totalX = oldX - massScale * det * (k22 * cx - k12 * cy) - impulseScale * oldX;
    let totalY = oldY - massScale * det * (k11 * cy - k12 * cx) - impulseScale * oldY;
    const most = r[o + J.maxForce] * step.h;
    const sq = totalX * totalX + totalY * totalY;
    if (sq > most * most) {
      const scale = most / Math.sqrt(sq);
      totalX *= scale;
      totalY *= scale;
    }
    r[o + J.linearImpulseX] = totalX;
    r[o + J.linearImpulseY] = totalY;
    const px = totalX - oldX;
    const py = totalY - oldY;
    vx += mB * px;
    vy += mB * py;
    w += iB * (rBx * py - rBy * px);
    states[sb + VX] = vx;
    states[sb + VY] = vy;
    states[sb + W] = w;
  },

  reaction(r, o, inverseH) {
    r[o + J.forceX] = r[o + J.linearImpulseX] * inverseH;
    r[o + J.forceY] = r[o + J.linearImpulseY] * inverseH;
    r[o + J.torque] = r[o + J.angularImpulse] * inverseH;
  },
};
