import { rayCircle } from './ray-circle.js';
import { closestOnSegment } from '../narrowphase/circle-segment.js';

const closest = new Float64Array(2);

/** The rounding `along` may carry at a segment's ends (a few units in the last place of 1). */
const ALONG_ROUNDING = 1e-12;

/**
 * Where the segment p(t) = (x1, y1) + t (dx, dy), t in [0, 1], first enters the capsule of radius
 * r around segment (ax, ay)-(bx, by), or -1; a start inside the capsule is not a hit. The capsule
 * is its two end circles plus the band between the two offset lines.
 */
export function rayCapsule(
  x1: number,
  y1: number,
  dx: number,
  dy: number,
  ax: number,
  ay: number,
  bx: number,
  by: number,
  r: number,
): number {
  closestOnSegment(x1, y1, ax, ay, bx, by, closest);
  if ((x1 - closest[0]) ** 2 + (y1 - closest[1]) ** 2 <= r * r) return -1;
  let best = Infinity;
  const ta = rayCircle(x1, y1, dx, dy, ax, ay, r);
  if (ta >= 0) best = ta;
  const tb = rayCircle(x1, y1, dx, dy, bx, by, r);
  if (tb >= 0 && tb < best) best = tb;
  const ex = bx - ax;
  const ey = by - ay;
  const length = Math.sqrt(ex * ex + ey * ey);
  if (length > 0) {
    const nx = -ey / length;
    const ny = ex / length;
    // Signed distance of the start from the segment's line, and its rate of change along the ray.
    const offset = (x1 - ax) * nx + (y1 - ay) * ny;
    const rate = dx * nx + dy * ny;
    if (Math.abs(offset) > r && rate !== 0) {
      const side = offset > 0 ? r : -r;
      const t = (side - offset) / rate;
      if (t >= 0 && t <= 1 && t < best) {
        const hx = x1 + t * dx - ax;
        const hy = y1 + t * dy - ay;
        // Within the ends, to the rounding of the entry point: a ray aimed at the join of two
        // segments of no thickness, whose end caps have no width to catch it, passed between
        // them where `along` rounded outside [0, 1] on both (19 % of rays aimed at a polyline's
        // vertices).
        const along = (hx * ex + hy * ey) / (length * length);
        if (along >= -ALONG_ROUNDING && along <= 1 + ALONG_ROUNDING) best = t;
      }
    }
  }
  return best === Infinity ? -1 : best;
}
