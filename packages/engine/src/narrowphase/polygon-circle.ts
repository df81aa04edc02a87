import type { WorldShape } from './world-shape.js';
import type { Manifold } from './manifold.js';

/**
 * A polygon (A, possibly rounded) and a circle (B): the edge the circle's centre lies farthest
 * outside of (or least inside, for a centre within the polygon), then whether the centre lies in
 * that edge's face region or beyond one of its ends, where the nearest feature is the vertex and
 * the normal points from it to the centre. One point, feature id = the edge or vertex.
 */
export function collidePolygonCircle(a: WorldShape, b: WorldShape, m: Manifold): void {
  const margin = m.margin;
  m.clear();
  const cx = b.x[0];
  const cy = b.y[0];
  const n = a.count;
  const radius = a.radius + b.radius;
  let edge = 0;
  let most = -Infinity;
  for (let i = 0; i < n; i++) {
    const s = a.nx[i] * (cx - a.x[i]) + a.ny[i] * (cy - a.y[i]);
    if (s > most) {
      most = s;
      edge = i;
    }
  }
  if (most - radius > margin) return;
  const next = edge + 1 === n ? 0 : edge + 1;
  const v1x = a.x[edge];
  const v1y = a.y[edge];
  const v2x = a.x[next];
  const v2y = a.y[next];
  const u1 = (cx - v1x) * (v2x - v1x) + (cy - v1y) * (v2y - v1y);
  const u2 = (cx - v2x) * (v1x - v2x) + (cy - v2y) * (v1y - v2y);
  if (most > 0 && (u1 < 0 || u2 < 0)) {
    // Beyond an end of the edge, outside the polygon: the vertex is the nearest feature.
    const vx = u1 < 0 ? v1x : v2x;
    const vy = u1 < 0 ? v1y : v2y;
    const dx = cx - vx;
    const dy = cy - vy;
    const distSq = dx * dx + dy * dy;
    const reach = radius + margin;
    if (distSq >= reach * reach) return;
    const dist = Math.sqrt(distSq);
    const nx = dx / dist;
    const ny = dy / dist;
    const separation = dist - radius;
    const along = a.radius + separation / 2;
    m.normalX = nx;
    m.normalY = ny;
    m.x[m.pointCount] = vx + along * nx;
    m.y[m.pointCount] = vy + along * ny;
    m.separation[m.pointCount] = separation;
    m.id[m.pointCount++] = 16 + (u1 < 0 ? edge : next);
    return;
  }
  const nx = a.nx[edge];
  const ny = a.ny[edge];
  const separation = most - radius;
  // The point midway between the circle's surface and the polygon's.
  const back = b.radius + separation / 2;
  m.normalX = nx;
  m.normalY = ny;
  m.x[m.pointCount] = cx - back * nx;
  m.y[m.pointCount] = cy - back * ny;
  m.separation[m.pointCount] = separation;
  m.id[m.pointCount++] = edge;
}
