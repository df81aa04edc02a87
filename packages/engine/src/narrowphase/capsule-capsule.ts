import type { WorldShape } from './world-shape.js';
import type { Manifold } from './manifold.js';
import { SegmentDistance } from './segment-distance.js';

const closest = new SegmentDistance();

/**
 * Two capsules. When each segment's span overlaps the other's along it and B's segment lies on
 * one side of A's line (capsules lying along each other, as in a stack), B's segment is clipped to
 * A's span and gives up to two points with A's normal: one point would let a capsule resting on
 * another rock about it. Otherwise (crossing, or meeting end to side) one point, along the line
 * between the segments' closest points.
 */
export function collideCapsules(a: WorldShape, b: WorldShape, margin: number, _slop: number, m: Manifold): void {
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
  if (length1 > 0 && length2 > 0 && !outsideA && !outsideB && fq2 !== fp2) {
    let nx = u1y;
    let ny = -u1x;
    let sp = (p2x - p1x) * nx + (p2y - p1y) * ny;
    let sq = (q2x - p1x) * nx + (q2y - p1y) * ny;
    if (sp * sq >= 0) {
      if (sp + sq < 0) {
        nx = -nx;
        ny = -ny;
        sp = -sp;
        sq = -sq;
      }
      // Clip B's segment to A's span [0, length1] along A.
      const lower = fp2 < fq2 ? 0 : 1;
      const fLow = lower === 0 ? fp2 : fq2;
      const fHigh = lower === 0 ? fq2 : fp2;
      const sLow = lower === 0 ? sp : sq;
      const sHigh = lower === 0 ? sq : sp;
      const tLow = fLow < 0 ? (0 - fLow) / (fHigh - fLow) : 0;
      const tHigh = fHigh > length1 ? (length1 - fLow) / (fHigh - fLow) : 1;
      m.normalX = nx;
      m.normalY = ny;
      for (let k = 0; k < 2; k++) {
        const t = k === 0 ? tLow : tHigh;
        const f = fLow + t * (fHigh - fLow);
        const separation = sLow + t * (sHigh - sLow) - radius;
        if (separation >= margin) continue;
        // On A's line at f, moved out to midway between the surfaces.
        const along = a.radius + separation / 2;
        m.x[m.pointCount] = p1x + f * u1x + along * nx;
        m.y[m.pointCount] = p1y + f * u1y + along * ny;
        m.separation[m.pointCount] = separation;
        m.id[m.pointCount++] = k;
      }
      if (m.pointCount > 0) return;
    }
  }
  const dx = closest.x2 - closest.x1;
  const dy = closest.y2 - closest.y1;
  const dist = Math.sqrt(closest.distanceSquared);
  let nx: number;
  let ny: number;
  if (dist > 0) {
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
