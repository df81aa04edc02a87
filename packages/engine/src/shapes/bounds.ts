import type { ShapeStore } from '../store/shape-store.js';
import { SHAPE_STRIDE, SHAPE_VERTICES, VERTEX } from '../store/shape-store.js';

/**
 * The axis-aligned box around shape `slot` of a body whose centre and rotation are in pose[0..3]
 * (x, y, cosine, sine): its points placed in the world, widened by its radius. Written to out as
 * minX, minY, maxX, maxY. The pose comes in an array, not as four arguments: V8 boxes each number
 * passed to a call it does not inline, and the step's containment calls this for every body that
 * reaches past a wall of the box (176 of the 1,000 bodies of a settled polygon-box scene).
 */
export function shapeBounds(shapes: ShapeStore, slot: number, pose: Float64Array, out: Float64Array): Float64Array {
  const px = pose[0];
  const py = pose[1];
  const c = pose[2];
  const s = pose[3];
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

/** The box around every shape of a body at `pose` (see shapeBounds); an empty box (Infinity, -Infinity) without shapes. */
export function bodyBounds(shapes: ShapeStore, first: number, pose: Float64Array, out: Float64Array): Float64Array {
  let minX = Infinity;
  let minY = Infinity;
  let maxX = -Infinity;
  let maxY = -Infinity;
  for (let shape = first; shape >= 0; shape = shapes.next[shape]) {
    shapeBounds(shapes, shape, pose, out);
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

/** Writes a pose for shapeBounds and bodyBounds into `pose` and returns it. */
export function poseOf(pose: Float64Array, px: number, py: number, c: number, s: number): Float64Array {
  pose[0] = px;
  pose[1] = py;
  pose[2] = c;
  pose[3] = s;
  return pose;
}
