import { J, JOINT_STRIDE } from '../../joints/joint-layout.js';
import { grownCapacity } from '../../util/grow.js';
import { BODY, DPX, DPY, DYNAMIC, VX, VY } from '../solver-body.js';
import { softSpring, Spring } from '../spring-frequency.js';
import type { SoftStepKernel } from '../soft-step-kernel.js';
import type { BodyStore } from '../../store/body-store.js';
import type { JointStore } from '../../joints/joint-store.js';

// The record's fields as this module's own constants, which V8 folds into the code (see J).
const { anchorAX: ANCHOR_AX, anchorAY: ANCHOR_AY, anchorBX: ANCHOR_BX, anchorBY: ANCHOR_BY, axialImpulse: AXIAL_IMPULSE, dampingRatio: DAMPING_RATIO, enableLimit: ENABLE_LIMIT, hertz: HERTZ, length: LENGTH_FIELD, maxLength: MAX_LENGTH, minLength: MIN_LENGTH, lowerImpulse: LOWER_IMPULSE, springImpulseSum: SPRING_IMPULSE_SUM, forceX: FORCE_X, forceY: FORCE_Y, torque: TORQUE, upperImpulse: UPPER_IMPULSE, worldAxisX: WORLD_AXIS_X, worldAxisY: WORLD_AXIS_Y } = J;

// A lane's fields. Lanes are stored in pairs, field by field, the two of a pair side by side, as
// the contacts are (soft-step.ts): field F of lane i is at (i >> 1) * LANE_PAIR + (i & 1) + F,
// so that assembly/point-distance-joints.ts loads a field of both lanes with one instruction.
const MA = 0;
const MB = 2;
/** Centre of B less centre of A at the step's start. */
const DCX = 4;
const DCY = 6;
/** The axis at the step's start, kept where the centres meet. */
const AX = 8;
const AY = 10;
const MASS = 12;
const LENGTH = 14;
/** The impulse kept for the warm start: the rigid joint's, or its spring's. */
const IMPULSE = 16;
/** Bias rate, mass scale and impulse scale of the biased pass; RELAX fields later, the relax pass's. */
const BIAS = 18;
const SCALE = 20;
const KEEP = 22;
const RELAX = 6;
export const LANE_PAIR = 30;

/** A spring joint's numbers in and softness out over the sub-step (see softSpring). */
const spring = new Float64Array(8);

/** Colours 0..COLOURS-1 hold joints that share no moving body; OVERFLOW, the rest, a pair each. */
const COLOURS = 31;
const OVERFLOW = COLOURS;
/** The colours as bits. */
const COLOUR_MASK = 2 ** COLOURS - 1;

/**
 * Whether the distance joint at record offset `o`, between bodies a and b, is a point joint this
 * module solves: both anchors at their bodies' centres of mass (the particles of ropes, jellies
 * and blobs, which no turn moves and on which the joint exerts no torque), and either rigid or a
 * spring without a range, so that one impulse, one softness and no limit describe it.
 */
export function isPointDistanceJoint(r: Float64Array, o: number, bodies: BodyStore, a: number, b: number): boolean {
  if (a < 0) return false;
  const { localCenterX, localCenterY } = bodies.rigid!;
  if (r[o + ANCHOR_AX] !== localCenterX[a] || r[o + ANCHOR_AY] !== localCenterY[a] || r[o + ANCHOR_BX] !== localCenterX[b] || r[o + ANCHOR_BY] !== localCenterY[b]) return false;
  if (r[o + ENABLE_LIMIT] === 0) return true;
  return r[o + HERTZ] > 0 && r[o + MIN_LENGTH] === 0 && r[o + MAX_LENGTH] === Infinity && r[o + LOWER_IMPULSE] === 0 && r[o + UPPER_IMPULSE] === 0;
}

/**
 * The point distance joints of a soft step (see isPointDistanceJoint), coloured like Box2D v3's
 * constraint graph: each colour holds joints that share no moving body, so the joints of a
 * colour are independent and are solved two at a time by the soft step's WebAssembly kernel
 * (assembly/point-distance-joints.ts), or one after the other by the loops below with the same
 * bits. Colours are taken greedily in slot order, which depends on the calls that made the joints
 * alone: the same bits with every broad-phase and thread count.
 *
 * Why: a ring or lattice of springs solved in slot order is one long chain of dependent
 * arithmetic (each joint waits for its neighbour's write), which left the processor idle; a
 * blob scene of 10,000 particles spent most of its step there.
 */
export class PointDistanceJoints {
  /** Lane data (LANE_PAIR doubles per pair of lanes) and each lane's two solver states. */
  private rows = new Float64Array(0);
  private pairs = new Int32Array(0);
  /** Each lane's joint slot, or -1 for an empty lane that closes a colour. */
  private slotOfLane = new Int32Array(0);
  /** Each joint's lane, by its place in prepare's lists (slot order). */
  private laneOf = new Int32Array(0);
  /** prepare's joints in slot order, for finish. */
  private slots: Int32Array = new Int32Array(0);
  private jointCount = 0;
  private laneCount = 0;
  private colourOf = new Uint8Array(0);
  private used = new Uint32Array(0);
  private readonly colourStart = new Int32Array(COLOURS + 2);
  private kernel: SoftStepKernel | null = null;

  get count(): number {
    return this.laneCount;
  }

  /**
   * Once per step, in place of the other joints' preparation: `slots[0..count)` are the point
   * joints in slot order, `stateA` and `stateB` their bodies' solver states (0: fixed); `soft` is
   * the rigid joints' softness over a sub-step h; `maxSpeed`, the speed limit that bounds a kept
   * impulse (see JointSolver's boundImpulses).
   */
  prepare(store: JointStore, bodies: BodyStore, slots: Int32Array, stateA: Int32Array, stateB: Int32Array, count: number, stateCount: number, h: number, soft: Float64Array, maxSpeed: number, kernel: SoftStepKernel | null): void {
    this.kernel = kernel;
    this.slots = slots;
    this.jointCount = count;
    this.colour(slots, stateA, stateB, count, stateCount);
    const lanes = this.laneCount;
    const rowsNeeded = (lanes >> 1) * LANE_PAIR;
    if (kernel !== null) {
      kernel.reserveJoints(rowsNeeded, 2 * lanes);
      this.rows = kernel.jointRows;
      this.pairs = kernel.jointPairs;
    } else {
      if (this.rows.length < rowsNeeded) this.rows = new Float64Array(grownCapacity(this.rows.length, rowsNeeded));
      if (this.pairs.length < 2 * lanes) this.pairs = new Int32Array(grownCapacity(this.pairs.length, 2 * lanes));
    }
    const { rows, pairs, slotOfLane, laneOf } = this;
    const r = store.record;
    const { x, y, invMass } = bodies;
    // What `spring` holds the softness of; -1, never a hertz, before the first.
    let lastHertz = -1;
    let lastZeta = -1;
    for (let i = 0; i < lanes; i++) {
      if (slotOfLane[i] >= 0) continue;
      const c = (i >> 1) * LANE_PAIR + (i & 1);
      pairs[2 * i] = 0;
      pairs[2 * i + 1] = 0;
      for (let f = 0; f < LANE_PAIR; f += 2) rows[c + f] = 0;
    }
    // In slot order, writing each joint into its lane: the joint records, far larger than the
    // lanes, are then read front to back once, where lane order jumped between them (a lattice
    // of 57,000 springs missed the cache at nearly every joint).
    for (let k = 0; k < count; k++) {
      const i = laneOf[k];
      const c = (i >> 1) * LANE_PAIR + (i & 1);
      const j = slots[k];
      const ia = stateA[k];
      const ib = stateB[k];
      const a = store.bodyA[j];
      const b = store.bodyB[j];
      const o = j * JOINT_STRIDE;
      pairs[2 * i] = ia;
      pairs[2 * i + 1] = ib;
      const mA = ia === 0 ? 0 : invMass[a];
      const mB = ib === 0 ? 0 : invMass[b];
      rows[c + MA] = mA;
      rows[c + MB] = mB;
      const dx = x[b] - x[a];
      const dy = y[b] - y[a];
      rows[c + DCX] = dx;
      rows[c + DCY] = dy;
      const length = Math.sqrt(dx * dx + dy * dy);
      const ax = length > 0 ? dx / length : 1;
      const ay = length > 0 ? dy / length : 0;
      rows[c + AX] = ax;
      rows[c + AY] = ay;
      const inverseMass = mA + mB;
      rows[c + MASS] = inverseMass > 0 ? 1 / inverseMass : 0;
      rows[c + LENGTH] = r[o + LENGTH_FIELD];
      // A kept impulse stays within what could change the bodies' relative speed by twice the
      // speed limit in a sub-step (see JointSolver's boundImpulses).
      const most = inverseMass > 0 ? (2 * maxSpeed) / inverseMass : 0;
      const rigid = r[o + ENABLE_LIMIT] === 0;
      const kept = r[o + (rigid ? AXIAL_IMPULSE : SPRING_IMPULSE_SUM)];
      rows[c + IMPULSE] = kept > most ? most : kept < -most ? -most : kept;
      if (rigid) {
        rows[c + BIAS] = soft[0];
        rows[c + SCALE] = soft[1];
        rows[c + KEEP] = soft[2];
        // The relax pass removes the bias's velocity and keeps nothing back.
        rows[c + RELAX + BIAS] = 0;
        rows[c + RELAX + SCALE] = 1;
        rows[c + RELAX + KEEP] = 0;
      } else {
        // Soft bodies' springs mostly share their hertz and damping ratio: the softness of the
        // last spring serves the next one with the same two (softSpring is a function of them and h).
        const hertz = r[o + HERTZ];
        const zeta = r[o + DAMPING_RATIO];
        if (hertz !== lastHertz || zeta !== lastZeta) {
          spring[Spring.hertz] = hertz;
          spring[Spring.zeta] = zeta;
          spring[Spring.h] = h;
          softSpring(spring);
          lastHertz = hertz;
          lastZeta = zeta;
        }
        rows[c + BIAS] = rows[c + RELAX + BIAS] = spring[Spring.bias];
        rows[c + SCALE] = rows[c + RELAX + SCALE] = spring[Spring.massScale];
        rows[c + KEEP] = rows[c + RELAX + KEEP] = spring[Spring.impulseScale];
      }
    }
  }

  /** Greedy colours by moving body, then lanes by colour: each colour in slot order, padded to whole pairs. */
  private colour(slots: Int32Array, stateA: Int32Array, stateB: Int32Array, count: number, stateCount: number): void {
    if (this.used.length < stateCount) this.used = new Uint32Array(grownCapacity(this.used.length, stateCount));
    if (this.colourOf.length < count) this.colourOf = new Uint8Array(grownCapacity(this.colourOf.length, count));
    const { used, colourOf, colourStart } = this;
    used.fill(0, 0, stateCount);
    colourStart.fill(0);
    for (let k = 0; k < count; k++) {
      const ia = stateA[k];
      const ib = stateB[k];
      // The lowest colour free for both: the lowest clear bit of what they use.
      const free = ~((ia === 0 ? 0 : used[ia]) | (ib === 0 ? 0 : used[ib])) & COLOUR_MASK;
      const colour = free === 0 ? OVERFLOW : 31 - Math.clz32(free & -free);
      if (colour !== OVERFLOW) {
        used[ia] |= 1 << colour;
        used[ib] |= 1 << colour;
      }
      colourOf[k] = colour;
      colourStart[colour + 1]++;
    }
    let lanes = 0;
    for (let c = 0; c <= COLOURS; c++) {
      const size = colourStart[c + 1];
      colourStart[c + 1] = lanes;
      lanes += c === OVERFLOW ? 2 * size : (size + 1) & -2;
    }
    this.laneCount = lanes;
    if (this.slotOfLane.length < lanes) this.slotOfLane = new Int32Array(grownCapacity(this.slotOfLane.length, lanes));
    if (this.laneOf.length < count) this.laneOf = new Int32Array(grownCapacity(this.laneOf.length, count));
    const { slotOfLane, laneOf } = this;
    slotOfLane.fill(-1, 0, lanes);
    for (let k = 0; k < count; k++) {
      const colour = colourOf[k];
      const lane = colourStart[colour + 1];
      slotOfLane[lane] = slots[k];
      laneOf[k] = lane;
      colourStart[colour + 1] = lane + (colour === OVERFLOW ? 2 : 1);
    }
  }

  /** Each sub-step: the kept impulses along the current axes. */
  warmStart(states: Float64Array): void {
    if (this.kernel !== null) this.kernel.pointDistanceWarmStart(this.laneCount);
    else this.sweep(states, 0, true);
  }

  /** Each sub-step, twice: with each joint's push back to its length (useBias), then in the relax pass. */
  solve(states: Float64Array, useBias: boolean): void {
    if (this.kernel !== null) this.kernel.pointDistanceSolve(this.laneCount, useBias ? 0 : RELAX);
    else this.sweep(states, useBias ? 0 : RELAX, false);
  }

  /**
   * The kernel's sweep (assembly/point-distance-joints.ts) one lane at a time: the warm start
   * (`warm`), or a solve with the softness at `pass`. Lanes of a pair share no moving body, so
   * this order gives each the bits the kernel gives it side by side.
   */
  private sweep(states: Float64Array, pass: number, warm: boolean): void {
    const { rows, pairs, slotOfLane } = this;
    for (let i = 0; i < this.laneCount; i++) {
      if (slotOfLane[i] < 0) continue;
      const c = (i >> 1) * LANE_PAIR + (i & 1);
      const sa = pairs[2 * i] * BODY;
      const sb = pairs[2 * i + 1] * BODY;
      const dx = states[sb + DPX] - states[sa + DPX] + rows[c + DCX];
      const dy = states[sb + DPY] - states[sa + DPY] + rows[c + DCY];
      const length = Math.sqrt(dx * dx + dy * dy);
      const ax = length > 0 ? dx / length : rows[c + AX];
      const ay = length > 0 ? dy / length : rows[c + AY];
      let impulse = rows[c + IMPULSE];
      if (!warm) {
        const C = length - rows[c + LENGTH];
        const speed = (states[sb + VX] - states[sa + VX]) * ax + (states[sb + VY] - states[sa + VY]) * ay;
        const accumulated = impulse;
        impulse = -rows[c + pass + SCALE] * rows[c + MASS] * (speed + rows[c + pass + BIAS] * C) - rows[c + pass + KEEP] * accumulated;
        rows[c + IMPULSE] = accumulated + impulse;
      }
      // B pushed away from A; like the kernel, only dynamic bodies are written.
      const px = impulse * ax;
      const py = impulse * ay;
      if (states[sa + DYNAMIC] === 1) {
        states[sa + VX] = states[sa + VX] - rows[c + MA] * px;
        states[sa + VY] = states[sa + VY] - rows[c + MA] * py;
      }
      if (states[sb + DYNAMIC] === 1) {
        states[sb + VX] = states[sb + VX] + rows[c + MB] * px;
        states[sb + VY] = states[sb + VY] + rows[c + MB] * py;
      }
    }
  }

  /**
   * After the sub-steps: each joint's impulse and axis back into its record, for the next step's
   * warm start, and its force on body B over the last sub-step (as distanceJoint.reaction gives).
   */
  finish(r: Float64Array, inverseH: number): void {
    const { rows, laneOf, slots } = this;
    // In slot order, as prepare reads the records.
    for (let k = 0; k < this.jointCount; k++) {
      const i = laneOf[k];
      const j = slots[k];
      const o = j * JOINT_STRIDE;
      const c = (i >> 1) * LANE_PAIR + (i & 1);
      const impulse = rows[c + IMPULSE];
      r[o + (r[o + ENABLE_LIMIT] === 0 ? AXIAL_IMPULSE : SPRING_IMPULSE_SUM)] = impulse;
      r[o + WORLD_AXIS_X] = rows[c + AX];
      r[o + WORLD_AXIS_Y] = rows[c + AY];
      const axial = impulse * inverseH;
      r[o + FORCE_X] = axial * rows[c + AX];
      r[o + FORCE_Y] = axial * rows[c + AY];
      r[o + TORQUE] = 0;
    }
  }

  memoryBytes(): number {
    return (this.kernel === null ? this.rows.byteLength + this.pairs.byteLength : 0) + this.slotOfLane.byteLength + this.laneOf.byteLength + this.colourOf.byteLength + this.used.byteLength;
  }
}
