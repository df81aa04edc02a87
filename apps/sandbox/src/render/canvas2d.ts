import { BodyTypeCode, type BodyViews } from '@maxgrid/engine';
import { JOINT_COLOR, PALETTE_SIZE, STATIC_COLOR, type BodyColors } from '../colors.js';
import type { ViewTransform } from '../view.js';
import { BACKGROUND, BOX_FILL, JOINT_DOT_PX, JOINT_LINE_ALPHA, JOINT_LINE_PX, SLEEP_DIM, type Renderer, type SceneShapes } from './renderer.js';
import { ShapeChains, addShapePath } from './shape-paths.js';

const TAU = 2 * Math.PI;

/**
 * The report's renderer (5.5): canvas 2D arcs. Bodies are filled one palette colour at a time, so
 * a frame costs PALETTE_SIZE fill calls rather than one per circle; circles under a pixel wide
 * become squares, which look the same and skip the arc tessellation.
 */
export class Canvas2DRenderer implements Renderer {
  private readonly ctx: CanvasRenderingContext2D;
  private readonly chains = new ShapeChains();

  constructor(readonly canvas: HTMLCanvasElement) {
    // willReadFrequently keeps this canvas on the CPU rasteriser. Chrome's GPU canvas re-tessellates
    // every arc each frame, and where the GPU is emulated (SwiftShader, as in the tests) that made
    // 2,000 circles run at 1 fps against about 14 on the CPU. Large counts are the WebGL renderer's job.
    const ctx = canvas.getContext('2d', { alpha: false, willReadFrequently: true });
    if (!ctx) throw new Error('this browser gives no canvas 2D context');
    this.ctx = ctx;
  }

  draw(v: BodyViews, colors: BodyColors, view: ViewTransform, box: { x: number; y: number; width: number; height: number }, shapes: SceneShapes): void {
    const ctx = this.ctx;
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.fillStyle = BACKGROUND;
    ctx.fillRect(0, 0, view.width, view.height);
    ctx.setTransform(view.scale, 0, 0, view.scale, view.offsetX, view.offsetY);
    ctx.fillStyle = BOX_FILL;
    ctx.fillRect(box.x, box.y, box.width, box.height);

    // Segments are capsules of radius `thickness`: a line that wide with round caps is exactly that.
    const seg = shapes.segments;
    ctx.strokeStyle = STATIC_COLOR;
    ctx.lineCap = 'round';
    for (let i = 0; i < seg.length; i += 5) {
      ctx.lineWidth = Math.max(2 * seg[i + 4], 1 / view.scale);
      ctx.beginPath();
      ctx.moveTo(seg[i], seg[i + 1]);
      ctx.lineTo(seg[i + 2], seg[i + 3]);
      ctx.stroke();
    }

    if (v.shapes) {
      this.drawShapes(v, colors, shapes);
      this.drawJoints(shapes, view);
      return;
    }
    const { x, y, radius, type, slotCount } = v;
    const { order, start } = colors;
    const tiny = 0.75 / view.scale;
    for (let p = 0; p < PALETTE_SIZE; p++) {
      const end = start[p + 1];
      if (end === start[p]) continue;
      ctx.beginPath();
      for (let k = start[p]; k < end; k++) {
        const s = order[k];
        if (s >= slotCount || type[s] === BodyTypeCode.free || type[s] === BodyTypeCode.static) continue;
        this.addCircle(x[s], y[s], radius[s], tiny);
      }
      ctx.fillStyle = colors.css[p];
      ctx.fill();
    }
    // Two more passes only when the scene has static circles or sleepers: one path each.
    if (shapes.staticCircles > 0) {
      ctx.beginPath();
      for (let s = 0; s < slotCount; s++) if (type[s] === BodyTypeCode.static) this.addCircle(x[s], y[s], radius[s], tiny);
      ctx.fillStyle = STATIC_COLOR;
      ctx.fill();
    }
    if (shapes.sleepers > 0) {
      const asleep = v.asleep;
      ctx.beginPath();
      for (let s = 0; s < slotCount; s++) if (asleep[s] === 1 && type[s] !== BodyTypeCode.free) this.addCircle(x[s], y[s], radius[s], tiny);
      ctx.fillStyle = SLEEP_DIM;
      ctx.fill();
    }
    this.drawJoints(shapes, view);
  }

  /**
   * A world of shapes: every shape with its body's rotation, one path per palette colour as for
   * circles, then static bodies in the static colour, then sleepers dimmed.
   */
  private drawShapes(v: BodyViews, colors: BodyColors, scene: SceneShapes): void {
    const ctx = this.ctx;
    const shapes = v.shapes!;
    const chains = this.chains;
    chains.update(v, shapes);
    const { first, next } = chains;
    const { type, slotCount } = v;
    const { order, start } = colors;
    for (let p = 0; p < PALETTE_SIZE; p++) {
      const end = start[p + 1];
      if (end === start[p]) continue;
      ctx.beginPath();
      for (let k = start[p]; k < end; k++) {
        const b = order[k];
        if (b >= slotCount || type[b] === BodyTypeCode.free || type[b] === BodyTypeCode.static) continue;
        for (let sh = first[b]; sh >= 0; sh = next[sh]) addShapePath(ctx, v, shapes, sh, b);
      }
      ctx.fillStyle = colors.css[p];
      ctx.fill();
    }
    ctx.beginPath();
    for (let b = 0; b < slotCount; b++) {
      if (type[b] !== BodyTypeCode.static) continue;
      for (let sh = first[b]; sh >= 0; sh = next[sh]) addShapePath(ctx, v, shapes, sh, b);
    }
    ctx.fillStyle = STATIC_COLOR;
    ctx.fill();
    if (scene.sleepers > 0) {
      ctx.beginPath();
      for (let b = 0; b < slotCount; b++) {
        if (v.asleep[b] !== 1 || type[b] === BodyTypeCode.free) continue;
        for (let sh = first[b]; sh >= 0; sh = next[sh]) addShapePath(ctx, v, shapes, sh, b);
      }
      ctx.fillStyle = SLEEP_DIM;
      ctx.fill();
    }
  }

  /**
   * Joints over the bodies they join: every line in one stroke, every anchor dot in one fill, sized
   * in pixels so they read the same at any zoom.
   */
  private drawJoints(scene: SceneShapes, view: ViewTransform): void {
    const j = scene.joints;
    if (j === null || j.count === 0) return;
    const ctx = this.ctx;
    const { anchorAX, anchorAY, anchorBX, anchorBY, count } = j;
    const pixel = view.dpr / view.scale;
    ctx.beginPath();
    for (let k = 0; k < count; k++) {
      ctx.moveTo(anchorAX[k], anchorAY[k]);
      ctx.lineTo(anchorBX[k], anchorBY[k]);
    }
    ctx.strokeStyle = JOINT_COLOR;
    ctx.lineWidth = JOINT_LINE_PX * pixel;
    ctx.lineCap = 'round';
    ctx.globalAlpha = JOINT_LINE_ALPHA;
    ctx.stroke();
    ctx.globalAlpha = 1;
    const r = JOINT_DOT_PX * pixel;
    ctx.beginPath();
    for (let k = 0; k < count; k++) {
      ctx.moveTo(anchorAX[k] + r, anchorAY[k]);
      ctx.arc(anchorAX[k], anchorAY[k], r, 0, TAU);
      // A pin's two anchors coincide: one dot is enough.
      if (anchorBX[k] !== anchorAX[k] || anchorBY[k] !== anchorAY[k]) {
        ctx.moveTo(anchorBX[k] + r, anchorBY[k]);
        ctx.arc(anchorBX[k], anchorBY[k], r, 0, TAU);
      }
    }
    ctx.fillStyle = JOINT_COLOR;
    ctx.fill();
  }

  private addCircle(cx: number, cy: number, r: number, tiny: number): void {
    const ctx = this.ctx;
    if (r < tiny) {
      ctx.rect(cx - tiny, cy - tiny, 2 * tiny, 2 * tiny);
    } else {
      ctx.moveTo(cx + r, cy);
      ctx.arc(cx, cy, r, 0, TAU);
    }
  }
}
