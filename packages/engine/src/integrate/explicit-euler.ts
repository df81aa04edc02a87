import type { BodyStore } from '../store/body-store.js';
import { TypeCode } from '../store/body-types.js';
import { moveVelocity, needsGeneralMotion } from './motion.js';

/** moveVelocity's answer. */
/** moveVelocity's velocity and speed limit. */
const moved = new Float64Array(3);

/**
 * The report's method (3.1.3, 5.6): position advances with the velocity from before the step,
 * then velocity advances by the acceleration. Kinematic bodies move with the velocity they were
 * given and ignore gravity and forces; static and free slots do not move.
 */
export function integrateExplicitEuler(
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
  if (bodies.kernel) return bodies.kernel.integrateExplicit(from, to, dvx, dvy, dt);
  const { x, y, vx, vy, type } = bodies;
  for (let i = from; i < to; i++) {
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

/** With per-body gravity scale, pending forces, damping, sleepers or a speed limit (see moveVelocity). */
function general(bodies: BodyStore, gx: number, gy: number, dt: number, from: number, to: number): void {
  const { x, y, vx, vy, type, invMass, gravityScale, linearDamping, forceX, forceY, asleep } = bodies;
  moved[2] = bodies.speedCap;
  for (let i = from; i < to; i++) {
    const t = type[i];
    if (t === TypeCode.dynamic) {
      if (asleep[i]) continue;
      moved[0] = vx[i];
      moved[1] = vy[i];
      moveVelocity(moved);
      x[i] += moved[0] * dt;
      y[i] += moved[1] * dt;
      const damping = 1 / (1 + dt * linearDamping[i]);
      vx[i] = (vx[i] + (gx * gravityScale[i] + forceX[i] * invMass[i]) * dt) * damping;
      vy[i] = (vy[i] + (gy * gravityScale[i] + forceY[i] * invMass[i]) * dt) * damping;
    } else if (t === TypeCode.kinematic) {
      x[i] += vx[i] * dt;
      y[i] += vy[i] * dt;
    }
  }
}
