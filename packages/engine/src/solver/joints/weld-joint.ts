import { J } from '../../joints/joint-layout.js';
import { W } from '../solver-body.js';
import { measureAngle, RIGID, softFromRecord, solvePoint, warmStartPoint, type JointKernel } from './joint-kernel.js';
import { applyTurn, pinnedTurn, turnIO, turnLinear, TURN_IMPULSE, TURN_MASS, TURN_X, TURN_Y, warmStartTurn } from './pinned-turn.js';

// The record's fields as this module's own constants, which V8 folds into the code (see J).
const { angle: ANGLE, angularHertz: ANGULAR_HERTZ, angularImpulse: ANGULAR_IMPULSE, forceX: FORCE_X, forceY: FORCE_Y, invInertiaA: INV_INERTIA_A, invInertiaB: INV_INERTIA_B, linearHertz: LINEAR_HERTZ, linearImpulseX: LINEAR_IMPULSE_X, linearImpulseY: LINEAR_IMPULSE_Y, softBias: SOFT_BIAS, softImpulse: SOFT_IMPULSE, softMass: SOFT_MASS, springBias: SPRING_BIAS, stateA: STATE_A, stateB: STATE_B, torque: TORQUE } = J;

/**
 * A weld joint: B keeps its pose in A's frame, the angle first, then the anchors together.
 * Rigid by default (the joints' soft push back in the biased pass); a linear or angular frequency
 * makes that part a spring of its own, acting in both passes (Box2D v3's weld joint). The angle
 * turns the bodies about the anchors, with the mass of that turn (pinned-turn.ts), as a revolute
 * joint's spring and limits do: a turn of the spins alone, with the mass 1 / (iA + iB) as in
 * Box2D, is undone by the point constraint wherever an anchor lies off a centre, so that a small
 * body welded far out sags under its weight and an angular spring there runs slow (figures in
 * docs/engine.md, Joints).
 */
export const weldJoint: JointKernel = {
  readsAngle() {
    return true;
  },

  prepare(r, o, step) {
    if (r[o + LINEAR_HERTZ] > 0) softFromRecord(r, o, LINEAR_HERTZ, SPRING_BIAS, step);
    if (r[o + ANGULAR_HERTZ] > 0) softFromRecord(r, o, ANGULAR_HERTZ, SOFT_BIAS, step);
  },

  warmStart(r, o, states) {
    warmStartPoint(r, o, states);
    if (r[o + ANGULAR_IMPULSE] === 0) return;
    turnIO[TURN_IMPULSE] = r[o + ANGULAR_IMPULSE];
    warmStartTurn(r, o, states);
  },

  solve(r, o, states, step, useBias) {
    const sa = r[o + STATE_A];
    const sb = r[o + STATE_B];
    const wA = states[sa + W];
    const wB = states[sb + W];
    const springyAngle = r[o + ANGULAR_HERTZ] > 0;
    let bias = 0;
    let massScale = 1;
    let impulseScale = 0;
    if (springyAngle || useBias) {
      measureAngle(r, o, states);
      const C = r[o + ANGLE];
      bias = (springyAngle ? r[o + SOFT_BIAS] : step.soft[0]) * C;
      massScale = springyAngle ? r[o + SOFT_MASS] : step.soft[1];
      impulseScale = springyAngle ? r[o + SOFT_IMPULSE] : step.soft[2];
    }
    const pointSoft = r[o + LINEAR_HERTZ] > 0 ? r : useBias ? step.soft : RIGID;
    const pointAt = r[o + LINEAR_HERTZ] > 0 ? o + SPRING_BIAS : 0;
    // Neither body turns: the angle takes no impulse.
    if (r[o + INV_INERTIA_A] + r[o + INV_INERTIA_B] === 0) {
      solvePoint(r, o, states, pointSoft, pointAt);
      return;
    }
    pinnedTurn(r, o, states);
    const accumulated = r[o + ANGULAR_IMPULSE];
    const impulse = -turnIO[TURN_MASS] * massScale * (wB - wA + bias) - impulseScale * accumulated;
    r[o + ANGULAR_IMPULSE] = accumulated + impulse;
    turnIO[TURN_IMPULSE] = impulse;
    // Its linear part stays the angle's: the point's soft solve decays its own kept impulse alone.
    applyTurn(r, o, states);
    solvePoint(r, o, states, pointSoft, pointAt);
  },

  reaction(r, o, inverseH, states) {
    // The force holds the anchors together: the point's impulse and the angle's turn's linear part.
    turnIO[TURN_IMPULSE] = r[o + ANGULAR_IMPULSE];
    turnLinear(r, o, states);
    r[o + FORCE_X] = (r[o + LINEAR_IMPULSE_X] + turnIO[TURN_X]) * inverseH;
    r[o + FORCE_Y] = (r[o + LINEAR_IMPULSE_Y] + turnIO[TURN_Y]) * inverseH;
    r[o + TORQUE] = r[o + ANGULAR_IMPULSE] * inverseH;
  },
};
