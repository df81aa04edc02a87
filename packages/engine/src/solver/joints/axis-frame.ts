import { J } from '../../joints/joint-layout.js';
import { DPX, DPY, DQC, DQS, VX, VY, W } from '../solver-body.js';
import { applyLimit, holdPushed, limitIO, turnAnchors, type JointStepContext } from './joint-kernel.js';

// The record's fields as this module's own constants, which V8 folds into the code (see J).
const { axialMass: AXIAL_MASS, lower: LOWER, lowerImpulse: LOWER_IMPULSE, springBias: SPRING_BIAS, springImpulse: SPRING_IMPULSE, springImpulseSum: SPRING_IMPULSE_SUM, springMass: SPRING_MASS, upper: UPPER, upperImpulse: UPPER_IMPULSE, deltaCenterX: DELTA_CENTER_X, deltaCenterY: DELTA_CENTER_Y, invInertiaA: INV_INERTIA_A, invInertiaB: INV_INERTIA_B, invMassA: INV_MASS_A, invMassB: INV_MASS_B, rAX: R_AX, rAY: R_AY, rBX: R_BX, rBY: R_BY, worldAxisX: WORLD_AXIS_X, worldAxisY: WORLD_AXIS_Y } = J;

/**
 * The frame of a joint that slides along an axis fixed in body A (prismatic, wheel), now: the
 * axis and its normal in the world, the translation of B's anchor along the axis from A's, and
 * the lever arms of an impulse along each (a1, a2 along the axis, s1, s2 across it). One record,
 * reused by every joint, which also carries the numbers the functions below give and take
 * (`speed` out; `along`, `across`, `angular` in): V8 boxes numbers passed to or returned from a
 * call it does not inline.
 */
export const axisFrame = { ax: 1, ay: 0, rAx: 0, rAy: 0, rBx: 0, rBy: 0, dx: 0, dy: 0, translation: 0, a1: 0, a2: 0, s1: 0, s2: 0, speed: 0, along: 0, across: 0, angular: 0, heldAcross: 0, heldAngular: 0 };
export type AxisFrame = typeof axisFrame;

export function currentAxisFrame(r: Float64Array, o: number, states: Float64Array, sa: number, sb: number): AxisFrame {
  const f = axisFrame;
  turnAnchors(r, o, states, sa, sb, f);
  const qAc = states[sa + DQC];
  const qAs = states[sa + DQS];
  f.ax = qAc * r[o + WORLD_AXIS_X] - qAs * r[o + WORLD_AXIS_Y];
  f.ay = qAs * r[o + WORLD_AXIS_X] + qAc * r[o + WORLD_AXIS_Y];
  f.dx = states[sb + DPX] - states[sa + DPX] + r[o + DELTA_CENTER_X] + f.rBx - f.rAx;
  f.dy = states[sb + DPY] - states[sa + DPY] + r[o + DELTA_CENTER_Y] + f.rBy - f.rAy;
  fillArms(f);
  return f;
}

/** The frame at the step's start, from the prepared fields alone. */
export function startAxisFrame(r: Float64Array, o: number): AxisFrame {
  const f = axisFrame;
  f.rAx = r[o + R_AX];
  f.rAy = r[o + R_AY];
  f.rBx = r[o + R_BX];
  f.rBy = r[o + R_BY];
  f.ax = r[o + WORLD_AXIS_X];
  f.ay = r[o + WORLD_AXIS_Y];
  f.dx = r[o + DELTA_CENTER_X] + f.rBx - f.rAx;
  f.dy = r[o + DELTA_CENTER_Y] + f.rBy - f.rAy;
  fillArms(f);
  return f;
}

function fillArms(f: AxisFrame): void {
  const { ax, ay } = f;
  f.translation = ax * f.dx + ay * f.dy;
  // Lever arms: A's from its centre to B's anchor (d + rA), B's from its centre (rB).
  const ux = f.dx + f.rAx;
  const uy = f.dy + f.rAy;
  f.a1 = ux * ay - uy * ax;
  f.a2 = f.rBx * ay - f.rBy * ax;
  // Across the axis, n = (-ay, ax).
  f.s1 = ux * ax + uy * ay;
  f.s2 = f.rBx * ax + f.rBy * ay;
  f.heldAcross = 0;
  f.heldAngular = 0;
}

/** Relative speed along the axis, into f.speed. */
export function axialSpeed(states: Float64Array, sa: number, sb: number, f: AxisFrame): void {
  f.speed = f.ax * (states[sb + VX] - states[sa + VX]) + f.ay * (states[sb + VY] - states[sa + VY]) + f.a2 * states[sb + W] - f.a1 * states[sa + W];
}

/** Relative speed across the axis, into f.speed. */
export function normalSpeed(states: Float64Array, sa: number, sb: number, f: AxisFrame): void {
  f.speed = -f.ay * (states[sb + VX] - states[sa + VX]) + f.ax * (states[sb + VY] - states[sa + VY]) + f.s2 * states[sb + W] - f.s1 * states[sa + W];
}

/** An impulse of `along` on the axis and `across` it, and an angular impulse, on B (A takes the opposite); see push. */
function applyAxisImpulse(r: Float64Array, o: number, states: Float64Array, sa: number, sb: number, f: AxisFrame): void {
  const along = f.along;
  const across = f.across;
  const angular = f.angular;
  const px = along * f.ax - across * f.ay;
  const py = along * f.ay + across * f.ax;
  const mA = r[o + INV_MASS_A];
  const mB = r[o + INV_MASS_B];
  // No moment on a body that does not turn (see warmStartPoint).
  const iA = r[o + INV_INERTIA_A];
  const iB = r[o + INV_INERTIA_B];
  states[sa + VX] -= mA * px;
  states[sa + VY] -= mA * py;
  if (iA !== 0) states[sa + W] -= iA * (along * f.a1 + across * f.s1 + angular);
  states[sb + VX] += mB * px;
  states[sb + VY] += mB * py;
  if (iB !== 0) states[sb + W] += iB * (along * f.a2 + across * f.s2 + angular);
  holdPushed(states, sa, sb);
}

/**
 * A slider's effective mass along its axis with its constraints across the axis and in angle
 * held, into the record's axial mass; and the impulses across the axis and in angle, per unit of
 * impulse along it, that hold them meanwhile, into f.heldAcross and f.heldAngular, for pushAlong.
 *
 * A limit, motor or spring that pushed along the axis alone, with the mass of the bodies' motion
 * along it (their spins about their centres included, as Box2D's prismatic joint does), would be
 * partly undone by the block across it wherever B's anchor lies off its centre: the push turns
 * the body, the angle's constraint turns it back, and what stopped it along the axis goes with the
 * turn. A slider whose anchor lay 0.5 from its centre, launched at 20 m/s into its limit 1 away,
 * went 1.21 out; 2 from its centre at 60 m/s, 7.0. Within the block K of (along, across, angle),
 * the response along the axis with the rest held is the Schur complement det K / det K2 of the
 * held block K2, and the held impulses per unit along are -K2^-1 k (pinnedTurn in
 * revolute-joint.ts is the pin's version). With m = mA + mB and the arms a1, a2 along and s1, s2
 * across (see fillArms), both determinants are sums of positive terms (Cauchy-Binet), so far arms
 * lose no digits to cancellation:
 *
 *   det K2 = m (iA + iB) + iA iB (s1 - s2)^2
 *   det K  = m^2 (iA + iB) + m iA iB ((s1 - s2)^2 + (a1 - a2)^2)
 *
 * Where they fail (neither body turns, or not finite), the push is along the axis alone.
 */
export function holdAcross(r: Float64Array, o: number, f: AxisFrame): void {
  const mA = r[o + INV_MASS_A];
  const mB = r[o + INV_MASS_B];
  const iA = r[o + INV_INERTIA_A];
  const iB = r[o + INV_INERTIA_B];
  const { a1, a2, s1, s2 } = f;
  const m = mA + mB;
  const iAB = iA * iB;
  const ds = s1 - s2;
  const da = a1 - a2;
  const det2 = m * (iA + iB) + iAB * ds * ds;
  const det3 = m * (m * (iA + iB) + iAB * (ds * ds + da * da));
  const mass = det2 / det3;
  const across = (-iAB * da * ds) / det2;
  const angular = -(m * (iA * a1 + iB * a2) + iAB * ds * (s1 * a2 - s2 * a1)) / det2;
  if (mass > 0 && mass < Infinity && Number.isFinite(across) && Number.isFinite(angular)) {
    r[o + AXIAL_MASS] = mass;
    f.heldAcross = across;
    f.heldAngular = angular;
  } else {
    const k = m + iA * a1 * a1 + iB * a2 * a2;
    r[o + AXIAL_MASS] = k > 0 ? 1 / k : 0;
    f.heldAcross = 0;
    f.heldAngular = 0;
  }
}

/**
 * Applies an impulse f.along along the axis, with the impulses across it and in angle that
 * f.heldAcross and f.heldAngular give per unit along: a slider's block held (see holdAcross),
 * none for a wheel, whose frame leaves them 0.
 */
export function pushAlong(r: Float64Array, o: number, states: Float64Array, sa: number, sb: number, f: AxisFrame): void {
  // Exactly +0 where nothing is held, as a push along the axis alone has always had.
  f.across = f.heldAcross === 0 ? 0 : f.along * f.heldAcross;
  f.angular = f.heldAngular === 0 ? 0 : f.along * f.heldAngular;
  applyAxisImpulse(r, o, states, sa, sb, f);
}

/** Applies f.along, f.across and f.angular. */
export function push(r: Float64Array, o: number, states: Float64Array, sa: number, sb: number, f: AxisFrame): void {
  applyAxisImpulse(r, o, states, sa, sb, f);
}

/** The spring along the axis, towards translation 0 (prismatic, wheel). */
export function axialSpring(r: Float64Array, o: number, states: Float64Array, sa: number, sb: number, f: AxisFrame): void {
  axialSpeed(states, sa, sb, f);
  const accumulated = r[o + SPRING_IMPULSE_SUM];
  const impulse = -r[o + SPRING_MASS] * r[o + AXIAL_MASS] * (f.speed + r[o + SPRING_BIAS] * f.translation) - r[o + SPRING_IMPULSE] * accumulated;
  r[o + SPRING_IMPULSE_SUM] = accumulated + impulse;
  f.along = impulse;
  pushAlong(r, o, states, sa, sb, f);
}

/** The translation limits, lower then upper (prismatic, wheel). */
export function axialLimits(r: Float64Array, o: number, states: Float64Array, sa: number, sb: number, f: AxisFrame, step: JointStepContext, useBias: boolean): void {
  axialSpeed(states, sa, sb, f);
  limitIO[0] = f.translation - r[o + LOWER];
  limitIO[1] = f.speed;
  limitIO[3] = r[o + AXIAL_MASS];
  applyLimit(r, o, LOWER_IMPULSE, step, useBias);
  f.along = limitIO[2];
  pushAlong(r, o, states, sa, sb, f);
  axialSpeed(states, sa, sb, f);
  limitIO[0] = r[o + UPPER] - f.translation;
  limitIO[1] = -f.speed;
  limitIO[3] = r[o + AXIAL_MASS];
  applyLimit(r, o, UPPER_IMPULSE, step, useBias);
  f.along = -limitIO[2];
  pushAlong(r, o, states, sa, sb, f);
}
