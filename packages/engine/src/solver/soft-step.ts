import type { BodyStore } from '../store/body-store.js';
import { TypeCode } from '../store/body-types.js';
import { BodyFlag } from '../store/rigid-columns.js';
import { ContactList, ContactPoint, POINT_STRIDE, WORLD } from '../narrowphase/contact-list.js';
import { grownCapacity } from '../util/grow.js';
import { SoftStepKernel } from './soft-step-kernel.js';
import type { JointSolver } from './joint-solver.js';
import { BODY, DPX, DPY, DQC, DQS, DYNAMIC, FAR_ARM, VX, VY, W, holdState, makeSoft } from './solver-body.js';
import { capSpeed } from './speed-limit.js';

// The contact point record's fields as this module's own constants, which V8 folds into the code.
const { anchorAX: PT_ANCHOR_AX, anchorAY: PT_ANCHOR_AY, anchorBX: PT_ANCHOR_BX, anchorBY: PT_ANCHOR_BY, approachSpeed: PT_APPROACH_SPEED, normalImpulse: PT_NORMAL_IMPULSE, separation: PT_SEPARATION, tangentImpulse: PT_TANGENT_IMPULSE, totalNormalImpulse: PT_TOTAL_NORMAL_IMPULSE } = ContactPoint;

/** The soft step's tuning, in the world's length units (see WorldOptions.lengthUnit). */
export interface SoftSettings {
  /** Sub-steps per step. Box2D v3's default is 4. */
  substeps: number;
  /** Stiffness of contacts, as a spring frequency; capped at a quarter of the sub-step rate. */
  contactHertz: number;
  /** Damping ratio of that spring. */
  contactDampingRatio: number;
  /** The fastest that overlap is pushed out, length units per second. */
  contactPushSpeed: number;
  /**
   * Separations up to this count as touching in the solve (a soft contact), not as a gap to close
   * (speculative, rigid); see solveContacts.
   */
  touchingGap: number;
  /** Approach speeds below this do not bounce. */
  restitutionThreshold: number;
  /** Bodies never move faster than this; Box2D's maximumLinearSpeed. */
  maxLinearSpeed: number;
}

// A contact constraint's fields, then two points of POINT fields each. Constraints are stored in
// pairs, field by field, the two of a pair side by side (lane 0, lane 1), so that a SIMD kernel
// loads a field of both with one instruction: field F of constraint i is at
// (i >> 1) * PAIR + (i & 1) + F, which is why every field offset below is even.
/** gatherBodies' capped velocity and the limit (see capSpeed). */
const capped = new Float64Array(3);

const NX = 0;
const NY = 2;
const FRICTION = 4;
const RESTITUTION = 6;
const ROLLING = 8;
const ROLLING_IMPULSE = 10;
const ROLLING_MASS = 12;
const MA = 14;
const IA = 16;
const MB = 18;
const IB = 20;
const BIAS_RATE = 22;
const MASS_SCALE = 24;
const IMPULSE_SCALE = 26;
/** 1 or 2; 0 for the empty lanes that pad a colour to whole pairs. */
const POINTS = 28;
/**
 * Where the points start: the header's fifteen fields and one unused fill four cache lines, so
 * that each point's fields start on one.
 */
const P = 32;
const RAX = 0;
const RAY = 2;
const RBX = 4;
const RBY = 6;
const BASE_SEPARATION = 8;
const NORMAL_IMPULSE = 10;
const TANGENT_IMPULSE = 12;
const MAX_NORMAL_IMPULSE = 14;
const NORMAL_MASS = 16;
const TANGENT_MASS = 18;
const RELATIVE_VELOCITY = 20;
/** The normal speed at the sub-step a point first took an impulse (negative, approaching), or 0. */
const IMPACT_VELOCITY = 22;
const POINT = 24;
/** Doubles per pair of constraints. */
export const PAIR = P + 2 * POINT;

/** The kinetic energy of velocities (vx, vy, w) on a body of inverse mass m and inverse inertia i: 0 for a body that does not move (m = 0). */
function bodyEnergy(vx: number, vy: number, w: number, m: number, i: number): number {
  return m > 0 ? (0.5 * (vx * vx + vy * vy)) / m + (i > 0 ? (0.5 * w * w) / i : 0) : 0;
}

/** The energy's cross term between velocities (vx, vy, w) and changes (dx, dy, dw) on the same body. */
function energyCross(vx: number, vy: number, w: number, dx: number, dy: number, dw: number, m: number, i: number): number {
  return m > 0 ? (0.5 * (vx * dx + vy * dy)) / m + (i > 0 ? (0.5 * w * dw) / i : 0) : 0;
}

/** Where constraint i's fields start (add a field offset). */
function at(i: number): number {
  return (i >> 1) * PAIR + (i & 1);
}

/**
 * 1, or the factor that brings a contact's lever arm (rx, ry) on a body of inverse mass invMass
 * and inverse inertia invInertia down to FAR_ARM of the body's radii of gyration, sqrt(I / m).
 * The passes turn an impulse p at the arm r into a spin change invInertia * (r x p), which rounds
 * by about 1e-16 |r| |p|; the contact's own effective mass knows nothing of that error, and the
 * next point answers it with an impulse some 1e-16 (r / gyration)^2 times p. Past 1e8 radii that
 * grows from point to point to infinity within one pass: a deep contact's midpoint, half its
 * depth from a small body's centre (a 1 x 0.001 box 1e47 inside a spinning box 1e49 wide), took
 * both to NaN in one step. Within FAR_ARM the factor is below 1e-4. No arm of a lone shape
 * comes near (a box's corner is under 2 radii out); a compound body with a shape of next to no
 * mass far out can, and only there is the arm, and the torque its friction and push exert,
 * shortened, along the same line.
 */
function armScale(rx: number, ry: number, invMass: number, invInertia: number): number {
  const r2 = rx * rx + ry * ry;
  if (!(r2 * invInertia > FAR_ARM * FAR_ARM * invMass)) return 1;
  return (FAR_ARM * Math.sqrt(invMass / invInertia)) / Math.sqrt(r2);
}

/** Colours of the constraint graph, as Box2D's B2_GRAPH_COLOR_COUNT less its overflow; contacts that find none come last. */
const COLOURS = 23;
/** Contacts between two moving bodies use the lower colours only, leaving the top ones to static contacts. */
const MOVING_COLOURS = COLOURS - 4;
const NO_COLOUR = 255;
/** The colours a contact between two moving bodies may take, as bits: 0 .. MOVING_COLOURS - 1. */
const MOVING_MASK = (1 << MOVING_COLOURS) - 1;
/** Those a contact with one moving body may take: 1 .. COLOURS - 1. */
const STATIC_MASK = ((1 << COLOURS) - 1) & ~1;
/** Lanes the kernel solves together (assembly/soft-step.ts): a colour is padded to a multiple of them. */
const LANES = 2;
/** Strides for visiting contacts when colouring them: the first that does not divide the count. */
const STRIDE_PRIMES = [7919, 7927, 7933, 7937];


let reusingColours = true;
/** Whether the soft step keeps last step's colouring where nothing it depends on changed (see colourAgain): for tests that compare the bits with and without. */
export function setColourReuse(on: boolean): void {
  reusingColours = on;
}

let reusingConstraints = true;
/** Whether prepare keeps the fields of kept contacts' constraints that it would write again with the same bits (see prepare): for tests that compare the bits with and without. */
export function setConstraintReuse(on: boolean): void {
  reusingConstraints = on;
}

/**
 * The contacts' stiffness over sub-steps of h: `contactHertz`, at most an eighth of the sub-step
 * rate, as Box2D v3 caps it (30 Hz at 60 Hz with 4 sub-steps, where the default's 30 is the
 * cap). A rigid joint is solved at twice this at most (JointSolver.prepare), a quarter of the
 * rate, Box2D's cap on joints. At coarser steps the stiffer contacts and joints of a quarter of
 * the rate kept piles and bridges ringing: 30 planks on revolute joints at 20 Hz held 93,000 J
 * of motion 15 s on, where they settle with these caps (see test/stacking.test.ts).
 */
export function contactHertzAt(contactHertz: number, h: number): number {
  return Math.min(contactHertz, 0.125 / h);
}

/** The most a body turns in one step, as in Box2D (B2_MAX_ROTATION): a quarter of a half turn. */
const MAX_ROTATION = 0.25 * Math.PI;

/**
 * Box2D v3's soft step (Catto, "Solver2D", 2024), the solver that holds stacks and piles:
 *
 *   prepare contacts once per step, from the manifolds found at the step's start, and joints; then
 *   per sub-step
 *     integrate velocities (gravity, forces, damping)
 *     warm start (apply last sub-step's impulses), joints first
 *     solve, with a soft bias that pushes overlap out as a damped spring would; joints first, so
 *       that contacts have the last word (JointSolver)
 *     integrate positions
 *     relax: solve again without the bias, removing the velocity the push-out added; friction and
 *       rolling resistance act here only, which stacks better (Box2D; Rapier's
 *       friction_in_bias_pass = false)
 *   then restitution on the points that took an impulse and approached faster than the threshold,
 *   and the impulses are stored for the next step's warm start.
 *
 * Separation within the step is tracked from anchors fixed at its start and each body's motion
 * since (delta position and delta rotation), so contacts need not be recomputed per sub-step.
 * Speculative points (apart by more than the touching gap) let a body close the gap and no more.
 *
 * Contacts are solved one after another in the list's canonical order, each reading and writing
 * its two bodies (Gauss-Seidel), so the result depends on that order alone. Awake dynamic and
 * kinematic bodies take part; static and sleeping ones are the "dummy" body 0, which never moves.
 *
 * Data: body states packed 8 doubles apart and constraints in pairs of PAIR doubles, in two
 * Float64Arrays, so that a constraint's solve touches three short runs of memory. Where the
 * runtime has WebAssembly SIMD they live in the kernel's memory, and its passes replace the
 * warm start, solve and relax loops below with the same bits (soft-step-kernel.ts); the choice is
 * made once, when the soft step is made.
 */
export class SoftStep {
  private readonly kernel = SoftStepKernel.create();

  /** Whether the sub-steps run in the WebAssembly kernel. */
  get usesKernel(): boolean {
    return this.kernel !== null;
  }
  /** Solver index per body slot (1..n), 0 for bodies that do not move in the solve. */
  private index = new Int32Array(0);
  private awake = new Int32Array(0);
  private awakeCount = 0;
  private states = new Float64Array(0);
  private constraints = new Float64Array(0);
  private pairs = new Int32Array(0);
  /** Constraint lanes in use: each colour padded with empty lanes to a multiple of LANES. */
  private laneCount = 0;
  private colourOf = new Uint8Array(0);
  /** Each contact's lane, by canonical position (-1: no moving body, not solved). */
  private laneAt = new Int32Array(0);
  private order = new Int32Array(0);
  private used = new Uint32Array(0);
  private readonly colourStart = new Int32Array(COLOURS + 2);
  /** Steps that kept the last colouring (see colourAgain). */
  coloursKept = 0;
  /** Contacts whose lanes prepare brought up to date rather than wrote anew, over all steps (see prepare). */
  get lanesKept(): number {
    return this.laneCounts[0];
  }
  /** lanesKept, counted in a typed array inside prepare's loop so that nothing follows the loop (see ShapeNarrowPhase.collidePairs). */
  private readonly laneCounts = new Float64Array(1);
  /** The awake bodies the last colouring was made for, and how many (-1: none yet); see colourAgain. */
  private colouredAwake = new Int32Array(0);
  private colouredCount = -1;
  /** The contact list's step (ContactList.steps) the colouring was last made or kept for. */
  private colouredStep = -1;
  /**
   * Whether every lane holds what the last prepare wrote into it: the colouring it was made for
   * is still the current one, and no array was replaced since. Not part of a snapshot (the
   * lanes are not): a restored world prepares every lane afresh.
   */
  private lanesPrepared = false;
  /** Bias rate, mass scale and impulse scale of contacts between moving bodies, and of those with a static one. */
  private readonly softness = new Float64Array(3);
  private readonly staticSoftness = new Float64Array(3);

  /** Bodies that moved in the last solve, by solver index - 1: their slots. */
  get movedCount(): number {
    return this.awakeCount;
  }

  movedSlot(k: number): number {
    return this.awake[k];
  }

  solve(bodies: BodyStore, contacts: ContactList, gx: number, gy: number, dt: number, settings: SoftSettings, joints: JointSolver | null): void {
    if (dt === 0) {
      // This step's contacts, which the next step's may equal (ContactList.unchanged), go
      // uncoloured: the colouring is not theirs (nor, then, the lanes).
      this.colouredCount = -1;
      return;
    }
    this.gatherBodies(bodies, settings.maxLinearSpeed, MAX_ROTATION / dt);
    const substeps = settings.substeps;
    const h = dt / substeps;
    const inverseH = 1 / h;
    this.prepare(bodies, contacts, h, settings);
    if (joints !== null) {
      joints.prepare(bodies, this.index, this.awake, this.awakeCount + 1, h, dt, contactHertzAt(settings.contactHertz, h), gx, gy, settings.maxLinearSpeed, MAX_ROTATION / dt, this.kernel);
      // The joints' lanes share the kernel's memory, and growing them moves the other regions.
      this.adoptKernelViews();
    }
    const { kernel, laneCount, awakeCount, states } = this;
    // Velocity plus gravity alone, the kernel's case: the general loop's terms are then 0 and its factors 1.
    const plain = kernel !== null && bodies.customMotionCount === 0 && !bodies.forcesPending;
    const maxAngular = MAX_ROTATION / dt;
    for (let i = 0; i < substeps; i++) {
      joints?.springsBefore(states);
      if (plain) kernel.integrateVelocities(awakeCount, h * (0 + gx), h * (0 + gy));
      else this.integrateVelocities(bodies, gx, gy, h);
      joints?.warmStart(states);
      if (kernel !== null) kernel.warmStart(laneCount);
      else this.warmStart();
      joints?.solve(states, true);
      if (kernel !== null) kernel.solve(laneCount, inverseH, settings.contactPushSpeed, settings.touchingGap);
      else this.solveContacts(inverseH, settings.contactPushSpeed, settings.touchingGap);
      if (kernel !== null) kernel.integratePositions(awakeCount, h, settings.maxLinearSpeed, maxAngular);
      else this.integratePositions(h, settings.maxLinearSpeed, maxAngular);
      joints?.springsAfter(states);
      joints?.solve(states, false);
      if (kernel !== null) kernel.relax(laneCount, inverseH);
      else this.relaxContacts(inverseH);
      // A joint made far from its constraint (or torn by a collision) can throw its bodies faster
      // than the speed limit in the relax pass, and the next sub-step's warm start and solve
      // would amplify that towards infinity: each sub-step starts within the limits.
      // A body past them marks a joint that cannot be met, whose kept impulses then grow every
      // sub-step: held within their bounds again before the next warm start (see holdImpulses).
      if (joints !== null) joints.holdImpulses(this.limitVelocities(settings.maxLinearSpeed, maxAngular));
    }
    this.applyRestitution(settings.restitutionThreshold, bodies, gx, gy, dt);
    this.store(contacts);
    joints?.finish(states);
    this.finish(bodies);
  }

  memoryBytes(): number {
    const solverBytes = this.kernel !== null ? this.kernel.memoryBytes() : this.states.byteLength + this.constraints.byteLength + this.pairs.byteLength;
    return this.index.byteLength + this.awake.byteLength + solverBytes;
  }

  /**
   * At least these lengths for the states, constraints and pairs. The kernel keeps all three
   * arrays' contents; the plain arrays are grown only before they are filled.
   */
  private reserve(states: number, constraints: number, pairs: number): void {
    const kernel = this.kernel;
    if (kernel !== null) {
      kernel.reserve(states, constraints, pairs);
      this.adoptKernelViews();
      return;
    }
    if (this.states.length < states) this.states = new Float64Array(states);
    if (this.constraints.length < constraints) {
      this.constraints = new Float64Array(constraints);
      this.lanesPrepared = false;
    }
    if (this.pairs.length < pairs) this.pairs = new Int32Array(pairs);
  }

  /** The kernel's current views of its regions, which any growth of its memory replaces. */
  private adoptKernelViews(): void {
    const kernel = this.kernel;
    if (kernel === null) return;
    this.states = kernel.states;
    this.constraints = kernel.constraints;
    this.pairs = kernel.pairs;
  }

  /**
   * The awake bodies' solver states. A dynamic body set faster than the speed limits since the
   * last step (created, set or given an impulse, up to 1e100; spun up to 1e100 rad/s) enters at
   * them: the warm start and solve would otherwise grow that speed through a long lever arm (a
   * shape's reach or a joint's anchor, up to 1e50) past the largest double, before
   * integratePositions caps it.
   */
  private gatherBodies(bodies: BodyStore, maxLinearSpeed: number, maxAngular: number): void {
    const { type, asleep, slotCount, vx, vy } = bodies;
    const rigid = bodies.rigid!;
    if (this.index.length < slotCount) {
      this.index = new Int32Array(grownCapacity(this.index.length, slotCount));
      this.awake = new Int32Array(this.index.length);
    }
    const { index, awake } = this;
    let n = 0;
    for (let slot = 0; slot < slotCount; slot++) {
      const t = type[slot];
      if (t === TypeCode.kinematic || (t === TypeCode.dynamic && asleep[slot] === 0)) {
        awake[n++] = slot;
        index[slot] = n;
      } else {
        index[slot] = 0;
      }
    }
    this.awakeCount = n;
    if (this.states.length < (n + 1) * BODY) this.reserve(grownCapacity(this.states.length, (n + 1) * BODY), 0, 0);
    const states = this.states;
    // Body 0: static, sleeping, or the world's shapes.
    states.fill(0, 0, BODY);
    states[DQC] = 1;
    const maxSq = maxLinearSpeed * maxLinearSpeed;
    const maxAngularSq = maxAngular * maxAngular;
    for (let k = 0; k < n; k++) {
      const slot = awake[k];
      const b = (k + 1) * BODY;
      const x = vx[slot];
      const y = vy[slot];
      if (!(x * x + y * y <= maxSq) && type[slot] === TypeCode.dynamic) {
        capped[0] = x;
        capped[1] = y;
        capped[2] = maxLinearSpeed;
        capSpeed(capped);
        states[b + VX] = capped[0];
        states[b + VY] = capped[1];
      } else {
        states[b + VX] = x;
        states[b + VY] = y;
      }
      states[b + W] = (rigid.flags[slot] & BodyFlag.fixedRotation) !== 0 ? 0 : rigid.angularVelocity[slot];
      states[b + DPX] = 0;
      states[b + DPY] = 0;
      states[b + DQC] = 1;
      states[b + DQS] = 0;
      states[b + DYNAMIC] = type[slot] === TypeCode.dynamic ? 1 : 0;
    }
    // Its own loop, reading the spin back as a double: merged into the one above, where it is
    // 0 or a column's value, V8 kept it tagged and boxed it for every body.
    for (let k = 1; k <= n; k++) {
      const b = k * BODY;
      const w = states[b + W];
      if (w * w > maxAngularSq && states[b + DYNAMIC] === 1) states[b + W] = w > 0 ? maxAngular : -maxAngular;
    }
  }

  private prepare(bodies: BodyStore, contacts: ContactList, h: number, settings: SoftSettings): void {
    const { invMass } = bodies;
    const rigid = bodies.rigid!;
    const invInertia = rigid.invInertia;
    const index = this.index;
    const count = contacts.count;
    // Stiffer against static bodies, so that a pile does not sink into the ground.
    const hertz = contactHertzAt(settings.contactHertz, h);
    const { softness, staticSoftness } = this;
    makeSoft(hertz, settings.contactDampingRatio, h, softness);
    makeSoft(2 * hertz, settings.contactDampingRatio, h, staticSoftness);
    // Colour the contacts (Box2D v3's constraint graph): each colour holds contacts that share no
    // moving body, and colours are solved in turn (see `colour`). Contacts with a static body
    // take colours from the top down, so that they come last and have the last word, and a pile
    // does not sink into the ground.
    if (this.colourAgain(contacts)) {
      this.colour(contacts, count);
      this.lanesPrepared = false;
    }
    const lanes = this.laneCount;
    if (this.constraints.length < (lanes >> 1) * PAIR) {
      const capacity = grownCapacity(this.constraints.length / PAIR, lanes >> 1);
      this.reserve(0, capacity * PAIR, 4 * capacity);
    }
    const { constraints, pairs, order, states, laneAt } = this;
    // A kept contact (ContactList.kept) in the lane it had last step, on bodies of the same
    // masses, at the same softness, has the normal, material, anchors and point count its lane
    // was prepared with, and needs only the fields that change from step to step (its
    // separations, impulses and velocities) written again: the rest would be written with the
    // same bits. All of a pile at rest is kept, and this skips most of preparing it.
    const reuse = reusingConstraints && this.lanesPrepared;
    this.lanesPrepared = true;
    const laneCounts = this.laneCounts;
    for (let i = 0; i < lanes; i++) {
      if (order[i] >= 0) continue;
      // The empty lane of a colour's last pair: no points, on the dummy body.
      const c = at(i);
      pairs[2 * i] = 0;
      pairs[2 * i + 1] = 0;
      constraints[c + POINTS] = 0;
      constraints[c + RESTITUTION] = 0;
      constraints[c + ROLLING] = 0;
      constraints[c + ROLLING_IMPULSE] = 0;
    }
    // In canonical order, writing each contact into its lane: the contact list's columns are then
    // read front to back once, where lane order would sweep them once per colour.
    const contactOrder = contacts.order;
    for (let n = 0; n < count; n++) {
      const i = laneAt[n];
      if (i < 0) continue;
      const k = contactOrder[n];
      const c = at(i);
      const a = contacts.bodyA[k];
      const b = contacts.bodyB[k];
      const ia = index[a];
      const ib = b === WORLD ? 0 : index[b];
      pairs[2 * i] = ia;
      pairs[2 * i + 1] = ib;
      const mA = ia === 0 ? 0 : invMass[a];
      const iA = ia === 0 ? 0 : invInertia[a];
      const mB = ib === 0 ? 0 : invMass[b];
      const iB = ib === 0 ? 0 : invInertia[b];
      const soft = ia === 0 || ib === 0 ? staticSoftness : softness;
      const kept =
        reuse &&
        contacts.kept[k] === 1 &&
        constraints[c + MA] === mA &&
        constraints[c + IA] === iA &&
        constraints[c + MB] === mB &&
        constraints[c + IB] === iB &&
        constraints[c + BIAS_RATE] === soft[0] &&
        constraints[c + MASS_SCALE] === soft[1] &&
        constraints[c + IMPULSE_SCALE] === soft[2];
      const nx = contacts.normalX[k];
      const ny = contacts.normalY[k];
      if (kept) laneCounts[0]++;
      else {
        constraints[c + BIAS_RATE] = soft[0];
        constraints[c + MASS_SCALE] = soft[1];
        constraints[c + IMPULSE_SCALE] = soft[2];
        constraints[c + NX] = nx;
        constraints[c + NY] = ny;
        constraints[c + FRICTION] = contacts.friction[k];
        constraints[c + RESTITUTION] = contacts.restitution[k];
        constraints[c + ROLLING] = contacts.rollingResistance[k];
        constraints[c + ROLLING_MASS] = contacts.rollingResistance[k] > 0 && iA + iB > 0 ? 1 / (iA + iB) : 0;
        constraints[c + MA] = mA;
        constraints[c + IA] = iA;
        constraints[c + MB] = mB;
        constraints[c + IB] = iB;
        constraints[c + POINTS] = contacts.pointCount[k];
      }
      constraints[c + ROLLING_IMPULSE] = contacts.rollingImpulse[k];
      const pointCount = contacts.pointCount[k];
      const sa = ia * BODY;
      const sb = ib * BODY;
      const vAx = states[sa + VX];
      const vAy = states[sa + VY];
      const wA = states[sa + W];
      const vBx = states[sb + VX];
      const vBy = states[sb + VY];
      const wB = states[sb + W];
      const tx = ny;
      const ty = -nx;
      for (let p = 0; p < pointCount; p++) {
        const point = (2 * k + p) * POINT_STRIDE;
        const q = c + P + p * POINT;
        let rAx: number;
        let rAy: number;
        let rBx: number;
        let rBy: number;
        if (kept) {
          rAx = constraints[q + RAX];
          rAy = constraints[q + RAY];
          rBx = constraints[q + RBX];
          rBy = constraints[q + RBY];
        } else {
          rAx = contacts.points[point + PT_ANCHOR_AX];
          rAy = contacts.points[point + PT_ANCHOR_AY];
          rBx = contacts.points[point + PT_ANCHOR_BX];
          rBy = contacts.points[point + PT_ANCHOR_BY];
          // armScale is called for far arms alone: its doubles, passed and returned, are boxed
          // wherever V8 does not inline it into this long function.
          if ((rAx * rAx + rAy * rAy) * iA > FAR_ARM * FAR_ARM * mA) {
            const short = armScale(rAx, rAy, mA, iA);
            rAx *= short;
            rAy *= short;
          }
          if ((rBx * rBx + rBy * rBy) * iB > FAR_ARM * FAR_ARM * mB) {
            const short = armScale(rBx, rBy, mB, iB);
            rBx *= short;
            rBy *= short;
          }
          constraints[q + RAX] = rAx;
          constraints[q + RAY] = rAy;
          constraints[q + RBX] = rBx;
          constraints[q + RBY] = rBy;
          const rnA = rAx * ny - rAy * nx;
          const rnB = rBx * ny - rBy * nx;
          const kNormal = mA + mB + iA * rnA * rnA + iB * rnB * rnB;
          constraints[q + NORMAL_MASS] = kNormal > 0 ? 1 / kNormal : 0;
          const rtA = rAx * ty - rAy * tx;
          const rtB = rBx * ty - rBy * tx;
          const kTangent = mA + mB + iA * rtA * rtA + iB * rtB * rtB;
          constraints[q + TANGENT_MASS] = kTangent > 0 ? 1 / kTangent : 0;
        }
        constraints[q + BASE_SEPARATION] = contacts.points[point + PT_SEPARATION] - ((rBx - rAx) * nx + (rBy - rAy) * ny);
        constraints[q + NORMAL_IMPULSE] = contacts.points[point + PT_NORMAL_IMPULSE];
        constraints[q + TANGENT_IMPULSE] = contacts.points[point + PT_TANGENT_IMPULSE];
        constraints[q + MAX_NORMAL_IMPULSE] = 0;
        const dvx = vBx - wB * rBy - (vAx - wA * rAy);
        const dvy = vBy + wB * rBx - (vAy + wA * rAx);
        const vn = dvx * nx + dvy * ny;
        constraints[q + RELATIVE_VELOCITY] = vn;
        constraints[q + IMPACT_VELOCITY] = 0;
        contacts.points[point + PT_APPROACH_SPEED] = -vn;
      }
    }
  }

  /**
   * Whether the contacts need colouring: not where the list is last step's (ContactList.unchanged)
   * and the same bodies are awake in the same order, the colouring's only inputs, which would give
   * last step's lanes again. A pile at rest keeps its contacts step after step; colouring them was
   * half a millisecond of a 5,050-box pyramid's 9.4.
   */
  private colourAgain(contacts: ContactList): boolean {
    // `unchanged` compares the list with the one before, which must be the one coloured: lists
    // the soft step never saw come between (steps of the elastic pass under solver 'auto', a
    // second collision pass in a step that woke sleepers). An empty list after an elastic step,
    // unchanged from it, kept the lanes of a contact two steps gone and solved it again.
    const seenBefore = contacts.steps === this.colouredStep + 1;
    this.colouredStep = contacts.steps;
    if (reusingColours && contacts.unchanged && seenBefore && this.awakeCount === this.colouredCount && this.sameAwake()) {
      this.coloursKept++;
      return false;
    }
    if (this.colouredAwake.length < this.awakeCount) this.colouredAwake = new Int32Array(this.awake.length);
    this.colouredCount = this.awakeCount;
    this.rememberAwake();
    return true;
  }

  // The two loops below have functions of their own with nothing after the loop (see greedyColours).

  /** Whether the awake bodies are those of the last colouring, in order. */
  private sameAwake(): boolean {
    const { awake, awakeCount, colouredAwake } = this;
    for (let k = 0; k < awakeCount; k++) if (awake[k] !== colouredAwake[k]) return false;
    return true;
  }

  private rememberAwake(): void {
    const { awake, awakeCount, colouredAwake } = this;
    for (let k = 0; k < awakeCount; k++) colouredAwake[k] = awake[k];
  }

  /**
   * Gives each contact with a moving body a colour (greedy: the lowest free for both bodies), and
   * lists them in `order` colour by colour, each colour in canonical order and padded to whole pairs; sets laneCount.
   *
   * Contacts are visited in a scattered order, k -> k * STRIDE_PRIME mod count, not in canonical
   * order: canonical order runs through space (slots follow creation), so a greedy sweep in it
   * fills each colour with a regular pattern of neighbours, and solving those patterns in turn
   * leans a pile to one side. On the 5,050-box pyramid the canonical sweep drifted boxes 0.29 of
   * their width and made the top sway 0.76; the scattered visit, 0.17, as Box2D's own colouring
   * does (0.18). The order depends on the contact count alone, so the result on the contacts.
   */
  private colour(contacts: ContactList, count: number): void {
    if (this.colourOf.length < count) {
      this.colourOf = new Uint8Array(grownCapacity(this.colourOf.length, count));
      this.laneAt = new Int32Array(this.colourOf.length);
    }
    const colourStart = this.colourStart;
    if (this.used.length < this.awakeCount + 1) this.used = new Uint32Array(grownCapacity(this.used.length, this.awakeCount + 1));
    this.used.fill(0, 0, this.awakeCount + 1);
    colourStart.fill(0);
    let stride = 1;
    for (let p = 0; p < STRIDE_PRIMES.length; p++) {
      if (count % STRIDE_PRIMES[p] !== 0) {
        stride = STRIDE_PRIMES[p];
        break;
      }
    }
    this.greedyColours(contacts, count, stride);
    // Lanes per colour: each colour rounded up to whole pairs (the kernel's two lanes);
    // the contacts with no colour left (more neighbours than colours) may share bodies, so each
    // takes a pair of its own, and they come after all the colours.
    let lanes = 0;
    for (let c = 0; c <= COLOURS; c++) {
      const size = colourStart[c + 1];
      colourStart[c + 1] = lanes;
      lanes += c === COLOURS ? LANES * size : (size + LANES - 1) & -LANES;
    }
    this.laneCount = lanes;
    if (this.order.length < lanes) this.order = new Int32Array(grownCapacity(this.order.length, lanes));
    this.order.fill(-1, 0, lanes);
    this.sortByColour(contacts.order, count);
  }

  // The colouring's two long loops are functions of their own with nothing after the loop: V8
  // compiles a loop this long during the first step (on-stack replacement), before the code after
  // it has run, and an operation there without feedback then left that code at every step.

  /** colour's greedy pass: each contact's colour in colourOf, colour sizes in colourStart. */
  private greedyColours(contacts: ContactList, count: number, stride: number): void {
    const { index, colourOf, colourStart, used } = this;
    const contactOrder = contacts.order;
    // n steps by stride modulo count; the step brought below count once, so that each visit
    // subtracts at most one count rather than dividing.
    const step = stride % count;
    for (let visit = 0, n = 0; visit < count; visit++) {
      const k = contactOrder[n];
      const b = contacts.bodyB[k];
      const ia = index[contacts.bodyA[k]];
      const ib = b === WORLD ? 0 : index[b];
      let colour = NO_COLOUR;
      if (ia !== 0 && ib !== 0) {
        // The lowest colour free for both: the lowest clear bit of what they use.
        const free = ~(used[ia] | used[ib]) & MOVING_MASK;
        colour = free === 0 ? COLOURS : 31 - Math.clz32(free & -free);
        if (free !== 0) {
          used[ia] |= 1 << colour;
          used[ib] |= 1 << colour;
        }
      } else if (ia !== 0 || ib !== 0) {
        // The highest colour free for the moving body, colour 0 left to moving pairs.
        const moving = ia !== 0 ? ia : ib;
        const free = ~used[moving] & STATIC_MASK;
        colour = free === 0 ? COLOURS : 31 - Math.clz32(free);
        if (free !== 0) used[moving] |= 1 << colour;
      }
      colourOf[n] = colour;
      if (colour !== NO_COLOUR) colourStart[colour + 1]++;
      n += step;
      if (n >= count) n -= count;
    }
  }

  /** colour's counting sort of the contacts into lanes, colour by colour (colourStart holds each colour's first lane). */
  private sortByColour(contactOrder: Int32Array, count: number): void {
    const { colourOf, colourStart, laneAt, order } = this;
    // Stable: each colour in canonical order; lanes hold contact slots.
    for (let n = 0; n < count; n++) {
      const colour = colourOf[n];
      if (colour === NO_COLOUR) {
        laneAt[n] = -1;
        continue;
      }
      const lane = colourStart[colour + 1];
      order[lane] = contactOrder[n];
      laneAt[n] = lane;
      colourStart[colour + 1] = lane + (colour === COLOURS ? LANES : 1);
    }
  }

  private integrateVelocities(bodies: BodyStore, gx: number, gy: number, h: number): void {
    const { awake, awakeCount, states } = this;
    const { invMass, gravityScale, linearDamping, forceX, forceY, type } = bodies;
    const rigid = bodies.rigid!;
    const { invInertia, torque, angularDamping, flags } = rigid;
    for (let k = 0; k < awakeCount; k++) {
      const slot = awake[k];
      if (type[slot] !== TypeCode.dynamic) continue;
      const b = (k + 1) * BODY;
      const m = invMass[slot];
      const linear = 1 / (1 + h * linearDamping[slot]);
      const angular = 1 / (1 + h * angularDamping[slot]);
      const g = gravityScale[slot];
      states[b + VX] = h * (m * forceX[slot] + g * gx) + linear * states[b + VX];
      states[b + VY] = h * (m * forceY[slot] + g * gy) + linear * states[b + VY];
      states[b + W] = (flags[slot] & BodyFlag.fixedRotation) !== 0 ? 0 : h * invInertia[slot] * torque[slot] + angular * states[b + W];
    }
  }

  private warmStart(): void {
    const { constraints, pairs, states } = this;
    const n = this.laneCount;
    for (let i = 0; i < n; i++) {
      const c = at(i);
      const sa = pairs[2 * i] * BODY;
      const sb = pairs[2 * i + 1] * BODY;
      const mA = constraints[c + MA];
      const iA = constraints[c + IA];
      const mB = constraints[c + MB];
      const iB = constraints[c + IB];
      const nx = constraints[c + NX];
      const ny = constraints[c + NY];
      let vAx = states[sa + VX];
      let vAy = states[sa + VY];
      let wA = states[sa + W];
      let vBx = states[sb + VX];
      let vBy = states[sb + VY];
      let wB = states[sb + W];
      const pointCount = constraints[c + POINTS];
      for (let p = 0; p < pointCount; p++) {
        const q = c + P + p * POINT;
        const rAx = constraints[q + RAX];
        const rAy = constraints[q + RAY];
        const rBx = constraints[q + RBX];
        const rBy = constraints[q + RBY];
        const pn = constraints[q + NORMAL_IMPULSE];
        const pt = constraints[q + TANGENT_IMPULSE];
        // P = pn n + pt t, with t = (ny, -nx).
        const px = pn * nx + pt * ny;
        const py = pn * ny - pt * nx;
        wA -= iA * (rAx * py - rAy * px);
        vAx -= mA * px;
        vAy -= mA * py;
        wB += iB * (rBx * py - rBy * px);
        vBx += mB * px;
        vBy += mB * py;
      }
      const rolling = constraints[c + ROLLING_IMPULSE];
      wA -= iA * rolling;
      wB += iB * rolling;
      if (states[sa + DYNAMIC] === 1) {
        states[sa + VX] = vAx;
        states[sa + VY] = vAy;
        states[sa + W] = wA;
      }
      if (states[sb + DYNAMIC] === 1) {
        states[sb + VX] = vBx;
        states[sb + VY] = vBy;
        states[sb + W] = wB;
      }
    }
  }

  /**
   * The biased solve of every contact: non-penetration with the soft push-out, no friction. One
   * point at a time, in colour order (Gauss-Seidel).
   */
  private solveContacts(inverseH: number, pushSpeed: number, touchingGap: number): void {
    const { constraints, pairs, states } = this;
    const n = this.laneCount;
    for (let i = 0; i < n; i++) {
      const c = at(i);
      const sa = pairs[2 * i] * BODY;
      const sb = pairs[2 * i + 1] * BODY;
      const mA = constraints[c + MA];
      const iA = constraints[c + IA];
      const mB = constraints[c + MB];
      const iB = constraints[c + IB];
      let vAx = states[sa + VX];
      let vAy = states[sa + VY];
      let wA = states[sa + W];
      const qAc = states[sa + DQC];
      const qAs = states[sa + DQS];
      let vBx = states[sb + VX];
      let vBy = states[sb + VY];
      let wB = states[sb + W];
      const qBc = states[sb + DQC];
      const qBs = states[sb + DQS];
      const dpx = states[sb + DPX] - states[sa + DPX];
      const dpy = states[sb + DPY] - states[sa + DPY];
      const nx = constraints[c + NX];
      const ny = constraints[c + NY];
      const pointCount = constraints[c + POINTS];
      const biasRate = constraints[c + BIAS_RATE];
      const softMassScale = constraints[c + MASS_SCALE];
      const softImpulseScale = constraints[c + IMPULSE_SCALE];
      // The second point's normal speed before this constraint's impulses, for noting its impact.
      const second = c + P + POINT;
      const before1 =
        pointCount === 2
          ? (vBx - wB * constraints[second + RBY] - (vAx - wA * constraints[second + RAY])) * nx +
            (vBy + wB * constraints[second + RBX] - (vAy + wA * constraints[second + RAX])) * ny
          : 0;
      for (let p = 0; p < pointCount; p++) {
        const q = c + P + p * POINT;
        const rAx = constraints[q + RAX];
        const rAy = constraints[q + RAY];
        const rBx = constraints[q + RBX];
        const rBy = constraints[q + RBY];
        // Current separation: the base plus how the anchors moved apart along the normal.
        const dsx = dpx + (qBc * rBx - qBs * rBy) - (qAc * rAx - qAs * rAy);
        const dsy = dpy + (qBs * rBx + qBc * rBy) - (qAs * rAx + qAc * rAy);
        const s = constraints[q + BASE_SEPARATION] + dsx * nx + dsy * ny;
        let bias: number;
        let massScale: number;
        let impulseScale: number;
        // Speculative: close the gap within the sub-step, no faster. A point within touchingGap
        // counts as touching, and soft, as one in overlap does: the speculative branch closes a
        // gap to a hair above 0 (about 1e-10 of a metre, where the passes leave it) rather than
        // to 0 or below, and a point held there would stay rigid among soft neighbours step after
        // step. Stacks placed with gaps of 1e-12 to 1e-3 m between their boxes swayed 17-26 cm
        // (1 m boxes) or fell (0.1 m boxes) that way, and stacks turned by 1 rad swayed 4 cm, where
        // Box2D v3 (in floats, whose round-off puts such points on either side) sways 1.2 cm. The
        // relax pass keeps Box2D's test, s > 0: without the push-out, a point within the gap
        // closes it at most at touchingGap / h, a millimetre a second.
        if (s > touchingGap) {
          bias = s * inverseH;
          massScale = 1;
          impulseScale = 0;
        } else {
          bias = Math.max(biasRate * softMassScale * s, -pushSpeed);
          massScale = softMassScale;
          impulseScale = softImpulseScale;
        }
        const dvx = vBx - wB * rBy - (vAx - wA * rAy);
        const dvy = vBy + wB * rBx - (vAy + wA * rAx);
        const vn = dvx * nx + dvy * ny;
        const accumulated = constraints[q + NORMAL_IMPULSE];
        let impulse = -constraints[q + NORMAL_MASS] * (massScale * vn + bias) - impulseScale * accumulated;
        const total = Math.max(accumulated + impulse, 0);
        impulse = total - accumulated;
        constraints[q + NORMAL_IMPULSE] = total;
        if (total > constraints[q + MAX_NORMAL_IMPULSE]) {
          // The first impulse this step: the moment of impact, and the speed restitution reverses,
          // as it was before this contact's first point acted on the second.
          if (constraints[q + MAX_NORMAL_IMPULSE] === 0) {
            const approach = p === 0 ? vn : before1;
            if (approach < 0) constraints[q + IMPACT_VELOCITY] = approach;
          }
          constraints[q + MAX_NORMAL_IMPULSE] = total;
        }
        const px = impulse * nx;
        const py = impulse * ny;
        vAx -= mA * px;
        vAy -= mA * py;
        wA -= iA * (rAx * py - rAy * px);
        vBx += mB * px;
        vBy += mB * py;
        wB += iB * (rBx * py - rBy * px);
      }
      if (states[sa + DYNAMIC] === 1) {
        states[sa + VX] = vAx;
        states[sa + VY] = vAy;
        states[sa + W] = wA;
      }
      if (states[sb + DYNAMIC] === 1) {
        states[sb + VX] = vBx;
        states[sb + VY] = vBy;
        states[sb + W] = wB;
      }
    }
  }

  /**
   * The relax pass: non-penetration without the push-out (speculative points still close their
   * gap), then friction and rolling resistance, which act here only.
   */
  private relaxContacts(inverseH: number): void {
    const { constraints, pairs, states } = this;
    const n = this.laneCount;
    for (let i = 0; i < n; i++) {
      const c = at(i);
      const sa = pairs[2 * i] * BODY;
      const sb = pairs[2 * i + 1] * BODY;
      const mA = constraints[c + MA];
      const iA = constraints[c + IA];
      const mB = constraints[c + MB];
      const iB = constraints[c + IB];
      let vAx = states[sa + VX];
      let vAy = states[sa + VY];
      let wA = states[sa + W];
      const qAc = states[sa + DQC];
      const qAs = states[sa + DQS];
      let vBx = states[sb + VX];
      let vBy = states[sb + VY];
      let wB = states[sb + W];
      const qBc = states[sb + DQC];
      const qBs = states[sb + DQS];
      const dpx = states[sb + DPX] - states[sa + DPX];
      const dpy = states[sb + DPY] - states[sa + DPY];
      const nx = constraints[c + NX];
      const ny = constraints[c + NY];
      const pointCount = constraints[c + POINTS];
      let totalNormalImpulse = 0;
      const second = c + P + POINT;
      const before1 =
        pointCount === 2
          ? (vBx - wB * constraints[second + RBY] - (vAx - wA * constraints[second + RAY])) * nx +
            (vBy + wB * constraints[second + RBX] - (vAy + wA * constraints[second + RAX])) * ny
          : 0;
      for (let p = 0; p < pointCount; p++) {
        const q = c + P + p * POINT;
        const rAx = constraints[q + RAX];
        const rAy = constraints[q + RAY];
        const rBx = constraints[q + RBX];
        const rBy = constraints[q + RBY];
        const dsx = dpx + (qBc * rBx - qBs * rBy) - (qAc * rAx - qAs * rAy);
        const dsy = dpy + (qBs * rBx + qBc * rBy) - (qAs * rAx + qAc * rAy);
        const s = constraints[q + BASE_SEPARATION] + dsx * nx + dsy * ny;
        const bias = s > 0 ? s * inverseH : 0;
        const dvx = vBx - wB * rBy - (vAx - wA * rAy);
        const dvy = vBy + wB * rBx - (vAy + wA * rAx);
        const vn = dvx * nx + dvy * ny;
        const accumulated = constraints[q + NORMAL_IMPULSE];
        let impulse = -constraints[q + NORMAL_MASS] * (vn + bias);
        const total = Math.max(accumulated + impulse, 0);
        impulse = total - accumulated;
        constraints[q + NORMAL_IMPULSE] = total;
        if (total > constraints[q + MAX_NORMAL_IMPULSE]) {
          // The first impulse this step: the moment of impact, and the speed restitution reverses,
          // as it was before this contact's first point acted on the second.
          if (constraints[q + MAX_NORMAL_IMPULSE] === 0) {
            const approach = p === 0 ? vn : before1;
            if (approach < 0) constraints[q + IMPACT_VELOCITY] = approach;
          }
          constraints[q + MAX_NORMAL_IMPULSE] = total;
        }
        totalNormalImpulse += total;
        const px = impulse * nx;
        const py = impulse * ny;
        vAx -= mA * px;
        vAy -= mA * py;
        wA -= iA * (rAx * py - rAy * px);
        vBx += mB * px;
        vBy += mB * py;
        wB += iB * (rBx * py - rBy * px);
      }
      const friction = constraints[c + FRICTION];
      const tx = ny;
      const ty = -nx;
      for (let p = 0; p < pointCount; p++) {
        const q = c + P + p * POINT;
        const rAx = constraints[q + RAX];
        const rAy = constraints[q + RAY];
        const rBx = constraints[q + RBX];
        const rBy = constraints[q + RBY];
        const dvx = vBx - wB * rBy - (vAx - wA * rAy);
        const dvy = vBy + wB * rBx - (vAy + wA * rAx);
        const vt = dvx * tx + dvy * ty;
        const accumulated = constraints[q + TANGENT_IMPULSE];
        const limit = friction * constraints[q + NORMAL_IMPULSE];
        let total = accumulated - constraints[q + TANGENT_MASS] * vt;
        total = total < -limit ? -limit : total > limit ? limit : total;
        const impulse = total - accumulated;
        constraints[q + TANGENT_IMPULSE] = total;
        const px = impulse * tx;
        const py = impulse * ty;
        vAx -= mA * px;
        vAy -= mA * py;
        wA -= iA * (rAx * py - rAy * px);
        vBx += mB * px;
        vBy += mB * py;
        wB += iB * (rBx * py - rBy * px);
      }
      const resistance = constraints[c + ROLLING];
      if (resistance > 0) {
        const limit = resistance * totalNormalImpulse;
        const accumulated = constraints[c + ROLLING_IMPULSE];
        let total = accumulated - constraints[c + ROLLING_MASS] * (wB - wA);
        total = total < -limit ? -limit : total > limit ? limit : total;
        const delta = total - accumulated;
        constraints[c + ROLLING_IMPULSE] = total;
        wA -= iA * delta;
        wB += iB * delta;
      }
      if (states[sa + DYNAMIC] === 1) {
        states[sa + VX] = vAx;
        states[sa + VY] = vAy;
        states[sa + W] = wA;
      }
      if (states[sb + DYNAMIC] === 1) {
        states[sb + VX] = vBx;
        states[sb + VY] = vBy;
        states[sb + W] = wB;
      }
    }
  }

  /** The speed limits integratePositions applies, without moving the bodies. */
  /** Holds every moving body within the speed limits; whether any was beyond them. */
  private limitVelocities(maxLinearSpeed: number, maxAngular: number): boolean {
    const { awakeCount, states } = this;
    const maxSpeedSq = maxLinearSpeed * maxLinearSpeed;
    const maxAngularSq = maxAngular * maxAngular;
    let held = false;
    // holdState's own test, inline, and the call only past the limits: a call for every body and
    // sub-step, returning what it did, cost the joint grid's 19,794 pins 0.3 ms of its 15.
    for (let k = 0; k < awakeCount; k++) {
      const b = (k + 1) * BODY;
      const vx = states[b + VX];
      const vy = states[b + VY];
      const w = states[b + W];
      if (vx * vx + vy * vy > maxSpeedSq || w * w > maxAngularSq) {
        holdState(states, b, maxLinearSpeed, maxAngular);
        held = true;
      }
    }
    return held;
  }

  /** A fixed rotation's spin is 0 throughout (gatherBodies, integrateVelocities), and its inertia infinite. */
  private integratePositions(h: number, maxLinearSpeed: number, maxAngular: number): void {
    const { awakeCount, states } = this;
    const maxSpeedSq = maxLinearSpeed * maxLinearSpeed;
    for (let k = 0; k < awakeCount; k++) {
      const b = (k + 1) * BODY;
      let vx = states[b + VX];
      let vy = states[b + VY];
      let w = states[b + W];
      const speedSq = vx * vx + vy * vy;
      if (speedSq > maxSpeedSq) {
        const ratio = maxLinearSpeed / Math.sqrt(speedSq);
        vx *= ratio;
        vy *= ratio;
      }
      if (w * w > maxAngular * maxAngular) w = w > 0 ? maxAngular : -maxAngular;
      states[b + VX] = vx;
      states[b + VY] = vy;
      states[b + W] = w;
      states[b + DPX] += h * vx;
      states[b + DPY] += h * vy;
      // Advance the rotation by h w without trigonometry, renormalised (Box2D's b2IntegrateRotation).
      const qc = states[b + DQC];
      const qs = states[b + DQS];
      const hw = h * w;
      const c2 = qc - hw * qs;
      const s2 = qs + hw * qc;
      const length = Math.sqrt(c2 * c2 + s2 * s2);
      const inverse = length > 0 ? 1 / length : 0;
      states[b + DQC] = c2 * inverse;
      states[b + DQS] = s2 * inverse;
    }
  }

  /**
   * The restitution pass: each point that took an impulse this step leaves with -e times its
   * approach speed, if that was faster than the threshold. The approach speed is the slower of the
   * point's speed at the step's start (Box2D's choice) and at the sub-step it first took an
   * impulse (the moment it collided): a point that only comes into contact after another bounced
   * the body (a spinning box's far corner) would otherwise bounce with a speed it never had, and a
   * gas of elastic boxes gained energy step after step. When both points of a manifold collide
   * they are solved together (the two-point problem as a block, as the elastic pass does): one
   * after the other, the second undoes part of the first, and a box landing flat on e = 1 gained
   * 8 % of its energy as a spurious spin.
   */
  private applyRestitution(threshold: number, bodies: BodyStore, gx: number, gy: number, dt: number): void {
    const { constraints, pairs, states } = this;
    const n = this.laneCount;
    for (let i = 0; i < n; i++) {
      const c = at(i);
      const e = constraints[c + RESTITUTION];
      if (e === 0) continue;
      const sa = pairs[2 * i] * BODY;
      const sb = pairs[2 * i + 1] * BODY;
      const mA = constraints[c + MA];
      const iA = constraints[c + IA];
      const mB = constraints[c + MB];
      const iB = constraints[c + IB];
      const nx = constraints[c + NX];
      const ny = constraints[c + NY];
      let vAx = states[sa + VX];
      let vAy = states[sa + VY];
      let wA = states[sa + W];
      let vBx = states[sb + VX];
      let vBy = states[sb + VY];
      let wB = states[sb + W];
      const pointCount = constraints[c + POINTS];
      const q0 = c + P;
      const q1 = c + P + POINT;
      // A point that took no impulse did not collide (a speculative point left apart).
      // Points that took an impulse this step, approaching faster than the threshold when they did.
      const bounce0 = Math.max(constraints[q0 + RELATIVE_VELOCITY], constraints[q0 + IMPACT_VELOCITY]);
      const bounce1 = pointCount === 2 ? Math.max(constraints[q1 + RELATIVE_VELOCITY], constraints[q1 + IMPACT_VELOCITY]) : 0;
      const active0 = bounce0 < -threshold;
      const active1 = pointCount === 2 && bounce1 < -threshold;
      // The restitution's impulse at each point, applied to the velocities below and kept in the
      // totals at the end (scaled back where friction would make it gain energy).
      let d0 = 0;
      let d1 = 0;
      const p0 = constraints[q0 + NORMAL_IMPULSE];
      const p1 = pointCount === 2 ? constraints[q1 + NORMAL_IMPULSE] : 0;
      let total0 = p0;
      let total1 = p1;
      const vAx0 = vAx;
      const vAy0 = vAy;
      const wA0 = wA;
      const vBx0 = vBx;
      const vBy0 = vBy;
      const wB0 = wB;
      if (active0 && active1) {
        const r0ax = constraints[q0 + RAX];
        const r0ay = constraints[q0 + RAY];
        const r0bx = constraints[q0 + RBX];
        const r0by = constraints[q0 + RBY];
        const r1ax = constraints[q1 + RAX];
        const r1ay = constraints[q1 + RAY];
        const r1bx = constraints[q1 + RBX];
        const r1by = constraints[q1 + RBY];
        const rn0a = r0ax * ny - r0ay * nx;
        const rn0b = r0bx * ny - r0by * nx;
        const rn1a = r1ax * ny - r1ay * nx;
        const rn1b = r1bx * ny - r1by * nx;
        const k00 = mA + mB + iA * rn0a * rn0a + iB * rn0b * rn0b;
        const k11 = mA + mB + iA * rn1a * rn1a + iB * rn1b * rn1b;
        const k01 = mA + mB + iA * rn0a * rn1a + iB * rn0b * rn1b;
        const vn0 = (vBx - wB * r0by - (vAx - wA * r0ay)) * nx + (vBy + wB * r0bx - (vAy + wA * r0ax)) * ny;
        const vn1 = (vBx - wB * r1by - (vAx - wA * r1ay)) * nx + (vBy + wB * r1bx - (vAy + wA * r1ax)) * ny;
        // In terms of the totals x: vn' = b + K x, with b the velocities less what the current totals did.
        const b0 = vn0 - (k00 * p0 + k01 * p1);
        const b1 = vn1 - (k01 * p0 + k11 * p1);
        const t0 = -e * bounce0;
        const t1 = -e * bounce1;
        let x0 = -1;
        let x1 = -1;
        const det = k00 * k11 - k01 * k01;
        if (det > 1e-9 * k00 * k11) {
          x0 = (k11 * (t0 - b0) - k01 * (t1 - b1)) / det;
          x1 = (k00 * (t1 - b1) - k01 * (t0 - b0)) / det;
        }
        if (!(x0 >= 0 && x1 >= 0)) {
          // One point alone, the other released; or neither. The released point's speed is
          // checked with a tolerance for round-off: a flat face (or fixed rotation) makes the
          // two points move alike, and a target met to the last bit must count as met.
          const tolerance = 1e-9 * (Math.abs(t0) + Math.abs(t1) + Math.abs(vn0) + Math.abs(vn1));
          x0 = (t0 - b0) / k00;
          x1 = 0;
          if (!(x0 >= 0 && b1 + k01 * x0 >= t1 - tolerance)) {
            x0 = 0;
            x1 = (t1 - b1) / k11;
            if (!(x1 >= 0 && b0 + k01 * x1 >= t0 - tolerance)) {
              x0 = p0;
              x1 = p1;
            }
          }
        }
        d0 = x0 - p0;
        d1 = x1 - p1;
        if (det > 1e-9 * k00 * k11) {
          // The targets come from the approach, the velocities from after the sub-steps, whose
          // push-out of an overlap the speculative margin missed has already turned the points
          // apart, each by its own amount: a rigid pair cannot then meet both targets, and the
          // point left free overshoots its own, which gained a pair of planks up to 22 % of
          // their energy at e = 1 (test/rigid-physics.test.ts). The kinetic energy an impulse at the two points changes is
          // v K^-1 v / 2 of their normal speeds v; the change (d0, d1) is scaled back where needed so
          // that this ends no higher than e^2 times its value at the approach speeds (in units of
          // twice the energy below).
          const limit = (e * e * (k11 * bounce0 * bounce0 - 2 * k01 * bounce0 * bounce1 + k00 * bounce1 * bounce1)) / det;
          const now = (k11 * vn0 * vn0 - 2 * k01 * vn0 * vn1 + k00 * vn1 * vn1) / det;
          const kd0 = k00 * d0 + k01 * d1;
          const kd1 = k01 * d0 + k11 * d1;
          // energy(v + lambda K d) = now + 2 lambda (v . d) + lambda^2 (d . K d)
          const linear = vn0 * d0 + vn1 * d1;
          const square = d0 * kd0 + d1 * kd1;
          if (now + 2 * linear + square > limit * (1 + 1e-9)) {
            let lambda = 0;
            if (now < limit && square > 0) {
              lambda = (-linear + Math.sqrt(linear * linear + square * (limit - now))) / square;
              lambda = lambda < 0 ? 0 : lambda > 1 ? 1 : lambda;
            }
            d0 *= lambda;
            d1 *= lambda;
            x0 = p0 + d0;
            x1 = p1 + d1;
          }
        }
        total0 = x0;
        total1 = x1;
        const px = (d0 + d1) * nx;
        const py = (d0 + d1) * ny;
        vAx -= mA * px;
        vAy -= mA * py;
        wA -= iA * (d0 * rn0a + d1 * rn1a);
        vBx += mB * px;
        vBy += mB * py;
        wB += iB * (d0 * rn0b + d1 * rn1b);
      } else {
        for (let p = 0; p < pointCount; p++) {
          if (!(p === 0 ? active0 : active1)) continue;
          const q = c + P + p * POINT;
          const rAx = constraints[q + RAX];
          const rAy = constraints[q + RAY];
          const rBx = constraints[q + RBX];
          const rBy = constraints[q + RBY];
          const dvx = vBx - wB * rBy - (vAx - wA * rAy);
          const dvy = vBy + wB * rBx - (vAy + wA * rAx);
          const vn = dvx * nx + dvy * ny;
          const accumulated = p === 0 ? p0 : p1;
          let impulse = -constraints[q + NORMAL_MASS] * (vn + e * (p === 0 ? bounce0 : bounce1));
          const total = Math.max(accumulated + impulse, 0);
          impulse = total - accumulated;
          if (p === 0) {
            d0 = impulse;
            total0 = total;
          } else {
            d1 = impulse;
            total1 = total;
          }
          const px = impulse * nx;
          const py = impulse * ny;
          vAx -= mA * px;
          vAy -= mA * py;
          wA -= iA * (rAx * py - rAy * px);
          vBx += mB * px;
          vBy += mB * py;
          wB += iB * (rBx * py - rBy * px);
        }
      }
      if (d0 === 0 && d1 === 0) continue;
      // Coulomb friction only takes energy, and restitution at most gives back what the impact
      // took: their bodies leave with no more kinetic energy than they would have had flying
      // free through the step (or than they had before this pass). The targets above restore
      // each point's normal speed, spin included, after friction has turned part of that spin
      // into sliding: a 2 x 0.5 box at 10 m/s spinning at 5 rad/s into a wall at e = 1,
      // friction 0.6, left with 2.45 % more energy than it came with. Without friction the
      // block above keeps the energy exactly, and kinematic bodies may give any.
      let lambda = 1;
      if (constraints[c + FRICTION] > 0 && (sa === 0 || states[sa + DYNAMIC] === 1) && (sb === 0 || states[sb + DYNAMIC] === 1)) {
        const before = bodyEnergy(vAx0, vAy0, wA0, mA, iA) + bodyEnergy(vBx0, vBy0, wB0, mB, iB);
        const after = bodyEnergy(vAx, vAy, wA, mA, iA) + bodyEnergy(vBx, vBy, wB, mB, iB);
        const free = this.freeEnergy(bodies, pairs[2 * i], mA, iA, gx, gy, dt) + this.freeEnergy(bodies, pairs[2 * i + 1], mB, iB, gx, gy, dt);
        const limit = Math.max(before, free);
        if (after > limit * (1 + 1e-12)) {
          // energy(v0 + lambda dv) = before + lambda linear + lambda^2 square
          const linear = 2 * (energyCross(vAx0, vAy0, wA0, vAx - vAx0, vAy - vAy0, wA - wA0, mA, iA) + energyCross(vBx0, vBy0, wB0, vBx - vBx0, vBy - vBy0, wB - wB0, mB, iB));
          const square = bodyEnergy(vAx - vAx0, vAy - vAy0, wA - wA0, mA, iA) + bodyEnergy(vBx - vBx0, vBy - vBy0, wB - wB0, mB, iB);
          lambda = square > 0 ? (-linear + Math.sqrt(Math.max(linear * linear + 4 * square * (limit - before), 0))) / (2 * square) : 0;
          lambda = lambda > 0 ? (lambda < 1 ? lambda : 1) : 0;
          vAx = vAx0 + lambda * (vAx - vAx0);
          vAy = vAy0 + lambda * (vAy - vAy0);
          wA = wA0 + lambda * (wA - wA0);
          vBx = vBx0 + lambda * (vBx - vBx0);
          vBy = vBy0 + lambda * (vBy - vBy0);
          wB = wB0 + lambda * (wB - wB0);
          total0 = p0 + lambda * d0;
          total1 = p1 + lambda * d1;
        }
      }
      constraints[q0 + NORMAL_IMPULSE] = total0;
      if (total0 > constraints[q0 + MAX_NORMAL_IMPULSE]) constraints[q0 + MAX_NORMAL_IMPULSE] = total0;
      if (pointCount === 2) {
        constraints[q1 + NORMAL_IMPULSE] = total1;
        if (total1 > constraints[q1 + MAX_NORMAL_IMPULSE]) constraints[q1 + MAX_NORMAL_IMPULSE] = total1;
      }
      if (states[sa + DYNAMIC] === 1) {
        states[sa + VX] = vAx;
        states[sa + VY] = vAy;
        states[sa + W] = wA;
      }
      if (states[sb + DYNAMIC] === 1) {
        states[sb + VX] = vBx;
        states[sb + VY] = vBy;
        states[sb + W] = wB;
      }
    }
  }

  /**
   * The kinetic energy body k (a solver index; 0, static, has none) would have at the step's end
   * flying free: its velocities at the step's start, which the store still holds, plus what
   * gravity, forces and torques add over the step (damping, which only takes, left out).
   */
  private freeEnergy(bodies: BodyStore, k: number, invMass: number, invInertia: number, gx: number, gy: number, dt: number): number {
    if (k === 0) return 0;
    const slot = this.awake[k - 1];
    const g = bodies.gravityScale[slot];
    const rigid = bodies.rigid!;
    const vx = bodies.vx[slot] + dt * (invMass * bodies.forceX[slot] + g * gx);
    const vy = bodies.vy[slot] + dt * (invMass * bodies.forceY[slot] + g * gy);
    const w = invInertia > 0 ? rigid.angularVelocity[slot] + dt * invInertia * rigid.torque[slot] : 0;
    return bodyEnergy(vx, vy, w, invMass, invInertia);
  }

  /** Keeps the impulses on the contacts, for the next step's warm start and for events. */
  private store(contacts: ContactList): void {
    const { constraints, laneAt } = this;
    const contactOrder = contacts.order;
    // In canonical order, as prepare reads them.
    for (let n = 0; n < contacts.count; n++) {
      const i = laneAt[n];
      if (i < 0) continue;
      const c = at(i);
      const pointCount = constraints[c + POINTS];
      if (pointCount === 0) continue;
      const k = contactOrder[n];
      contacts.rollingImpulse[k] = constraints[c + ROLLING_IMPULSE];
      for (let p = 0; p < pointCount; p++) {
        const q = c + P + p * POINT;
        const point = (2 * k + p) * POINT_STRIDE;
        contacts.points[point + PT_NORMAL_IMPULSE] = constraints[q + NORMAL_IMPULSE];
        contacts.points[point + PT_TANGENT_IMPULSE] = constraints[q + TANGENT_IMPULSE];
        contacts.points[point + PT_TOTAL_NORMAL_IMPULSE] = constraints[q + MAX_NORMAL_IMPULSE];
      }
    }
  }

  /** Applies each moving body's motion over the step to its position and rotation, and its velocity to the columns. */
  private finish(bodies: BodyStore): void {
    const { awake, awakeCount, states } = this;
    const { x, y, vx, vy } = bodies;
    const rigid = bodies.rigid!;
    const { c, s, angularVelocity } = rigid;
    for (let k = 0; k < awakeCount; k++) {
      const slot = awake[k];
      const b = (k + 1) * BODY;
      x[slot] += states[b + DPX];
      y[slot] += states[b + DPY];
      vx[slot] = states[b + VX];
      vy[slot] = states[b + VY];
      angularVelocity[slot] = states[b + W];
      const dc = states[b + DQC];
      const ds = states[b + DQS];
      const c0 = c[slot];
      const s0 = s[slot];
      const c2 = dc * c0 - ds * s0;
      const s2 = ds * c0 + dc * s0;
      const length = Math.sqrt(c2 * c2 + s2 * s2);
      c[slot] = c2 / length;
      s[slot] = s2 / length;
    }
  }
}
