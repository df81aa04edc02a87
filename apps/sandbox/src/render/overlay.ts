import { BodyTypeCode, type GridGeometry, type World } from '@maxgrid/engine';
import type { HitEvents } from '../hit-events.js';
import type { QueryTool } from '../query-tool.js';
import type { TouchEvents } from '../touch-events.js';
import type { ViewTransform } from '../view.js';

export interface OverlayOptions {
  grid: boolean;
  aabb: boolean;
  /** Contact points and their normals (world.contactPoints). */
  contacts: boolean;
  /** Handle of the body being dragged, or -1. */
  held: number;
  /** The drag spring of a held shape: from its grab point to the pointer. */
  grab: { x: number; y: number; toX: number; toY: number } | null;
  /** Static segments (x1, y1, x2, y2, thickness each), for their AABBs. */
  segments: Float64Array;
  touches: TouchEvents;
  hits: HitEvents;
  query: QueryTool;
  /** The box's walls, where the grid overlay stops; null for an open scene. */
  bounds: { x: number; y: number; width: number; height: number } | null;
}

export const RAY_COLOR = '#f0f6fc';
export const HIT_COLOR = '#ff7b72';
const POINT_COLOR = '#e3b341';
/** Contact points (dots) and their normals. */
export const CONTACT_COLOR = '#3fb950';
const NORMAL_COLOR = 'rgba(63, 185, 80, 0.7)';
const FLASH_COLOR = 'rgba(255, 255, 255, 0.85)';
/** Rings at hit bodies: a colour nothing else on the overlay uses, so they can be told apart. */
export const HIT_RING_COLOR = '#d2a8ff';
/** The Box tool's rectangle and the circles found in it. */
export const BOX_COLOR = '#56d4dd';
const BOX_FILL = 'rgba(86, 212, 221, 0.08)';

/**
 * A transparent 2D canvas above the renderer: the report's draw-grid function (5.11.2), AABBs of
 * bodies and segments, a ring around the held body, flashes where touches began, rings where hits
 * happened, and the query tools' rays, hits, boxes and highlights. It works over either renderer, and stays blank (one clear)
 * when nothing is switched on.
 */
export class Overlay {
  private readonly ctx: CanvasRenderingContext2D;
  private wasEmpty = false;

  constructor(readonly canvas: HTMLCanvasElement) {
    const ctx = canvas.getContext('2d', { willReadFrequently: true });
    if (!ctx) throw new Error('this browser gives no canvas 2D context');
    this.ctx = ctx;
  }

  draw(world: World, view: ViewTransform, o: OverlayOptions): void {
    const ctx = this.ctx;
    const q = o.query;
    const querying = (q.tool === 'ray' && q.hasRay) || (q.tool === 'point' && q.hasPoint) || (q.tool === 'box' && q.hasBox);
    const empty = !o.grid && !o.aabb && !o.contacts && o.held < 0 && !o.touches.enabled && !o.hits.showing && !querying;
    if (empty && this.wasEmpty) return;
    this.wasEmpty = empty;
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.clearRect(0, 0, view.width, view.height);
    if (empty) return;
    ctx.setTransform(view.scale, 0, 0, view.scale, view.offsetX, view.offsetY);
    const hairline = 1 / view.scale;
    ctx.lineWidth = hairline;

    if (o.grid) {
      const g = world.gridGeometry();
      if (g && g.cellSize > 0) this.drawGrid(g, view, o.bounds);
    }
    if (o.aabb) this.drawBoxes(world, o.segments);
    if (o.touches.enabled) this.drawFlashes(world, o.touches, hairline);
    if (o.hits.showing) this.drawHits(world, o.hits, hairline);
    if (o.contacts) this.drawContacts(world, hairline);
    if (o.held >= 0 && world.hasBody(o.held)) {
      const v = world.views();
      const s = world.slotOfHandle(o.held);
      ctx.strokeStyle = '#ffffff';
      ctx.lineWidth = 2 * hairline;
      ctx.beginPath();
      ctx.arc(v.x[s], v.y[s], v.radius[s] + 3 * hairline, 0, 2 * Math.PI);
      ctx.stroke();
      const g = o.grab;
      if (g) {
        // The drag spring: from where the shape was grabbed to the pointer.
        ctx.beginPath();
        ctx.moveTo(g.x, g.y);
        ctx.lineTo(g.toX, g.toY);
        ctx.stroke();
        ctx.beginPath();
        ctx.arc(g.x, g.y, 3 * hairline, 0, 2 * Math.PI);
        ctx.fillStyle = '#ffffff';
        ctx.fill();
      }
    }
    if (q.tool === 'ray' && q.hasRay) this.drawRay(q, hairline);
    if (q.tool === 'point' && q.hasPoint) this.drawPoint(world, q, hairline);
    if (q.tool === 'box' && q.hasBox) this.drawBox(world, q, hairline);
  }

  private drawBoxes(world: World, seg: Float64Array): void {
    const ctx = this.ctx;
    const v = world.views();
    ctx.strokeStyle = 'rgba(255, 210, 80, 0.55)';
    ctx.beginPath();
    const shapes = v.shapes;
    if (shapes) {
      // Each shape's own box: its points placed with its body's pose, widened by its radius.
      const { vertices, stride, vertexStart, body, vertexCount, radius, live } = shapes;
      for (let k = 0; k < shapes.slotCount; k++) {
        if (!live[k]) continue;
        const b = body[k];
        const c = v.c[b];
        const sn = v.s[b];
        let minX = Infinity;
        let minY = Infinity;
        let maxX = -Infinity;
        let maxY = -Infinity;
        for (let i = 0, at = k * stride + vertexStart; i < vertexCount[k]; i++, at += 4) {
          const px = v.x[b] + c * vertices[at] - sn * vertices[at + 1];
          const py = v.y[b] + sn * vertices[at] + c * vertices[at + 1];
          minX = Math.min(minX, px);
          maxX = Math.max(maxX, px);
          minY = Math.min(minY, py);
          maxY = Math.max(maxY, py);
        }
        const r = radius[k];
        ctx.rect(minX - r, minY - r, maxX - minX + 2 * r, maxY - minY + 2 * r);
      }
    } else {
      for (let s = 0; s < v.slotCount; s++) {
        if (v.type[s] === BodyTypeCode.free) continue;
        const r = v.radius[s];
        ctx.rect(v.x[s] - r, v.y[s] - r, 2 * r, 2 * r);
      }
    }
    for (let i = 0; i < seg.length; i += 5) {
      const t = seg[i + 4];
      const minX = Math.min(seg[i], seg[i + 2]) - t;
      const minY = Math.min(seg[i + 1], seg[i + 3]) - t;
      ctx.rect(minX, minY, Math.max(seg[i], seg[i + 2]) + t - minX, Math.max(seg[i + 1], seg[i + 3]) + t - minY);
    }
    ctx.stroke();
  }

  /** A dot at each contact point and its manifold's normal, 12 device pixels long. */
  private drawContacts(world: World, hairline: number): void {
    const ctx = this.ctx;
    const points = world.contactPoints();
    const length = 12 * hairline;
    ctx.strokeStyle = NORMAL_COLOR;
    ctx.lineWidth = 1.5 * hairline;
    ctx.beginPath();
    for (let k = 0; k < points.count; k++) {
      ctx.moveTo(points.x[k], points.y[k]);
      ctx.lineTo(points.x[k] + points.nx[k] * length, points.y[k] + points.ny[k] * length);
    }
    ctx.stroke();
    ctx.fillStyle = CONTACT_COLOR;
    ctx.beginPath();
    const r = 2 * hairline;
    for (let k = 0; k < points.count; k++) ctx.rect(points.x[k] - r, points.y[k] - r, 2 * r, 2 * r);
    ctx.fill();
  }

  // A ring rather than a fill: in a pile touches begin every step, and fills would hide the bodies.
  private drawFlashes(world: World, touches: TouchEvents, hairline: number): void {
    const ctx = this.ctx;
    const v = world.views();
    ctx.strokeStyle = FLASH_COLOR;
    ctx.lineWidth = 1.5 * hairline;
    ctx.beginPath();
    for (let s = 0; s < v.slotCount; s++) {
      if (v.type[s] === BodyTypeCode.free || !touches.flashing(s)) continue;
      ctx.moveTo(v.x[s] + v.radius[s], v.y[s]);
      ctx.arc(v.x[s], v.y[s], v.radius[s], 0, 2 * Math.PI);
    }
    ctx.stroke();
  }

  /**
   * A ring just outside each body hit in the last few steps, its gap growing with the hit's speed
   * over the threshold: 3 device pixels at the threshold, 4 more per doubling, up to 19. A log
   * scale, since approach speeds span orders of magnitude in one scene. One path for all rings.
   */
  private drawHits(world: World, hits: HitEvents, hairline: number): void {
    const ctx = this.ctx;
    const v = world.views();
    const speeds = hits.hitSpeed;
    ctx.strokeStyle = HIT_RING_COLOR;
    ctx.lineWidth = 2 * hairline;
    ctx.beginPath();
    for (let s = 0; s < v.slotCount; s++) {
      if (v.type[s] === BodyTypeCode.free || !hits.ringing(s)) continue;
      const gap = Math.min(19, 3 + 4 * Math.log2(Math.max(1, speeds[s] / hits.threshold)));
      const r = v.radius[s] + gap * hairline;
      ctx.moveTo(v.x[s] + r, v.y[s]);
      ctx.arc(v.x[s], v.y[s], r, 0, 2 * Math.PI);
    }
    ctx.stroke();
  }

  // Highlights found bodies through the views and their slots: a large box holds thousands of
  // bodies, and getCircle would allocate an object for each of them every frame.
  private drawBox(world: World, q: QueryTool, hairline: number): void {
    const ctx = this.ctx;
    const x = Math.min(q.bx1, q.bx2);
    const y = Math.min(q.by1, q.by2);
    const w = Math.abs(q.bx2 - q.bx1);
    const h = Math.abs(q.by2 - q.by1);
    ctx.fillStyle = BOX_FILL;
    ctx.fillRect(x, y, w, h);
    ctx.strokeStyle = BOX_COLOR;
    ctx.lineWidth = 1.5 * hairline;
    ctx.strokeRect(x, y, w, h);
    const v = world.views();
    ctx.lineWidth = 2.5 * hairline;
    ctx.beginPath();
    for (const handle of q.inBox) {
      if (!world.hasBody(handle)) continue;
      const s = world.slotOfHandle(handle);
      const r = v.radius[s] + 2 * hairline;
      ctx.moveTo(v.x[s] + r, v.y[s]);
      ctx.arc(v.x[s], v.y[s], r, 0, 2 * Math.PI);
    }
    ctx.stroke();
  }

  private drawRay(q: QueryTool, hairline: number): void {
    const ctx = this.ctx;
    ctx.strokeStyle = RAY_COLOR;
    ctx.lineWidth = 1.5 * hairline;
    ctx.beginPath();
    ctx.moveTo(q.x1, q.y1);
    ctx.lineTo(q.x2, q.y2);
    ctx.stroke();
    // Each hit: a dot where the ray enters, and the surface normal there, 18 device pixels long.
    const normal = 18 * hairline;
    ctx.strokeStyle = HIT_COLOR;
    ctx.fillStyle = HIT_COLOR;
    ctx.lineWidth = 2 * hairline;
    for (let k = 0; k < q.hits.length; k++) {
      const h = q.hits[k];
      ctx.beginPath();
      ctx.arc(h.x, h.y, (k === 0 ? 5 : 3.5) * hairline, 0, 2 * Math.PI);
      ctx.fill();
      ctx.beginPath();
      ctx.moveTo(h.x, h.y);
      ctx.lineTo(h.x + h.normalX * normal, h.y + h.normalY * normal);
      ctx.stroke();
    }
  }

  private drawPoint(world: World, q: QueryTool, hairline: number): void {
    const ctx = this.ctx;
    ctx.strokeStyle = POINT_COLOR;
    ctx.lineWidth = 2.5 * hairline;
    ctx.beginPath();
    const v = world.views();
    for (const h of q.under) {
      if (!world.hasBody(h)) continue;
      const s = world.slotOfHandle(h);
      const r = v.radius[s] + 2 * hairline;
      ctx.moveTo(v.x[s] + r, v.y[s]);
      ctx.arc(v.x[s], v.y[s], r, 0, 2 * Math.PI);
    }
    ctx.stroke();
  }

  // Cells thinner than ~3 device pixels would paint the whole box grey; draw every k-th line then.
  private drawGrid(g: GridGeometry, view: ViewTransform, bounds: OverlayOptions['bounds']): void {
    const ctx = this.ctx;
    // The grid is whole cells over the circles' extent, so its last row and column can reach past
    // the walls (up to a cell, ~19 px); no body can be there, so the picture stops at the box.
    ctx.save();
    if (bounds) {
      ctx.beginPath();
      ctx.rect(bounds.x, bounds.y, bounds.width, bounds.height);
      ctx.clip();
    }
    const every = Math.max(1, Math.ceil(3 / (g.cellSize * view.scale)));
    const x1 = g.originX + g.columns * g.cellSize;
    const y1 = g.originY + g.rows * g.cellSize;
    ctx.strokeStyle = 'rgba(88, 166, 255, 0.45)';
    ctx.lineWidth = 1 / view.scale;
    ctx.beginPath();
    for (let c = 0; c <= g.columns; c += every) {
      const x = g.originX + c * g.cellSize;
      ctx.moveTo(x, g.originY);
      ctx.lineTo(x, y1);
    }
    for (let r = 0; r <= g.rows; r += every) {
      const y = g.originY + r * g.cellSize;
      ctx.moveTo(g.originX, y);
      ctx.lineTo(x1, y);
    }
    ctx.stroke();
    ctx.restore();
  }
}
