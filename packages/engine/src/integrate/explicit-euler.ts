import type { BodyStore } from '../store/body-store.js';
import { TypeCode } from '../store/body-types.js';

/**
 * The report's method (3.1.3, 5.6): position advances with the velocity from before the step,
 * then velocity advances by the acceleration. Kinematic bodies move with the velocity they were
 * given and ignore gravity; static and free slots do not move.
 */
export function integrateExplicitEuler(bodies: BodyStore, gx: number, gy: number, dt: number): void {
  const { x, y, vx, vy, type, slotCount } = bodies;
  const dvx = gx * dt;
  const dvy = gy * dt;
  for (let i = 0; i < slotCount; i++) {
    const t = type[i];
    if (t === TypeCode.dynamic) {
      x[i] += vx[i] * dt;
      y[i] += vy[i] * dt;
      vx[i] += dvx;
      vy[i] += dvy;
    } else if (t === TypeCode.kinematic) {
      x[i] += vx[i] * dt;
      y[i] += vy[i] * dt;
    }
  }
}
