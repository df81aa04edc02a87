import type { WorldShape } from './world-shape.js';
import type { Manifold } from './manifold.js';
import { SegmentDistance } from './segment-distance.js';

const closest = new SegmentDistance();

/**
 * Two capsules (a static segment is one, its thickness the radius), as Box2D v3 does. Where each
 * segment's span overlaps the other's along it, the reference segment is the one along whose
 * normal the other lies farthest out (the separating axis test on the two lines, A's unless B's
 * is farther by more than a tenth of the slop: a bias, as Box2D's, so that near ties do not flip
 * from step to step), and the
 * other is clipped to its span: two points with its normal, so that a capsule resting on another
 * or on a floor does not rock about one point. They are kept where one of them lies within a slop
 * of the segments' true distance; otherwise (capsules meeting at an angle near an end, whose clip
 * measures the gap along the wrong normal, 1 / cos of the angle too wide) and wherever one span
 * lies outside the other, one point along the line between the segments' closest points.
 */
export function collideCapsules(a: WorldShape, b: WorldShape, m: Manifold): void {
  const margin = m.margin;
  const slop = m.slop;
  m.clear();
  const p1x = a.x[0];
  const p1y = a.y[0];
  const q1x = a.x[1];
  const q1y = a.y[1];
  const p2x = b.x[0];
  const p2y = b.y[0];
  const q2x = b.x[1];
  const q2y = b.y[1];
  const radius = a.radius + b.radius;
  const reach = radius + margin;
  closest.computeEdges(a, 0, 1, b, 0, 1);
  if (closest.distanceSquared >= reach * reach) return;
  const d1x = q1x - p1x;
  const d1y = q1y - p1y;
  const length1 = Math.sqrt(d1x * d1x + d1y * d1y);
  // A core too short for its place (length 1e-17 at 1, or 3 at 1e17) rounds to one point: that
  // capsule is a circle, with no direction of its own, and neither its clip nor its normal below.
  const u1x = length1 > 0 ? d1x / length1 : 0;
  const u1y = length1 > 0 ? d1y / length1 : 0;
  const d2x = q2x - p2x;
  const d2y = q2y - p2y;
  const length2 = Math.sqrt(d2x * d2x + d2y * d2y);
  const u2x = length2 > 0 ? d2x / length2 : 0;
  const u2y = length2 > 0 ? d2y / length2 : 0;
  // Where B's ends fall along A, and A's along B.
  const fp2 = (p2x - p1x) * u1x + (p2y - p1y) * u1y;
  const fq2 = (q2x - p1x) * u1x + (q2y - p1y) * u1y;
  const fp1 = (p1x - p2x) * u2x + (p1y - p2y) * u2y;
  const fq1 = (q1x - p2x) * u2x + (q1y - p2y) * u2y;
  const outsideA = (fp2 <= 0 && fq2 <= 0) || (fp2 >= length1 && fq2 >= length1);
  const outsideB = (fp1 <= 0 && fq1 <= 0) || (fp1 >= length2 && fq1 >= length2);
  const dist = Math.sqrt(closest.distanceSquared);
  if (length1 > 0 && length2 > 0 && !outsideA && !outsideB) {
    // How far B lies out along A's normal, on the side where it lies farthest (the nearer of its
    // ends), and A along B's.
    const nx = u1y;
    const ny = -u1x;
    const sp = (p2x - p1x) * nx + (p2y - p1y) * ny;
    const sq = (q2x - p1x) * nx + (q2y - p1y) * ny;
    const flipA = Math.min(sp, sq) >= Math.min(-sp, -sq) ? 1 : -1;
    const separationA = Math.min(flipA * sp, flipA * sq);
    const mx = u2y;
    const my = -u2x;
    const rp = (p1x - p2x) * mx + (p1y - p2y) * my;
    const rq = (q1x - p2x) * mx + (q1y - p2y) * my;
    const flipB = Math.min(rp, rq) >= Math.min(-rp, -rq) ? 1 : -1;
    const separationB = Math.min(flipB * rp, flipB * rq);
    if (separationA + 0.1 * slop >= separationB) {
      if (fq2 !== fp2) clipOnto(m, p1x, p1y, u1x, u1y, length1, fp2, fq2, flipA * sp, flipA * sq, flipA * nx, flipA * ny, a.radius, radius, margin, dist + slop, 1, 0);
    } else if (fq1 !== fp1) {
      clipOnto(m, p2x, p2y, u2x, u2y, length2, fp1, fq1, flipB * rp, flipB * rq, flipB * mx, flipB * my, b.radius, radius, margin, dist + slop, -1, 3);
    }
    if (m.pointCount > 0) return;
  }
  const dx = closest.x2 - closest.x1;
  const dy = closest.y2 - closest.y1;
  let nx: number;
  let ny: number;
  // Closest points a rounding apart (cores that cross, one end on the other's line) give no
  // direction: the gap between them is round-off, pointing anywhere, and changes step to step.
  if (dist > 1e-12 * (length1 + length2 + radius)) {
    nx = dx / dist;
    ny = dy / dist;
  } else {
    // Crossing segments: push along A's normal (B's, where A's core is a point; +x where both
    // are, as for concentric circles), towards B's centre.
    nx = length1 > 0 ? u1y : length2 > 0 ? u2y : 1;
    ny = length1 > 0 ? -u1x : length2 > 0 ? -u2x : 0;
    if ((p2x + q2x) / 2 * nx + (p2y + q2y) / 2 * ny < (p1x + q1x) / 2 * nx + (p1y + q1y) / 2 * ny) {
      nx = -nx;
      ny = -ny;
    }
  }
  const separation = dist - radius;
  const along = a.radius + separation / 2;
  m.normalX = nx;
  m.normalY = ny;
  m.x[m.pointCount] = closest.x1 + along * nx;
  m.y[m.pointCount] = closest.y1 + along * ny;
  m.separation[m.pointCount] = separation;
  m.id[m.pointCount++] = 2;
}

/**
 * The two-point contact of a capsule lying along a reference segment (from (ox, oy) along the
 * unit (ux, uy) for `length`): the other segment, whose ends lie at fP and fQ along it and sP and
 * sQ out along its normal (nx, ny), is clipped to the reference's span; an end closer than
 * the margin gives a point midway between the surfaces, and so does the other end then
 * (refRadius is the reference capsule's), where one of them lies no farther out than `within`.
 * `sign` is 1 where the reference is A, -1 where it is B (the normal then turns to run from A
 * to B); ids start at idBase.
 */
function clipOnto(m: Manifold, ox: number, oy: number, ux: number, uy: number, length: number, fP: number, fQ: number, sP: number, sQ: number, nx: number, ny: number, refRadius: number, radius: number, margin: number, within: number, sign: number, idBase: number): void {
  const lower = fP < fQ ? 0 : 1;
  const fLow = lower === 0 ? fP : fQ;
  const fHigh = lower === 0 ? fQ : fP;
  const sLow = lower === 0 ? sP : sQ;
  const sHigh = lower === 0 ? sQ : sP;
  const tLow = fLow < 0 ? (0 - fLow) / (fHigh - fLow) : 0;
  const tHigh = fHigh > length ? (length - fLow) / (fHigh - fLow) : 1;
  const separationLow = sLow + tLow * (sHigh - sLow) - radius;
  const separationHigh = sLow + tHigh * (sHigh - sLow) - radius;
  // Both points or none, as collidePolygons keeps them: a capsule striking a wall with one end
  // turns about it, and without a speculative point at its other end the solve swings that
  // one through.
  if (separationLow >= margin && separationHigh >= margin) return;
  // Neither clipped end near the segments' true distance (`within`: it plus a slop): the reference
  // normal is not the direction between them.
  if (separationLow + radius > within && separationHigh + radius > within) return;
  m.normalX = sign * nx;
  m.normalY = sign * ny;
  for (let k = 0; k < 2; k++) {
    const t = k === 0 ? tLow : tHigh;
    const f = fLow + t * (fHigh - fLow);
    const separation = k === 0 ? separationLow : separationHigh;
    // On the reference line at f, moved out to midway between the surfaces.
    const along = refRadius + separation / 2;
    m.x[m.pointCount] = ox + f * ux + along * nx;
    m.y[m.pointCount] = oy + f * uy + along * ny;
    m.separation[m.pointCount] = separation;
    m.id[m.pointCount++] = idBase + k;
  }
}
