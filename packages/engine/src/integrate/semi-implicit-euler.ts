import type { BodyStore } from '../store/body-store.js';
import { TypeCode } from '../store/body-types.js';

/**
 * Symplectic (semi-implicit) Euler, as Box2D and Rapier use: velocity first, then position with
 * the new velocity. Its energy error stays bounded instead of drifting, which matters for the
 * report's bouncing-ball test.
 */
export function integrateSemiImplicitEuler(bodies: BodyStore, gx: number, gy: number, dt: number): void {
  const { x, y, vx, vy, type, slotCount } = bodies;
  const dvx = gx * dt;
  const dvy = gy * dt;
  for (let i = 0; i < slotCount; i++) {
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
