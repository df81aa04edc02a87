import { J } from '../../joints/joint-layout.js';
import { DPX, DPY, DQC, DQS, VX, VY, W } from '../solver-body.js';
import { applyLimit, limitIO, softFromRecord, type JointKernel, type JointStepContext } from './joint-kernel.js';

/**
 * A distance joint: the anchors kept `length` apart, rigidly; or, with a range
 * (minLength < maxLength), free within it (a rope) and pulled towards `length` by a spring of
 * `hertz` where one is given. One scalar constraint along the line between the anchors, as in
 * Box2D v3's distance joint; the spring acts in both passes, the range's ends as limits.
 */
export const distanceJoint: JointKernel = {
  prepare(r, o, step) {
    const dx = r[o + J.deltaCenterX] + r[o + J.rBX] - r[o + J.rAX];
    const dy = r[o + J.deltaCenterY] + r[o + J.rBY] - r[o + J.rAY];
    const length = Math.sqrt(dx * dx + dy * dy);
    const ax = length > 0 ? dx / length : 1;
    const ay = length > 0 ? dy / length : 0;
    r[o + J.worldAxisX] = ax;
    r[o + J.worldAxisY] = ay;
    const crA = r[o + J.rAX] * ay - r[o + J.rAY] * ax;
    const crB = r[o + J.rBX] * ay - r[o + J.rBY] * ax;
    const k = r[o + J.invMassA] + r[o + J.invMassB] + r[o + J.invInertiaA] * crA * crA + r[o + J.invInertiaB] * crB * crB;
    r[o + J.axialMass] = k > 0 ? 1 / k : 0;
    if (r[o + J.hertz] > 0) softFromRecord(r, o, J.hertz, J.springBias, step);
    else r[o + J.springImpulseSum] = 0;
    if (r[o + J.enableLimit] === 0) {
      r[o + J.lowerImpulse] = 0;
      r[o + J.upperImpulse] = 0;
    } else {
      r[o + J.axialImpulse] = 0;
    }
  },

  warmStart(r, o, states) {
    const sa = r[o + J.stateA];
    const sb = r[o + J.stateB];
    const frame = currentFrame(r, o, states, sa, sb);
    frame.impulse = r[o + J.axialImpulse] + r[o + J.springImpulseSum] + r[o + J.lowerImpulse] - r[o + J.upperImpulse];
    apply(r, o, states, sa, sb, frame);
  },

  solve(r, o, states, step, useBias) {
    const sa = r[o + J.stateA];
    const sb = r[o + J.stateB];
    const f = currentFrame(r, o, states, sa, sb);
    const axialMass = r[o + J.axialMass];
    if (r[o + J.enableLimit] === 0) {
      // Rigid: the length held, with the joints' soft push back in the biased pass.
      const C = f.length - r[o + J.length];
      let bias = 0;
      let massScale = 1;
      let impulseScale = 0;
      if (useBias) {
        bias = step.soft[0] * C;
        massScale = step.soft[1];
        impulseScale = step.soft[2];
      }
      speedAlong(states, sa, sb, f);
      const accumulated = r[o + J.axialImpulse];
      const impulse = -massScale * axialMass * (f.speed + bias) - impulseScale * accumulated;
      r[o + J.axialImpulse] = accumulated + impulse;
      f.impulse = impulse;
      apply(r, o, states, sa, sb, f);
      return;
    }
    if (r[o + J.hertz] > 0) {
      const C = f.length - r[o + J.length];
      speedAlong(states, sa, sb, f);
      const accumulated = r[o + J.springImpulseSum];
      const impulse = -r[o + J.springMass] * axialMass * (f.speed + r[o + J.springBias] * C) - r[o + J.springImpulse] * accumulated;
      r[o + J.springImpulseSum] = accumulated + impulse;
      f.impulse = impulse;
      apply(r, o, states, sa, sb, f);
    }
    if (r[o + J.minLength] > 0) {
      limitIO[0] = f.length - r[o + J.minLength];
      limit(r, o, states, sa, sb, f, step, useBias, J.lowerImpulse, 1);
    }
    if (r[o + J.maxLength] < Infinity) {
      limitIO[0] = r[o + J.maxLength] - f.length;
      limit(r, o, states, sa, sb, f, step, useBias, J.upperImpulse, -1);
    }
  },

  reaction(r, o, inverseH) {
    const axial = (r[o + J.axialImpulse] + r[o + J.springImpulseSum] + r[o + J.lowerImpulse] - r[o + J.upperImpulse]) * inverseH;
    r[o + J.forceX] = axial * r[o + J.worldAxisX];
    r[o + J.forceY] = axial * r[o + J.worldAxisY];
    r[o + J.torque] = 0;
  },
};

/**
 * The anchors from each centre and the axis between them now; one record reused by every joint,
 * which also carries the speed along the axis (out of speedAlong) and the impulse (into apply):
 * V8 boxes numbers passed to or returned from a call it does not inline.
 */
const frame = { rAx: 0, rAy: 0, rBx: 0, rBy: 0, ax: 1, ay: 0, length: 0, speed: 0, impulse: 0 };
type Frame = typeof frame;

function currentFrame(r: Float64Array, o: number, states: Float64Array, sa: number, sb: number): Frame {
  const f = frame;
  const qAc = states[sa + DQC];
  const qAs = states[sa + DQS];
  const qBc = states[sb + DQC];
  const qBs = states[sb + DQS];
  f.rAx = qAc * r[o + J.rAX] - qAs * r[o + J.rAY];
  f.rAy = qAs * r[o + J.rAX] + qAc * r[o + J.rAY];
  f.rBx = qBc * r[o + J.rBX] - qBs * r[o + J.rBY];
  f.rBy = qBs * r[o + J.rBX] + qBc * r[o + J.rBY];
  const dx = states[sb + DPX] - states[sa + DPX] + r[o + J.deltaCenterX] + f.rBx - f.rAx;
  const dy = states[sb + DPY] - states[sa + DPY] + r[o + J.deltaCenterY] + f.rBy - f.rAy;
  const length = Math.sqrt(dx * dx + dy * dy);
  f.length = length;
  // Anchors that meet keep the axis they had at the step's start.
  f.ax = length > 0 ? dx / length : r[o + J.worldAxisX];
  f.ay = length > 0 ? dy / length : r[o + J.worldAxisY];
  return f;
}

/** B's anchor's speed away from A's, along the axis, into f.speed. */
function speedAlong(states: Float64Array, sa: number, sb: number, f: Frame): void {
  const dvx = states[sb + VX] - states[sb + W] * f.rBy - (states[sa + VX] - states[sa + W] * f.rAy);
  const dvy = states[sb + VY] + states[sb + W] * f.rBx - (states[sa + VY] + states[sa + W] * f.rAx);
  f.speed = dvx * f.ax + dvy * f.ay;
}

/** The impulse f.impulse along the axis, pushing B's anchor away from A's. */
function apply(r: Float64Array, o: number, states: Float64Array, sa: number, sb: number, f: Frame): void {
  const px = f.impulse * f.ax;
  const py = f.impulse * f.ay;
  const mA = r[o + J.invMassA];
  const mB = r[o + J.invMassB];
  states[sa + VX] -= mA * px;
  states[sa + VY] -= mA * py;
  states[sa + W] -= r[o + J.invInertiaA] * (f.rAx * py - f.rAy * px);
  states[sb + VX] += mB * px;
  states[sb + VY] += mB * py;
  states[sb + W] += r[o + J.invInertiaB] * (f.rBx * py - f.rBy * px);
}

/** One end of the range, its gap C >= 0 in limitIO[0]: `sign` 1 for the lower end (pushing apart), -1 for the upper. */
function limit(r: Float64Array, o: number, states: Float64Array, sa: number, sb: number, f: Frame, step: JointStepContext, useBias: boolean, field: number, sign: number): void {
  speedAlong(states, sa, sb, f);
  limitIO[1] = sign * f.speed;
  applyLimit(r, o, field, step, useBias);
  f.impulse = sign * limitIO[2];
  apply(r, o, states, sa, sb, f);
}
