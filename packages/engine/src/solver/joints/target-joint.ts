import { J } from '../../joints/joint-layout.js';
import { DPX, DPY, DQC, DQS, VX, VY, W } from '../solver-body.js';
import { softFromRecord, solvePointBlock, WELL_POSED, type JointKernel } from './joint-kernel.js';

// The record's fields as this module's own constants, which V8 folds into the code (see J).
const { angularImpulse: ANGULAR_IMPULSE, deltaCenterX: DELTA_CENTER_X, deltaCenterY: DELTA_CENTER_Y, forceX: FORCE_X, forceY: FORCE_Y, hertz: HERTZ, invInertiaB: INV_INERTIA_B, invMassB: INV_MASS_B, linearImpulseX: LINEAR_IMPULSE_X, linearImpulseY: LINEAR_IMPULSE_Y, maxForce: MAX_FORCE, rBX: R_BX, rBY: R_BY, softBias: SOFT_BIAS, softImpulse: SOFT_IMPULSE, softMass: SOFT_MASS, springBias: SPRING_BIAS, springImpulse: SPRING_IMPULSE, springMass: SPRING_MASS, stateB: STATE_B, torque: TORQUE } = J;

/** The spin damping of a dragged body, as Box2D's mouse joint has: a weak soft constraint on its spin alone. */
export const SPIN_HERTZ = 0.5;
export const SPIN_DAMPING = 0.1;

/**
 * A target joint (Box2D's mouse joint): a spring of `hertz` pulling one body's anchor towards a
 * point in the world, with at most `maxForce`, the same in both passes; it also damps the body's
 * spin a little, so that a dragged body does not whirl. Body A is the world (state 0).
 */
export const targetJoint: JointKernel = {
  readsAngle() {
    return false;
  },

  prepare(r, o, step) {
    softFromRecord(r, o, HERTZ, SPRING_BIAS, step);
    r[o + SOFT_BIAS] = step.spinSoft[0];
    r[o + SOFT_MASS] = step.spinSoft[1];
    r[o + SOFT_IMPULSE] = step.spinSoft[2];
  },

  warmStart(r, o, states) {
    const sb = r[o + STATE_B];
    const rBx = states[sb + DQC] * r[o + R_BX] - states[sb + DQS] * r[o + R_BY];
    const rBy = states[sb + DQS] * r[o + R_BX] + states[sb + DQC] * r[o + R_BY];
    const px = r[o + LINEAR_IMPULSE_X];
    const py = r[o + LINEAR_IMPULSE_Y];
    states[sb + VX] += r[o + INV_MASS_B] * px;
    states[sb + VY] += r[o + INV_MASS_B] * py;
    // No moment on a body that does not turn (see warmStartPoint).
    if (r[o + INV_INERTIA_B] !== 0) states[sb + W] += r[o + INV_INERTIA_B] * (rBx * py - rBy * px + r[o + ANGULAR_IMPULSE]);
  },

  solve(r, o, states, step) {
    const sb = r[o + STATE_B];
    const mB = r[o + INV_MASS_B];
    const iB = r[o + INV_INERTIA_B];
    let vx = states[sb + VX];
    let vy = states[sb + VY];
    let w = states[sb + W];
    {
      const accumulated = r[o + ANGULAR_IMPULSE];
      const impulse = r[o + SOFT_MASS] * (iB > 0 ? -w / iB : 0) - r[o + SOFT_IMPULSE] * accumulated;
      r[o + ANGULAR_IMPULSE] = accumulated + impulse;
      w += iB * impulse;
    }
    const rBx = states[sb + DQC] * r[o + R_BX] - states[sb + DQS] * r[o + R_BY];
    const rBy = states[sb + DQS] * r[o + R_BX] + states[sb + DQC] * r[o + R_BY];
    const bias = r[o + SPRING_BIAS];
    const cx = vx - w * rBy + bias * (states[sb + DPX] + r[o + DELTA_CENTER_X] + rBx);
    const cy = vy + w * rBx + bias * (states[sb + DPY] + r[o + DELTA_CENTER_Y] + rBy);
    const k11 = mB + iB * rBy * rBy;
    const k12 = -iB * rBx * rBy;
    const k22 = mB + iB * rBx * rBx;
    let det = k11 * k22 - k12 * k12;
    const massScale = r[o + SPRING_MASS];
    const impulseScale = r[o + SPRING_IMPULSE];
    const oldX = r[o + LINEAR_IMPULSE_X];
    const oldY = r[o + LINEAR_IMPULSE_Y];
    let totalX = 0;
    let totalY = 0;
    let plainFinite = false;
    if (det > WELL_POSED * k11 * k22) {
      det = 1 / det;
      totalX = oldX - massScale * det * (k22 * cx - k12 * cy) - impulseScale * oldX;
      totalY = oldY - massScale * det * (k11 * cy - k12 * cx) - impulseScale * oldY;
      plainFinite = Number.isFinite(totalX) && Number.isFinite(totalY);
    }
    if (!plainFinite) {
      const block = solvePointBlock(mB, 0, 0, 0, iB, rBx, rBy, cx, cy);
      totalX = oldX - massScale * block[0] - impulseScale * oldX;
      totalY = oldY - massScale * block[1] - impulseScale * oldY;
    }
    const most = r[o + MAX_FORCE] * step.h;
    const sq = totalX * totalX + totalY * totalY;
    if (sq > most * most) {
      const scale = most / Math.sqrt(sq);
      totalX *= scale;
      totalY *= scale;
    }
    r[o + LINEAR_IMPULSE_X] = totalX;
    r[o + LINEAR_IMPULSE_Y] = totalY;
    const px = totalX - oldX;
    const py = totalY - oldY;
    vx += mB * px;
    vy += mB * py;
    if (iB !== 0) w += iB * (rBx * py - rBy * px);
    states[sb + VX] = vx;
    states[sb + VY] = vy;
    states[sb + W] = w;
  },

  reaction(r, o, inverseH) {
    r[o + FORCE_X] = r[o + LINEAR_IMPULSE_X] * inverseH;
    r[o + FORCE_Y] = r[o + LINEAR_IMPULSE_Y] * inverseH;
    r[o + TORQUE] = r[o + ANGULAR_IMPULSE] * inverseH;
  },
};
