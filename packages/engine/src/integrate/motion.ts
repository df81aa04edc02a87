import type { BodyStore } from '../store/body-store.js';
import { MAX_MAGNITUDE } from '../util/validate.js';
import { capSpeed } from '../solver/speed-limit.js';

/**
 * Whether any body needs more than "velocity plus uniform gravity", or the circle route's motion a
 * speed limit (BodyStore.speedCap). Plain scenes, the report's and the lab's, keep the short loop
 * that touches four columns; the general loop reads five more.
 */
export function needsGeneralMotion(bodies: BodyStore): boolean {
  return bodies.customMotionCount > 0 || bodies.forcesPending || bodies.sleepingCount > 0 || bodies.speedCap < MAX_MAGNITUDE;
}

/**
 * The velocity (io[0], io[1]) brought within the speed io[2] (capSpeed), in place: the velocity a
 * body moves with in the general loops, which keep the speed limit through a step as Box2D does
 * (it caps the velocity before moving a body): a velocity set between steps, or a force's
 * change, would otherwise carry it any distance before the step's last stage caps it. Its own
 * bits within. The numbers travel in the array: wherever V8 does not inline this call, doubles
 * passed to it would be boxed, once a body and step.
 */
export function moveVelocity(io: Float64Array): void {
  const vx = io[0];
  const vy = io[1];
  const maxSpeed = io[2];
  if (vx * vx + vy * vy <= maxSpeed * maxSpeed) return;
  capSpeed(io);
}

/**
 * Forces and torques last one step: the step applies them, then this clears them. A step of dt 0
 * (a pause) applies nothing and keeps them for the next, as Box2D does.
 */
export function clearForces(bodies: BodyStore): void {
  if (!bodies.forcesPending) return;
  bodies.forceX.fill(0, 0, bodies.slotCount);
  bodies.forceY.fill(0, 0, bodies.slotCount);
  bodies.rigid?.torque.fill(0, 0, bodies.slotCount);
  bodies.forcesPending = false;
}
