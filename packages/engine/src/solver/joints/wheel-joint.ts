import { J } from '../../joints/joint-layout.js';
import { W } from '../solver-body.js';
import { applyLimit, limitIO, prepareSpringLimitMotor, type JointKernel } from './joint-kernel.js';
import { axialSpeed, currentAxisFrame, normalSpeed, push, pushAlong, startAxisFrame } from './axis-frame.js';

/**
 * A wheel joint: B's anchor stays on the line through A's anchor along A's axis (the
 * suspension's travel), pulled back to translation 0 by a spring of `hertz` along it, with B free
 * to turn, driven by a motor of bounded torque; optional translation limits (Box2D v3's wheel
 * joint).
 */
export const wheelJoint: JointKernel = {
  prepare(r, o, step) {
    const f = startAxisFrame(r, o);
    const mA = r[o + J.invMassA];
    const mB = r[o + J.invMassB];
    const iA = r[o + J.invInertiaA];
    const iB = r[o + J.invInertiaB];
    const ka = mA + mB + iA * f.a1 * f.a1 + iB * f.a2 * f.a2;
    r[o + J.axialMass] = ka > 0 ? 1 / ka : 0;
    const kp = mA + mB + iA * f.s1 * f.s1 + iB * f.s2 * f.s2;
    r[o + J.perpMass] = kp > 0 ? 1 / kp : 0;
    r[o + J.motorMass] = iA + iB > 0 ? 1 / (iA + iB) : 0;
    prepareSpringLimitMotor(r, o, step);
  },

  warmStart(r, o, states) {
    const sa = r[o + J.stateA];
    const sb = r[o + J.stateB];
    const f = currentAxisFrame(r, o, states, sa, sb);
    f.along = r[o + J.springImpulseSum] + r[o + J.lowerImpulse] - r[o + J.upperImpulse];
    f.across = r[o + J.axialImpulse];
    f.angular = r[o + J.motorImpulse];
    push(r, o, states, sa, sb, f);
  },

  solve(r, o, states, step, useBias) {
    const sa = r[o + J.stateA];
    const sb = r[o + J.stateB];
    const f = currentAxisFrame(r, o, states, sa, sb);
    if (r[o + J.enableMotor] === 1) {
      const accumulated = r[o + J.motorImpulse];
      const most = r[o + J.maxMotor] * step.h;
      let total = accumulated - r[o + J.motorMass] * (states[sb + W] - states[sa + W] - r[o + J.motorSpeed]);
      total = total < -most ? -most : total > most ? most : total;
      r[o + J.motorImpulse] = total;
      f.along = 0;
      f.across = 0;
      f.angular = total - accumulated;
      push(r, o, states, sa, sb, f);
    }
    const axialMass = r[o + J.axialMass];
    if (r[o + J.hertz] > 0) {
      axialSpeed(states, sa, sb, f);
      const accumulated = r[o + J.springImpulseSum];
      const impulse = -r[o + J.springMass] * axialMass * (f.speed + r[o + J.springBias] * f.translation) - r[o + J.springImpulse] * accumulated;
      r[o + J.springImpulseSum] = accumulated + impulse;
      f.along = impulse;
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
    let bias = 0;
    let massScale = 1;
    let impulseScale = 0;
    if (useBias) {
      bias = step.soft[0] * (-f.ay * f.dx + f.ax * f.dy);
      massScale = step.soft[1];
      impulseScale = step.soft[2];
    }
    normalSpeed(states, sa, sb, f);
    const accumulated = r[o + J.axialImpulse];
    const impulse = -massScale * r[o + J.perpMass] * (f.speed + bias) - impulseScale * accumulated;
    r[o + J.axialImpulse] = accumulated + impulse;
    f.along = 0;
    f.across = impulse;
    f.angular = 0;
    push(r, o, states, sa, sb, f);
  },

  reaction(r, o, inverseH) {
    const along = r[o + J.springImpulseSum] + r[o + J.lowerImpulse] - r[o + J.upperImpulse];
    const across = r[o + J.axialImpulse];
    const ax = r[o + J.worldAxisX];
    const ay = r[o + J.worldAxisY];
    r[o + J.forceX] = (along * ax - across * ay) * inverseH;
    r[o + J.forceY] = (along * ay + across * ax) * inverseH;
    r[o + J.torque] = r[o + J.motorImpulse] * inverseH;
  },
};
