import type { BodyStore } from '../store/body-store.js';
import { TypeCode } from '../store/body-types.js';
import { moveVelocity, needsGeneralMotion } from './motion.js';

/** moveVelocity's answer. */
/** moveVelocity's velocity and speed limit. */
const moved = new Float64Array(3);

/**
 * Symplectic (semi-implicit) Euler, as Box2D and Rapier use: velocity first, then position with
 * the new velocity. Its energy error stays bounded instead of drifting, which matters for the
 * report's bouncing-ball test.
 */
export function integrateSemiImplicitEuler(
  bodies: BodyStore,
  gx: number,
  gy: number,
  dt: number,
  from = 0,
  to = bodies.slotCount,
): void {
  if (needsGeneralMotion(bodies)) return general(bodies, gx, gy, dt, from, to);
  const dvx = gx * dt;
  const dvy = gy * dt;
  if (bodies.kernel) return bodies.kernel.integrateSemiImplicit(from, to, dvx, dvy, dt);
  const { x, y, vx, vy, type } = bodies;
  for (let i = from; i < to; i++) {
    const t = type[i];
    if (t === TypeCode.dynamic) {
      vx[i] += dvx;
      vy[i] += dvy;
      x[i] += vx[i] * dt;
      y[i] += vy[i] * dt;
    } else if (t === TypeCode.kinematic) {
      x[i] += vx[i] * dt;
      y[i] += vy[i] * dt;
    }
  }
}

/** With per-body gravity scale, pending forces, damping, sleepers or a speed limit (see moveVelocity). */
function general(bodies: BodyStore, gx: number, gy: number, dt: number, from: number, to: number): void {
  const { x, y, vx, vy, type, invMass, gravityScale, linearDamping, forceX, forceY, asleep } = bodies;
  moved[2] = bodies.speedCap;
  for (let i = from; i < to; i++) {
    const t = type[i];
    if (t === TypeCode.dynamic) {
      if (asleep[i]) continue;
      const damping = 1 / (1 + dt * linearDamping[i]);
      moved[0] = (vx[i] + (gx * gravityScale[i] + forceX[i] * invMass[i]) * dt) * damping;
      moved[1] = (vy[i] + (gy * gravityScale[i] + forceY[i] * invMass[i]) * dt) * damping;
      moveVelocity(moved);
      vx[i] = moved[0];
      vy[i] = moved[1];
      x[i] += vx[i] * dt;
      y[i] += vy[i] * dt;
    } else if (t === TypeCode.kinematic) {
      x[i] += vx[i] * dt;
      y[i] += vy[i] * dt;
    }
  }
}
