import { MAX_POLYGON_VERTICES, ShapeKind, type ShapeKindCode } from '../shapes/geometry.js';
import type { ShapeStore } from '../store/shape-store.js';
import type { SegmentStore } from '../store/segment-store.js';
import { SHAPE_STRIDE, SHAPE_VERTICES, ShapeField, VERTEX } from '../store/shape-store.js';

/**
 * A shape placed in the world for one narrow-phase test: its points and edge normals in world
 * coordinates, and its rounding radius. Every shape kind reads as a rounded convex polygon here
 * (a circle has one point, a capsule two), so the pair functions take this one form whatever
 * stores the shape: a body's shape, a static segment, or a wall of the world's box.
 * Two of these are reused by the narrow-phase: filling one allocates nothing.
 */
const POSE = new Float64Array(4);

export class WorldShape {
  kind: ShapeKindCode = ShapeKind.circle;
  count = 0;
  radius = 0;
  readonly x = new Float64Array(MAX_POLYGON_VERTICES);
  readonly y = new Float64Array(MAX_POLYGON_VERTICES);
  readonly nx = new Float64Array(MAX_POLYGON_VERTICES);
  readonly ny = new Float64Array(MAX_POLYGON_VERTICES);

  /** Shape `slot` of a body whose centre of mass is at (px, py), turned by (c, s). */
  fromStore(shapes: ShapeStore, slot: number, px: number, py: number, c: number, s: number): this {
    POSE[0] = px;
    POSE[1] = py;
    POSE[2] = c;
    POSE[3] = s;
    return this.fromPose(shapes, slot, POSE, 0);
  }

  /**
   * `fromStore` with the pose read from pose[at..at+3] (x, y, cosine, sine): for the narrow-phase's
   * loop, since V8 boxes each number passed to a call it does not inline, an allocation apiece.
   */
  fromPose(shapes: ShapeStore, slot: number, pose: Float64Array, at: number): this {
    const px = pose[at];
    const py = pose[at + 1];
    const c = pose[at + 2];
    const s = pose[at + 3];
    const g = shapes.record;
    const base = slot * SHAPE_STRIDE;
    const n = g[base + ShapeField.count];
    this.kind = g[base + ShapeField.kind] as ShapeKindCode;
    this.count = n;
    this.radius = g[base + ShapeField.radius];
    const { x, y, nx, ny } = this;
    for (let i = 0, at = base + SHAPE_VERTICES; i < n; i++, at += VERTEX) {
      const lx = g[at];
      const ly = g[at + 1];
      const qx = g[at + 2];
      const qy = g[at + 3];
      x[i] = px + c * lx - s * ly;
      y[i] = py + s * lx + c * ly;
      nx[i] = c * qx - s * qy;
      ny[i] = s * qx + c * qy;
    }
    return this;
  }

  /** Makes this shape a copy of `from`. */
  copy(from: WorldShape): this {
    this.kind = from.kind;
    this.count = from.count;
    this.radius = from.radius;
    for (let i = 0; i < from.count; i++) {
      this.x[i] = from.x[i];
      this.y[i] = from.y[i];
      this.nx[i] = from.nx[i];
      this.ny[i] = from.ny[i];
    }
    return this;
  }

  /** A circle of radius r at (cx, cy). */
  circle(cx: number, cy: number, r: number): this {
    this.kind = ShapeKind.circle;
    this.count = 1;
    this.radius = r;
    this.x[0] = cx;
    this.y[0] = cy;
    return this;
  }

  /**
   * Static segment g: a capsule of its thickness around it, a circle where it has no length. Read
   * from the store here rather than passed in, since V8 boxes each number passed to a call it does
   * not inline, five allocations per pair.
   */
  segment(segments: SegmentStore, g: number): this {
    this.x[0] = segments.ax[g];
    this.y[0] = segments.ay[g];
    this.x[1] = segments.bx[g];
    this.y[1] = segments.by[g];
    this.radius = segments.thickness[g];
    return this.asCapsule();
  }

  /**
   * The capsule of `radius` around (x[0], y[0])-(x[1], y[1]), which the caller has set (numbers
   * are not passed, for the reason in `segment`); a circle where the two meet.
   */
  asCapsule(): this {
    const ex = this.x[1] - this.x[0];
    const ey = this.y[1] - this.y[0];
    const length = Math.sqrt(ex * ex + ey * ey);
    if (!(length > 0)) {
      this.kind = ShapeKind.circle;
      this.count = 1;
      return this;
    }
    this.kind = ShapeKind.capsule;
    this.count = 2;
    this.nx[0] = ey / length;
    this.ny[0] = -ex / length;
    this.nx[1] = -ey / length;
    this.ny[1] = ex / length;
    return this;
  }

  /** The axis-aligned rectangle [minX, maxX] x [minY, maxY], from bounds[0..3] (for the reason in `segment`). */
  rectangle(bounds: Float64Array): this {
    const minX = bounds[0];
    const minY = bounds[1];
    const maxX = bounds[2];
    const maxY = bounds[3];
    this.kind = ShapeKind.polygon;
    this.count = 4;
    this.radius = 0;
    this.x[0] = minX;
    this.y[0] = minY;
    this.x[1] = maxX;
    this.y[1] = minY;
    this.x[2] = maxX;
    this.y[2] = maxY;
    this.x[3] = minX;
    this.y[3] = maxY;
    this.nx[0] = 0;
    this.ny[0] = -1;
    this.nx[1] = 1;
    this.ny[1] = 0;
    this.nx[2] = 0;
    this.ny[2] = 1;
    this.nx[3] = -1;
    this.ny[3] = 0;
    return this;
  }
}
