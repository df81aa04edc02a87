import { BodyTypeCode, type BodyViews, type ShapeViews } from '@maxgrid/engine';

/** Shape kind codes of ShapeViews.kind. */
export const CIRCLE = 0;
export const CAPSULE = 1;
export const POLYGON = 2;

/**
 * Each body's shapes as a chain, rebuilt when the shape table grows: ShapeViews lists each
 * shape's body, the renderers walk bodies (grouped by colour) and need their shapes.
 */
export class ShapeChains {
  first = new Int32Array(0);
  next = new Int32Array(0);
  private shapeSlots = -1;
  private bodySlots = -1;

  update(v: BodyViews, shapes: ShapeViews): void {
    if (shapes.slotCount === this.shapeSlots && v.slotCount === this.bodySlots) return;
    this.shapeSlots = shapes.slotCount;
    this.bodySlots = v.slotCount;
    if (this.first.length < v.slotCount) this.first = new Int32Array(Math.max(v.slotCount, 2 * this.first.length));
    if (this.next.length < shapes.slotCount) this.next = new Int32Array(Math.max(shapes.slotCount, 2 * this.next.length));
    this.first.fill(-1, 0, v.slotCount);
    // Backwards, so each chain lists its shapes in slot order.
    for (let k = shapes.slotCount - 1; k >= 0; k--) {
      if (!shapes.live[k]) continue;
      const b = shapes.body[k];
      this.next[k] = this.first[b];
      this.first[b] = k;
    }
  }
}

/**
 * Adds shape k of body b to the current canvas path, placed with the body's pose: a circle as an
 * arc, a capsule as two half circles joined, a polygon by its vertices, rounded (each corner an
 * arc of the radius between its two edges' normals) when it has a radius.
 */
export function addShapePath(ctx: CanvasRenderingContext2D, v: BodyViews, shapes: ShapeViews, k: number, b: number): void {
  const { vertices, stride, vertexStart, vertexCount, radius, kind } = shapes;
  const x = v.x[b];
  const y = v.y[b];
  const c = v.c.length > 0 ? v.c[b] : 1;
  const s = v.s.length > 0 ? v.s[b] : 0;
  const at = k * stride + vertexStart;
  const r = radius[k];
  const px = (i: number) => x + c * vertices[at + 4 * i] - s * vertices[at + 4 * i + 1];
  const py = (i: number) => y + s * vertices[at + 4 * i] + c * vertices[at + 4 * i + 1];
  const t = kind[k];
  if (t === CIRCLE) {
    ctx.moveTo(px(0) + r, py(0));
    ctx.arc(px(0), py(0), r, 0, 2 * Math.PI);
    return;
  }
  if (t === CAPSULE) {
    const ax = px(0);
    const ay = py(0);
    const bx = px(1);
    const by = py(1);
    const theta = Math.atan2(by - ay, bx - ax);
    ctx.moveTo(bx + r * Math.cos(theta - Math.PI / 2), by + r * Math.sin(theta - Math.PI / 2));
    ctx.arc(bx, by, r, theta - Math.PI / 2, theta + Math.PI / 2);
    ctx.arc(ax, ay, r, theta + Math.PI / 2, theta + (3 * Math.PI) / 2);
    ctx.closePath();
    return;
  }
  const n = vertexCount[k];
  if (r <= 0) {
    ctx.moveTo(px(0), py(0));
    for (let i = 1; i < n; i++) ctx.lineTo(px(i), py(i));
    ctx.closePath();
    return;
  }
  // The normal of the edge from vertex i, turned with the body.
  const normal = (i: number) => Math.atan2(s * vertices[at + 4 * i + 2] + c * vertices[at + 4 * i + 3], c * vertices[at + 4 * i + 2] - s * vertices[at + 4 * i + 3]);
  for (let i = 0; i < n; i++) {
    const before = normal((i + n - 1) % n);
    let after = normal(i);
    if (after < before) after += 2 * Math.PI;
    if (i === 0) ctx.moveTo(px(i) + r * Math.cos(before), py(i) + r * Math.sin(before));
    ctx.arc(px(i), py(i), r, before, after);
  }
  ctx.closePath();
}

/** Whether body b is drawn in the static colour: static bodies, as static circles and segments are. */
export function isStaticBody(v: BodyViews, b: number): boolean {
  return v.type[b] === BodyTypeCode.static;
}
