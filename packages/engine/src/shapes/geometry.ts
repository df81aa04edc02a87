import { atan2 } from '../math/trig.js';

/** Shape kinds, as stored in the shape store; the narrow-phase dispatches on a pair of them. */
export const ShapeKind = { circle: 0, capsule: 1, polygon: 2 } as const;
export type ShapeKindCode = (typeof ShapeKind)[keyof typeof ShapeKind];
/** Every stored shape kind, indexed by the code that `ShapeViews.kind` holds (a box is stored as a polygon). */
export const SHAPE_KIND_NAMES = ['circle', 'capsule', 'polygon'] as const;

/** The most vertices a convex polygon may have, as in Box2D (B2_MAX_POLYGON_VERTICES). */
export const MAX_POLYGON_VERTICES = 8;

/**
 * A convex shape in its body's frame: `count` points with a rounding `radius` around them, every
 * kind being a rounded convex polygon in this sense (Box2D's view): a circle is one point, a
 * capsule two, a polygon three to eight in counter-clockwise order (positive signed area), each
 * with the outward unit normal of the edge from it to the next.
 */
export class Geometry {
  kind: ShapeKindCode = ShapeKind.circle;
  count = 0;
  radius = 0;
  readonly x = new Float64Array(MAX_POLYGON_VERTICES);
  readonly y = new Float64Array(MAX_POLYGON_VERTICES);
  readonly nx = new Float64Array(MAX_POLYGON_VERTICES);
  readonly ny = new Float64Array(MAX_POLYGON_VERTICES);

  setCircle(cx: number, cy: number, radius: number): this {
    this.kind = ShapeKind.circle;
    this.count = 1;
    this.radius = radius;
    this.x[0] = cx;
    this.y[0] = cy;
    this.nx[0] = 0;
    this.ny[0] = 0;
    return this;
  }

  /** A capsule: the segment (x1, y1)-(x2, y2), which must have a length, with a radius around it. */
  setCapsule(x1: number, y1: number, x2: number, y2: number, radius: number): this {
    this.kind = ShapeKind.capsule;
    this.count = 2;
    this.radius = radius;
    this.x[0] = x1;
    this.y[0] = y1;
    this.x[1] = x2;
    this.y[1] = y2;
    const ex = x2 - x1;
    const ey = y2 - y1;
    const length = Math.sqrt(ex * ex + ey * ey);
    this.nx[0] = ey / length;
    this.ny[0] = -ex / length;
    this.nx[1] = -this.nx[0];
    this.ny[1] = -this.ny[0];
    return this;
  }

  /** A polygon from points already checked convex and counter-clockwise (see checkPolygon). */
  setPolygon(xs: ArrayLike<number>, ys: ArrayLike<number>, count: number, radius: number): this {
    this.kind = ShapeKind.polygon;
    this.count = count;
    this.radius = radius;
    for (let i = 0; i < count; i++) {
      this.x[i] = xs[i];
      this.y[i] = ys[i];
    }
    for (let i = 0; i < count; i++) {
      const j = i + 1 === count ? 0 : i + 1;
      const ex = this.x[j] - this.x[i];
      const ey = this.y[j] - this.y[i];
      const length = Math.sqrt(ex * ex + ey * ey);
      this.nx[i] = ey / length;
      this.ny[i] = -ex / length;
    }
    return this;
  }

  copyFrom(other: Geometry): this {
    this.kind = other.kind;
    this.count = other.count;
    this.radius = other.radius;
    this.x.set(other.x);
    this.y.set(other.y);
    this.nx.set(other.nx);
    this.ny.set(other.ny);
    return this;
  }

  /** Moves the shape by (dx, dy) in its frame (normals do not change). */
  translate(dx: number, dy: number): void {
    for (let i = 0; i < this.count; i++) {
      this.x[i] += dx;
      this.y[i] += dy;
    }
  }

  /** Rotates by (c, s) about the frame's origin, then moves by (dx, dy): an offset transform. */
  transform(c: number, s: number, dx: number, dy: number): void {
    for (let i = 0; i < this.count; i++) {
      const px = this.x[i];
      const py = this.y[i];
      this.x[i] = c * px - s * py + dx;
      this.y[i] = s * px + c * py + dy;
      const qx = this.nx[i];
      const qy = this.ny[i];
      this.nx[i] = c * qx - s * qy;
      this.ny[i] = s * qx + c * qy;
    }
  }

  /** The largest distance from (px, py) to the shape's surface: its bounding radius about that point. */
  extentFrom(px: number, py: number): number {
    let most = 0;
    for (let i = 0; i < this.count; i++) {
      const dx = this.x[i] - px;
      const dy = this.y[i] - py;
      const d = dx * dx + dy * dy;
      if (d > most) most = d;
    }
    return Math.sqrt(most) + this.radius;
  }
}

/**
 * Mass properties of a shape of density 1: area, centroid, and the polar moment of inertia about
 * the centroid (per unit density).
 */
export interface AreaProperties {
  area: number;
  cx: number;
  cy: number;
  inertia: number;
}

export function emptyAreaProperties(): AreaProperties {
  return { area: 0, cx: 0, cy: 0, inertia: 0 };
}

/**
 * Area, first moment and polar moment about a reference point, accumulated over pieces. The
 * reference is a point of the shape: moments taken about the frame's origin would cancel
 * catastrophically in the shift to the centroid for a shape far from that origin (a 10 x 10
 * square 1e9 away would get inertia 0).
 */
class Moments {
  area = 0;
  mx = 0;
  my = 0;
  polar = 0;
  private refX = 0;
  private refY = 0;

  clear(refX: number, refY: number): void {
    this.area = 0;
    this.mx = 0;
    this.my = 0;
    this.polar = 0;
    this.refX = refX;
    this.refY = refY;
  }

  /** A counter-clockwise convex polygon, as triangles fanned from its first vertex. */
  addPolygon(xs: ArrayLike<number>, ys: ArrayLike<number>, count: number): void {
    const rx = xs[0] - this.refX;
    const ry = ys[0] - this.refY;
    let area = 0;
    let mx = 0;
    let my = 0;
    let polar = 0;
    for (let i = 1; i + 1 < count; i++) {
      const e1x = xs[i] - xs[0];
      const e1y = ys[i] - ys[0];
      const e2x = xs[i + 1] - xs[0];
      const e2y = ys[i + 1] - ys[0];
      const d = e1x * e2y - e1y * e2x;
      const triangle = d / 2;
      area += triangle;
      mx += (triangle * (e1x + e2x)) / 3;
      my += (triangle * (e1y + e2y)) / 3;
      // The triangle's polar moment about its vertex at the reference point.
      polar += (d / 12) * (e1x * e1x + e1x * e2x + e2x * e2x + e1y * e1y + e1y * e2y + e2y * e2y);
    }
    // Moved from the first vertex to the reference point: polar about r, plus the parallel-axis terms.
    this.area += area;
    this.mx += mx + area * rx;
    this.my += my + area * ry;
    this.polar += polar + 2 * (rx * mx + ry * my) + area * (rx * rx + ry * ry);
  }

  /** A disc sector of radius r and angle theta with its apex at (ax, ay), bisected by the unit (bx, by). */
  addSector(px: number, py: number, bx: number, by: number, r: number, theta: number, halfSin: number): void {
    const ax = px - this.refX;
    const ay = py - this.refY;
    const area = (theta * r * r) / 2;
    // The centroid lies 4 r sin(theta/2) / (3 theta) from the apex along the bisector (2r/3 as theta -> 0).
    const d = theta > 1e-12 ? (4 * r * halfSin) / (3 * theta) : (2 * r) / 3;
    const qx = d * bx;
    const qy = d * by;
    this.area += area;
    this.mx += area * (ax + qx);
    this.my += area * (ay + qy);
    // About the apex a sector's polar moment is area r^2 / 2 whatever its angle.
    this.polar += (area * r * r) / 2 + area * (ax * ax + ay * ay + 2 * (ax * qx + ay * qy));
  }

  addDisc(px: number, py: number, r: number): void {
    const cx = px - this.refX;
    const cy = py - this.refY;
    const area = Math.PI * r * r;
    this.area += area;
    this.mx += area * cx;
    this.my += area * cy;
    this.polar += (area * r * r) / 2 + area * (cx * cx + cy * cy);
  }

  write(out: AreaProperties): AreaProperties {
    const cx = this.area > 0 ? this.mx / this.area : 0;
    const cy = this.area > 0 ? this.my / this.area : 0;
    out.area = this.area;
    out.cx = this.refX + cx;
    out.cy = this.refY + cy;
    out.inertia = this.polar - this.area * (cx * cx + cy * cy);
    return out;
  }
}

const moments = new Moments();
const quadX = new Float64Array(4);
const quadY = new Float64Array(4);

/**
 * Area properties of a shape, exact for every kind: a rounded polygon is its core polygon, plus a
 * rectangle of width `radius` outside each edge, plus a disc sector at each vertex (their angles
 * add up to a full turn). Box2D approximates the rounded polygon instead; here mass, centroid and
 * inertia match the shape that collides.
 */
export function areaProperties(g: Geometry, out: AreaProperties): AreaProperties {
  moments.clear(g.x[0], g.y[0]);
  const r = g.radius;
  if (g.kind === ShapeKind.circle) {
    moments.addDisc(g.x[0], g.y[0], r);
    return moments.write(out);
  }
  if (g.kind === ShapeKind.polygon) moments.addPolygon(g.x, g.y, g.count);
  if (r === 0) return moments.write(out);
  const n = g.count;
  for (let i = 0; i < n; i++) {
    const j = i + 1 === n ? 0 : i + 1;
    // The edge's band: a, a + r n, b + r n, b is counter-clockwise for an outward normal n.
    // A capsule's two "edges" are the two sides of its segment, so each band appears once.
    if (g.kind === ShapeKind.capsule && i === 1) break;
    const ax = g.x[i];
    const ay = g.y[i];
    const bx = g.x[j];
    const by = g.y[j];
    const nx = g.nx[i];
    const ny = g.ny[i];
    quadX[0] = ax;
    quadY[0] = ay;
    quadX[1] = ax + r * nx;
    quadY[1] = ay + r * ny;
    quadX[2] = bx + r * nx;
    quadY[2] = by + r * ny;
    quadX[3] = bx;
    quadY[3] = by;
    moments.addPolygon(quadX, quadY, 4);
  }
  if (g.kind === ShapeKind.capsule) {
    // The other side of the segment, and two half discs at the ends.
    const ax = g.x[0];
    const ay = g.y[0];
    const bx = g.x[1];
    const by = g.y[1];
    const nx = -g.nx[0];
    const ny = -g.ny[0];
    quadX[0] = bx;
    quadY[0] = by;
    quadX[1] = bx + r * nx;
    quadY[1] = by + r * ny;
    quadX[2] = ax + r * nx;
    quadY[2] = ay + r * ny;
    quadX[3] = ax;
    quadY[3] = ay;
    moments.addPolygon(quadX, quadY, 4);
    const ex = bx - ax;
    const ey = by - ay;
    const length = Math.sqrt(ex * ex + ey * ey);
    // A core offset so far from its body's origin that its ends round to one point (length 2 at
    // 1e16) has no direction of its own: its normal still has one, and the two half discs make
    // the disc it collides as.
    const ux = length > 0 ? ex / length : -g.ny[0];
    const uy = length > 0 ? ey / length : g.nx[0];
    moments.addSector(bx, by, ux, uy, r, Math.PI, 1);
    moments.addSector(ax, ay, -ux, -uy, r, Math.PI, 1);
    return moments.write(out);
  }
  for (let i = 0; i < n; i++) {
    const p = i === 0 ? n - 1 : i - 1;
    const dot = g.nx[p] * g.nx[i] + g.ny[p] * g.ny[i];
    const cross = g.nx[p] * g.ny[i] - g.ny[p] * g.nx[i];
    const theta = atan2(cross, dot);
    const bx = g.nx[p] + g.nx[i];
    const by = g.ny[p] + g.ny[i];
    const length = Math.sqrt(bx * bx + by * by);
    const halfSin = Math.sqrt(Math.max(0, (1 - dot) / 2));
    moments.addSector(g.x[i], g.y[i], bx / length, by / length, r, theta, halfSin);
  }
  return moments.write(out);
}

/**
 * Why `checkPolygon` refused a set of points, with the index of the vertex at fault: the world
 * turns it into an error that names the field.
 */
export type PolygonProblem =
  | { problem: 'count'; count: number }
  | { problem: 'area' }
  | { problem: 'duplicate'; index: number; other: number; distance: number; size: number }
  | { problem: 'collinear'; index: number; distance: number; size: number }
  | { problem: 'concave'; index: number; edge: number };

/** Points this close to each other, or to the line through their neighbours, relative to the polygon's size, are rejected. */
export const POLYGON_TOLERANCE = 1e-6;

/**
 * Checks points for a convex polygon and puts them in counter-clockwise order (positive signed
 * area, `reversed` says whether they came clockwise) in xs, ys. Refuses: fewer than 3 or more
 * than MAX_POLYGON_VERTICES points, no area, two points closer than POLYGON_TOLERANCE times the
 * polygon's size, a point that close to the line through its neighbours (collinear), and any
 * point on the inner side of an edge it does not belong to (concave or self-intersecting).
 */
export function checkPolygon(xs: Float64Array, ys: Float64Array, count: number): PolygonProblem | { problem: null; reversed: boolean } {
  if (count < 3 || count > MAX_POLYGON_VERTICES) return { problem: 'count', count };
  let size = 0;
  for (let i = 1; i < count; i++) size = Math.max(size, Math.abs(xs[i] - xs[0]), Math.abs(ys[i] - ys[0]));
  if (!(size > 0)) return { problem: 'area' };
  const tolerance = POLYGON_TOLERANCE * size;
  for (let i = 0; i < count; i++) {
    for (let j = i + 1; j < count; j++) {
      const dx = xs[j] - xs[i];
      const dy = ys[j] - ys[i];
      if (dx * dx + dy * dy <= tolerance * tolerance) return { problem: 'duplicate', index: j, other: i, distance: Math.sqrt(dx * dx + dy * dy), size };
    }
  }
  // From the first point, not the frame's origin: products of far coordinates would round away
  // the area of a polygon far from its body's origin.
  let twiceArea = 0;
  for (let i = 1; i + 1 < count; i++) twiceArea += (xs[i] - xs[0]) * (ys[i + 1] - ys[0]) - (xs[i + 1] - xs[0]) * (ys[i] - ys[0]);
  if (!(Math.abs(twiceArea) > tolerance * size)) return { problem: 'area' };
  const reversed = twiceArea < 0;
  if (reversed) {
    for (let i = 0, j = count - 1; i < j; i++, j--) {
      const tx = xs[i];
      xs[i] = xs[j];
      xs[j] = tx;
      const ty = ys[i];
      ys[i] = ys[j];
      ys[j] = ty;
    }
  }
  for (let i = 0; i < count; i++) {
    const p = i === 0 ? count - 1 : i - 1;
    const n = i + 1 === count ? 0 : i + 1;
    const ex = xs[n] - xs[p];
    const ey = ys[n] - ys[p];
    const length = Math.sqrt(ex * ex + ey * ey);
    // Distance of point i from the line through its neighbours, positive outside.
    const bulge = ((xs[i] - xs[p]) * ey - (ys[i] - ys[p]) * ex) / length;
    if (Math.abs(bulge) <= tolerance) return { problem: 'collinear', index: reversed ? count - 1 - i : i, distance: Math.abs(bulge), size };
    // Inside the line through its neighbours: a reflex corner, the point where convexity fails.
    if (bulge < 0) return { problem: 'concave', index: reversed ? count - 1 - i : i, edge: reversed ? count - 1 - n : p };
  }
  for (let e = 0; e < count; e++) {
    const f = e + 1 === count ? 0 : e + 1;
    const ex = xs[f] - xs[e];
    const ey = ys[f] - ys[e];
    const length = Math.sqrt(ex * ex + ey * ey);
    for (let k = 0; k < count; k++) {
      if (k === e || k === f) continue;
      // Signed distance to the left of edge e (inside for a counter-clockwise polygon).
      const inside = (ex * (ys[k] - ys[e]) - ey * (xs[k] - xs[e])) / length;
      if (!(inside > tolerance)) {
        const index = reversed ? count - 1 - k : k;
        const edge = reversed ? count - 1 - f : e;
        return { problem: 'concave', index, edge };
      }
    }
  }
  return { problem: null, reversed };
}
