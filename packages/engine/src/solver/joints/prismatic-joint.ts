import { J } from '../../joints/joint-layout.js';
import { W } from '../solver-body.js';
import { measureAngle, prepareSpringLimitMotor, WELL_POSED, type JointKernel } from './joint-kernel.js';
import { axialLimits, axialSpeed, axialSpring, currentAxisFrame, holdAcross, normalSpeed, push, pushAlong, startAxisFrame } from './axis-frame.js';

// The record's fields as this module's own constants, which V8 folds into the code (see J).
const { angle: ANGLE, angularImpulse: ANGULAR_IMPULSE, axialImpulse: AXIAL_IMPULSE, axialMass: AXIAL_MASS, enableLimit: ENABLE_LIMIT, enableMotor: ENABLE_MOTOR, forceX: FORCE_X, forceY: FORCE_Y, hertz: HERTZ, invInertiaA: INV_INERTIA_A, invInertiaB: INV_INERTIA_B, invMassA: INV_MASS_A, invMassB: INV_MASS_B, lowerImpulse: LOWER_IMPULSE, maxMotor: MAX_MOTOR, motorImpulse: MOTOR_IMPULSE, motorSpeed: MOTOR_SPEED, springImpulseSum: SPRING_IMPULSE_SUM, stateA: STATE_A, stateB: STATE_B, torque: TORQUE, upperImpulse: UPPER_IMPULSE, worldAxisX: WORLD_AXIS_X, worldAxisY: WORLD_AXIS_Y } = J;

const sliderBlock = new Float64Array(2);

/**
 * The solution b of K b = c for the block across the axis and of the angle, K = [m + iA s1^2 +
 * iB s2^2, iA s1 + iB s2; iA s1 + iB s2, iA + iB] (1 for the last where neither body turns),
 * where the plain arithmetic fails: far arms make the entries' determinant cancel to its rounding,
 * and products of huge entries and speeds pass the largest double although the solution does not.
 * The determinant comes from its terms here, each positive, m (iA + iB) + iA iB (s1 - s2)^2, with
 * the block scaled by its largest entry. A block past the largest double, or an answer that is,
 * gives no impulse. Into a reused array: b = (out[0], out[1]).
 */
function solveSliderBlock(m: number, iA: number, iB: number, s1: number, s2: number, c1: number, c2: number): Float64Array {
  const turns = iA + iB;
  const k11 = m + iA * s1 * s1 + iB * s2 * s2;
  const k12 = iA * s1 + iB * s2;
  const k22 = turns > 0 ? turns : 1;
  const scale = Math.max(k11, k22);
  sliderBlock[0] = 0;
  sliderBlock[1] = 0;
  if (!(scale < Infinity)) return sliderBlock;
  const a = k11 / scale;
  const b = k12 / scale;
  const d = k22 / scale;
  const split = ((Math.sqrt(iA) * Math.sqrt(iB)) * (s1 - s2)) / scale;
  const det = turns > 0 ? (m / scale) * d + split * split : a * d;
  if (!(det > 0)) return sliderBlock;
  const inverse = 1 / (det * scale);
  const b1 = inverse * (d * c1 - b * c2);
  const b2 = inverse * (a * c2 - b * c1);
  if (Number.isFinite(b1) && Number.isFinite(b2)) {
    sliderBlock[0] = b1;
    sliderBlock[1] = b2;
  }
  return sliderBlock;
}

/**
 * A prismatic joint (a slider): B keeps A's angle (plus the reference) and its anchor stays on
 * the line through A's anchor along A's axis, both as one 2x2 block; along the line, an optional
 * spring towards translation 0, a motor of bounded force and translation limits (Box2D v3's
 * prismatic joint), each pushing along the axis with the block held (see holdAcross).
 */
export const prismaticJoint: JointKernel = {
  readsAngle() {
    return true;
  },

  // No refresh: warmStart and solve take the axial mass from where the bodies stand at each pass
  // (holdAcross), which is what a refresh would do before them.
  prepare(r, o, step) {
    holdAcross(r, o, startAxisFrame(r, o));
    prepareSpringLimitMotor(r, o, step);
  },

  warmStart(r, o, states) {
    const sa = r[o + STATE_A];
    const sb = r[o + STATE_B];
    const f = currentAxisFrame(r, o, states, sa, sb);
    holdAcross(r, o, f);
    const along = r[o + SPRING_IMPULSE_SUM] + r[o + MOTOR_IMPULSE] + r[o + LOWER_IMPULSE] - r[o + UPPER_IMPULSE];
    f.along = along;
    f.across = r[o + AXIAL_IMPULSE] + along * f.heldAcross;
    f.angular = r[o + ANGULAR_IMPULSE] + along * f.heldAngular;
    push(r, o, states, sa, sb, f);
  },

  solve(r, o, states, step, useBias) {
    const sa = r[o + STATE_A];
    const sb = r[o + STATE_B];
    const f = currentAxisFrame(r, o, states, sa, sb);
    holdAcross(r, o, f);
    const axialMass = r[o + AXIAL_MASS];
    if (r[o + HERTZ] > 0) axialSpring(r, o, states, sa, sb, f);
    if (r[o + ENABLE_MOTOR] === 1) {
      axialSpeed(states, sa, sb, f);
      const accumulated = r[o + MOTOR_IMPULSE];
      const most = r[o + MAX_MOTOR] * step.h;
      let total = accumulated + axialMass * (r[o + MOTOR_SPEED] - f.speed);
      total = total < -most ? -most : total > most ? most : total;
      r[o + MOTOR_IMPULSE] = total;
      f.along = total - accumulated;
      pushAlong(r, o, states, sa, sb, f);
    }
    if (r[o + ENABLE_LIMIT] === 1) axialLimits(r, o, states, sa, sb, f, step, useBias);
    // Across the axis and in angle, together.
    const mA = r[o + INV_MASS_A];
    const mB = r[o + INV_MASS_B];
    const iA = r[o + INV_INERTIA_A];
    const iB = r[o + INV_INERTIA_B];
    normalSpeed(states, sa, sb, f);
    let c1 = f.speed;
    let c2 = states[sb + W] - states[sa + W];
    let massScale = 1;
    let impulseScale = 0;
    if (useBias) {
      const bias = step.soft[0];
      measureAngle(r, o, states);
      c1 += bias * (-f.ay * f.dx + f.ax * f.dy);
      c2 += bias * r[o + ANGLE];
      massScale = step.soft[1];
      impulseScale = step.soft[2];
    }
    const k11 = mA + mB + iA * f.s1 * f.s1 + iB * f.s2 * f.s2;
    const k12 = iA * f.s1 + iB * f.s2;
    let k22 = iA + iB;
    // Neither body turns: the angle needs no impulse, and the block stays solvable.
    if (k22 === 0) k22 = 1;
    let det = k11 * k22 - k12 * k12;
    let b1 = 0;
    let b2 = 0;
    let plainFinite = false;
    if (det > WELL_POSED * k11 * k22) {
      det = 1 / det;
      b1 = det * (k22 * c1 - k12 * c2);
      b2 = det * (k11 * c2 - k12 * c1);
      plainFinite = Number.isFinite(b1) && Number.isFinite(b2);
    }
    if (!plainFinite) {
      const block = solveSliderBlock(mA + mB, iA, iB, f.s1, f.s2, c1, c2);
      b1 = block[0];
      b2 = block[1];
    }
    const across = -massScale * b1 - impulseScale * r[o + AXIAL_IMPULSE];
    const angular = -massScale * b2 - impulseScale * r[o + ANGULAR_IMPULSE];
    r[o + AXIAL_IMPULSE] += across;
    r[o + ANGULAR_IMPULSE] += angular;
    f.along = 0;
    f.across = across;
    f.angular = angular;
    push(r, o, states, sa, sb, f);
  },

  reaction(r, o, inverseH) {
    const along = r[o + SPRING_IMPULSE_SUM] + r[o + MOTOR_IMPULSE] + r[o + LOWER_IMPULSE] - r[o + UPPER_IMPULSE];
    // What held the slider across the axis and in angle while the push along it acted (see holdAcross).
    const f = startAxisFrame(r, o);
    holdAcross(r, o, f);
    const across = r[o + AXIAL_IMPULSE] + along * f.heldAcross;
    const ax = r[o + WORLD_AXIS_X];
    const ay = r[o + WORLD_AXIS_Y];
    r[o + FORCE_X] = (along * ax - across * ay) * inverseH;
    r[o + FORCE_Y] = (along * ay + across * ax) * inverseH;
    r[o + TORQUE] = (r[o + ANGULAR_IMPULSE] + along * f.heldAngular) * inverseH;
  },
};
