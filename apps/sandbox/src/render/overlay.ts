import { BodyTypeCode, type GridGeometry, type World } from '@maxgrid/engine';
import type { ViewTransform } from '../view.js';

export interface OverlayOptions {
  grid: boolean;
  aabb: boolean;
  /** Handle of the body being dragged, or -1. */
  held: number;
}

/**
 * A transparent 2D canvas above the renderer: the report's draw-grid function (5.11.2), each
 * body's AABB, and a ring around the held body. It works over either renderer, and stays blank
 * (one clear) when nothing is switched on.
 */
export class Overlay {
  private readonly ctx: CanvasRenderingContext2D;
  private wasEmpty = false;

  constructor(readonly canvas: HTMLCanvasElement) {
    const ctx = canvas.getContext('2d', { willReadFrequently: true });
    if (!ctx) throw new Error('this browser gives no canvas 2D context');
    this.ctx = ctx;
  }

  draw(world: World, view: ViewTransform, options: OverlayOptions): void {
    const ctx = this.ctx;
    const empty = !options.grid && !options.aabb && options.held < 0;
    if (empty && this.wasEmpty) return;
    this.wasEmpty = empty;
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.clearRect(0, 0, view.width, view.height);
    if (empty) return;
    ctx.setTransform(view.scale, 0, 0, view.scale, view.offsetX, view.offsetY);
    const hairline = 1 / view.scale;
    ctx.lineWidth = hairline;

    if (options.grid) {
      const g = world.gridGeometry();
      if (g && g.cellSize > 0) this.drawGrid(g, view);
    }
    if (options.aabb) {
      const v = world.views();
      ctx.strokeStyle = 'rgba(255, 210, 80, 0.55)';
      ctx.beginPath();
      for (let s = 0; s < v.slotCount; s++) {
        if (v.type[s] === BodyTypeCode.free) continue;
        const r = v.radius[s];
        ctx.rect(v.x[s] - r, v.y[s] - r, 2 * r, 2 * r);
      }
      ctx.stroke();
    }
    if (options.held >= 0 && world.hasBody(options.held)) {
      const c = world.getCircle(options.held);
      ctx.strokeStyle = '#ffffff';
      ctx.lineWidth = 2 * hairline;
      ctx.beginPath();
      ctx.arc(c.x, c.y, c.radius + 3 * hairline, 0, 2 * Math.PI);
      ctx.stroke();
    }
  }

  // Cells thinner than ~3 device pixels would paint the whole box grey; draw every k-th line then.
  private drawGrid(g: GridGeometry, view: ViewTransform): void {
    const ctx = this.ctx;
    const every = Math.max(1, Math.ceil(3 / (g.cellSize * view.scale)));
    const x1 = g.originX + g.columns * g.cellSize;
    const y1 = g.originY + g.rows * g.cellSize;
    ctx.strokeStyle = 'rgba(88, 166, 255, 0.45)';
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
  }
}
