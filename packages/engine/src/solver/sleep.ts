import type { BodyStore } from '../store/body-store.js';
import { TypeCode } from '../store/body-types.js';

/**
 * Sleeping (report 3.1.4.1, 5.3.3). A dynamic body slower than `speed` accumulates still time;
 * past `time` seconds it falls asleep with zero velocity and is skipped by integration and, paired
 * with another sleeper or a static body, by the narrow-phase. It wakes when a moving body touches
 * it (in the solver) and whenever the user changes it (velocity, position, type, force, impulse).
 *
 * Waking is per contact rather than per island: a woken body wakes its sleeping neighbours on the
 * next step, as soon as it touches them. Simple, deterministic, and it cannot miss a wake-up the
 * way a cached island can (Matter.js issues #1112 and #875).
 */
export function updateSleep(bodies: BodyStore, dt: number, speed: number, time: number): void {
  const { vx, vy, type, asleep, sleepTime, slotCount } = bodies;
  const limit = speed * speed;
  for (let i = 0; i < slotCount; i++) {
    if (type[i] !== TypeCode.dynamic || asleep[i]) continue;
    if (vx[i] * vx[i] + vy[i] * vy[i] > limit) {
      sleepTime[i] = 0;
      continue;
    }
    sleepTime[i] += dt;
    if (sleepTime[i] >= time) bodies.fallAsleep(i);
  }
}
