import type { BodyStore } from '../store/body-store.js';
import { TypeCode } from '../store/body-types.js';
import { BodyFlag } from '../store/rigid-columns.js';
import { cosSin } from '../math/trig.js';

const turn = new Float64Array(2);

/**
 * Turns body i's rotation by the angle a exactly (the engine's own cosine and sine, so the same
 * bits everywhere): free flight keeps its angular velocity, and the first-order step the soft
 * solver takes per small sub-step would lag here by atan(w dt) against w dt.
 */
function turnBy(c: Float64Array, s: Float64Array, i: number, a: number): void {
  cosSin(a, turn);
  const c0 = c[i];
  const s0 = s[i];
  const c2 = c0 * turn[0] - s0 * turn[1];
  const s2 = s0 * turn[0] + c0 * turn[1];
  // Renormalised, so that round-off does not grow the rotation's length over many steps.
  const length = Math.sqrt(c2 * c2 + s2 * s2);
  c[i] = c2 / length;
  s[i] = s2 / length;
}

/**
 * Integration of bodies that turn, for the shape route's elastic pass (the soft step integrates
 * within its sub-steps): positions and velocities as the world's integrator says (the report's
 * explicit Euler, or semi-implicit), with forces, damping and gravity scale, and the rotation
 * turned by its angular velocity times dt (turnBy).
 * Kinematic bodies move and turn as they were told; sleepers and static bodies stay.
 */
export function integrateRigid(bodies: BodyStore, gx: number, gy: number, dt: number, explicit: boolean): void {
  const { x, y, vx, vy, type, asleep, invMass, gravityScale, linearDamping, forceX, forceY, slotCount } = bodies;
  const rigid = bodies.rigid!;
  const { c, s, angularVelocity, invInertia, torque, angularDamping, flags } = rigid;
  for (let i = 0; i < slotCount; i++) {
    const t = type[i];
    if (t !== TypeCode.dynamic && t !== TypeCode.kinematic) continue;
    if (asleep[i]) continue;
    let w = angularVelocity[i];
    if (t === TypeCode.kinematic) {
      x[i] += vx[i] * dt;
      y[i] += vy[i] * dt;
    } else {
      const damping = 1 / (1 + dt * linearDamping[i]);
      const ax = gx * gravityScale[i] + forceX[i] * invMass[i];
      const ay = gy * gravityScale[i] + forceY[i] * invMass[i];
      const alpha = invInertia[i] * torque[i];
      const spin = 1 / (1 + dt * angularDamping[i]);
      if (explicit) {
        x[i] += vx[i] * dt;
        y[i] += vy[i] * dt;
        vx[i] = (vx[i] + ax * dt) * damping;
        vy[i] = (vy[i] + ay * dt) * damping;
        angularVelocity[i] = (flags[i] & BodyFlag.fixedRotation) !== 0 ? 0 : (w + alpha * dt) * spin;
      } else {
        vx[i] = (vx[i] + ax * dt) * damping;
        vy[i] = (vy[i] + ay * dt) * damping;
        x[i] += vx[i] * dt;
        y[i] += vy[i] * dt;
        w = (flags[i] & BodyFlag.fixedRotation) !== 0 ? 0 : (w + alpha * dt) * spin;
        angularVelocity[i] = w;
      }
    }
    if (w !== 0) turnBy(c, s, i, w * dt);
  }
}

/**
 * The circle route's rotation: frictionless circles exchange no torque, so a turning circle only
 * needs its angle advanced (and its spin changed by torque and damping), after the circle stages.
 */
export function turnCircles(bodies: BodyStore, dt: number): void {
  const { type, asleep, slotCount } = bodies;
  const rigid = bodies.rigid!;
  const { c, s, angularVelocity, invInertia, torque, angularDamping, flags } = rigid;
  for (let i = 0; i < slotCount; i++) {
    const t = type[i];
    if ((t !== TypeCode.dynamic && t !== TypeCode.kinematic) || asleep[i]) continue;
    let w = angularVelocity[i];
    if (t === TypeCode.dynamic) {
      w = (flags[i] & BodyFlag.fixedRotation) !== 0 ? 0 : (w + invInertia[i] * torque[i] * dt) / (1 + dt * angularDamping[i]);
      angularVelocity[i] = w;
    }
    if (w !== 0) turnBy(c, s, i, w * dt);
  }
}
