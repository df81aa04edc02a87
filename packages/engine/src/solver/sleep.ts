import type { BodyStore } from '../store/body-store.js';
import type { ContactBuffer } from '../store/contact-buffer.js';
import { TypeCode } from '../store/body-types.js';
import { grownCapacity } from '../util/grow.js';

/**
 * Sleeping (report 3.1.4.1, 5.3.3). A dynamic body slower than `speed` accumulates still time;
 * once it has been still for `time` seconds it may fall asleep: zero velocity, skipped by
 * integration and, paired with another sleeper or a static body, by the narrow-phase. It wakes
 * when a body faster than `speed` touches it (in the solver, see touchSleeper) and whenever the
 * user changes it (velocity, position, type, force, impulse).
 *
 * A still body falls asleep only together with the awake bodies it touches: only when every one of
 * them is still too. A pile therefore sleeps as a whole, in the step its last body comes to rest,
 * and a slow body resting on sleepers leaves them asleep (they hold it as static bodies would).
 * Without that, each body of a pile fell asleep on its own and its slow neighbours woke it the
 * next step; waking on any touch by a body not yet still (a woken one, say) set off waves of
 * wake-ups through a sleeping pile instead. No islands are kept: the rule reads this step's
 * contacts only, so waking cannot miss a body the way a cached island can (Matter.js issues #1112
 * and #875).
 */
export class SleepStage {
  private blocked = new Int32Array(0);
  private stamp = 0;

  update(bodies: BodyStore, contacts: ContactBuffer, dt: number, speed: number, time: number): void {
    const { vx, vy, type, asleep, sleepTime, slotCount } = bodies;
    const limit = speed * speed;
    for (let i = 0; i < slotCount; i++) {
      if (type[i] !== TypeCode.dynamic || asleep[i]) continue;
      if (vx[i] * vx[i] + vy[i] * vy[i] > limit) sleepTime[i] = 0;
      else sleepTime[i] += dt;
    }
    // A body touching an awake body that is not still must stay awake.
    if (this.blocked.length < slotCount) {
      this.blocked = new Int32Array(grownCapacity(this.blocked.length, slotCount));
      this.stamp = 0;
    }
    const stamp = ++this.stamp;
    const { blocked } = this;
    const { lo, hi, count } = contacts;
    for (let k = 0; k < count; k++) {
      const i = lo[k];
      const j = hi[k];
      if (!isStill(bodies, i, time)) blocked[j] = stamp;
      if (!isStill(bodies, j, time)) blocked[i] = stamp;
    }
    for (let i = 0; i < slotCount; i++) {
      if (type[i] !== TypeCode.dynamic || asleep[i]) continue;
      if (stillFor(sleepTime[i], time) && blocked[i] !== stamp) bodies.fallAsleep(i);
    }
  }

  memoryBytes(): number {
    return this.blocked.byteLength;
  }
}

/**
 * Whether the body in `slot` lets the awake bodies it touches fall asleep: static bodies and
 * sleepers do, dynamic bodies once still for `time` seconds; kinematic bodies never (they move as
 * they were told).
 */
function isStill(bodies: BodyStore, slot: number, time: number): boolean {
  const t = bodies.type[slot];
  if (t === TypeCode.static || bodies.asleep[slot]) return true;
  return t === TypeCode.dynamic && stillFor(bodies.sleepTime[slot], time);
}

/**
 * Still for `time` seconds: a timer that a fast body reset to 0 has not started, so with
 * `sleepTime: 0` a body must have been slow through one step, not merely have a zero timer (which
 * put bodies at 300 px/s to sleep in their first step).
 */
function stillFor(timer: number, time: number): boolean {
  return timer > 0 && timer >= time;
}

/**
 * The solvers' rule for a contact of the sleeper in `sleeper` with the body in `other`, applied
 * before the contact is solved: the sleeper wakes when `other` is kinematic or moves faster than
 * `speed` (the world's sleepSpeed); otherwise it stays asleep and takes the contact as a static
 * body would. Returns the inverse mass to solve the contact with on the sleeper's side.
 */
export function touchSleeper(bodies: BodyStore, sleeper: number, other: number, speed: number): number {
  const t = bodies.type[other];
  const { vx, vy } = bodies;
  const wakes = t === TypeCode.kinematic || (t === TypeCode.dynamic && !bodies.asleep[other] && vx[other] * vx[other] + vy[other] * vy[other] > speed * speed);
  if (!wakes) return 0;
  bodies.wake(sleeper);
  return bodies.invMass[sleeper];
}
