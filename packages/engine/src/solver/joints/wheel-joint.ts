import { J } from '../../joints/joint-layout.js';
import { W } from '../solver-body.js';
import { prepareSpringLimitMotor, type JointKernel } from './joint-kernel.js';
import { axialLimits, axialSpring, currentAxisFrame, normalSpeed, push, startAxisFrame, type AxisFrame } from './axis-frame.js';

// The record's fields as this module's own constants, which V8 folds into the code (see J).
const { axialImpulse: AXIAL_IMPULSE, axialMass: AXIAL_MASS, enableLimit: ENABLE_LIMIT, enableMotor: ENABLE_MOTOR, forceX: FORCE_X, forceY: FORCE_Y, hertz: HERTZ, invInertiaA: INV_INERTIA_A, invInertiaB: INV_INERTIA_B, invMassA: INV_MASS_A, invMassB: INV_MASS_B, lowerImpulse: LOWER_IMPULSE, maxMotor: MAX_MOTOR, motorImpulse: MOTOR_IMPULSE, motorMass: MOTOR_MASS, motorSpeed: MOTOR_SPEED, perpMass: PERP_MASS, springImpulseSum: SPRING_IMPULSE_SUM, stateA: STATE_A, stateB: STATE_B, torque: TORQUE, upperImpulse: UPPER_IMPULSE, worldAxisX: WORLD_AXIS_X, worldAxisY: WORLD_AXIS_Y } = J;

/** The effective masses along the axis and across it, from the arms of frame f. */
function axisMasses(r: Float64Array, o: number, f: AxisFrame): void {
  const mA = r[o + INV_MASS_A];
  const mB = r[o + INV_MASS_B];
  const iA = r[o + INV_INERTIA_A];
  const iB = r[o + INV_INERTIA_B];
  const ka = mA + mB + iA * f.a1 * f.a1 + iB * f.a2 * f.a2;
  r[o + AXIAL_MASS] = ka > 0 ? 1 / ka : 0;
  const kp = mA + mB + iA * f.s1 * f.s1 + iB * f.s2 * f.s2;
  r[o + PERP_MASS] = kp > 0 ? 1 / kp : 0;
}

/**
 * A wheel joint: B's anchor stays on the line through A's anchor along A's axis (the
 * suspension's travel), pulled back to translation 0 by a spring of `hertz` along it, with B free
 * to turn, driven by a motor of bounded torque; optional translation limits (Box2D v3's wheel
 * joint).
 */
export const wheelJoint: JointKernel = {
  readsAngle() {
    return false;
  },

  prepare(r, o, step) {
    axisMasses(r, o, startAxisFrame(r, o));
    const iA = r[o + INV_INERTIA_A];
    const iB = r[o + INV_INERTIA_B];
    r[o + MOTOR_MASS] = iA + iB > 0 ? 1 / (iA + iB) : 0;
    prepareSpringLimitMotor(r, o, step);
  },

  refresh(r, o, states) {
    axisMasses(r, o, currentAxisFrame(r, o, states, r[o + STATE_A], r[o + STATE_B]));
  },

  warmStart(r, o, states) {
    const sa = r[o + STATE_A];
    const sb = r[o + STATE_B];
    const f = currentAxisFrame(r, o, states, sa, sb);
    f.along = r[o + SPRING_IMPULSE_SUM] + r[o + LOWER_IMPULSE] - r[o + UPPER_IMPULSE];
    f.across = r[o + AXIAL_IMPULSE];
    f.angular = r[o + MOTOR_IMPULSE];
    push(r, o, states, sa, sb, f);
  },

  solve(r, o, states, step, useBias) {
    const sa = r[o + STATE_A];
    const sb = r[o + STATE_B];
    const f = currentAxisFrame(r, o, states, sa, sb);
    if (r[o + ENABLE_MOTOR] === 1) {
      const accumulated = r[o + MOTOR_IMPULSE];
      const most = r[o + MAX_MOTOR] * step.h;
      let total = accumulated - r[o + MOTOR_MASS] * (states[sb + W] - states[sa + W] - r[o + MOTOR_SPEED]);
      total = total < -most ? -most : total > most ? most : total;
      r[o + MOTOR_IMPULSE] = total;
      f.along = 0;
      f.across = 0;
      f.angular = total - accumulated;
      push(r, o, states, sa, sb, f);
    }
    if (r[o + HERTZ] > 0) axialSpring(r, o, states, sa, sb, f);
    if (r[o + ENABLE_LIMIT] === 1) axialLimits(r, o, states, sa, sb, f, step, useBias);
    let bias = 0;
    let massScale = 1;
    let impulseScale = 0;
    if (useBias) {
      bias = step.soft[0] * (-f.ay * f.dx + f.ax * f.dy);
      massScale = step.soft[1];
      impulseScale = step.soft[2];
    }
    normalSpeed(states, sa, sb, f);
    const accumulated = r[o + AXIAL_IMPULSE];
    const impulse = -massScale * r[o + PERP_MASS] * (f.speed + bias) - impulseScale * accumulated;
    r[o + AXIAL_IMPULSE] = accumulated + impulse;
    f.along = 0;
    f.across = impulse;
    f.angular = 0;
    push(r, o, states, sa, sb, f);
  },

  reaction(r, o, inverseH) {
    const along = r[o + SPRING_IMPULSE_SUM] + r[o + LOWER_IMPULSE] - r[o + UPPER_IMPULSE];
    const across = r[o + AXIAL_IMPULSE];
    const ax = r[o + WORLD_AXIS_X];
    const ay = r[o + WORLD_AXIS_Y];
    r[o + FORCE_X] = (along * ax - across * ay) * inverseH;
    r[o + FORCE_Y] = (along * ay + across * ax) * inverseH;
    r[o + TORQUE] = r[o + MOTOR_IMPULSE] * inverseH;
  },
};
