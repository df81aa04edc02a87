import type { ShapeStore } from '../store/shape-store.js';
import { ShapeKind } from '../shapes/geometry.js';
import { WorldShape } from '../narrowphase/world-shape.js';
import { ShapeDistance } from '../narrowphase/distance.js';
import { norm, rayCircle, rayCircleEntry } from './ray-circle.js';
import { rayCapsule } from './ray-capsule.js';
import { shapeBounds } from '../shapes/bounds.js';
import type { SegmentStore } from '../store/segment-store.js';

const placed = new WorldShape();
const probe = new WorldShape();
const distance = new ShapeDistance();
const bounds = new Float64Array(4);

/** Where the last rayShape hit entered: the outward unit normal there. */
export const rayNormal = { x: 0, y: 0 };
/**
 * And the point itself, taken from the shape's geometry: the start plus the fraction times the
 * ray rounds at the start's distance (a ray from 1e15 away) and would leave the surface.
 */
export const rayPoint = { x: 0, y: 0 };

/** Whether shape `slot` of a body at (px, py) turned (c, s) contains the point (boundary included). */
export function shapeContains(shapes: ShapeStore, slot: number, px: number, py: number, c: number, s: number, qx: number, qy: number): boolean {
  placed.fromStore(shapes, slot, px, py, c, s);
  probe.circle(qx, qy, 0);
  return distance.compute(placed, probe).distance <= placed.radius;
}

/**
 * Whether shape `slot` of a body at pose at[0..3] (x, y, cosine, sine) overlaps the box `area`
 * ([minX, minY, maxX, maxY], touching included). A shape whose bounding box lies inside the query
 * box, or wholly apart from it, is decided by that box alone: the distance to a box far larger
 * than the shape loses the shape in its rounding. Pose and box come in arrays: the sensors' stage
 * asks this of many shapes each step, and a call V8 does not inline boxes each number passed.
 */
export function shapeOverlapsBox(shapes: ShapeStore, slot: number, at: Float64Array, area: Float64Array): boolean {
  const b = shapeBounds(shapes, slot, at, bounds);
  if (b[0] >= area[0] && b[2] <= area[2] && b[1] >= area[1] && b[3] <= area[3]) return true;
  if (b[2] < area[0] || b[0] > area[2] || b[3] < area[1] || b[1] > area[3]) return false;
  placed.fromPose(shapes, slot, at, 0);
  probe.rectangle(area);
  return distance.compute(placed, probe).distance <= placed.radius;
}

/**
 * The fraction in [0, 1] at which the segment (x1, y1) + t (dx, dy) enters the shape, or -1; a
 * start inside the shape is not a hit, as for circles. The entry's normal goes to `rayNormal`.
 * A polygon without rounding clips the ray against its edges (Cyrus-Beck); a rounded one is the
 * union of its core and a capsule around each edge, and a ray from outside meets a capsule first.
 */
export function rayShape(shapes: ShapeStore, slot: number, px: number, py: number, c: number, s: number, x1: number, y1: number, dx: number, dy: number): number {
  return rayPlaced(placed.fromStore(shapes, slot, px, py, c, s), px, py, x1, y1, dx, dy);
}

/** Whether static segment g (a capsule of its thickness) contains the point, boundary included. */
export function segmentContains(segments: SegmentStore, g: number, qx: number, qy: number): boolean {
  placed.segment(segments, g);
  probe.circle(qx, qy, 0);
  return distance.compute(placed, probe).distance <= placed.radius;
}

/** Whether static segment g overlaps the box `area`, touching included: shapeOverlapsBox's test. */
export function segmentOverlapsBox(segments: SegmentStore, g: number, area: Float64Array): boolean {
  const t = segments.thickness[g];
  const minX = Math.min(segments.ax[g], segments.bx[g]) - t;
  const minY = Math.min(segments.ay[g], segments.by[g]) - t;
  const maxX = Math.max(segments.ax[g], segments.bx[g]) + t;
  const maxY = Math.max(segments.ay[g], segments.by[g]) + t;
  if (minX >= area[0] && maxX <= area[2] && minY >= area[1] && maxY <= area[3]) return true;
  if (maxX < area[0] || minX > area[2] || maxY < area[1] || minY > area[3]) return false;
  placed.segment(segments, g);
  probe.rectangle(area);
  return distance.compute(placed, probe).distance <= placed.radius;
}

/** rayShape for static segment g, a capsule of its thickness (a segment of thickness 0 is hit where the ray crosses it). */
export function raySegment(segments: SegmentStore, g: number, x1: number, y1: number, dx: number, dy: number): number {
  // Halves summed: the sum of two coordinates near the largest double overflows.
  const mx = segments.ax[g] / 2 + segments.bx[g] / 2;
  const my = segments.ay[g] / 2 + segments.by[g] / 2;
  return rayPlaced(placed.segment(segments, g), mx, my, x1, y1, dx, dy);
}

/** rayShape for shape `g` once placed, (px, py) a point of it (its body's origin, a segment's midpoint). */
function rayPlaced(g: WorldShape, px: number, py: number, x1: number, y1: number, dx: number, dy: number): number {
  const r = g.radius;
  if (g.kind === ShapeKind.circle) {
    const t = rayCircle(x1, y1, dx, dy, g.x[0], g.y[0], r);
    if (t >= 0) normalAtCircle(x1, y1, dx, dy, g.x[0], g.y[0], r);
    return t;
  }
  // A start far from the shape moves along the ray to just before the shape's reach (the entry
  // can lie no earlier): the tests below take differences of the start and the vertices, which
  // round at the start's size, and from 1e16 away a ray passing 0.25 outside a box hit it. The
  // new start is placed from the shape's side, the line's closest approach to its centre (as
  // rayCircleEntry finds it), since a fraction of a ray 2e20 long resolves no finer than 2e4.
  // Twice the shape's reach from the centre, so that the new start lies clear of it.
  let reach = 0;
  for (let i = 0; i < g.count; i++) reach = Math.max(reach, Math.abs(g.x[i] - px) + Math.abs(g.y[i] - py));
  reach = 2 * (reach + r);
  const length = norm(dx, dy);
  const ux = dx / length;
  const uy = dy / length;
  const along = (px - x1) * ux + (py - y1) * uy;
  if (!(along > reach)) return rayShapeFrom(g, x1, y1, dx, dy);
  const h = (x1 - px) * uy - (y1 - py) * ux;
  const sx = px + h * uy - reach * ux;
  const sy = py - h * ux - reach * uy;
  const ex = x1 + dx - sx;
  const ey = y1 + dy - sy;
  // The end before the new start: the ray stops short of the shape's reach.
  if (!(ex * ux + ey * uy > 0)) return -1;
  const t = rayShapeFrom(g, sx, sy, ex, ey);
  const from = Math.min((along - reach) / length, 1);
  return t < 0 ? t : from + t * (1 - from);
}

/** rayShape for a polygon or capsule already placed, `g`, from a start near it. */
function rayShapeFrom(g: WorldShape, x1: number, y1: number, dx: number, dy: number): number {
  const r = g.radius;
  if (g.kind === ShapeKind.capsule || r > 0) {
    let best = -1;
    const edges = g.kind === ShapeKind.capsule ? 1 : g.count;
    // A start inside the rounded shape is not a hit.
    probe.circle(x1, y1, 0);
    if (distance.compute(g, probe).distance <= r) return -1;
    for (let i = 0; i < edges; i++) {
      const j = i + 1 === g.count ? 0 : i + 1;
      const t = rayCapsule(x1, y1, dx, dy, g.x[i], g.y[i], g.x[j], g.y[j], r);
      if (t >= 0 && (best < 0 || t < best)) {
        best = t;
        // The normal from the edge's closest point to the entry point: from the shape's geometry
        // rather than that point, which rounds at the start's distance and, past a radius that
        // is small beside it, onto the core itself (a normal of length 0).
        const hx = x1 + t * dx;
        const hy = y1 + t * dy;
        const ex = g.x[j] - g.x[i];
        const ey = g.y[j] - g.y[i];
        const lengthSq = ex * ex + ey * ey;
        const u = lengthSq > 0 ? ((hx - g.x[i]) * ex + (hy - g.y[i]) * ey) / lengthSq : 0;
        if (u > 0 && u < 1) {
          // The side of the band the ray came from.
          const length = Math.sqrt(lengthSq);
          const side = (x1 - g.x[i]) * ey - (y1 - g.y[i]) * ex > 0 ? 1 : -1;
          rayNormal.x = (side * ey) / length;
          rayNormal.y = (-side * ex) / length;
          rayPoint.x = g.x[i] + u * ex + r * rayNormal.x;
          rayPoint.y = g.y[i] + u * ey + r * rayNormal.y;
        } else {
          const end = u <= 0 ? i : j;
          normalAtCircle(x1, y1, dx, dy, g.x[end], g.y[end], r);
        }
      }
    }
    return best;
  }
  // Cyrus-Beck: the ray's parameter range inside every edge's half-plane.
  let enter = 0;
  let exit = 1;
  let entering = -1;
  for (let i = 0; i < g.count; i++) {
    const nx = g.nx[i];
    const ny = g.ny[i];
    const numerator = nx * (g.x[i] - x1) + ny * (g.y[i] - y1);
    const denominator = nx * dx + ny * dy;
    if (denominator === 0) {
      if (numerator < 0) return -1;
      continue;
    }
    const t = numerator / denominator;
    if (denominator < 0) {
      if (t > enter) {
        enter = t;
        entering = i;
      }
    } else if (t < exit) {
      exit = t;
    }
    if (exit < enter) return -1;
  }
  // No entering edge: the start lies inside.
  if (entering < 0) return -1;
  rayNormal.x = g.nx[entering];
  rayNormal.y = g.ny[entering];
  // Onto the entering edge's line.
  const hx = x1 + enter * dx;
  const hy = y1 + enter * dy;
  const off = rayNormal.x * (hx - g.x[entering]) + rayNormal.y * (hy - g.y[entering]);
  rayPoint.x = hx - off * rayNormal.x;
  rayPoint.y = hy - off * rayNormal.y;
  return enter;
}

const entry = { x: 0, y: 0 };

/**
 * The outward normal where the ray enters the circle at (cx, cy) of radius r: from its entry
 * relative to the centre (rayCircleEntry), which stays on the circle however far the ray starts
 * and however small the circle; for a circle of radius 0, the ray's direction reversed. The
 * entry itself into rayPoint.
 */
function normalAtCircle(x1: number, y1: number, dx: number, dy: number, cx: number, cy: number, r: number): void {
  rayCircleEntry(x1, y1, dx, dy, cx, cy, r, entry);
  if (!unitNormal(entry.x, entry.y)) unitNormal(-dx, -dy);
  rayPoint.x = cx + entry.x;
  rayPoint.y = cy + entry.y;
}

/**
 * (x, y) over its length into rayNormal, scaled by a power of two first where squaring it would
 * underflow or overflow (a radius below 1e-154); false for (0, 0).
 */
function unitNormal(x: number, y: number): boolean {
  const largest = Math.max(Math.abs(x), Math.abs(y));
  if (largest === 0) return false;
  const scale = largest < 2 ** -500 ? 2 ** 600 : largest > 2 ** 500 ? 2 ** -600 : 1;
  const sx = x * scale;
  const sy = y * scale;
  const length = Math.sqrt(sx * sx + sy * sy);
  rayNormal.x = sx / length;
  rayNormal.y = sy / length;
  return true;
}
