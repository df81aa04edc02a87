import type { WorldShape } from './world-shape.js';

/**
 * Closest points between segment 1, p1 + s (q1 - p1), and segment 2, p2 + t (q2 - p2), with s and
 * t in [0, 1] (Ericson, Real-Time Collision Detection, 5.1.9): written to `closest` as the two
 * points, their parameters and the squared distance. Degenerate (point) segments are handled.
 * The segments go in through `segments` (p1, q1, p2, q2, x then y) rather than as arguments:
 * V8 boxes each number passed to a call it does not inline, eight allocations per pair.
 */
export class SegmentDistance {
  readonly segments = new Float64Array(8);
  x1 = 0;
  y1 = 0;
  x2 = 0;
  y2 = 0;
  fraction1 = 0;
  fraction2 = 0;
  distanceSquared = 0;

  /** Between the edge (a[i1], a[j1]) of one shape and (b[i2], b[j2]) of another: their points by index, so no number is passed. */
  computeEdges(a: WorldShape, i1: number, j1: number, b: WorldShape, i2: number, j2: number): this {
    const g = this.segments;
    g[0] = a.x[i1];
    g[1] = a.y[i1];
    g[2] = a.x[j1];
    g[3] = a.y[j1];
    g[4] = b.x[i2];
    g[5] = b.y[i2];
    g[6] = b.x[j2];
    g[7] = b.y[j2];
    return this.compute();
  }

  compute(): this {
    const g = this.segments;
    const p1x = g[0];
    const p1y = g[1];
    const q1x = g[2];
    const q1y = g[3];
    const p2x = g[4];
    const p2y = g[5];
    const q2x = g[6];
    const q2y = g[7];
    let d1x = q1x - p1x;
    let d1y = q1y - p1y;
    let d2x = q2x - p2x;
    let d2y = q2y - p2y;
    let rx = p1x - p2x;
    let ry = p1y - p2y;
    let a = d1x * d1x + d1y * d1y;
    let e = d2x * d2x + d2y * d2y;
    if (a + e + (rx * rx + ry * ry) > HUGE) {
      // The parameters below multiply squared lengths together, past the largest double for
      // lengths beyond about 1e77: they are found from the segments scaled by a power of two,
      // which changes no bit of s and t, and the points from the segments themselves.
      d1x *= SHRINK;
      d1y *= SHRINK;
      d2x *= SHRINK;
      d2y *= SHRINK;
      rx *= SHRINK;
      ry *= SHRINK;
      a = d1x * d1x + d1y * d1y;
      e = d2x * d2x + d2y * d2y;
    }
    const f = d2x * rx + d2y * ry;
    let s = 0;
    let t = 0;
    if (a === 0 && e === 0) {
      s = 0;
      t = 0;
    } else if (a === 0) {
      t = clamp01(f / e);
    } else {
      const c = d1x * rx + d1y * ry;
      if (e === 0) {
        s = clamp01(-c / a);
      } else {
        const b = d1x * d2x + d1y * d2y;
        const denominator = a * e - b * b;
        // Parallel segments (denominator 0): any s works; 0 is then corrected by the clamps below.
        s = denominator > 0 ? clamp01((b * f - c * e) / denominator) : 0;
        t = (b * s + f) / e;
        if (t < 0) {
          t = 0;
          s = clamp01(-c / a);
        } else if (t > 1) {
          t = 1;
          s = clamp01((b - c) / a);
        }
      }
    }
    this.fraction1 = s;
    this.fraction2 = t;
    this.x1 = p1x + s * (q1x - p1x);
    this.y1 = p1y + s * (q1y - p1y);
    this.x2 = p2x + t * (q2x - p2x);
    this.y2 = p2y + t * (q2y - p2y);
    const dx = this.x2 - this.x1;
    const dy = this.y2 - this.y1;
    this.distanceSquared = dx * dx + dy * dy;
    return this;
  }
}

/** Above this sum of squared lengths the products of two of them could overflow (see compute). */
const HUGE = 1e150;
/** 2^-300: lengths up to 1e101 become about 1e10. */
const SHRINK = 2 ** -300;

function clamp01(v: number): number {
  return v < 0 ? 0 : v > 1 ? 1 : v;
}
