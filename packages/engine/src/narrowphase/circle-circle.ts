import type { WorldShape } from './world-shape.js';
import type { Manifold } from './manifold.js';
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

/**
 * The manifold of two circles: one point midway between the surfaces along the line of centres.
 * Concentric circles have no such line and are pushed apart along +x, as in the circle route.
 */
export function collideCircles(a: WorldShape, b: WorldShape, m: Manifold): void {
  const margin = m.margin;
  m.clear();
  const dx = b.x[0] - a.x[0];
  const dy = b.y[0] - a.y[0];
  const reach = a.radius + b.radius + margin;
  const distSq = dx * dx + dy * dy;
  if (distSq >= reach * reach) return;
  const dist = Math.sqrt(distSq);
  const nx = dist > 0 ? dx / dist : 1;
  const ny = dist > 0 ? dy / dist : 0;
  const separation = dist - a.radius - b.radius;
  const along = a.radius + separation / 2;
  m.normalX = nx;
  m.normalY = ny;
  m.x[m.pointCount] = a.x[0] + along * nx;
  m.y[m.pointCount] = a.y[0] + along * ny;
  m.separation[m.pointCount] = separation;
  m.id[m.pointCount++] = 0;
}
