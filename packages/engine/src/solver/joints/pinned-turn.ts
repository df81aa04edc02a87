import { J } from '../../joints/joint-layout.js';
import { DQC, DQS, VX, VY, W } from '../solver-body.js';
import { holdPushed } from './joint-kernel.js';

// The record's fields as this module's own constants, which V8 folds into the code (see J).
const { invMassA: INV_MASS_A, invMassB: INV_MASS_B, invInertiaA: INV_INERTIA_A, invInertiaB: INV_INERTIA_B, rAX: R_AX, rAY: R_AY, rBX: R_BX, rBY: R_BY, stateA: STATE_A, stateB: STATE_B } = J;

// A turn of a joint's two bodies about the point that joins them, for the joints whose anchors
// meet (revolute: its spring, motor and limits; weld: its angle).

/**
 * Where pinnedTurn leaves its results (the turn's mass, its linear impulse per unit of turn, and
 * each body's spin per unit of turn) and applyTurn takes its impulse (V8 boxes numbers passed to
 * or returned from calls it does not inline).
 */
export const turnIO = new Float64Array(6);
/**
 * pinnedIO[0]: 1 where the turn is taken about the anchors (the joint is its bodies' only one,
 * JointSolver's loneJoints), 0 where it is the spins' alone, as Box2D's. The solver sets it
 * before each joint's passes.
 */
export const pinnedIO = new Uint8Array([1]);
export const TURN_MASS = 0;
export const TURN_X = 1;
export const TURN_Y = 2;
export const TURN_IMPULSE = 3;
export const TURN_SPIN_A = 4;
export const TURN_SPIN_B = 5;

/**
 * The effective mass of the bodies' relative turn with the anchors held together, into
 * turnIO[TURN_MASS], and the linear impulse at the anchors, per unit of angular impulse on B,
 * that keeps the anchors' relative speed meanwhile, into turnIO[TURN_X..TURN_Y]; the arms now
 * into armsIO, for applyTurn.
 *
 * A limit that pushed on the turn alone, with the mass 1 / (iA + iB) of the bodies' spins about
 * their centres (as Box2D's do), would be undone by the point constraint wherever an anchor lies
 * off a centre:
 * a pendulum's bob swings about the pin, and an impulse that stops its spin leaves its speed,
 * which the pin turns back into spin (on a 5 cm disc 1 m from its pin, all but 1/801 of it).
 * The swing would then be left to the soft push back once past the limit, and a fast bob would
 * pass it by radians. Within the 3x3 block of the pin and the turn, K = [K2 k; k^T k33], the
 * turn's response with the pin held is the Schur complement s = k33 - k^T K2^-1 k =
 * det K / det K2, and the pin's impulse per unit of turn impulse is -K2^-1 k. Both
 * determinants are sums of positive terms (m = mA + mB, X = rA x rB):
 *
 *   det K2 = m (m + iA |rA|^2 + iB |rB|^2) + iA iB X^2
 *   det K  = m (m (iA + iB) + iA iB |rA - rB|^2)
 *
 * and adj(K2) k holds no difference of large terms either, so a far anchor loses no digits to
 * cancellation here. Where they still fail (not finite), the joint falls back to the spin alone.
 *
 * The spring and motor turn the bodies the same way: a motor or spring that pushed on the spin
 * alone, held by a limit that turns them about the pin, would leave the pin to carry the
 * difference, and its soft hold would give under it (0.1 m under a 1000 N m motor on a 2 m bar).
 *
 * The mass of the turn about the pin is the bodies' with nothing else holding them. Where a body
 * has another joint, it is not (a chain's links are held at both ends), and sub-step after
 * sub-step the pass overshot: two 1 x 0.25 boxes welded end to end off a wall reached 132 J in
 * ten steps and flailed, and a 5-box weld cantilever of alternating densities 10:1 blew up at
 * every scale, where Box2D's settle. There (pinnedIO[0] = 0) the turn is the spins' alone, with
 * the mass 1 / (iA + iB), as in Box2D.
 */
export function pinnedTurn(r: Float64Array, o: number, states: Float64Array): void {
  const sa = r[o + STATE_A];
  const sb = r[o + STATE_B];
  const qAc = states[sa + DQC];
  const qAs = states[sa + DQS];
  const qBc = states[sb + DQC];
  const qBs = states[sb + DQS];
  armsIO[0] = qAc * r[o + R_AX] - qAs * r[o + R_AY];
  armsIO[1] = qAs * r[o + R_AX] + qAc * r[o + R_AY];
  armsIO[2] = qBc * r[o + R_BX] - qBs * r[o + R_BY];
  armsIO[3] = qBs * r[o + R_BX] + qBc * r[o + R_BY];
  turnAbout(r, o);
}

/** pinnedTurn with the arms as the step starts: for the bound on the limits' kept impulses (JointSolver's boundImpulses). */
export function pinnedTurnAtStart(r: Float64Array, o: number): void {
  armsIO[0] = r[o + R_AX];
  armsIO[1] = r[o + R_AY];
  armsIO[2] = r[o + R_BX];
  armsIO[3] = r[o + R_BY];
  turnAbout(r, o);
}

/** The arms from each centre to the anchors, (rAx, rAy, rBx, rBy), that turnAbout and applyTurn read. */
const armsIO = new Float64Array(4);

function turnAbout(r: Float64Array, o: number): void {
  const iA = r[o + INV_INERTIA_A];
  const iB = r[o + INV_INERTIA_B];
  if (pinnedIO[0] === 0) {
    spinsAlone(iA, iB);
    return;
  }
  const mA = r[o + INV_MASS_A];
  const mB = r[o + INV_MASS_B];
  const rAx = armsIO[0];
  const rAy = armsIO[1];
  const rBx = armsIO[2];
  const rBy = armsIO[3];
  const m = mA + mB;
  const cross = rAx * rBy - rAy * rBx;
  const dx = rAx - rBx;
  const dy = rAy - rBy;
  const iAB = iA * iB;
  const det2 = m * (m + iA * (rAx * rAx + rAy * rAy) + iB * (rBx * rBx + rBy * rBy)) + iAB * cross * cross;
  const det3 = m * (m * (iA + iB) + iAB * (dx * dx + dy * dy));
  const mass = det2 / det3;
  const ux = (iAB * dx * cross + m * (iA * rAy + iB * rBy)) / det2;
  const uy = (iAB * dy * cross - m * (iA * rAx + iB * rBx)) / det2;
  // Each body's spin per unit of turn, in closed form: B's is iB (1 + rB x u), and
  // 1 + rB x u = m (m + iA rA . (rA - rB)) / det K2 (A's likewise). Computed as that difference,
  // from an anchor many radii of gyration out, it is the rounding of terms near 1 that cancel to
  // the small remainder, times the body's inverse inertia: a 9 mm triangle welded 42 m out spun
  // at 1e196 rad/s, and a revolute spring 36 m out on it reached NaN.
  const spinA = (iA * m * (m + iB * (rBx * (rBx - rAx) + rBy * (rBy - rAy)))) / det2;
  const spinB = (iB * m * (m + iA * (rAx * dx + rAy * dy))) / det2;
  if (mass > 0 && mass < Infinity && Number.isFinite(ux) && Number.isFinite(uy) && Number.isFinite(spinA) && Number.isFinite(spinB)) {
    turnIO[TURN_MASS] = mass;
    turnIO[TURN_X] = ux;
    turnIO[TURN_Y] = uy;
    turnIO[TURN_SPIN_A] = spinA;
    turnIO[TURN_SPIN_B] = spinB;
  } else spinsAlone(iA, iB);
}

/** The turn of the spins alone (Box2D's): the mass 1 / (iA + iB), no linear part. */
function spinsAlone(iA: number, iB: number): void {
  turnIO[TURN_MASS] = iA + iB > 0 ? 1 / (iA + iB) : 0;
  turnIO[TURN_X] = 0;
  turnIO[TURN_Y] = 0;
  turnIO[TURN_SPIN_A] = iA;
  turnIO[TURN_SPIN_B] = iB;
}

/**
 * The angular impulse turnIO[TURN_IMPULSE] on B (A takes the opposite), with the linear impulse
 * at the anchors that pinnedTurn found keeps their relative speed, and the spins it found. That
 * linear part is not added to the joint's kept linear impulse, which is the point's alone: the
 * kept angular impulse carries it (see warmStartTurn).
 */
export function applyTurn(r: Float64Array, o: number, states: Float64Array): void {
  const sa = r[o + STATE_A];
  const sb = r[o + STATE_B];
  const angular = turnIO[TURN_IMPULSE];
  const px = turnIO[TURN_X] * angular;
  const py = turnIO[TURN_Y] * angular;
  const mA = r[o + INV_MASS_A];
  const mB = r[o + INV_MASS_B];
  states[sa + VX] -= mA * px;
  states[sa + VY] -= mA * py;
  // No spin on a body that does not turn (see warmStartPoint); the spins from pinnedTurn's closed form.
  if (r[o + INV_INERTIA_A] !== 0) states[sa + W] -= turnIO[TURN_SPIN_A] * angular;
  states[sb + VX] += mB * px;
  states[sb + VY] += mB * py;
  if (r[o + INV_INERTIA_B] !== 0) states[sb + W] += turnIO[TURN_SPIN_B] * angular;
  holdPushed(states, sa, sb);
}

/**
 * The warm start of the angular impulse turnIO[TURN_IMPULSE] that a joint keeps apart from its
 * point's (a revolute joint's spring, motor and limits, a weld's angle): a turn about the
 * anchors, its linear part and spins taken from the arms as they lie now. Kept with the point's
 * impulse and applied as its moment, that part, from arms a sub-step old, cancelled the turn's
 * moment but for its change with the arms, which on a body whose anchor lies many radii of
 * gyration out came back as spin, times the inverse inertia, and grew at every sub-step (a
 * 9 mm triangle welded 42 m out reached 1e196 rad/s).
 */
export function warmStartTurn(r: Float64Array, o: number, states: Float64Array): void {
  if (r[o + INV_INERTIA_A] + r[o + INV_INERTIA_B] === 0) return;
  pinnedTurn(r, o, states);
  applyTurn(r, o, states);
}

/**
 * The linear impulse at the anchors that the kept angular impulse turnIO[TURN_IMPULSE] carries
 * with its turn, from the arms as the last sub-step left them, into turnIO[TURN_X..TURN_Y]: with
 * the point's, the force that holds the anchors together (the joints' reactions).
 */
export function turnLinear(r: Float64Array, o: number, states: Float64Array): void {
  const angular = turnIO[TURN_IMPULSE];
  if (angular === 0 || r[o + INV_INERTIA_A] + r[o + INV_INERTIA_B] === 0) {
    turnIO[TURN_X] = 0;
    turnIO[TURN_Y] = 0;
    return;
  }
  pinnedTurn(r, o, states);
  turnIO[TURN_X] *= angular;
  turnIO[TURN_Y] *= angular;
}
