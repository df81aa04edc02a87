import type { BodyStore } from '../store/body-store.js';
import { TypeCode } from '../store/body-types.js';
import { J, JOINT_STRIDE } from '../joints/joint-layout.js';
import type { JointStore } from '../joints/joint-store.js';
import { BODY, DPX, DPY, DYNAMIC, VX, VY } from './solver-body.js';
import { grownCapacity } from '../util/grow.js';

// The record's fields as this module's own constants, which V8 folds into the code (see J).
const { length: LENGTH, stiffness: STIFFNESS } = J;

/** The area a ring may be squeezed to, as a fraction of its rest area, before its pressure stops rising. */
const LEAST_AREA = 0.05;

/**
 * Gas pressure inside rings of bodies (joints of kind 'pressure'): the pressure blob of soft-body
 * simulators. A ring's gas follows the ideal gas law at a constant temperature, P = p0 A0 / A,
 * with A the polygon area of its bodies' centres now and A0 at rest (when made); P pushes each
 * edge outwards with P times its length, shared by its two ends. Applied in each sub-step of the
 * soft step as an impulse before the velocity update (semi-implicit), as force springs are.
 * The area from the shoelace formula needs no square root: an edge's outward normal scaled by its
 * length is the edge turned a quarter turn, its sense set by the area's sign.
 */
export class GasPressure {
  private joints = new Int32Array(0);
  private count = 0;
  /** Per ring member, in ring order: its solver state's offset and its position at the step's start. */
  private state = new Int32Array(0);
  private baseX = new Float64Array(0);
  private baseY = new Float64Array(0);
  private invMass = new Float64Array(0);
  /** Per ring member, its position in the current sub-step. */
  private px = new Float64Array(0);
  private py = new Float64Array(0);
  private start = new Int32Array(0);

  prepare(store: JointStore, joints: Int32Array, count: number, bodies: BodyStore, index: Int32Array): void {
    if (this.joints.length < count) {
      this.joints = new Int32Array(grownCapacity(this.joints.length, count));
      this.start = new Int32Array(this.joints.length + 1);
    }
    this.joints.set(joints.subarray(0, count));
    this.count = count;
    let members = 0;
    for (let k = 0; k < count; k++) members += store.ring(joints[k]).length;
    if (this.state.length < members) {
      const capacity = grownCapacity(this.state.length, members);
      this.state = new Int32Array(capacity);
      this.baseX = new Float64Array(capacity);
      this.baseY = new Float64Array(capacity);
      this.invMass = new Float64Array(capacity);
      this.px = new Float64Array(capacity);
      this.py = new Float64Array(capacity);
    }
    let m = 0;
    for (let k = 0; k < count; k++) {
      this.start[k] = m;
      const ring = store.ring(joints[k]);
      for (let i = 0; i < ring.length; i++, m++) {
        const slot = ring[i];
        const moving = index[slot];
        this.state[m] = moving * BODY;
        this.baseX[m] = bodies.x[slot];
        this.baseY[m] = bodies.y[slot];
        this.invMass[m] = moving !== 0 && bodies.type[slot] === TypeCode.dynamic ? bodies.invMass[slot] : 0;
      }
    }
    this.start[count] = m;
  }

  /** Each sub-step, before the velocity update: every ring's pressure on its bodies over h. */
  apply(r: Float64Array, states: Float64Array, step: { h: number }): void {
    const h = step.h;
    const { state, baseX, baseY, invMass, start, px, py } = this;
    for (let k = 0; k < this.count; k++) {
      const o = this.joints[k] * JOINT_STRIDE;
      const from = start[k];
      const to = start[k + 1];
      // Where each body is now, once (only velocities change below), and the shoelace sum.
      const x0 = baseX[from] + states[state[from] + DPX];
      const y0 = baseY[from] + states[state[from] + DPY];
      px[from] = x0;
      py[from] = y0;
      let twice = 0;
      let xi = x0;
      let yi = y0;
      for (let j = from + 1; j < to; j++) {
        const xj = baseX[j] + states[state[j] + DPX];
        const yj = baseY[j] + states[state[j] + DPY];
        px[j] = xj;
        py[j] = yj;
        twice += xi * yj - xj * yi;
        xi = xj;
        yi = yj;
      }
      twice += xi * y0 - x0 * yi;
      const rest = r[o + LENGTH];
      const area = Math.max(Math.abs(0.5 * twice), LEAST_AREA * rest);
      // The pressure, with the sense of the ring's winding folded in: (ey, -ex) points out of a
      // ring of positive area, (-ey, ex) out of one of negative area. The areas' ratio first, at
      // most 1 / LEAST_AREA: the pressure times an area 1e212 wide (a ring 1e106 across) is past
      // the largest double.
      const p = (twice >= 0 ? 1 : -1) * r[o + STIFFNESS] * (rest / area);
      const share = 0.5 * h * p;
      for (let i = from; i < to; i++) {
        const j = i + 1 === to ? from : i + 1;
        const ex = px[j] - px[i];
        const ey = py[j] - py[i];
        const ix = share * ey;
        const iy = -share * ex;
        const si = state[i];
        const sj = state[j];
        if (states[si + DYNAMIC] === 1) {
          states[si + VX] += invMass[i] * ix;
          states[si + VY] += invMass[i] * iy;
        }
        if (states[sj + DYNAMIC] === 1) {
          states[sj + VX] += invMass[j] * ix;
          states[sj + VY] += invMass[j] * iy;
        }
      }
    }
  }

  memoryBytes(): number {
    return this.joints.byteLength + this.start.byteLength + this.state.byteLength + this.baseX.byteLength * 5;
  }
}
