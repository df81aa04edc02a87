import { J } from '../../joints/joint-layout.js';
import { W } from '../solver-body.js';
import { measureAngle, RIGID, softFromRecord, solvePoint, warmStartPoint, type JointKernel } from './joint-kernel.js';

/**
 * A weld joint: B keeps its pose in A's frame, the angle first, then the anchors together.
 * Rigid by default (the joints' soft push back in the biased pass); a linear or angular frequency
 * makes that part a spring of its own, acting in both passes (Box2D v3's weld joint).
 */
export const weldJoint: JointKernel = {
  prepare(r, o, step) {
    const k = r[o + J.invInertiaA] + r[o + J.invInertiaB];
    r[o + J.axialMass] = k > 0 ? 1 / k : 0;
    if (r[o + J.linearHertz] > 0) softFromRecord(r, o, J.linearHertz, J.springBias, step);
    if (r[o + J.angularHertz] > 0) softFromRecord(r, o, J.angularHertz, J.softBias, step);
  },

  warmStart(r, o, states) {
    warmStartPoint(r, o, states, false);
  },

  solve(r, o, states, step, useBias) {
    const sa = r[o + J.stateA];
    const sb = r[o + J.stateB];
    const wA = states[sa + W];
    const wB = states[sb + W];
    const springyAngle = r[o + J.angularHertz] > 0;
    let bias = 0;
    let massScale = 1;
    let impulseScale = 0;
    if (springyAngle || useBias) {
      measureAngle(r, o, states);
      const C = r[o + J.angle];
      bias = (springyAngle ? r[o + J.softBias] : step.soft[0]) * C;
      massScale = springyAngle ? r[o + J.softMass] : step.soft[1];
      impulseScale = springyAngle ? r[o + J.softImpulse] : step.soft[2];
    }
    const accumulated = r[o + J.angularImpulse];
    const impulse = -r[o + J.axialMass] * massScale * (wB - wA + bias) - impulseScale * accumulated;
    r[o + J.angularImpulse] = accumulated + impulse;
    states[sa + W] = wA - r[o + J.invInertiaA] * impulse;
    states[sb + W] = wB + r[o + J.invInertiaB] * impulse;
    if (r[o + J.linearHertz] > 0) solvePoint(r, o, states, r, o + J.springBias);
    else solvePoint(r, o, states, useBias ? step.soft : RIGID, 0);
  },

  reaction(r, o, inverseH) {
    r[o + J.forceX] = r[o + J.linearImpulseX] * inverseH;
    r[o + J.forceY] = r[o + J.linearImpulseY] * inverseH;
    r[o + J.torque] = r[o + J.angularImpulse] * inverseH;
  },
};
