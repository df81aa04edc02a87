import type { BodyStore } from '../store/body-store.js';
import { TypeCode } from '../store/body-types.js';
import { BodyFlag } from '../store/rigid-columns.js';
import { turn } from '../math/trig.js';
import { moveVelocity, needsGeneralMotion } from './motion.js';
import type { IntegratorName } from './integrator.js';

/** The turn of a step, for `turn` (see there). */
const angle = new Float64Array(1);
/** moveVelocity's velocity and speed limit. */
const moved = new Float64Array(3);

/**
 * Integration of bodies that turn, for the shape route's elastic pass (the soft step integrates
 * within its sub-steps): positions and velocities as the world's integrator says (the report's
 * explicit Euler, semi-implicit, or Runge-Kutta's exact parabola), with forces, damping and gravity scale, and the rotation
 * turned by its angular velocity times dt exactly (trig.ts `turn`): free flight keeps its angular
 * velocity, where the first-order step the soft solver takes per small sub-step would lag by
 * atan(w dt) against w dt.
 * Kinematic bodies move and turn as they were told; sleepers and static bodies stay.
 *
 * A dynamic body moves at most `maxSpeed` (the world's maxLinearSpeed), as Box2D caps the
 * velocity before it moves a body: a velocity set between steps, or a force's change, would
 * otherwise carry it any distance before the step's last stage caps its speed. Under the cap, the
 * same bits as without it.
 */
export function integrateRigid(bodies: BodyStore, gx: number, gy: number, dt: number, integrator: IntegratorName, maxSpeed: number): void {
  const explicit = integrator === 'explicit-euler';
  // Under forces constant over the step Runge-Kutta's four stages agree: the exact parabola,
  // x + (v + a dt / 2) dt, which is the mean of the two Euler methods' positions.
  const rk4 = integrator === 'rk4';
  moved[2] = maxSpeed;
  if (!needsGeneralMotion(bodies)) return integratePlain(bodies, gx, gy, dt, explicit, rk4);
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
      if (explicit || rk4) {
        moved[0] = rk4 ? vx[i] + 0.5 * ax * dt : vx[i];
        moved[1] = rk4 ? vy[i] + 0.5 * ay * dt : vy[i];
        moveVelocity(moved);
        x[i] += moved[0] * dt;
        y[i] += moved[1] * dt;
        vx[i] = (vx[i] + ax * dt) * damping;
        vy[i] = (vy[i] + ay * dt) * damping;
        const fixed = (flags[i] & BodyFlag.fixedRotation) !== 0;
        angularVelocity[i] = fixed ? 0 : (w + alpha * dt) * spin;
        // Explicit Euler turns by the spin it had; Runge-Kutta by the mean over the step.
        if (rk4) w = fixed ? 0 : w + 0.5 * alpha * dt;
      } else {
        moved[0] = (vx[i] + ax * dt) * damping;
        moved[1] = (vy[i] + ay * dt) * damping;
        moveVelocity(moved);
        vx[i] = moved[0];
        vy[i] = moved[1];
        x[i] += vx[i] * dt;
        y[i] += vy[i] * dt;
        w = (flags[i] & BodyFlag.fixedRotation) !== 0 ? 0 : (w + alpha * dt) * spin;
        angularVelocity[i] = w;
      }
    }
    if (w !== 0) {
      angle[0] = w * dt;
      turn(c, s, i, angle);
    }
  }
}

/**
 * integrateRigid where no body has forces, torques, damping, a gravity scale or sleep: its
 * arithmetic less the factors that are 1 and the terms that are 0, from half the columns (at
 * 64,000 bodies the loop is bound by memory: it reads each column once).
 */
function integratePlain(bodies: BodyStore, gx: number, gy: number, dt: number, explicit: boolean, rk4: boolean): void {
  const { x, y, vx, vy, type, slotCount } = bodies;
  const rigid = bodies.rigid!;
  const { c, s, angularVelocity, flags } = rigid;
  const dvx = gx * dt;
  const dvy = gy * dt;
  for (let i = 0; i < slotCount; i++) {
    const t = type[i];
    if (t === TypeCode.dynamic) {
      if (rk4 || explicit) {
        moved[0] = rk4 ? vx[i] + 0.5 * dvx : vx[i];
        moved[1] = rk4 ? vy[i] + 0.5 * dvy : vy[i];
        moveVelocity(moved);
        x[i] += moved[0] * dt;
        y[i] += moved[1] * dt;
        vx[i] += dvx;
        vy[i] += dvy;
      } else {
        moved[0] = vx[i] + dvx;
        moved[1] = vy[i] + dvy;
        moveVelocity(moved);
        vx[i] = moved[0];
        vy[i] = moved[1];
        x[i] += vx[i] * dt;
        y[i] += vy[i] * dt;
      }
    } else if (t === TypeCode.kinematic) {
      x[i] += vx[i] * dt;
      y[i] += vy[i] * dt;
    } else {
      continue;
    }
    const w = angularVelocity[i];
    if (w === 0) continue;
    if (t === TypeCode.dynamic && (flags[i] & BodyFlag.fixedRotation) !== 0) {
      angularVelocity[i] = 0;
      continue;
    }
    angle[0] = w * dt;
    turn(c, s, i, angle);
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
    if (w !== 0) {
      angle[0] = w * dt;
      turn(c, s, i, angle);
    }
  }
}
