import type { BodyStore } from '../store/body-store.js';
import type { ContactBuffer } from '../store/contact-buffer.js';
import type { ContactEvents } from '../store/contact-events.js';
import { TypeCode } from '../store/body-types.js';
import { grownCapacity, grow } from '../util/grow.js';
import { mixRestitution } from './restitution.js';
import type { SolverSettings } from './contact-solver.js';
import type { SegmentGrid, SegmentStore } from '../store/segment-store.js';
import { closestOnSegment, segmentNormal } from '../narrowphase/circle-segment.js';
import { touchSleeper } from './sleep.js';

/** Static contacts are keyed by body, then by this: a box wall's side (0-3), or FIRST_SEGMENT + the segment's slot. */
const FIRST_SEGMENT = 4;

const closest = new Float64Array(2);
/** The unit normal from a segment's closest point towards a body (segmentNormal's result). */
const normal = new Float64Array(2);

/**
 * The solve for `solverIterations` above 1: sequential impulses as in Box2D v2, for piles and
 * stacks, which the report's one pass (contact-solver.ts) cannot hold up.
 *
 * - Every contact keeps an accumulated normal impulse, clamped at zero (contacts push, never
 *   pull), and each of `iterations` passes corrects it towards the velocity the contact should
 *   have: the restitution bounce of its approach speed at the start of the solve, or zero.
 * - The box walls and the static segments take part as static contacts: a moving body whose
 *   centre lies within its radius (and the slop) of a wall, where the walls stage left it, or that
 *   overlaps a segment's capsule. Without them, nothing in the solve carries a pile's weight down
 *   to the floor or the ramp. Segment contacts are the ones solveSegmentContacts would find, in
 *   the same order, with the same touch and hit events; that pass does not run after this one.
 * - Impulses are warm-started: a contact, or static contact, that already existed in the last
 *   step starts from last step's impulse. The lists are in ascending slot order, so one merge
 *   matches them, with no hashing (as PairDiff does for events); a slot whose handle changed
 *   holds a new body, which starts from zero.
 * - Then `iterations` passes of separation, with the positionCorrection and contactSlop of the
 *   single pass, the static contacts pushed out in the same loop.
 *
 * Serial, in the canonical order, so its bits do not depend on the broad-phase or thread count;
 * they differ from the single pass, which stays the default and the report's model.
 */
export class IterativeSolver {
  private normalX = new Float64Array(0);
  private normalY = new Float64Array(0);
  private bounce = new Float64Array(0);
  private impulse = new Float64Array(0);
  /** Inverse masses on each side of a contact: 0 for a sleeper that stays asleep (see sleep.ts). */
  private inverseLo = new Float64Array(0);
  private inverseHi = new Float64Array(0);
  private lastLo = new Int32Array(0);
  private lastHi = new Int32Array(0);
  /** The handles in those slots then: a slot reused by a new body must not inherit an impulse. */
  private lastHandleLo = new Float64Array(0);
  private lastHandleHi = new Float64Array(0);
  private lastImpulse = new Float64Array(0);
  private lastCount = 0;
  // Static contacts: body slot, key (a wall's side: 0 x = 0, 1 x = width, 2 y = 0, 3 y = height;
  // or FIRST_SEGMENT + segment slot), normal towards the body, bounce, impulse.
  private staticBody = new Int32Array(16);
  private staticKey = new Int32Array(16);
  private staticNormalX = new Float64Array(16);
  private staticNormalY = new Float64Array(16);
  private staticBounce = new Float64Array(16);
  private staticImpulse = new Float64Array(16);
  private staticCount = 0;
  private lastStaticBody = new Int32Array(0);
  private lastStaticHandle = new Float64Array(0);
  /** The segment's handle for a segment contact (-1 for a wall): a reused segment slot starts from zero too. */
  private lastStaticOther = new Float64Array(0);
  private lastStaticKey = new Int32Array(0);
  private lastStaticImpulse = new Float64Array(0);
  private lastStaticCount = 0;

  /** Returns the number of body-segment contacts, as solveSegmentContacts does. */
  solve(
    bodies: BodyStore,
    contacts: ContactBuffer,
    segments: SegmentStore,
    segmentGrid: SegmentGrid,
    settings: SolverSettings,
    box: { width: number; height: number } | null,
    iterations: number,
    events: ContactEvents | null,
  ): number {
    const { lo, hi, count } = contacts;
    this.ensure(count);
    this.prepare(bodies, lo, hi, count, settings, events);
    const segmentContacts = this.findStatic(bodies, box, segments, segmentGrid, settings, events);
    this.warmStart(bodies, segments, lo, hi, count);
    for (let pass = 0; pass < iterations; pass++) this.velocityPass(bodies, lo, hi, count);
    for (let pass = 0; pass < iterations; pass++) this.positionPass(bodies, lo, hi, count, settings, box, segments);
    this.remember(bodies, segments, lo, hi, count);
    return segmentContacts;
  }

  /** Normals, and the bounce each contact should end with, from the state before any impulse. */
  private prepare(bodies: BodyStore, lo: Int32Array, hi: Int32Array, count: number, settings: SolverSettings, events: ContactEvents | null): void {
    const { x, y, vx, vy, restitution, asleep, invMass } = bodies;
    const { normalX, normalY, bounce, inverseLo, inverseHi } = this;
    for (let k = 0; k < count; k++) {
      const i = lo[k];
      const j = hi[k];
      inverseLo[k] = invMass[i];
      inverseHi[k] = invMass[j];
      if (bodies.sleepingCount > 0) {
        if (asleep[i]) inverseLo[k] = touchSleeper(bodies, i, j, settings.wakeSpeed);
        if (asleep[j]) inverseHi[k] = touchSleeper(bodies, j, i, settings.wakeSpeed);
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

  /**
   * Static contacts of the moving bodies, in slot order, each body's walls then its segments in
   * slot order: the walls the walls stage left it touching, and the segments whose capsule it
   * overlaps (noted for the events as solveSegmentContacts notes them). Returns the segment count.
   */
  private findStatic(
    bodies: BodyStore,
    box: { width: number; height: number } | null,
    segments: SegmentStore,
    grid: SegmentGrid,
    settings: SolverSettings,
    events: ContactEvents | null,
  ): number {
    this.staticCount = 0;
    const { x, y, vx, vy, radius, restitution, type, asleep, category, mask, slotCount } = bodies;
    const slop = settings.contactSlop;
    const reach = bodies.maxRadius() + slop;
    const withSegments = segments.count > 0;
    let segmentContacts = 0;
    for (let i = 0; i < slotCount; i++) {
      if (type[i] !== TypeCode.dynamic || asleep[i]) continue;
      const px = x[i];
      const py = y[i];
      const r = radius[i];
      if (box && !(px > reach && px < box.width - reach && py > reach && py < box.height - reach)) {
        if (px <= r + slop) this.addStatic(i, 0, 1, 0, 0);
        else if (px >= box.width - r - slop) this.addStatic(i, 1, -1, 0, 0);
        if (py <= r + slop) this.addStatic(i, 2, 0, 1, 0);
        else if (py >= box.height - r - slop) this.addStatic(i, 3, 0, -1, 0);
      }
      if (!withSegments) continue;
      const near = grid.box;
      near[0] = px - r;
      near[1] = py - r;
      near[2] = px + r;
      near[3] = py + r;
      const found = grid.queryBox(segments);
      for (let k = 0; k < found; k++) {
        const s = grid.found[k];
        if ((category[i] & segments.mask[s]) === 0 || (segments.category[s] & mask[i]) === 0) continue;
        closestOnSegment(px, py, segments.ax[s], segments.ay[s], segments.bx[s], segments.by[s], closest);
        const dx = px - closest[0];
        const dy = py - closest[1];
        const touch = r + segments.thickness[s];
        const distSq = dx * dx + dy * dy;
        if (distSq >= touch * touch) continue;
        segmentContacts++;
        events?.noteSegmentTouch(i, s);
        const dist = Math.sqrt(distSq);
        segmentNormal(dx, dy, dist, segments.ax[s], segments.ay[s], segments.bx[s], segments.by[s], normal);
        const vn = vx[i] * normal[0] + vy[i] * normal[1];
        if (vn < 0 && -vn >= settings.hitThreshold && events) events.recordSegmentHit(bodies, i, segments, s, -vn);
        const bounce = vn < 0 && -vn >= settings.restitutionThreshold ? -mixRestitution(restitution[i], segments.restitution[s]) * vn : 0;
        this.addStatic(i, FIRST_SEGMENT + s, normal[0], normal[1], bounce);
      }
    }
    return segmentContacts;
  }

  private addStatic(i: number, key: number, nx: number, ny: number, bounce: number): void {
    if (this.staticCount === this.staticBody.length) {
      const capacity = grownCapacity(this.staticBody.length, this.staticCount + 1);
      this.staticBody = grow(this.staticBody, capacity);
      this.staticKey = grow(this.staticKey, capacity);
      this.staticNormalX = grow(this.staticNormalX, capacity);
      this.staticNormalY = grow(this.staticNormalY, capacity);
      this.staticBounce = grow(this.staticBounce, capacity);
      this.staticImpulse = grow(this.staticImpulse, capacity);
    }
    const k = this.staticCount++;
    this.staticBody[k] = i;
    this.staticKey[k] = key;
    this.staticNormalX[k] = nx;
    this.staticNormalY[k] = ny;
    this.staticBounce[k] = bounce;
  }

  /** Starts each contact from last step's impulse where it existed then, and applies it. */
  private warmStart(bodies: BodyStore, segments: SegmentStore, lo: Int32Array, hi: Int32Array, count: number): void {
    const { vx, vy, invMass } = bodies;
    const { impulse, normalX, normalY, inverseLo, inverseHi, lastLo, lastHi, lastHandleLo, lastHandleHi, lastImpulse, lastCount } = this;
    let p = 0;
    for (let k = 0; k < count; k++) {
      const i = lo[k];
      const j = hi[k];
      while (p < lastCount && (lastLo[p] < i || (lastLo[p] === i && lastHi[p] < j))) p++;
      const same = p < lastCount && lastLo[p] === i && lastHi[p] === j && lastHandleLo[p] === bodies.handleOf(i) && lastHandleHi[p] === bodies.handleOf(j);
      const carried = same ? lastImpulse[p] : 0;
      impulse[k] = carried;
      if (carried === 0) continue;
      vx[i] -= carried * inverseLo[k] * normalX[k];
      vy[i] -= carried * inverseLo[k] * normalY[k];
      vx[j] += carried * inverseHi[k] * normalX[k];
      vy[j] += carried * inverseHi[k] * normalY[k];
    }
    const { staticBody, staticKey, staticNormalX, staticNormalY, staticImpulse, staticCount, lastStaticBody, lastStaticHandle, lastStaticKey, lastStaticImpulse, lastStaticCount } =
      this;
    let q = 0;
    for (let c = 0; c < staticCount; c++) {
      const i = staticBody[c];
      const key = staticKey[c];
      while (q < lastStaticCount && (lastStaticBody[q] < i || (lastStaticBody[q] === i && lastStaticKey[q] < key))) q++;
      const same =
        q < lastStaticCount &&
        lastStaticBody[q] === i &&
        lastStaticKey[q] === key &&
        lastStaticHandle[q] === bodies.handleOf(i) &&
        this.lastStaticOther[q] === otherHandle(segments, key);
      const carried = same ? lastStaticImpulse[q] : 0;
      staticImpulse[c] = carried;
      if (carried === 0) continue;
      vx[i] += carried * invMass[i] * staticNormalX[c];
      vy[i] += carried * invMass[i] * staticNormalY[c];
    }
  }

  /** One pass of clamped impulses over the contacts, then over the wall contacts. */
  private velocityPass(bodies: BodyStore, lo: Int32Array, hi: Int32Array, count: number): void {
    const { vx, vy, invMass } = bodies;
    const { impulse, normalX, normalY, bounce, inverseLo, inverseHi } = this;
    for (let k = 0; k < count; k++) {
      const i = lo[k];
      const j = hi[k];
      const wi = inverseLo[k];
      const wj = inverseHi[k];
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
    const { staticBody, staticNormalX, staticNormalY, staticBounce, staticImpulse, staticCount } = this;
    for (let c = 0; c < staticCount; c++) {
      const i = staticBody[c];
      const wi = invMass[i];
      const nx = staticNormalX[c];
      const ny = staticNormalY[c];
      // Speed away from the wall or segment. The walls stage has bounced the body already, so a
      // wall's bounce is 0; a segment's is its restitution's.
      const vn = vx[i] * nx + vy[i] * ny;
      const total = Math.max(0, staticImpulse[c] + (staticBounce[c] - vn) / wi);
      const delta = total - staticImpulse[c];
      staticImpulse[c] = total;
      vx[i] += delta * wi * nx;
      vy[i] += delta * wi * ny;
    }
  }

  /** One pass of separation (the single pass's, without its impulse), then the static contacts'. */
  private positionPass(
    bodies: BodyStore,
    lo: Int32Array,
    hi: Int32Array,
    count: number,
    settings: SolverSettings,
    box: { width: number; height: number } | null,
    segments: SegmentStore,
  ): void {
    const { x, y, radius } = bodies;
    const { positionCorrection, contactSlop } = settings;
    const { inverseLo, inverseHi } = this;
    for (let k = 0; k < count; k++) {
      const i = lo[k];
      const j = hi[k];
      const wi = inverseLo[k];
      const wj = inverseHi[k];
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
    const { staticBody, staticKey, staticCount } = this;
    for (let c = 0; c < staticCount; c++) {
      const i = staticBody[c];
      const key = staticKey[c];
      const r = radius[i];
      if (key < FIRST_SEGMENT) {
        // A wall: projected back onto it, as the correct stage would.
        if (key === 0 && x[i] < r) x[i] = r;
        else if (key === 1 && x[i] > box!.width - r) x[i] = box!.width - r;
        else if (key === 2 && y[i] < r) y[i] = r;
        else if (key === 3 && y[i] > box!.height - r) y[i] = box!.height - r;
        continue;
      }
      const s = key - FIRST_SEGMENT;
      closestOnSegment(x[i], y[i], segments.ax[s], segments.ay[s], segments.bx[s], segments.by[s], closest);
      const dx = x[i] - closest[0];
      const dy = y[i] - closest[1];
      const dist = Math.sqrt(dx * dx + dy * dy);
      const excess = r + segments.thickness[s] - dist - contactSlop;
      if (!(excess > 0)) continue;
      segmentNormal(dx, dy, dist, segments.ax[s], segments.ay[s], segments.bx[s], segments.by[s], normal);
      x[i] += excess * positionCorrection * normal[0];
      y[i] += excess * positionCorrection * normal[1];
    }
  }

  /** Keeps this step's contacts and impulses for the next step's warm start. */
  private remember(bodies: BodyStore, segments: SegmentStore, lo: Int32Array, hi: Int32Array, count: number): void {
    if (this.lastLo.length < count) {
      const capacity = grownCapacity(this.lastLo.length, count);
      this.lastLo = new Int32Array(capacity);
      this.lastHi = new Int32Array(capacity);
      this.lastHandleLo = new Float64Array(capacity);
      this.lastHandleHi = new Float64Array(capacity);
      this.lastImpulse = new Float64Array(capacity);
    }
    // Copied by hand: subarray() would make objects every step.
    for (let k = 0; k < count; k++) {
      this.lastLo[k] = lo[k];
      this.lastHi[k] = hi[k];
      this.lastHandleLo[k] = bodies.handleOf(lo[k]);
      this.lastHandleHi[k] = bodies.handleOf(hi[k]);
      this.lastImpulse[k] = this.impulse[k];
    }
    this.lastCount = count;
    if (this.lastStaticBody.length < this.staticCount) {
      const capacity = grownCapacity(this.lastStaticBody.length, this.staticCount);
      this.lastStaticBody = new Int32Array(capacity);
      this.lastStaticHandle = new Float64Array(capacity);
      this.lastStaticOther = new Float64Array(capacity);
      this.lastStaticKey = new Int32Array(capacity);
      this.lastStaticImpulse = new Float64Array(capacity);
    }
    for (let c = 0; c < this.staticCount; c++) {
      this.lastStaticBody[c] = this.staticBody[c];
      this.lastStaticHandle[c] = bodies.handleOf(this.staticBody[c]);
      this.lastStaticOther[c] = otherHandle(segments, this.staticKey[c]);
      this.lastStaticKey[c] = this.staticKey[c];
      this.lastStaticImpulse[c] = this.staticImpulse[c];
    }
    this.lastStaticCount = this.staticCount;
  }

  private ensure(count: number): void {
    if (this.impulse.length >= count) return;
    const capacity = grownCapacity(this.impulse.length, count);
    this.normalX = new Float64Array(capacity);
    this.normalY = new Float64Array(capacity);
    this.bounce = new Float64Array(capacity);
    this.impulse = new Float64Array(capacity);
    this.inverseLo = new Float64Array(capacity);
    this.inverseHi = new Float64Array(capacity);
  }

  memoryBytes(): number {
    // Six float64 columns per contact, two int32 and three float64 per remembered contact; per
    // static contact two int32 and four float64, and two int32 and three float64 remembered.
    return this.impulse.length * 48 + this.lastImpulse.length * 32 + this.staticBody.length * 40 + this.lastStaticBody.length * 32;
  }
}

/** What a static contact's key names beyond the body: a segment's handle, or -1 for a wall. */
function otherHandle(segments: SegmentStore, key: number): number {
  return key < FIRST_SEGMENT ? -1 : segments.handleOf(key - FIRST_SEGMENT);
}
