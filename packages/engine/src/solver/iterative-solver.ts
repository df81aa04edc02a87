import type { BodyStore } from '../store/body-store.js';
import type { ContactBuffer } from '../store/contact-buffer.js';
import type { ContactEvents } from '../store/contact-events.js';
import { TypeCode } from '../store/body-types.js';
import { grownCapacity, grow } from '../util/grow.js';
import { mixRestitution } from './restitution.js';
import type { SolverSettings } from './contact-solver.js';

/**
 * The solve for `solverIterations` above 1: sequential impulses as in Box2D v2, for piles and
 * stacks, which the report's one pass (contact-solver.ts) cannot hold up.
 *
 * - Every contact keeps an accumulated normal impulse, clamped at zero (contacts push, never
 *   pull), and each of `iterations` passes corrects it towards the velocity the contact should
 *   have: the restitution bounce of its approach speed at the start of the solve, or zero.
 * - The box walls take part as contacts: a moving body whose centre lies within its radius (and
 *   the slop) of a wall, where the walls stage left it, gets a wall contact. Without that, nothing
 *   in the solve carries a pile's weight down to the floor.
 * - Impulses are warm-started: a contact, or wall contact, that already existed in the last step
 *   starts from last step's impulse. Both lists are in ascending slot order, so one merge matches
 *   them, with no hashing (as PairDiff does for events).
 * - Then `iterations` passes of separation, with the positionCorrection and contactSlop of the
 *   single pass, and the walls projected in the same loop.
 *
 * Serial, in the canonical order, so its bits do not depend on the broad-phase or thread count;
 * they differ from the single pass, which stays the default and the report's model.
 */
export class IterativeSolver {
  private normalX = new Float64Array(0);
  private normalY = new Float64Array(0);
  private bounce = new Float64Array(0);
  private impulse = new Float64Array(0);
  private lastLo = new Int32Array(0);
  private lastHi = new Int32Array(0);
  private lastImpulse = new Float64Array(0);
  private lastCount = 0;
  // Wall contacts: body slot, wall (0: x = 0, 1: x = width, 2: y = 0, 3: y = height), impulse.
  private wallBody = new Int32Array(16);
  private wallSide = new Int32Array(16);
  private wallImpulse = new Float64Array(16);
  private wallCount = 0;
  private lastWallBody = new Int32Array(0);
  private lastWallSide = new Int32Array(0);
  private lastWallImpulse = new Float64Array(0);
  private lastWallCount = 0;

  solve(
    bodies: BodyStore,
    contacts: ContactBuffer,
    settings: SolverSettings,
    box: { width: number; height: number } | null,
    iterations: number,
    events: ContactEvents | null,
  ): void {
    const { lo, hi, count } = contacts;
    this.ensure(count);
    this.prepare(bodies, lo, hi, count, settings, events);
    this.findWalls(bodies, box, settings.contactSlop);
    this.warmStart(bodies, lo, hi, count);
    for (let pass = 0; pass < iterations; pass++) this.velocityPass(bodies, lo, hi, count);
    for (let pass = 0; pass < iterations; pass++) this.positionPass(bodies, lo, hi, count, settings, box);
    this.remember(lo, hi, count);
  }

  /** Normals, and the bounce each contact should end with, from the state before any impulse. */
  private prepare(bodies: BodyStore, lo: Int32Array, hi: Int32Array, count: number, settings: SolverSettings, events: ContactEvents | null): void {
    const { x, y, vx, vy, restitution, asleep } = bodies;
    const { normalX, normalY, bounce } = this;
    for (let k = 0; k < count; k++) {
      const i = lo[k];
      const j = hi[k];
      if (bodies.sleepingCount > 0) {
        if (asleep[i]) bodies.wake(i);
        if (asleep[j]) bodies.wake(j);
      }
      const dx = x[j] - x[i];
      const dy = y[j] - y[i];
      const dist = Math.sqrt(dx * dx + dy * dy);
      // Concentric circles: pushed apart along +x, as in the single pass.
      const nx = dist > 0 ? dx / dist : 1;
      const ny = dist > 0 ? dy / dist : 0;
      normalX[k] = nx;
      normalY[k] = ny;
      const vn = (vx[j] - vx[i]) * nx + (vy[j] - vy[i]) * ny;
      if (vn < 0 && -vn >= settings.hitThreshold && events) events.recordHit(bodies, i, j, -vn);
      bounce[k] = vn < 0 && -vn >= settings.restitutionThreshold ? -mixRestitution(restitution[i], restitution[j]) * vn : 0;
    }
  }

  /** Wall contacts of the moving bodies the walls stage left touching a wall, in slot then wall order. */
  private findWalls(bodies: BodyStore, box: { width: number; height: number } | null, slop: number): void {
    this.wallCount = 0;
    if (!box) return;
    const { x, y, radius, type, asleep, invMass, slotCount } = bodies;
    const reach = bodies.maxRadius() + slop;
    for (let i = 0; i < slotCount; i++) {
      const px = x[i];
      const py = y[i];
      if (px > reach && px < box.width - reach && py > reach && py < box.height - reach) continue;
      if (type[i] !== TypeCode.dynamic || asleep[i] || invMass[i] === 0) continue;
      const r = radius[i] + slop;
      if (px <= r) this.addWall(i, 0);
      else if (px >= box.width - r) this.addWall(i, 1);
      if (py <= r) this.addWall(i, 2);
      else if (py >= box.height - r) this.addWall(i, 3);
    }
  }

  private addWall(i: number, side: number): void {
    if (this.wallCount === this.wallBody.length) {
      const capacity = grownCapacity(this.wallBody.length, this.wallCount + 1);
      this.wallBody = grow(this.wallBody, capacity);
      this.wallSide = grow(this.wallSide, capacity);
      this.wallImpulse = grow(this.wallImpulse, capacity);
    }
    this.wallBody[this.wallCount] = i;
    this.wallSide[this.wallCount++] = side;
  }

  /** Starts each contact from last step's impulse where it existed then, and applies it. */
  private warmStart(bodies: BodyStore, lo: Int32Array, hi: Int32Array, count: number): void {
    const { vx, vy, invMass } = bodies;
    const { impulse, normalX, normalY, lastLo, lastHi, lastImpulse, lastCount } = this;
    let p = 0;
    for (let k = 0; k < count; k++) {
      const i = lo[k];
      const j = hi[k];
      while (p < lastCount && (lastLo[p] < i || (lastLo[p] === i && lastHi[p] < j))) p++;
      const carried = p < lastCount && lastLo[p] === i && lastHi[p] === j ? lastImpulse[p] : 0;
      impulse[k] = carried;
      if (carried === 0) continue;
      vx[i] -= carried * invMass[i] * normalX[k];
      vy[i] -= carried * invMass[i] * normalY[k];
      vx[j] += carried * invMass[j] * normalX[k];
      vy[j] += carried * invMass[j] * normalY[k];
    }
    const { wallBody, wallSide, wallImpulse, wallCount, lastWallBody, lastWallSide, lastWallImpulse, lastWallCount } = this;
    let q = 0;
    for (let w = 0; w < wallCount; w++) {
      const i = wallBody[w];
      const side = wallSide[w];
      while (q < lastWallCount && (lastWallBody[q] < i || (lastWallBody[q] === i && lastWallSide[q] < side))) q++;
      const carried = q < lastWallCount && lastWallBody[q] === i && lastWallSide[q] === side ? lastWallImpulse[q] : 0;
      wallImpulse[w] = carried;
      if (carried === 0) continue;
      if (side < 2) vx[i] += carried * invMass[i] * inward(side);
      else vy[i] += carried * invMass[i] * inward(side);
    }
  }

  /** One pass of clamped impulses over the contacts, then over the wall contacts. */
  private velocityPass(bodies: BodyStore, lo: Int32Array, hi: Int32Array, count: number): void {
    const { vx, vy, invMass } = bodies;
    const { impulse, normalX, normalY, bounce } = this;
    for (let k = 0; k < count; k++) {
      const i = lo[k];
      const j = hi[k];
      const wi = invMass[i];
      const wj = invMass[j];
      const w = wi + wj;
      if (w === 0) continue;
      const nx = normalX[k];
      const ny = normalY[k];
      const vn = (vx[j] - vx[i]) * nx + (vy[j] - vy[i]) * ny;
      const total = Math.max(0, impulse[k] + (bounce[k] - vn) / w);
      const delta = total - impulse[k];
      impulse[k] = total;
      vx[i] -= delta * wi * nx;
      vy[i] -= delta * wi * ny;
      vx[j] += delta * wj * nx;
      vy[j] += delta * wj * ny;
    }
    const { wallBody, wallSide, wallImpulse, wallCount } = this;
    for (let w = 0; w < wallCount; w++) {
      const i = wallBody[w];
      const side = wallSide[w];
      const n = inward(side);
      const wi = invMass[i];
      // Speed away from the wall; the walls stage has already bounced it, so the target is 0.
      const vn = (side < 2 ? vx[i] : vy[i]) * n;
      const total = Math.max(0, wallImpulse[w] - vn / wi);
      const delta = total - wallImpulse[w];
      wallImpulse[w] = total;
      if (side < 2) vx[i] += delta * wi * n;
      else vy[i] += delta * wi * n;
    }
  }

  /** One pass of separation (the single pass's, without its impulse), with the walls projected. */
  private positionPass(
    bodies: BodyStore,
    lo: Int32Array,
    hi: Int32Array,
    count: number,
    settings: SolverSettings,
    box: { width: number; height: number } | null,
  ): void {
    const { x, y, radius, invMass } = bodies;
    const { positionCorrection, contactSlop } = settings;
    for (let k = 0; k < count; k++) {
      const i = lo[k];
      const j = hi[k];
      const wi = invMass[i];
      const wj = invMass[j];
      const w = wi + wj;
      if (w === 0) continue;
      const dx = x[j] - x[i];
      const dy = y[j] - y[i];
      const dist = Math.sqrt(dx * dx + dy * dy);
      const excess = radius[i] + radius[j] - dist - contactSlop;
      if (!(excess > 0)) continue;
      const nx = dist > 0 ? dx / dist : 1;
      const ny = dist > 0 ? dy / dist : 0;
      const push = excess * positionCorrection;
      x[i] -= ((push * wi) / w) * nx;
      y[i] -= ((push * wi) / w) * ny;
      x[j] += ((push * wj) / w) * nx;
      y[j] += ((push * wj) / w) * ny;
    }
    if (!box) return;
    const { wallBody, wallCount } = this;
    for (let w = 0; w < wallCount; w++) {
      const i = wallBody[w];
      const r = radius[i];
      if (x[i] < r) x[i] = r;
      else if (x[i] > box.width - r) x[i] = box.width - r;
      if (y[i] < r) y[i] = r;
      else if (y[i] > box.height - r) y[i] = box.height - r;
    }
  }

  /** Keeps this step's contacts and impulses for the next step's warm start. */
  private remember(lo: Int32Array, hi: Int32Array, count: number): void {
    if (this.lastLo.length < count) {
      const capacity = grownCapacity(this.lastLo.length, count);
      this.lastLo = new Int32Array(capacity);
      this.lastHi = new Int32Array(capacity);
      this.lastImpulse = new Float64Array(capacity);
    }
    // Copied by hand: subarray() would make objects every step.
    for (let k = 0; k < count; k++) {
      this.lastLo[k] = lo[k];
      this.lastHi[k] = hi[k];
      this.lastImpulse[k] = this.impulse[k];
    }
    this.lastCount = count;
    if (this.lastWallBody.length < this.wallCount) {
      const capacity = grownCapacity(this.lastWallBody.length, this.wallCount);
      this.lastWallBody = new Int32Array(capacity);
      this.lastWallSide = new Int32Array(capacity);
      this.lastWallImpulse = new Float64Array(capacity);
    }
    for (let w = 0; w < this.wallCount; w++) {
      this.lastWallBody[w] = this.wallBody[w];
      this.lastWallSide[w] = this.wallSide[w];
      this.lastWallImpulse[w] = this.wallImpulse[w];
    }
    this.lastWallCount = this.wallCount;
  }

  private ensure(count: number): void {
    if (this.impulse.length >= count) return;
    const capacity = grownCapacity(this.impulse.length, count);
    this.normalX = new Float64Array(capacity);
    this.normalY = new Float64Array(capacity);
    this.bounce = new Float64Array(capacity);
    this.impulse = new Float64Array(capacity);
  }

  memoryBytes(): number {
    // Four float64 columns per contact, two int32 and a float64 per remembered contact, and the
    // same two int32 and a float64 for each wall contact, current and remembered.
    return this.impulse.length * 32 + this.lastImpulse.length * 16 + (this.wallBody.length + this.lastWallBody.length) * 16;
  }
}

/** +1 for the low wall of an axis (the body must move up from it), -1 for the high one. */
function inward(side: number): number {
  return (side & 1) === 0 ? 1 : -1;
}
