import type { WorldShape } from './world-shape.js';
import type { Manifold } from './manifold.js';
import { SegmentDistance } from './segment-distance.js';

/**
 * Whether the line (dx, dy) from the reference edge's nearest vertex (v11 where f1 is 0, v12
 * where it is 1) to the incident vertex leaves that edge's end by more than a tenth of the slop,
 * along the edge: a true corner meeting. Parallel edges of the same length whose ends line up
 * (a capsule of length 1 on a box 1 wide, a box with a rounded core as wide as the face below)
 * have their nearest points at the vertices too, exactly, in doubles, with the line between them
 * along the normal: they meet face to face, and take two clipped points, or they rock on one.
 */
function beyondEnd(v11x: number, v11y: number, v12x: number, v12y: number, dx: number, dy: number, f1: number, slop: number): boolean {
  const tx = v12x - v11x;
  const ty = v12y - v11y;
  const along = (dx * tx + dy * ty) / Math.sqrt(tx * tx + ty * ty);
  return f1 === 0 ? along < -0.1 * slop : along > 0.1 * slop;
}

/**
 * Two convex polygons, either possibly rounded, by the separating axis test and reference-face
 * clipping, the method of Box2D v3, planck and Matter.js.
 *
 * Why SAT and not MPR (which the report names) or GJK/EPA: in 2D the candidate axes are just the
 * edge normals, at most 8 + 8, so SAT finds the exact separation and the face that gives it in a
 * few dozen multiply-adds, and clipping the facing edge against that face yields the two-point
 * manifold with stable feature ids that stacking needs. MPR answers "do they overlap", and its
 * portal gives neither an exact depth nor the contact features without more iterations; GJK/EPA
 * reaches the same depth iteratively and still needs the clipping step for two points. What a
 * pair costs on the boxes of the lab's pyramid is in docs/engine.md, Numbers.
 *
 * 1. For each polygon, the edge along whose normal the other polygon lies farthest out: the
 *    larger of the two is the separation of their cores. Beyond the margin plus both radii, no
 *    contact.
 * 2. The reference face is that edge, on A unless B's is larger (as Box2D v3); a flip between
 *    steps keeps the points' order and ids (see the clipping below). The incident edge is the
 *    other polygon's edge facing it most directly.
 * 3. Cores apart by more than a tenth of the slop whose nearest features are two vertices (corners
 *    meeting, or rounded corners, where the face normal would be wrong), the incident one more than
 *    that beyond the reference edge's end (see beyondEnd): one point along the line between them.
 * 4. Otherwise the incident edge is clipped to the reference face's span: two points, each
 *    midway between the surfaces. Both are kept even when one lies beyond the margin, as Box2D
 *    keeps them: a box meeting a thin wall corner first at speed turns about that corner, and
 *    without a speculative point on its other corner the solve lets that one swing through.
 *
 * A capsule is a two-point polygon here, its two edges the two sides of its segment.
 */
export function collidePolygons(a: WorldShape, b: WorldShape, m: Manifold): void {
  const margin = m.margin;
  const slop = m.slop;
  m.clear();
  const radius = a.radius + b.radius;
  const limit = margin + radius;
  found[2] = limit;
  maxSeparation(a, b);
  const separationA = found[0];
  const edgeA = found[1];
  if (separationA > limit) return;
  maxSeparation(b, a);
  const separationB = found[0];
  const edgeB = found[1];
  if (separationB > limit) return;
  const flip = separationB > separationA;
  const ref = flip ? b : a;
  const inc = flip ? a : b;
  const edge = flip ? edgeB : edgeA;
  const separation = flip ? separationB : separationA;
  const n = ref.count;
  const i11 = edge;
  const i12 = edge + 1 === n ? 0 : edge + 1;
  const nx = ref.nx[edge];
  const ny = ref.ny[edge];
  // The incident edge: the one whose normal is most opposed to the reference normal.
  let i21 = 0;
  let least = Infinity;
  for (let i = 0; i < inc.count; i++) {
    const d = inc.nx[i] * nx + inc.ny[i] * ny;
    if (d < least) {
      least = d;
      i21 = i;
    }
  }
  const i22 = i21 + 1 === inc.count ? 0 : i21 + 1;
  const v11x = ref.x[i11];
  const v11y = ref.y[i11];
  const v12x = ref.x[i12];
  const v12y = ref.y[i12];
  const v21x = inc.x[i21];
  const v21y = inc.y[i21];
  const v22x = inc.x[i22];
  const v22y = inc.y[i22];
  const r1 = ref.radius;
  const r2 = inc.radius;
  if (separation > 0.1 * slop) {
    edges.computeEdges(ref, i11, i12, inc, i21, i22);
    const f1 = edges.fraction1;
    const f2 = edges.fraction2;
    if ((f1 === 0 || f1 === 1) && (f2 === 0 || f2 === 1) && beyondEnd(v11x, v11y, v12x, v12y, edges.x2 - edges.x1, edges.y2 - edges.y1, f1, slop)) {
      // Vertex against vertex.
      const distance = Math.sqrt(edges.distanceSquared);
      const gap = distance - radius;
      if (gap > margin || !(distance > 0)) return;
      let ux = (edges.x2 - edges.x1) / distance;
      let uy = (edges.y2 - edges.y1) / distance;
      const along = r1 + gap / 2;
      const px = edges.x1 + along * ux;
      const py = edges.y1 + along * uy;
      const refVertex = f1 === 0 ? i11 : i12;
      const incVertex = f2 === 0 ? i21 : i22;
      // Ids name A's feature, then B's, whichever was the reference (see the clipping ids below).
      const id = 128 + (flip ? incVertex * 8 + refVertex : refVertex * 8 + incVertex);
      if (flip) {
        ux = -ux;
        uy = -uy;
      }
      m.normalX = ux;
      m.normalY = uy;
      m.x[m.pointCount] = px;
      m.y[m.pointCount] = py;
      m.separation[m.pointCount] = gap;
      m.id[m.pointCount++] = id;
      return;
    }
  }
  // Clip the incident edge (which runs against the reference edge) to the reference edge's span.
  const tx = v12x - v11x;
  const ty = v12y - v11y;
  const length = Math.sqrt(tx * tx + ty * ty);
  const ux = tx / length;
  const uy = ty / length;
  const upper1 = length;
  const upper2 = (v21x - v11x) * ux + (v21y - v11y) * uy;
  const lower2 = (v22x - v11x) * ux + (v22y - v11y) * uy;
  const span = upper2 - lower2;
  let vLowX = v22x;
  let vLowY = v22y;
  if (lower2 < 0 && span > 0) {
    const t = (0 - lower2) / span;
    vLowX = v22x + t * (v21x - v22x);
    vLowY = v22y + t * (v21y - v22y);
  }
  let vHighX = v21x;
  let vHighY = v21y;
  if (upper2 > upper1 && span > 0) {
    const t = (upper1 - lower2) / span;
    vHighX = v22x + t * (v21x - v22x);
    vHighY = v22y + t * (v21y - v22y);
  }
  const sepLow = (vLowX - v11x) * nx + (vLowY - v11y) * ny - radius;
  const sepHigh = (vHighX - v11x) * nx + (vHighY - v11y) * ny - radius;
  // Midway between the surfaces: the incident point sits r2 inside its surface, the reference
  // surface lies r1 out along n.
  const lowBack = r2 + sepLow / 2;
  const highBack = r2 + sepHigh / 2;
  if (sepLow > margin && sepHigh > margin) return;
  // A point's id names the feature of A, then that of B (an edge by its first vertex), whichever
  // polygon is the reference, as Box2D does: when a near tie flips the reference between steps,
  // points made by the same two features keep their ids and so their warm-started impulses.
  // The low end first, or the high end first where B holds the reference face.
  const low = flip ? 1 : 0;
  const high = 1 - low;
  m.normalX = flip ? -nx : nx;
  m.normalY = flip ? -ny : ny;
  m.x[low] = vLowX - lowBack * nx;
  m.y[low] = vLowY - lowBack * ny;
  m.separation[low] = sepLow;
  m.id[low] = flip ? i22 * 8 + i11 : i11 * 8 + i22;
  m.x[high] = vHighX - highBack * nx;
  m.y[high] = vHighY - highBack * ny;
  m.separation[high] = sepHigh;
  m.id[high] = flip ? i21 * 8 + i12 : i12 * 8 + i21;
  m.pointCount = 2;
}

/**
 * maxSeparation's answer, the separation and its edge, and its limit (found[2]): in a typed
 * array, since V8 boxes a number passed to or returned from a call it does not inline, an
 * allocation per pair.
 */
const found = new Float64Array(3);
const edges = new SegmentDistance();

/**
 * The largest, over p's edges, of how far q's deepest point lies outside that edge, into found[0],
 * and that edge, into found[1]. Stops at the first edge beyond the limit (found[2]), which settles
 * that the two are apart (most pairs the broad-phase hands on are), and leaves an edge as soon as
 * one of q's points lies no further out than the best so far.
 */
function maxSeparation(p: WorldShape, q: WorldShape): void {
  const limit = found[2];
  let best = -Infinity;
  let bestEdge = 0;
  const qn = q.count;
  for (let i = 0; i < p.count; i++) {
    const nx = p.nx[i];
    const ny = p.ny[i];
    const vx = p.x[i];
    const vy = p.y[i];
    let deepest = Infinity;
    for (let j = 0; j < qn; j++) {
      const s = nx * (q.x[j] - vx) + ny * (q.y[j] - vy);
      if (s < deepest) {
        deepest = s;
        // This edge can no longer be the best one.
        if (deepest <= best) break;
      }
    }
    if (deepest > best) {
      best = deepest;
      bestEdge = i;
      if (best > limit) break;
    }
  }
  found[0] = best;
  found[1] = bestEdge;
}
