import type { BodyStore } from '../store/body-store.js';
import { J, JOINT_STRIDE } from '../joints/joint-layout.js';
import type { IntegratorName } from '../integrate/integrator.js';
import { BODY, DPX, DPY, DYNAMIC, VX, VY } from './solver-body.js';
import { grownCapacity } from '../util/grow.js';
import { TypeCode } from '../store/body-types.js';

// The record's fields as this module's own constants, which V8 folds into the code (see J).
const { damping: DAMPING, deltaCenterX: DELTA_CENTER_X, deltaCenterY: DELTA_CENTER_Y, forceX: FORCE_X, forceY: FORCE_Y, length: LENGTH, stateA: STATE_A, stateB: STATE_B, stiffness: STIFFNESS, torque: TORQUE } = J;

/**
 * Force-driven springs (joints of kind 'spring'): Hooke's law between two bodies' centres,
 * F = k (length - rest) + c (speed apart), integrated in each sub-step of the soft step by the
 * world's integrator, as the report's section 7.4 proposes for soft bodies:
 *
 *   semi-implicit Euler  before the sub-step's velocity update: v += h F(x, v) / m, then the
 *                        solver moves the bodies with the new velocity
 *   explicit Euler       the same impulse, applied after the bodies moved with the old velocity
 *   rk4                  classical Runge-Kutta over the sub-step, of the bodies on springs under
 *                        their springs and gravity alone: their velocity takes its increment
 *                        (less gravity's, which the sub-step adds as for every body), and their
 *                        motion its position increment (as a correction after the solver moved
 *                        them with their velocity)
 *
 * Contacts and joints act on top within the same sub-step, as impulses after the springs
 * (operator splitting): Runge-Kutta's order holds for the springs between collisions, and a
 * contact changes a velocity at once whatever the integrator.
 */
export class ForceSprings {
  private joints = new Int32Array(0);
  private count = 0;
  /** Per solver state: its member index, or -1; members are the moving bodies on springs. */
  private memberOf = new Int32Array(0);
  private members = new Int32Array(0);
  private memberCount = 0;
  /** Per member: gravity (0 but for dynamic bodies), inverse mass, and the Runge-Kutta buffers. */
  private buffers = new Float64Array(0);

  /** Once per step: the live spring joints (slots), whose common fields JointSolver.prepare set. */
  prepare(store: { record: Float64Array }, joints: Int32Array, count: number, stateCount: number, bodies: BodyStore, slotOfState: Int32Array, gx: number, gy: number): void {
    if (this.joints.length < count) this.joints = new Int32Array(grownCapacity(this.joints.length, count));
    this.joints.set(joints.subarray(0, count));
    this.count = count;
    if (this.memberOf.length < stateCount) {
      const capacity = grownCapacity(this.memberOf.length, stateCount);
      this.memberOf = new Int32Array(capacity);
      this.members = new Int32Array(capacity);
    }
    this.memberOf.fill(-1, 0, stateCount);
    let n = 0;
    const r = store.record;
    for (let k = 0; k < count; k++) {
      const o = joints[k] * JOINT_STRIDE;
      n = this.join(r[o + STATE_A] / BODY, n);
      n = this.join(r[o + STATE_B] / BODY, n);
    }
    this.memberCount = n;
    if (this.buffers.length < n * MEMBER) this.buffers = new Float64Array(grownCapacity(this.buffers.length / MEMBER, n) * MEMBER);
    const b = this.buffers;
    for (let m = 0; m < n; m++) {
      const slot = slotOfState[this.members[m] - 1];
      const gravity = bodies.type[slot] === TypeCode.dynamic ? bodies.gravityScale[slot] : 0;
      b[m * MEMBER + INV_MASS] = bodies.invMass[slot];
      b[m * MEMBER + GX] = gx * gravity;
      b[m * MEMBER + GY] = gy * gravity;
    }
  }

  /** Makes solver state `state` a member (the fixed dummy, 0, never is); returns the member count. */
  private join(state: number, n: number): number {
    if (state === 0 || this.memberOf[state] >= 0) return n;
    this.memberOf[state] = n;
    this.members[n] = state;
    return n + 1;
  }

  /** Before the sub-step's velocity update; limits[0] is the soft step's speed limit. */
  before(r: Float64Array, states: Float64Array, step: { h: number }, integrator: IntegratorName, limits: Float64Array): void {
    if (this.count === 0) return;
    if (integrator === 'rk4') this.rungeKutta(r, states, step, limits);
    else this.euler(r, states, step, integrator === 'explicit-euler', limits[0]);
  }

  /** After the solver moved the bodies: explicit Euler's impulse, Runge-Kutta's position correction. */
  after(states: Float64Array, integrator: IntegratorName, limits: Float64Array): void {
    if (this.count === 0 || integrator === 'semi-implicit-euler') return;
    const maxSpeed = limits[0];
    const b = this.buffers;
    for (let m = 0; m < this.memberCount; m++) {
      const s = this.members[m] * BODY;
      const at = m * MEMBER;
      if (integrator === 'rk4') {
        states[s + DPX] += b[at + CORRECT_X];
        states[s + DPY] += b[at + CORRECT_Y];
      } else if (states[s + DYNAMIC] === 1) {
        states[s + VX] = held(states[s + VX] + b[at + AX], maxSpeed);
        states[s + VY] = held(states[s + VY] + b[at + AY], maxSpeed);
      }
    }
  }

  /**
   * After the step: each spring's force on B (A takes the opposite), from where the bodies are
   * at its end, for getJoint and breaking.
   */
  finish(r: Float64Array, states: Float64Array): void {
    for (let k = 0; k < this.count; k++) {
      const o = this.joints[k] * JOINT_STRIDE;
      const sa = r[o + STATE_A];
      const sb = r[o + STATE_B];
      io[DX] = states[sb + DPX] - states[sa + DPX];
      io[DY] = states[sb + DPY] - states[sa + DPY];
      io[DVX] = states[sb + VX] - states[sa + VX];
      io[DVY] = states[sb + VY] - states[sa + VY];
      tension(r, o);
      r[o + FORCE_X] = -io[PULL] * io[UNIT_X];
      r[o + FORCE_Y] = -io[PULL] * io[UNIT_Y];
      r[o + TORQUE] = 0;
    }
  }

  memoryBytes(): number {
    return this.joints.byteLength + this.memberOf.byteLength * 2 + this.buffers.byteLength;
  }

  /** One evaluation at the sub-step's start: semi-implicit applies it now, explicit after the move. */
  private euler(r: Float64Array, states: Float64Array, step: { h: number }, explicit: boolean, maxSpeed: number): void {
    const h = step.h;
    const b = this.buffers;
    const n = this.memberCount;
    for (let m = 0; m < n; m++) {
      const s = this.members[m] * BODY;
      const at = m * MEMBER;
      b[at + PX] = states[s + DPX];
      b[at + PY] = states[s + DPY];
      b[at + SVX] = states[s + VX];
      b[at + SVY] = states[s + VY];
    }
    this.accelerations(r, false);
    for (let m = 0; m < n; m++) {
      const s = this.members[m] * BODY;
      const at = m * MEMBER;
      const dvx = h * b[at + AX];
      const dvy = h * b[at + AY];
      if (explicit) {
        b[at + AX] = dvx;
        b[at + AY] = dvy;
      } else if (states[s + DYNAMIC] === 1) {
        states[s + VX] = held(states[s + VX] + dvx, maxSpeed);
        states[s + VY] = held(states[s + VY] + dvy, maxSpeed);
      }
    }
  }

  /**
   * Past its stability limit (omega h about 2.8) Runge-Kutta's stages grow without bound; the
   * stages' velocities are held to the speed limit and the position correction to a sub-step's
   * travel at it, so that a spring too stiff for the step blows up within the speed limit, as
   * every other body does, never to infinity.
   */
  private rungeKutta(r: Float64Array, states: Float64Array, step: { h: number }, limits: Float64Array): void {
    const h = step.h;
    const maxSpeed = limits[0];
    const b = this.buffers;
    const n = this.memberCount;
    for (let m = 0; m < n; m++) {
      const s = this.members[m] * BODY;
      const at = m * MEMBER;
      b[at + X0] = states[s + DPX];
      b[at + Y0] = states[s + DPY];
      b[at + VX0] = states[s + VX];
      b[at + VY0] = states[s + VY];
      b[at + SUM_X] = 0;
      b[at + SUM_Y] = 0;
      b[at + SUM_VX] = 0;
      b[at + SUM_VY] = 0;
      b[at + PX] = b[at + X0];
      b[at + PY] = b[at + Y0];
      b[at + SVX] = b[at + VX0];
      b[at + SVY] = b[at + VY0];
    }
    // Stages 1 to 4: k = f(state), weighted 1, 2, 2, 1; the next stage's state is the start plus
    // h/2, h/2 and h times this k.
    for (let stage = 0; stage < 4; stage++) {
      this.accelerations(r, true);
      const weight = stage === 0 || stage === 3 ? 1 : 2;
      const ahead = stage < 2 ? 0.5 * h : h;
      for (let m = 0; m < n; m++) {
        const at = m * MEMBER;
        const kx = b[at + SVX];
        const ky = b[at + SVY];
        const kvx = b[at + AX];
        const kvy = b[at + AY];
        b[at + SUM_X] += weight * kx;
        b[at + SUM_Y] += weight * ky;
        b[at + SUM_VX] += weight * kvx;
        b[at + SUM_VY] += weight * kvy;
        if (stage < 3) {
          b[at + PX] = b[at + X0] + ahead * kx;
          b[at + PY] = b[at + Y0] + ahead * ky;
          const svx = b[at + VX0] + ahead * kvx;
          const svy = b[at + VY0] + ahead * kvy;
          b[at + SVX] = held(svx, maxSpeed);
          b[at + SVY] = held(svy, maxSpeed);
        }
      }
    }
    const sixth = h / 6;
    for (let m = 0; m < n; m++) {
      const s = this.members[m] * BODY;
      const at = m * MEMBER;
      const dx = sixth * b[at + SUM_X];
      const dy = sixth * b[at + SUM_Y];
      let vx = b[at + VX0];
      let vy = b[at + VY0];
      if (states[s + DYNAMIC] === 1) {
        // The sub-step adds gravity's h g itself, as for every body.
        vx = held(vx + sixth * b[at + SUM_VX] - h * b[at + GX], maxSpeed);
        vy = held(vy + sixth * b[at + SUM_VY] - h * b[at + GY], maxSpeed);
        states[s + VX] = vx;
        states[s + VY] = vy;
        vx += h * b[at + GX];
        vy += h * b[at + GY];
      }
      // The solver will move the body by h v; the rest of Runge-Kutta's increment comes after.
      const most = h * maxSpeed;
      const cx = dx - h * vx;
      const cy = dy - h * vy;
      b[at + CORRECT_X] = held(cx, most);
      b[at + CORRECT_Y] = held(cy, most);
    }
  }

  /** Each member's acceleration at the stage state (PX, PY, SVX, SVY) into AX, AY; with gravity for Runge-Kutta's stages. */
  private accelerations(r: Float64Array, gravity: boolean): void {
    const b = this.buffers;
    const { memberOf } = this;
    const n = this.memberCount;
    for (let m = 0; m < n; m++) {
      const at = m * MEMBER;
      b[at + AX] = gravity ? b[at + GX] : 0;
      b[at + AY] = gravity ? b[at + GY] : 0;
    }
    for (let k = 0; k < this.count; k++) {
      const o = this.joints[k] * JOINT_STRIDE;
      const ma = memberOf[r[o + STATE_A] / BODY];
      const mb = memberOf[r[o + STATE_B] / BODY];
      const a = ma * MEMBER;
      const c = mb * MEMBER;
      const pax = ma < 0 ? 0 : b[a + PX];
      const pay = ma < 0 ? 0 : b[a + PY];
      const vax = ma < 0 ? 0 : b[a + SVX];
      const vay = ma < 0 ? 0 : b[a + SVY];
      const pbx = mb < 0 ? 0 : b[c + PX];
      const pby = mb < 0 ? 0 : b[c + PY];
      const vbx = mb < 0 ? 0 : b[c + SVX];
      const vby = mb < 0 ? 0 : b[c + SVY];
      io[DX] = pbx - pax;
      io[DY] = pby - pay;
      io[DVX] = vbx - vax;
      io[DVY] = vby - vay;
      tension(r, o);
      const fx = io[PULL] * io[UNIT_X];
      const fy = io[PULL] * io[UNIT_Y];
      if (ma >= 0) {
        b[a + AX] += fx * b[a + INV_MASS];
        b[a + AY] += fy * b[a + INV_MASS];
      }
      if (mb >= 0) {
        b[c + AX] -= fx * b[c + INV_MASS];
        b[c + AY] -= fy * b[c + INV_MASS];
      }
    }
  }
}

/**
 * tension's input, B's centre's move from A's since the step's start and its speed away (DX, DY,
 * DVX, DVY), and its output, the pull (positive: B drawn towards A) and the unit vector from A's
 * centre to B's: numbers pass through this array, which V8 would box as arguments and results of
 * a call it does not inline.
 */
const io = new Float64Array(7);
const DX = 0;
const DY = 1;
const DVX = 2;
const DVY = 3;
const PULL = 4;
const UNIT_X = 5;
const UNIT_Y = 6;

function tension(r: Float64Array, o: number): void {
  const x = r[o + DELTA_CENTER_X] + io[DX];
  const y = r[o + DELTA_CENTER_Y] + io[DY];
  const length = Math.sqrt(x * x + y * y);
  if (!(length > 0)) {
    io[UNIT_X] = 0;
    io[UNIT_Y] = 0;
    io[PULL] = 0;
    return;
  }
  io[UNIT_X] = x / length;
  io[UNIT_Y] = y / length;
  io[PULL] = r[o + STIFFNESS] * (length - r[o + LENGTH]) + r[o + DAMPING] * (io[DVX] * io[UNIT_X] + io[DVY] * io[UNIT_Y]);
}

/** Doubles per member in `buffers`. */
const INV_MASS = 0;
const GX = 1;
const GY = 2;
const X0 = 3;
const Y0 = 4;
const VX0 = 5;
const VY0 = 6;
/** The stage's state, and its acceleration. */
const PX = 7;
const PY = 8;
const SVX = 9;
const SVY = 10;
const AX = 11;
const AY = 12;
const SUM_X = 13;
const SUM_Y = 14;
const SUM_VX = 15;
const SUM_VY = 16;
const CORRECT_X = 17;
const CORRECT_Y = 18;
const MEMBER = 19;

/**
 * A velocity component held within the soft step's speed limit. A spring too stiff for the step
 * (or on a body too light for it) gives an increment the joints solved next would overflow on;
 * held here, the spring blows up within the limit, as every other body does.
 */
function held(v: number, most: number): number {
  return v > most ? most : v < -most ? -most : v;
}
