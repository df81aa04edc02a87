import type { BodyStore } from '../store/body-store.js';
import { TypeCode } from '../store/body-types.js';

/** limitSpeeds' square of the speed limit, passed to the kernel in an array rather than boxed. */
const limit = new Float64Array(1);

/** capSpeed's velocity and limit. */
const capped = new Float64Array(3);

/**
 * The velocity (io[0], io[1]), faster than the limit io[2], slowed to it in its direction, in
 * place. By the larger component first, so that a speed whose square would overflow scales too.
 * The numbers travel in the array: callers run it for every body too fast, and V8 boxes each
 * double passed to, or returned from, a call it does not inline.
 */
export function capSpeed(io: Float64Array): void {
  let x = io[0];
  let y = io[1];
  const maxSpeed = io[2];
  const m = Math.max(Math.abs(x), Math.abs(y));
  x = (x / m) * maxSpeed;
  y = (y / m) * maxSpeed;
  const k = maxSpeed / Math.sqrt(x * x + y * y);
  if (k < 1) {
    x *= k;
    y *= k;
  }
  io[0] = x;
  io[1] = y;
}

/**
 * Whether some body moves faster than `speed` (any body, for a quick answer: the circle route
 * takes its capped general motion only in steps that may need it, see World.step). The body
 * kernel's scan where it holds the columns.
 */
export function anyFaster(bodies: BodyStore, speed: number): boolean {
  if (!(speed > 0)) return true;
  const { vx, vy, slotCount } = bodies;
  const speedSq = speed * speed;
  const kernel = bodies.kernel;
  if (kernel !== null) {
    limit[0] = speedSq;
    return kernel.firstTooFast(0, slotCount, limit) < slotCount;
  }
  for (let i = 0; i < slotCount; i++) if (!(vx[i] * vx[i] + vy[i] * vy[i] <= speedSq)) return true;
  return false;
}

/**
 * Caps every moving dynamic body's speed at `maxSpeed` (keeping its direction) and its spin at
 * `maxSpin`, the last stage of every step. A world's inputs are bounded (util/validate.ts), so a
 * step grows a speed by at most a bounded factor; capping what it leaves keeps every later step
 * bounded too: a restitution above 1 saturates at the top speed instead of running to infinity,
 * and no NaN follows. Returns how many bodies it slowed. Touches only what it slows.
 */
export function limitSpeeds(bodies: BodyStore, maxSpeed: number, maxSpin: number): number {
  const { vx, vy, type, asleep, slotCount } = bodies;
  const spin = bodies.rigid?.angularVelocity ?? null;
  const maxSq = maxSpeed * maxSpeed;
  let slowed = 0;
  // Where the body kernel holds the columns and no body turns, it finds the first body that may be
  // too fast (usually none), and the loop starts there.
  const kernel = bodies.kernel;
  let from = 0;
  if (kernel !== null && spin === null) {
    limit[0] = maxSq;
    from = kernel.firstTooFast(0, slotCount, limit);
  }
  for (let i = from; i < slotCount; i++) {
    const x = vx[i];
    const y = vy[i];
    // The speed first, the body's type only for the rare one too fast: this runs over every body
    // of every step, and two reads a body are half the four.
    if (!(x * x + y * y <= maxSq) && type[i] === TypeCode.dynamic && !asleep[i]) {
      capped[0] = x;
      capped[1] = y;
      capped[2] = maxSpeed;
      capSpeed(capped);
      vx[i] = capped[0];
      vy[i] = capped[1];
      slowed++;
    }
    if (spin !== null && Math.abs(spin[i]) > maxSpin && type[i] === TypeCode.dynamic && !asleep[i]) {
      spin[i] = spin[i] > 0 ? maxSpin : -maxSpin;
      slowed++;
    }
  }
  return slowed;
}
