import { ShapeKind } from '../shapes/geometry.js';
import { SmoothJoin, type SegmentStore } from '../store/segment-store.js';
import type { WorldShape } from './world-shape.js';
import type { Manifold } from './manifold.js';

/** A manifold normal this close to the link's face normal (its cosine) is the face's own. */
const FACE_COSINE = 1 - 1e-9;

/** Feature ids of the points smoothSegment writes, apart from the pair functions' (below 128). */
const SMOOTH_ID = 128;

/**
 * Smooth joins between the links of a chain (World.createChain), as Box2D's chain segments keep
 * with their ghost vertices. A shape crossing the join of two flush links meets the second link's
 * end: the pair function sees that end as a corner and answers with a normal along the floor (a
 * box's side against the corner), and the shape stops at a seam that is not there (a box sliding
 * at 4 m/s over loose 1 m segments stopped at a join 2 m on; a rolling disc lost a quarter of its
 * speed to bumps). Here a manifold whose normal is not the link's face normal is kept only where
 * the join bends away from the shape (a convex corner, such as a cliff's edge) and the normal lies
 * between the two links' face normals, which is where the corner itself is touched; otherwise it
 * is replaced by the face's: the shape's points nearest the link (its incident edge, its core
 * point) clipped to the link's length, so that past the join the next link answers alone.
 * `shape` is the body's shape, A of the manifold `m` (normal from the shape to the segment); the
 * face is the side of the link's line that holds the shape's centre.
 */
export function smoothSegment(shape: WorldShape, segments: SegmentStore, g: number, m: Manifold): void {
  if (m.pointCount === 0) return;
  const ax = segments.ax[g];
  const ay = segments.ay[g];
  const ex = segments.bx[g] - ax;
  const ey = segments.by[g] - ay;
  const length = Math.sqrt(ex * ex + ey * ey);
  if (!(length > 0)) return;
  const ux = ex / length;
  const uy = ey / length;
  let cx = 0;
  let cy = 0;
  for (let k = 0; k < shape.count; k++) {
    cx += shape.x[k];
    cy += shape.y[k];
  }
  cx /= shape.count;
  cy /= shape.count;
  const offset = (cx - ax) * -uy + (cy - ay) * ux;
  if (offset === 0) return;
  const side = offset > 0 ? 1 : -1;
  // The face normal towards the shape, and the manifold's normal from the link to the shape.
  const fx = -uy * side;
  const fy = ux * side;
  const qx = -m.normalX;
  const qy = -m.normalY;
  if (qx * fx + qy * fy >= FACE_COSINE) return;
  // The join the contact lies at: the nearer end of the link to the manifold's points.
  let along = 0;
  for (let p = 0; p < m.pointCount; p++) along += (m.x[p] - ax) * ux + (m.y[p] - ay) * uy;
  const atStart = along / m.pointCount < length / 2;
  const joins = segments.smooth[g];
  if ((joins & (atStart ? SmoothJoin.start : SmoothJoin.end)) === 0) return;
  // The neighbour's direction along the chain, and how its far point lies from the join.
  const vx = atStart ? ax : segments.bx[g];
  const vy = atStart ? ay : segments.by[g];
  const gx = atStart ? segments.prevX[g] : segments.nextX[g];
  const gy = atStart ? segments.prevY[g] : segments.nextY[g];
  let wx = atStart ? vx - gx : gx - vx;
  let wy = atStart ? vy - gy : gy - vy;
  const w = Math.sqrt(wx * wx + wy * wy);
  if (w > 0 && (gx - vx) * fx + (gy - vy) * fy < 0) {
    // A convex join: the corner is touched where the normal lies between the two faces' normals.
    wx /= w;
    wy /= w;
    const nx = -wy * side;
    const ny = wx * side;
    const turn = nx * fy - ny * fx;
    if ((nx * qy - ny * qx) * turn >= 0 && (qx * fy - qy * fx) * turn >= 0 && qx * (nx + fx) + qy * (ny + fy) > 0) return;
  }
  faceContact(shape, ax, ay, ux, uy, length, fx, fy, segments.thickness[g], m);
}

/**
 * The manifold of `shape` against the link's face (normal (fx, fy) towards the shape, the link from
 * (ax, ay) along (ux, uy) for `length`, a capsule of `thickness`): the shape's points nearest the
 * face (a polygon's edge most against the normal, a capsule's core, a circle's centre), clipped to
 * the link's length, each kept within the margin.
 */
function faceContact(shape: WorldShape, ax: number, ay: number, ux: number, uy: number, length: number, fx: number, fy: number, thickness: number, m: Manifold): void {
  let i1 = 0;
  let i2 = 0;
  if (shape.kind === ShapeKind.polygon) {
    let least = Infinity;
    for (let k = 0; k < shape.count; k++) {
      const d = shape.nx[k] * fx + shape.ny[k] * fy;
      if (d < least) {
        least = d;
        i1 = k;
      }
    }
    i2 = i1 + 1 === shape.count ? 0 : i1 + 1;
  } else if (shape.count > 1) {
    i2 = 1;
  }
  const margin = m.margin;
  const r = shape.radius;
  m.clear();
  m.normalX = -fx;
  m.normalY = -fy;
  const x1 = shape.x[i1];
  const y1 = shape.y[i1];
  const x2 = shape.x[i2];
  const y2 = shape.y[i2];
  const s1 = (x1 - ax) * ux + (y1 - ay) * uy;
  const s2 = (x2 - ax) * ux + (y2 - ay) * uy;
  for (let k = 0; k < (i1 === i2 ? 1 : 2); k++) {
    let px = k === 0 ? x1 : x2;
    let py = k === 0 ? y1 : y2;
    const s = k === 0 ? s1 : s2;
    if (s < 0 || s > length) {
      // Along the edge to the link's end it crosses; a point whose edge stays beyond is dropped.
      const other = k === 0 ? s2 : s1;
      const bound = s < 0 ? 0 : length;
      if ((s < 0 && other < 0) || (s > length && other > length) || other === s) continue;
      const t = (bound - s) / (other - s);
      px += t * ((k === 0 ? x2 : x1) - px);
      py += t * ((k === 0 ? y2 : y1) - py);
    }
    const separation = (px - ax) * fx + (py - ay) * fy - thickness - r;
    if (separation > margin) continue;
    const back = r + separation / 2;
    m.x[m.pointCount] = px - back * fx;
    m.y[m.pointCount] = py - back * fy;
    m.separation[m.pointCount] = separation;
    m.id[m.pointCount++] = SMOOTH_ID + (k === 0 ? i1 : i2);
  }
}
