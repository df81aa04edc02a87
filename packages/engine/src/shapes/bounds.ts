import type { ShapeStore } from '../store/shape-store.js';
import { SHAPE_STRIDE, SHAPE_VERTICES, VERTEX } from '../store/shape-store.js';

/**
 * The axis-aligned box around shape `slot` of a body at centre (px, py) turned by (c, s): its
 * points placed in the world, widened by its radius. Written to out as minX, minY, maxX, maxY.
 */
export function shapeBounds(shapes: ShapeStore, slot: number, px: number, py: number, c: number, s: number, out: Float64Array): Float64Array {
  const n = shapes.vertexCount[slot];
  const g = shapes.record;
  let minX = Infinity;
  let minY = Infinity;
  let maxX = -Infinity;
  let maxY = -Infinity;
  for (let i = 0, at = slot * SHAPE_STRIDE + SHAPE_VERTICES; i < n; i++, at += VERTEX) {
    const lx = g[at];
    const ly = g[at + 1];
    const wx = px + c * lx - s * ly;
    const wy = py + s * lx + c * ly;
    if (wx < minX) minX = wx;
    if (wx > maxX) maxX = wx;
    if (wy < minY) minY = wy;
    if (wy > maxY) maxY = wy;
  }
  const r = shapes.radius[slot];
  out[0] = minX - r;
  out[1] = minY - r;
  out[2] = maxX + r;
  out[3] = maxY + r;
  return out;
}

/** The box around every shape of a body (see shapeBounds); an empty box (Infinity, -Infinity) without shapes. */
export function bodyBounds(shapes: ShapeStore, first: number, px: number, py: number, c: number, s: number, out: Float64Array): Float64Array {
  let minX = Infinity;
  let minY = Infinity;
  let maxX = -Infinity;
  let maxY = -Infinity;
  for (let shape = first; shape >= 0; shape = shapes.next[shape]) {
    shapeBounds(shapes, shape, px, py, c, s, out);
    if (out[0] < minX) minX = out[0];
    if (out[1] < minY) minY = out[1];
    if (out[2] > maxX) maxX = out[2];
    if (out[3] > maxY) maxY = out[3];
  }
  out[0] = minX;
  out[1] = minY;
  out[2] = maxX;
  out[3] = maxY;
  return out;
}
