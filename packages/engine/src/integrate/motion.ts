import type { BodyStore } from '../store/body-store.js';

/**
 * Whether any body needs more than "velocity plus uniform gravity". Plain scenes, the report's
 * and the lab's, keep the short loop that touches four columns; the general loop reads five more.
 */
export function needsGeneralMotion(bodies: BodyStore): boolean {
  return bodies.customMotionCount > 0 || bodies.forcesPending || bodies.sleepingCount > 0;
}

/** Forces last one step: the step applies them, then this clears them. */
export function clearForces(bodies: BodyStore): void {
  if (!bodies.forcesPending) return;
  bodies.forceX.fill(0, 0, bodies.slotCount);
  bodies.forceY.fill(0, 0, bodies.slotCount);
  bodies.forcesPending = false;
}
