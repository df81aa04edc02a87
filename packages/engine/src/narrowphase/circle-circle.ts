import type { BodyStore } from '../store/body-store.js';

/**
 * True when two circles overlap: squared distance against the squared sum of radii, no sqrt
 * (report 5.9). Tangent circles do not count: they exert nothing on each other this step.
 * `(xj - xi)` and `(xi - xj)` square to the same bits, so the answer does not depend on which way
 * round a broad-phase reported the pair.
 */
export function circlesOverlap(bodies: BodyStore, i: number, j: number): boolean {
  const dx = bodies.x[j] - bodies.x[i];
  const dy = bodies.y[j] - bodies.y[i];
  const reach = bodies.radius[i] + bodies.radius[j];
  return dx * dx + dy * dy < reach * reach;
}
