import type { BodyStore } from '../store/body-store.js';
import type { ContactBuffer } from '../store/contact-buffer.js';
import { mixRestitution } from './restitution.js';
import { outsideBox } from './box-walls.js';
import type { ContactEvents } from '../store/contact-events.js';
import { touchSleeper } from './sleep.js';

/**
 * Resolves contacts one after another, in the buffer's canonical order (report 3.1.5, 5.10).
 *
 * For each pair, from the current positions (an earlier contact may have moved either body):
 * 1. if the bodies approach along the normal, an impulse j = -(1 + e) vn / (1/ma + 1/mb) is applied
 *    equal and opposite, which conserves momentum and, at e = 1, kinetic energy;
 * 2. the overlap is removed by moving each body along the normal in proportion to its inverse mass,
 *    so the pair ends tangent and the heavier body moves less (the report's mass-weighted split).
 *    With `positionCorrection` under 1 or a `contactSlop`, only that fraction of the overlap beyond
 *    the slop is removed: the pair stays a little overlapped, so it is a contact again next step
 *    and its impulse, not a jump in position, holds it up (Box2D's Baumgarte correction and slop).
 *    At the defaults, 1 and 0, the arithmetic is the report's to the bit.
 *
 * Static and kinematic bodies have inverse mass 0: they neither change velocity nor move. Pairs
 * that are already separating keep their velocities, so a pair is never pulled back together.
 * Concentric circles, which have no normal, are pushed apart along +x.
 *
 * Approach speeds under `restitutionThreshold` bounce with restitution 0 (Box2D's threshold).
 * A sleeping body touched by one faster than the sleep speed wakes here, before its contact is
 * solved, so waking follows the canonical order too; touched by a slower one, it stays asleep and
 * takes the contact as a static body (see sleep.ts). Hits at or above `hitThreshold` approach speed are recorded.
 */
export interface SolverSettings {
  /** Approach speeds below this bounce with restitution 0. */
  restitutionThreshold: number;
  /** Approach speeds at or above this are recorded as hit events. */
  hitThreshold: number;
  /** Fraction of the overlap beyond the slop removed per step, in (0, 1]. */
  positionCorrection: number;
  /** Overlap left in place. */
  contactSlop: number;
  /** 1: this module's single pass; more: IterativeSolver. */
  iterations: number;
  /** A sleeper touched by a body faster than this wakes (the world's sleepSpeed; see sleep.ts). */
  wakeSpeed: number;
}

/**
 * Returns true when the body kernel solved and, given a box, noted in `bodies.kernel.escaped` every
 * body separation left outside it: the correct stage then clamps those alone (see EscapeLog).
 */
export function solveContacts(
  bodies: BodyStore,
  contacts: ContactBuffer,
  events: ContactEvents | null,
  settings: SolverSettings,
  box: { width: number; height: number } | null = null,
): boolean {
  const { lo, hi, count } = contacts;
  // The kernel's loop is resolveContact without hit events or waking.
  if (bodies.kernel && events === null && bodies.sleepingCount === 0) {
    bodies.kernel.solveContacts(lo, hi, count, settings, box?.width ?? 0, box?.height ?? 0);
    return true;
  }
  for (let k = 0; k < count; k++) resolveContact(bodies, lo[k], hi[k], settings, events);
  return false;
}

/**
 * Resolves a block [from, to) of the canonical order on one thread of a parallel step, beside
 * other threads doing the blocks after it, deferring what must wait. A contact is deferred when
 * either body appears in a contact before the block (another thread may be moving it now, and it
 * must see that thread's result first) or in a contact deferred already (so each body's contacts
 * keep their order). Every other contact reads and writes bodies no earlier block touches and no
 * later block touches before its deferred pass, so resolving the deferred ones afterwards, in
 * order, gives each body exactly the serial sequence of updates: the same bits.
 * `mark` (one entry per slot, thread-private) is stamped rather than cleared. Returns how many
 * contact indices were written to `deferred` from `from` on.
 */
export function solveContactBlock(
  bodies: BodyStore,
  lo: Int32Array,
  hi: Int32Array,
  from: number,
  to: number,
  settings: SolverSettings,
  mark: Int32Array,
  stamp: number,
  deferred: Int32Array,
  escapes: EscapeLog,
): number {
  // Only bodies this block can touch need marks: in canonical order every contact of the block has
  // lo >= lo[from] (and hi > lo), while earlier contacts have lo <= lo[from].
  const least = from < to ? lo[from] : 0;
  for (let k = 0; k < from; k++) {
    if (lo[k] >= least) mark[lo[k]] = stamp;
    if (hi[k] >= least) mark[hi[k]] = stamp;
  }
  let waiting = 0;
  // With the body kernel, the contacts not deferred are queued and resolved there, in order: which
  // are deferred depends on the marks alone, not on what resolving does.
  const kernel = bodies.kernel;
  for (let k = from; k < to; k++) {
    const i = lo[k];
    const j = hi[k];
    if (mark[i] === stamp || mark[j] === stamp) {
      mark[i] = stamp;
      mark[j] = stamp;
      deferred[from + waiting++] = k;
      continue;
    }
    if (kernel) {
      kernel.queue(i, j);
      continue;
    }
    resolveContact(bodies, i, j, settings, null);
    escapes.note(bodies, i, j);
  }
  if (kernel) {
    kernel.solveQueue(settings, escapes.width, escapes.height);
    escapes.noteSlots(kernel.escaped, kernel.escapedCount);
  }
  return waiting;
}

/**
 * Bodies that separation pushed out of the box, noted as it happens, so that correct clamps just
 * those instead of every contact body: a body can only end the solve outside if some contact left
 * it outside, and clamping one that came back inside changes nothing. Writes slots to
 * `list[at..at+count)`; with width 0 (no box) it notes nothing.
 */
export class EscapeLog {
  list: Int32Array = new Int32Array(0);
  at = 0;
  count = 0;
  width = 0;
  height = 0;

  reset(list: Int32Array, at: number, width: number, height: number): void {
    this.list = list;
    this.at = at;
    this.count = 0;
    this.width = width;
    this.height = height;
  }

  /** Notes slots already known to be outside (the body kernel's solve found them). */
  noteSlots(slots: Int32Array, count: number): void {
    for (let e = 0; e < count; e++) this.list[this.at + this.count++] = slots[e];
  }

  note(bodies: BodyStore, i: number, j: number): void {
    if (this.width === 0) return;
    if (outsideBox(bodies, i, this.width, this.height)) this.list[this.at + this.count++] = i;
    if (outsideBox(bodies, j, this.width, this.height)) this.list[this.at + this.count++] = j;
  }
}

/** Resolves one contact (lo slot i, hi slot j): the body of the loop described above. */
export function resolveContact(bodies: BodyStore, i: number, j: number, settings: SolverSettings, events: ContactEvents | null): void {
  const { x, y, vx, vy, radius, invMass, restitution, asleep } = bodies;
  const dx = x[j] - x[i];
  const dy = y[j] - y[i];
  const reach = radius[i] + radius[j];
  const distSq = dx * dx + dy * dy;
  if (distSq >= reach * reach) return;
  let wi = invMass[i];
  let wj = invMass[j];
  if (bodies.sleepingCount > 0) {
    if (asleep[i]) wi = touchSleeper(bodies, i, j, settings.wakeSpeed);
    if (asleep[j]) wj = touchSleeper(bodies, j, i, settings.wakeSpeed);
  }
  const w = wi + wj;
  if (w === 0) return;
  let nx = 1;
  let ny = 0;
  const dist = Math.sqrt(distSq);
  if (dist > 0) {
    nx = dx / dist;
    ny = dy / dist;
  }
  const vn = (vx[j] - vx[i]) * nx + (vy[j] - vy[i]) * ny;
  if (vn < 0) {
    if (-vn >= settings.hitThreshold && events) events.recordHit(bodies, i, j, -vn);
    const e = -vn < settings.restitutionThreshold ? 0 : mixRestitution(restitution[i], restitution[j]);
    const impulse = (-(1 + e) * vn) / w;
    const pi = impulse * wi;
    const pj = impulse * wj;
    vx[i] -= pi * nx;
    vy[i] -= pi * ny;
    vx[j] += pj * nx;
    vy[j] += pj * ny;
  }
  // Subtracting 0 and multiplying by 1 leave a double unchanged: the defaults keep the report's bits.
  const excess = reach - dist - settings.contactSlop;
  if (!(excess > 0)) return;
  const push = excess * settings.positionCorrection;
  const si = (push * wi) / w;
  const sj = (push * wj) / w;
  x[i] -= si * nx;
  y[i] -= si * ny;
  x[j] += sj * nx;
  y[j] += sj * ny;
}
