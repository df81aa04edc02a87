import { J } from '../../joints/joint-layout.js';
import { DPX, DPY, VX, VY, W } from '../solver-body.js';
import { applyLimit, limitIO, softFromRecord, turnAnchors, type JointKernel, type JointStepContext } from './joint-kernel.js';

// The record's fields as this module's own constants, which V8 folds into the code (see J).
const { axialImpulse: AXIAL_IMPULSE, axialMass: AXIAL_MASS, deltaCenterX: DELTA_CENTER_X, deltaCenterY: DELTA_CENTER_Y, enableLimit: ENABLE_LIMIT, forceX: FORCE_X, forceY: FORCE_Y, hertz: HERTZ, invInertiaA: INV_INERTIA_A, invInertiaB: INV_INERTIA_B, invMassA: INV_MASS_A, invMassB: INV_MASS_B, length: LENGTH, lowerImpulse: LOWER_IMPULSE, maxLength: MAX_LENGTH, minLength: MIN_LENGTH, rAX: R_AX, rAY: R_AY, rBX: R_BX, rBY: R_BY, springBias: SPRING_BIAS, springImpulse: SPRING_IMPULSE, springImpulseSum: SPRING_IMPULSE_SUM, springMass: SPRING_MASS, stateA: STATE_A, stateB: STATE_B, torque: TORQUE, upperImpulse: UPPER_IMPULSE, worldAxisX: WORLD_AXIS_X, worldAxisY: WORLD_AXIS_Y } = J;

/**
 * A distance joint: the anchors kept `length` apart, rigidly; or, with a range
 * (minLength < maxLength), free within it (a rope) and pulled towards `length` by a spring of
 * `hertz` where one is given. One scalar constraint along the line between the anchors, as in
 * Box2D v3's distance joint; the spring acts in both passes, the range's ends as limits.
 */
export const distanceJoint: JointKernel = {
  readsAngle() {
    return false;
  },

  prepare(r, o, step) {
    const dx = r[o + DELTA_CENTER_X] + r[o + R_BX] - r[o + R_AX];
    const dy = r[o + DELTA_CENTER_Y] + r[o + R_BY] - r[o + R_AY];
    const length = Math.sqrt(dx * dx + dy * dy);
    const ax = length > 0 ? dx / length : 1;
    const ay = length > 0 ? dy / length : 0;
    r[o + WORLD_AXIS_X] = ax;
    r[o + WORLD_AXIS_Y] = ay;
    const crA = r[o + R_AX] * ay - r[o + R_AY] * ax;
    const crB = r[o + R_BX] * ay - r[o + R_BY] * ax;
    const k = r[o + INV_MASS_A] + r[o + INV_MASS_B] + r[o + INV_INERTIA_A] * crA * crA + r[o + INV_INERTIA_B] * crB * crB;
    r[o + AXIAL_MASS] = k > 0 ? 1 / k : 0;
    if (r[o + HERTZ] > 0) softFromRecord(r, o, HERTZ, SPRING_BIAS, step);
    else r[o + SPRING_IMPULSE_SUM] = 0;
    if (r[o + ENABLE_LIMIT] === 0) {
      r[o + LOWER_IMPULSE] = 0;
      r[o + UPPER_IMPULSE] = 0;
    } else {
      r[o + AXIAL_IMPULSE] = 0;
    }
  },

  warmStart(r, o, states) {
    const sa = r[o + STATE_A];
    const sb = r[o + STATE_B];
    const frame = currentFrame(r, o, states, sa, sb);
    frame.impulse = r[o + AXIAL_IMPULSE] + r[o + SPRING_IMPULSE_SUM] + r[o + LOWER_IMPULSE] - r[o + UPPER_IMPULSE];
    apply(r, o, states, sa, sb, frame);
  },

  solve(r, o, states, step, useBias) {
    const sa = r[o + STATE_A];
    const sb = r[o + STATE_B];
    const f = currentFrame(r, o, states, sa, sb);
    const axialMass = r[o + AXIAL_MASS];
    if (r[o + ENABLE_LIMIT] === 0) {
      // Rigid: the length held, with the joints' soft push back in the biased pass.
      const C = f.length - r[o + LENGTH];
      let bias = 0;
      let massScale = 1;
      let impulseScale = 0;
      if (useBias) {
        bias = step.soft[0] * C;
        massScale = step.soft[1];
        impulseScale = step.soft[2];
      }
      speedAlong(states, sa, sb, f);
      const accumulated = r[o + AXIAL_IMPULSE];
      const impulse = -massScale * axialMass * (f.speed + bias) - impulseScale * accumulated;
      r[o + AXIAL_IMPULSE] = accumulated + impulse;
      f.impulse = impulse;
      apply(r, o, states, sa, sb, f);
      return;
    }
    if (r[o + HERTZ] > 0) {
      const C = f.length - r[o + LENGTH];
      speedAlong(states, sa, sb, f);
      const accumulated = r[o + SPRING_IMPULSE_SUM];
      const impulse = -r[o + SPRING_MASS] * axialMass * (f.speed + r[o + SPRING_BIAS] * C) - r[o + SPRING_IMPULSE] * accumulated;
      r[o + SPRING_IMPULSE_SUM] = accumulated + impulse;
      f.impulse = impulse;
      apply(r, o, states, sa, sb, f);
    }
    if (r[o + MIN_LENGTH] > 0) {
      limitIO[0] = f.length - r[o + MIN_LENGTH];
      limit(r, o, states, sa, sb, f, step, useBias, LOWER_IMPULSE, 1);
    }
    if (r[o + MAX_LENGTH] < Infinity) {
      limitIO[0] = r[o + MAX_LENGTH] - f.length;
      limit(r, o, states, sa, sb, f, step, useBias, UPPER_IMPULSE, -1);
    }
  },

  reaction(r, o, inverseH) {
    const axial = (r[o + AXIAL_IMPULSE] + r[o + SPRING_IMPULSE_SUM] + r[o + LOWER_IMPULSE] - r[o + UPPER_IMPULSE]) * inverseH;
    r[o + FORCE_X] = axial * r[o + WORLD_AXIS_X];
    r[o + FORCE_Y] = axial * r[o + WORLD_AXIS_Y];
    r[o + TORQUE] = 0;
  },
};

/**
 * The anchors from each centre and the axis between them now; one record reused by every joint,
 * which also carries the speed along the axis (out of speedAlong) and the impulse (into apply):
 * V8 boxes numbers passed to or returned from a call it does not inline.
 */
const frame = { rAx: 0, rAy: 0, rBx: 0, rBy: 0, ax: 1, ay: 0, length: 0, speed: 0, impulse: 0, point: false };
type Frame = typeof frame;

function currentFrame(r: Float64Array, o: number, states: Float64Array, sa: number, sb: number): Frame {
  const f = frame;
  // Anchors at both centres (the particles of ropes, jellies and blobs): no turn can move them, and
  // the joint exerts no torque, so the passes skip the rotations, which halves a lattice's solve.
  f.point = r[o + R_AX] === 0 && r[o + R_AY] === 0 && r[o + R_BX] === 0 && r[o + R_BY] === 0;
  let dx = states[sb + DPX] - states[sa + DPX] + r[o + DELTA_CENTER_X];
  let dy = states[sb + DPY] - states[sa + DPY] + r[o + DELTA_CENTER_Y];
  if (!f.point) {
    turnAnchors(r, o, states, sa, sb, f);
    dx = dx + f.rBx - f.rAx;
    dy = dy + f.rBy - f.rAy;
  }
  const length = Math.sqrt(dx * dx + dy * dy);
  f.length = length;
  // Anchors that meet keep the axis they had at the step's start.
  f.ax = length > 0 ? dx / length : r[o + WORLD_AXIS_X];
  f.ay = length > 0 ? dy / length : r[o + WORLD_AXIS_Y];
  return f;
}

/** B's anchor's speed away from A's, along the axis, into f.speed. */
function speedAlong(states: Float64Array, sa: number, sb: number, f: Frame): void {
  if (f.point) {
    f.speed = (states[sb + VX] - states[sa + VX]) * f.ax + (states[sb + VY] - states[sa + VY]) * f.ay;
    return;
  }
  const dvx = states[sb + VX] - states[sb + W] * f.rBy - (states[sa + VX] - states[sa + W] * f.rAy);
  const dvy = states[sb + VY] + states[sb + W] * f.rBx - (states[sa + VY] + states[sa + W] * f.rAx);
  f.speed = dvx * f.ax + dvy * f.ay;
}

/** The impulse f.impulse along the axis, pushing B's anchor away from A's. */
function apply(r: Float64Array, o: number, states: Float64Array, sa: number, sb: number, f: Frame): void {
  const px = f.impulse * f.ax;
  const py = f.impulse * f.ay;
  const mA = r[o + INV_MASS_A];
  const mB = r[o + INV_MASS_B];
  states[sa + VX] -= mA * px;
  states[sa + VY] -= mA * py;
  states[sb + VX] += mB * px;
  states[sb + VY] += mB * py;
  if (f.point) return;
  // No moment on a body that does not turn (see warmStartPoint).
  const iA = r[o + INV_INERTIA_A];
  const iB = r[o + INV_INERTIA_B];
  if (iA !== 0) states[sa + W] -= iA * (f.rAx * py - f.rAy * px);
  if (iB !== 0) states[sb + W] += iB * (f.rBx * py - f.rBy * px);
}

/** One end of the range, its gap C >= 0 in limitIO[0]: `sign` 1 for the lower end (pushing apart), -1 for the upper. */
function limit(r: Float64Array, o: number, states: Float64Array, sa: number, sb: number, f: Frame, step: JointStepContext, useBias: boolean, field: number, sign: number): void {
  speedAlong(states, sa, sb, f);
  limitIO[1] = sign * f.speed;
  limitIO[3] = r[o + AXIAL_MASS];
  applyLimit(r, o, field, step, useBias);
  f.impulse = sign * limitIO[2];
  apply(r, o, states, sa, sb, f);
}
