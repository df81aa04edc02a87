import type { BodyStore } from '../store/body-store.js';
import { TypeCode } from '../store/body-types.js';
import { mixRestitution } from './restitution.js';
import type { ContactBuffer } from '../store/contact-buffer.js';
import type { ContactEvents } from '../store/contact-events.js';

/** The box walls as events name them: the wall at x = 0, x = width, y = 0 and y = height. */
export const BoxWall = { minX: 0, maxX: 1, minY: 2, maxY: 3 } as const;

/** After this many bounces inside one step the rest of the path is folded in closed form. */
const MAX_BOUNCES = 16;

/**
 * Box walls (report 5.7). A circle whose centre left [lo, hi] on an axis is mirrored back by its
 * penetration depth scaled by restitution, and its normal velocity is reversed and scaled by
 * restitution: it stands where it would be had it bounced at the moment of impact. At restitution
 * 1 that is exactly the report's rule. A circle fast enough to cross the box several times in a
 * step bounces repeatedly; past MAX_BOUNCES the remaining path is folded modulo the box, so no
 * speed can leave a circle outside.
 *
 * Normal speeds under `restitutionThreshold` bounce with restitution 0, as between bodies.
 *
 * Slots [from, to), all by default: each body is handled on its own, so ranges may run in parallel.
 *
 * Kinematic bodies are contained too, with restitution 1: they keep the speed they were given, but
 * the box is the world's domain and nothing ends a step outside it.
 *
 * Where the store has a body kernel, assembly/body-kernel.ts runs this same loop.
 */
export function bounceOffBox(
  bodies: BodyStore,
  width: number,
  height: number,
  wallRestitution: number,
  restitutionThreshold: number,
  from = 0,
  to = bodies.slotCount,
): void {
  if (bodies.kernel) return bodies.kernel.bounceOffBox(from, to, width, height, wallRestitution, restitutionThreshold);
  const { x, y, vx, vy, radius, restitution, type } = bodies;
  for (let i = from; i < to; i++) {
    const t = type[i];
    if (t !== TypeCode.dynamic && t !== TypeCode.kinematic) continue;
    const r = radius[i];
    const px = x[i];
    if (px < r || px > width - r) {
      const e = t === TypeCode.dynamic ? mixRestitution(restitution[i], wallRestitution) : 1;
      fold(px, vx[i], r, width - r, Math.abs(vx[i]) < restitutionThreshold ? 0 : e);
      x[i] = folded[0];
      vx[i] = folded[1];
    }
    const py = y[i];
    if (py < r || py > height - r) {
      const e = t === TypeCode.dynamic ? mixRestitution(restitution[i], wallRestitution) : 1;
      fold(py, vy[i], r, height - r, Math.abs(vy[i]) < restitutionThreshold ? 0 : e);
      y[i] = folded[0];
      vy[i] = folded[1];
    }
  }
}

/**
 * For the events, before bounceOffBox and with its tests: each moving body whose centre lies
 * within its radius of a wall is about to bounce, so it touches that wall this step; if it
 * approaches at `hitThreshold` or faster, that is a wall hit. Only reads: the bounce itself stays
 * the one loop (or kernel) that steps without events, so events never change the bits. Notes go
 * in slot order, then BoxWall order, as the touch diff needs. Asleep bodies touch nothing, as with
 * segments. A body fast enough to cross the box within one step is noted at the first wall only.
 */
export function noteWallContacts(bodies: BodyStore, width: number, height: number, events: ContactEvents, hitThreshold: number): void {
  const { x, y, vx, vy, radius, type, asleep, slotCount } = bodies;
  // As in the body kernel's moveInBox: most bodies lie farther than the largest radius from every
  // wall, and are passed over reading only their position.
  const reach = bodies.maxRadius();
  for (let i = 0; i < slotCount; i++) {
    const px = x[i];
    const py = y[i];
    if (px >= reach && px <= width - reach && py >= reach && py <= height - reach) continue;
    const t = type[i];
    if ((t !== TypeCode.dynamic && t !== TypeCode.kinematic) || asleep[i]) continue;
    const r = radius[i];
    if (px < r) noteWall(bodies, events, i, BoxWall.minX, -vx[i], hitThreshold);
    else if (px > width - r) noteWall(bodies, events, i, BoxWall.maxX, vx[i], hitThreshold);
    if (py < r) noteWall(bodies, events, i, BoxWall.minY, -vy[i], hitThreshold);
    else if (py > height - r) noteWall(bodies, events, i, BoxWall.maxY, vy[i], hitThreshold);
  }
}

function noteWall(bodies: BodyStore, events: ContactEvents, i: number, wall: number, approach: number, hitThreshold: number): void {
  events.noteWallTouch(i, wall);
  if (approach > 0 && approach >= hitThreshold) events.recordWallHit(bodies, i, wall, approach);
}

/**
 * Puts positions back inside the box after contact separation pushed them out; velocities stay.
 * Only bodies the solver moved can be outside, so with `contacts` given only their bodies are
 * checked: O(contacts) rather than O(bodies). Without it (segment contacts moved bodies too),
 * every body is.
 */
export function clampIntoBox(bodies: BodyStore, width: number, height: number, contacts: ContactBuffer | null): void {
  if (contacts) {
    const { lo, hi, count } = contacts;
    for (let k = 0; k < count; k++) {
      clampBody(bodies, lo[k], width, height);
      clampBody(bodies, hi[k], width, height);
    }
    return;
  }
  for (let i = 0; i < bodies.slotCount; i++) clampBody(bodies, i, width, height);
}

/**
 * clampIntoBox for the contact bodies whose slot lies in [from, to): each thread of a parallel step
 * reads every contact but writes only its own slots, so no two threads ever touch one body.
 */
export function clampContactBodiesInRange(
  bodies: BodyStore,
  lo: Int32Array,
  hi: Int32Array,
  count: number,
  width: number,
  height: number,
  from: number,
  to: number,
): void {
  for (let k = 0; k < count; k++) {
    const i = lo[k];
    const j = hi[k];
    if (i >= from && i < to) clampBody(bodies, i, width, height);
    if (j >= from && j < to) clampBody(bodies, j, width, height);
  }
}

/** Whether clampBody would move body i: the same tests, for noting escapes as they happen. */
export function outsideBox(bodies: BodyStore, i: number, width: number, height: number): boolean {
  const r = bodies.radius[i];
  const px = bodies.x[i];
  const py = bodies.y[i];
  return px < r || px > width - r || py < r || py > height - r;
}

/** clampBody for each of `slots[from..to)`. */
export function clampBodies(bodies: BodyStore, slots: Int32Array, from: number, to: number, width: number, height: number): void {
  for (let k = from; k < to; k++) clampBody(bodies, slots[k], width, height);
}

function clampBody(bodies: BodyStore, i: number, width: number, height: number): void {
  const t = bodies.type[i];
  if (t !== TypeCode.dynamic && t !== TypeCode.kinematic) return;
  const { x, y } = bodies;
  const r = bodies.radius[i];
  const px = x[i];
  if (px < r) x[i] = r;
  else if (px > width - r) x[i] = width - r;
  const py = y[i];
  if (py < r) y[i] = r;
  else if (py > height - r) y[i] = height - r;
}

// Results of `fold` (position, velocity), in a typed array so the hot loop returns two numbers
// without allocating: a double stored in a module-level `let` is boxed, one heap number per store.
const folded = new Float64Array(2);

function fold(p: number, v: number, lo: number, hi: number, e: number): void {
  for (let bounce = 0; bounce < MAX_BOUNCES; bounce++) {
    if (p < lo) p = lo + (lo - p) * e;
    else if (p > hi) p = hi - (p - hi) * e;
    else break;
    v = -v * e;
  }
  if (!(p >= lo && p <= hi)) {
    // Still outside after many bounces: only near-elastic, absurdly fast bodies get here. Fold the
    // leftover path over a period of two box lengths, reversing velocity on the way back.
    const span = hi - lo;
    if (!Number.isFinite(p) || span <= 0) {
      p = lo + span / 2;
    } else {
      let u = (p - lo) % (2 * span);
      if (u < 0) u += 2 * span;
      if (u > span) {
        u = 2 * span - u;
        v = -v;
      }
      p = Math.min(hi, Math.max(lo, lo + u));
    }
  }
  folded[0] = p;
  folded[1] = v;
}
