import { J } from '../../joints/joint-layout.js';
import { W } from '../solver-body.js';
import { applyLimit, limitIO, measureAngle, prepareSpringLimitMotor, type JointKernel } from './joint-kernel.js';
import { axialSpeed, currentAxisFrame, normalSpeed, push, pushAlong, startAxisFrame } from './axis-frame.js';

/**
 * A prismatic joint (a slider): B keeps A's angle (plus the reference) and its anchor stays on
 * the line through A's anchor along A's axis, both as one 2x2 block; along the line, an optional
 * spring towards translation 0, a motor of bounded force and translation limits (Box2D v3's
 * prismatic joint).
 */
export const prismaticJoint: JointKernel = {
  prepare(r, o, step) {
    const f = startAxisFrame(r, o);
    const mA = r[o + J.invMassA];
    const mB = r[o + J.invMassB];
    const iA = r[o + J.invInertiaA];
    const iB = r[o + J.invInertiaB];
    const k = mA + mB + iA * f.a1 * f.a1 + iB * f.a2 * f.a2;
    r[o + J.axialMass] = k > 0 ? 1 / k : 0;
    prepareSpringLimitMotor(r, o, step);
  },

  warmStart(r, o, states) {
    const sa = r[o + J.stateA];
    const sb = r[o + J.stateB];
    const f = currentAxisFrame(r, o, states, sa, sb);
    f.along = r[o + J.springImpulseSum] + r[o + J.motorImpulse] + r[o + J.lowerImpulse] - r[o + J.upperImpulse];
    f.across = r[o + J.axialImpulse];
    f.angular = r[o + J.angularImpulse];
    push(r, o, states, sa, sb, f);
  },

  solve(r, o, states, step, useBias) {
    const sa = r[o + J.stateA];
    const sb = r[o + J.stateB];
    const f = currentAxisFrame(r, o, states, sa, sb);
    const axialMass = r[o + J.axialMass];
    if (r[o + J.hertz] > 0) {
      axialSpeed(states, sa, sb, f);
      const accumulated = r[o + J.springImpulseSum];
      const impulse = -r[o + J.springMass] * axialMass * (f.speed + r[o + J.springBias] * f.translation) - r[o + J.springImpulse] * accumulated;
      r[o + J.springImpulseSum] = accumulated + impulse;
      f.along = impulse;
      pushAlong(r, o, states, sa, sb, f);
    }
    if (r[o + J.enableMotor] === 1) {
      axialSpeed(states, sa, sb, f);
      const accumulated = r[o + J.motorImpulse];
      const most = r[o + J.maxMotor] * step.h;
      let total = accumulated + axialMass * (r[o + J.motorSpeed] - f.speed);
      total = total < -most ? -most : total > most ? most : total;
      r[o + J.motorImpulse] = total;
      f.along = total - accumulated;
      pushAlong(r, o, states, sa, sb, f);
    }
    if (r[o + J.enableLimit] === 1) {
      axialSpeed(states, sa, sb, f);
      limitIO[0] = f.translation - r[o + J.lower];
      limitIO[1] = f.speed;
      applyLimit(r, o, J.lowerImpulse, step, useBias);
      f.along = limitIO[2];
      pushAlong(r, o, states, sa, sb, f);
      axialSpeed(states, sa, sb, f);
      limitIO[0] = r[o + J.upper] - f.translation;
      limitIO[1] = -f.speed;
      applyLimit(r, o, J.upperImpulse, step, useBias);
      f.along = -limitIO[2];
      pushAlong(r, o, states, sa, sb, f);
    }
    // Across the axis and in angle, together.
    const mA = r[o + J.invMassA];
    const mB = r[o + J.invMassB];
    const iA = r[o + J.invInertiaA];
    const iB = r[o + J.invInertiaB];
    normalSpeed(states, sa, sb, f);
    let c1 = f.speed;
    let c2 = states[sb + W] - states[sa + W];
    let massScale = 1;
    let impulseScale = 0;
    if (useBias) {
      const bias = step.soft[0];
      measureAngle(r, o, states);
      c1 += bias * (-f.ay * f.dx + f.ax * f.dy);
      c2 += bias * r[o + J.angle];
      massScale = step.soft[1];
      impulseScale = step.soft[2];
    }
    const k11 = mA + mB + iA * f.s1 * f.s1 + iB * f.s2 * f.s2;
    const k12 = iA * f.s1 + iB * f.s2;
    let k22 = iA + iB;
    // Neither body turns: the angle needs no impulse, and the block stays solvable.
    if (k22 === 0) k22 = 1;
    let det = k11 * k22 - k12 * k12;
    det = det !== 0 ? 1 / det : 0;
    const b1 = det * (k22 * c1 - k12 * c2);
    const b2 = det * (k11 * c2 - k12 * c1);
    const across = -massScale * b1 - impulseScale * r[o + J.axialImpulse];
    const angular = -massScale * b2 - impulseScale * r[o + J.angularImpulse];
    r[o + J.axialImpulse] += across;
    r[o + J.angularImpulse] += angular;
    f.along = 0;
    f.across = across;
    f.angular = angular;
    push(r, o, states, sa, sb, f);
  },

  reaction(r, o, inverseH) {
    const along = r[o + J.springImpulseSum] + r[o + J.motorImpulse] + r[o + J.lowerImpulse] - r[o + J.upperImpulse];
    const across = r[o + J.axialImpulse];
    const ax = r[o + J.worldAxisX];
    const ay = r[o + J.worldAxisY];
    r[o + J.forceX] = (along * ax - across * ay) * inverseH;
    r[o + J.forceY] = (along * ay + across * ax) * inverseH;
    r[o + J.torque] = r[o + J.angularImpulse] * inverseH;
  },
};
