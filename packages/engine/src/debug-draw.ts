import type { BodyStore } from './store/body-store.js';
import { TypeCode } from './store/body-types.js';
import type { SegmentStore } from './store/segment-store.js';
import { SHAPE_STRIDE, SHAPE_VERTICES, VERTEX, type ShapeStore } from './store/shape-store.js';
import { MAX_POLYGON_VERTICES, ShapeKind } from './shapes/geometry.js';
import { cosSin } from './math/trig.js';
import { grownCapacity } from './util/grow.js';

/**
 * The world as coloured line segments, for any renderer to draw (Rapier's `debugRender()` buffers,
 * Box2D's b2DebugDraw): `lineCount` lines, line k from vertex 2k to 2k + 1, vertex v at
 * vertices[2v], vertices[2v + 1], its colour (red, green, blue, alpha in [0, 1]) at colors[4v..].
 * The object and its arrays are reused by every call.
 */
export interface DebugRenderBuffers {
  lineCount: number;
  vertices: Float32Array;
  colors: Float32Array;
}

/** What debugRender draws; each part is on by default. */
export interface DebugRenderOptions {
  /** Every shape's outline, with a line from a circle's centre showing its turn. */
  shapes?: boolean | undefined;
  /** Static segments and the box. */
  statics?: boolean | undefined;
  /** A line between each joint's anchors. */
  joints?: boolean | undefined;
  /** Each contact point's normal, `contactLength` long. */
  contacts?: boolean | undefined;
  contactLength?: number | undefined;
}

/** Colours by what a line shows. */
export const DEBUG_COLORS = {
  dynamic: [0.95, 0.65, 0.55, 1],
  sleeping: [0.55, 0.55, 0.6, 1],
  kinematic: [0.55, 0.6, 0.95, 1],
  static: [0.55, 0.9, 0.55, 1],
  sensor: [0.95, 0.9, 0.35, 1],
  world: [0.85, 0.85, 0.85, 1],
  joint: [0.6, 0.95, 1, 1],
  contact: [1, 0.3, 0.3, 1],
} as const;

/** Segments of a full circle's outline (an arc of a capsule gets half). */
const ROUND = 16;
const AROUND = new Float64Array(2 * (ROUND + 1));
for (let k = 0; k <= ROUND; k++) {
  const at = new Float64Array(2);
  cosSin((2 * Math.PI * k) / ROUND, at);
  AROUND[2 * k] = at[0];
  AROUND[2 * k + 1] = at[1];
}

const placed = new Float64Array(2 * MAX_POLYGON_VERTICES);

/** Fills the buffers; the world hands it its stores. */
export class DebugDraw {
  readonly out: DebugRenderBuffers = { lineCount: 0, vertices: new Float32Array(0), colors: new Float32Array(0) };

  begin(): void {
    this.out.lineCount = 0;
  }

  line(x1: number, y1: number, x2: number, y2: number, color: readonly number[]): void {
    const out = this.out;
    const k = out.lineCount;
    if (4 * (k + 1) > out.vertices.length) {
      const capacity = grownCapacity(out.vertices.length / 4, k + 1);
      const vertices = new Float32Array(4 * capacity);
      vertices.set(out.vertices);
      const colors = new Float32Array(8 * capacity);
      colors.set(out.colors);
      out.vertices = vertices;
      out.colors = colors;
    }
    out.vertices[4 * k] = x1;
    out.vertices[4 * k + 1] = y1;
    out.vertices[4 * k + 2] = x2;
    out.vertices[4 * k + 3] = y2;
    for (let v = 0; v < 2; v++) for (let c = 0; c < 4; c++) out.colors[8 * k + 4 * v + c] = color[c];
    out.lineCount = k + 1;
  }

  /** A circle's outline and a radius showing its turn (c, s). */
  circle(x: number, y: number, r: number, c: number, s: number, color: readonly number[]): void {
    for (let k = 0; k < ROUND; k++) this.line(x + r * AROUND[2 * k], y + r * AROUND[2 * k + 1], x + r * AROUND[2 * k + 2], y + r * AROUND[2 * k + 3], color);
    this.line(x, y, x + r * c, y + r * s, color);
  }

  /** Half a circle's outline from direction (ux, uy) turning towards +90 degrees. */
  private arc(x: number, y: number, r: number, ux: number, uy: number, color: readonly number[]): void {
    const half = ROUND / 2;
    for (let k = 0; k < half; k++) {
      const c0 = AROUND[2 * k];
      const s0 = AROUND[2 * k + 1];
      const c1 = AROUND[2 * k + 2];
      const s1 = AROUND[2 * k + 3];
      this.line(x + r * (ux * c0 - uy * s0), y + r * (uy * c0 + ux * s0), x + r * (ux * c1 - uy * s1), y + r * (uy * c1 + ux * s1), color);
    }
  }

  /** Every body's shapes (or, in a world of the report's circles, the circles themselves). */
  bodies(bodies: BodyStore, shapes: ShapeStore | null): void {
    const { type, asleep, x, y, radius, slotCount } = bodies;
    const rigid = bodies.rigid;
    for (let i = 0; i < slotCount; i++) {
      const t = type[i];
      if (t === TypeCode.free) continue;
      const color = t === TypeCode.static ? DEBUG_COLORS.static : t === TypeCode.kinematic ? DEBUG_COLORS.kinematic : asleep[i] ? DEBUG_COLORS.sleeping : DEBUG_COLORS.dynamic;
      const c = rigid ? rigid.c[i] : 1;
      const s = rigid ? rigid.s[i] : 0;
      if (shapes === null || rigid === null) {
        this.circle(x[i], y[i], radius[i], c, s, color);
        continue;
      }
      for (let k = rigid.firstShape[i]; k >= 0; k = shapes.next[k]) this.shape(shapes, k, x[i], y[i], c, s, shapes.sensor[k] ? DEBUG_COLORS.sensor : color);
    }
  }

  /** One shape of a body whose centre of mass is at (px, py), turned by (c, s). */
  private shape(shapes: ShapeStore, k: number, px: number, py: number, c: number, s: number, color: readonly number[]): void {
    const record = shapes.record;
    const base = k * SHAPE_STRIDE + SHAPE_VERTICES;
    const r = shapes.radius[k];
    const n = shapes.vertexCount[k];
    const kind = shapes.kind[k];
    // The shape's vertices in the world, into a scratch array reused by every shape.
    for (let v = 0; v < n; v++) {
      const lx = record[base + v * VERTEX];
      const ly = record[base + v * VERTEX + 1];
      placed[2 * v] = px + c * lx - s * ly;
      placed[2 * v + 1] = py + s * lx + c * ly;
    }
    if (kind === ShapeKind.circle) {
      this.circle(placed[0], placed[1], r, c, s, color);
      return;
    }
    if (kind === ShapeKind.capsule) {
      const ax = placed[0];
      const ay = placed[1];
      const bx = placed[2];
      const by = placed[3];
      const length = Math.sqrt((bx - ax) * (bx - ax) + (by - ay) * (by - ay));
      const ux = length > 0 ? (bx - ax) / length : c;
      const uy = length > 0 ? (by - ay) / length : s;
      // The sides, then the two ends, each half a circle around its end of the core.
      this.line(ax - r * uy, ay + r * ux, bx - r * uy, by + r * ux, color);
      this.line(ax + r * uy, ay - r * ux, bx + r * uy, by - r * ux, color);
      this.arc(bx, by, r, uy, -ux, color);
      this.arc(ax, ay, r, -uy, ux, color);
      return;
    }
    // A polygon's edges, each pushed out by the rounding radius along its normal (the corners' arcs are left out).
    for (let v = 0; v < n; v++) {
      const w = v + 1 === n ? 0 : v + 1;
      const nx = record[base + v * VERTEX + 2];
      const ny = record[base + v * VERTEX + 3];
      const ox = r * (c * nx - s * ny);
      const oy = r * (s * nx + c * ny);
      this.line(placed[2 * v] + ox, placed[2 * v + 1] + oy, placed[2 * w] + ox, placed[2 * w + 1] + oy, color);
    }
  }

  /** Static segments (their core line, and both sides where they are thick) and the box. */
  statics(segments: SegmentStore, box: { width: number; height: number } | null): void {
    const color = DEBUG_COLORS.world;
    for (let g = 0; g < segments.slotCount; g++) {
      if (segments.live[g] !== 1) continue;
      const ax = segments.ax[g];
      const ay = segments.ay[g];
      const bx = segments.bx[g];
      const by = segments.by[g];
      const t = segments.thickness[g];
      this.line(ax, ay, bx, by, color);
      if (t > 0) {
        const length = Math.sqrt((bx - ax) * (bx - ax) + (by - ay) * (by - ay));
        if (length > 0) {
          const nx = (-(by - ay) / length) * t;
          const ny = ((bx - ax) / length) * t;
          this.line(ax + nx, ay + ny, bx + nx, by + ny, color);
          this.line(ax - nx, ay - ny, bx - nx, by - ny, color);
        }
      }
    }
    if (box !== null) {
      const { width, height } = box;
      this.line(0, 0, width, 0, color);
      this.line(width, 0, width, height, color);
      this.line(width, height, 0, height, color);
      this.line(0, height, 0, 0, color);
    }
  }
}
