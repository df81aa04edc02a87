import type { WorldShape } from './world-shape.js';
import type { Manifold } from './manifold.js';

/**
 * A capsule (A) and a circle (B): the circle's centre against the closest point of the capsule's
 * segment, one point. A centre exactly on the segment is pushed out along the segment's normal.
 */
export function collideCapsuleCircle(a: WorldShape, b: WorldShape, m: Manifold): void {
  const margin = m.margin;
  m.clear();
  const ax = a.x[0];
  const ay = a.y[0];
  const ex = a.x[1] - ax;
  const ey = a.y[1] - ay;
  const cx = b.x[0];
  const cy = b.y[0];
  const lengthSq = ex * ex + ey * ey;
  let t = lengthSq > 0 ? ((cx - ax) * ex + (cy - ay) * ey) / lengthSq : 0;
  if (t < 0) t = 0;
  else if (t > 1) t = 1;
  const qx = ax + t * ex;
  const qy = ay + t * ey;
  const dx = cx - qx;
  const dy = cy - qy;
  const reach = a.radius + b.radius + margin;
  const distSq = dx * dx + dy * dy;
  if (distSq >= reach * reach) return;
  const dist = Math.sqrt(distSq);
  const nx = dist > 0 ? dx / dist : a.nx[0];
  const ny = dist > 0 ? dy / dist : a.ny[0];
  const separation = dist - a.radius - b.radius;
  const along = a.radius + separation / 2;
  m.normalX = nx;
  m.normalY = ny;
  m.x[m.pointCount] = qx + along * nx;
  m.y[m.pointCount] = qy + along * ny;
  m.separation[m.pointCount] = separation;
  m.id[m.pointCount++] = 0;
}
