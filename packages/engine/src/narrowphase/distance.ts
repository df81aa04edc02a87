import type { WorldShape } from './world-shape.js';

/**
 * The distance between the cores of two convex shapes (their points, without the rounding
 * radius), by GJK over the Minkowski difference in 2D, as Box2D's b2ShapeDistance: a simplex of
 * at most three support points is moved towards the origin until no support point gets closer.
 * Results in the fields: `distance` (0 when the cores overlap), the closest points (x1, y1) on a
 * and (x2, y2) on b, and `iterations`.
 */
export class ShapeDistance {
  distance = 0;
  x1 = 0;
  y1 = 0;
  x2 = 0;
  y2 = 0;
  iterations = 0;
  // The simplex: up to three vertices, each a point of a and one of b, their difference, a weight.
  private readonly ax = new Float64Array(3);
  private readonly ay = new Float64Array(3);
  private readonly bx = new Float64Array(3);
  private readonly by = new Float64Array(3);
  private readonly wx = new Float64Array(3);
  private readonly wy = new Float64Array(3);
  private readonly weight = new Float64Array(3);
  private readonly indexA = new Int32Array(3);
  private readonly indexB = new Int32Array(3);
  private count = 0;
  private readonly savedA = new Int32Array(3);
  private readonly savedB = new Int32Array(3);

  compute(a: WorldShape, b: WorldShape): this {
    this.count = 1;
    this.setVertex(0, a, 0, b, 0);
    this.weight[0] = 1;
    const { savedA, savedB } = this;
    let iteration = 0;
    for (; iteration < 20; iteration++) {
      const saved = this.count;
      for (let i = 0; i < saved; i++) {
        savedA[i] = this.indexA[i];
        savedB[i] = this.indexB[i];
      }
      if (this.count === 2) this.solve2();
      else if (this.count === 3) this.solve3();
      if (this.count === 3) break;
      // Search towards the origin from the simplex.
      let dx: number;
      let dy: number;
      if (this.count === 1) {
        dx = -this.wx[0];
        dy = -this.wy[0];
      } else {
        const ex = this.wx[1] - this.wx[0];
        const ey = this.wy[1] - this.wy[0];
        const side = ex * -this.wy[0] - ey * -this.wx[0];
        if (side > 0) {
          dx = -ey;
          dy = ex;
        } else {
          dx = ey;
          dy = -ex;
        }
      }
      if (dx * dx + dy * dy < 1e-300) break;
      // A new vertex: a's support against d, b's along d (w = b - a grows along d).
      const ia = support(a, -dx, -dy);
      const ib = support(b, dx, dy);
      let duplicate = false;
      for (let i = 0; i < saved; i++) {
        if (savedA[i] === ia && savedB[i] === ib) {
          duplicate = true;
          break;
        }
      }
      if (duplicate) break;
      this.setVertex(this.count, a, ia, b, ib);
      this.count++;
    }
    this.iterations = iteration;
    let x1 = 0;
    let y1 = 0;
    let x2 = 0;
    let y2 = 0;
    for (let i = 0; i < this.count; i++) {
      x1 += this.weight[i] * this.ax[i];
      y1 += this.weight[i] * this.ay[i];
      x2 += this.weight[i] * this.bx[i];
      y2 += this.weight[i] * this.by[i];
    }
    this.x1 = x1;
    this.y1 = y1;
    this.x2 = x2;
    this.y2 = y2;
    this.distance = this.count === 3 ? 0 : Math.sqrt((x2 - x1) * (x2 - x1) + (y2 - y1) * (y2 - y1));
    return this;
  }

  private setVertex(k: number, a: WorldShape, ia: number, b: WorldShape, ib: number): void {
    this.indexA[k] = ia;
    this.indexB[k] = ib;
    this.ax[k] = a.x[ia];
    this.ay[k] = a.y[ia];
    this.bx[k] = b.x[ib];
    this.by[k] = b.y[ib];
    this.wx[k] = b.x[ib] - a.x[ia];
    this.wy[k] = b.y[ib] - a.y[ia];
  }

  private copyVertex(to: number, from: number): void {
    this.indexA[to] = this.indexA[from];
    this.indexB[to] = this.indexB[from];
    this.ax[to] = this.ax[from];
    this.ay[to] = this.ay[from];
    this.bx[to] = this.bx[from];
    this.by[to] = this.by[from];
    this.wx[to] = this.wx[from];
    this.wy[to] = this.wy[from];
  }

  /** The closest point of segment w0-w1 to the origin, as weights; drops a vertex outside its region. */
  private solve2(): void {
    const { wx, wy, weight } = this;
    const ex = wx[1] - wx[0];
    const ey = wy[1] - wy[0];
    const d2 = -(wx[0] * ex + wy[0] * ey);
    if (d2 <= 0) {
      weight[0] = 1;
      this.count = 1;
      return;
    }
    const d1 = wx[1] * ex + wy[1] * ey;
    if (d1 <= 0) {
      this.copyVertex(0, 1);
      weight[0] = 1;
      this.count = 1;
      return;
    }
    const inverse = 1 / (d1 + d2);
    weight[0] = d1 * inverse;
    weight[1] = d2 * inverse;
    this.count = 2;
  }

  /** The closest point of triangle w0 w1 w2 to the origin, by its Voronoi regions. */
  private solve3(): void {
    const { wx, wy, weight } = this;
    const w1x = wx[0];
    const w1y = wy[0];
    const w2x = wx[1];
    const w2y = wy[1];
    const w3x = wx[2];
    const w3y = wy[2];
    // Edges 12, 13, 23 and their barycentric terms.
    const e12x = w2x - w1x;
    const e12y = w2y - w1y;
    const d12_1 = w2x * e12x + w2y * e12y;
    const d12_2 = -(w1x * e12x + w1y * e12y);
    const e13x = w3x - w1x;
    const e13y = w3y - w1y;
    const d13_1 = w3x * e13x + w3y * e13y;
    const d13_2 = -(w1x * e13x + w1y * e13y);
    const e23x = w3x - w2x;
    const e23y = w3y - w2y;
    const d23_1 = w3x * e23x + w3y * e23y;
    const d23_2 = -(w2x * e23x + w2y * e23y);
    const n123 = e12x * e13y - e12y * e13x;
    const d123_1 = n123 * (w2x * w3y - w2y * w3x);
    const d123_2 = n123 * (w3x * w1y - w3y * w1x);
    const d123_3 = n123 * (w1x * w2y - w1y * w2x);
    if (d12_2 <= 0 && d13_2 <= 0) {
      weight[0] = 1;
      this.count = 1;
      return;
    }
    if (d12_1 > 0 && d12_2 > 0 && d123_3 <= 0) {
      const inverse = 1 / (d12_1 + d12_2);
      weight[0] = d12_1 * inverse;
      weight[1] = d12_2 * inverse;
      this.count = 2;
      return;
    }
    if (d13_1 > 0 && d13_2 > 0 && d123_2 <= 0) {
      const inverse = 1 / (d13_1 + d13_2);
      weight[0] = d13_1 * inverse;
      weight[1] = d13_2 * inverse;
      this.copyVertex(1, 2);
      this.count = 2;
      return;
    }
    if (d12_1 <= 0 && d23_2 <= 0) {
      this.copyVertex(0, 1);
      weight[0] = 1;
      this.count = 1;
      return;
    }
    if (d13_1 <= 0 && d23_1 <= 0) {
      this.copyVertex(0, 2);
      weight[0] = 1;
      this.count = 1;
      return;
    }
    if (d23_1 > 0 && d23_2 > 0 && d123_1 <= 0) {
      const inverse = 1 / (d23_1 + d23_2);
      this.copyVertex(0, 2);
      weight[0] = d23_2 * inverse;
      weight[1] = d23_1 * inverse;
      this.count = 2;
      return;
    }
    const inverse = 1 / (d123_1 + d123_2 + d123_3);
    weight[0] = d123_1 * inverse;
    weight[1] = d123_2 * inverse;
    weight[2] = d123_3 * inverse;
    this.count = 3;
  }
}

/** The index of the point of s farthest along (dx, dy). */
function support(s: WorldShape, dx: number, dy: number): number {
  let best = 0;
  let most = s.x[0] * dx + s.y[0] * dy;
  for (let i = 1; i < s.count; i++) {
    const d = s.x[i] * dx + s.y[i] * dy;
    if (d > most) {
      most = d;
      best = i;
    }
  }
  return best;
}
