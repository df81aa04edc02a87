import type { Ring } from './ring.js';

export interface Line {
  ring: Ring;
  color: string;
}

/**
 * A live line chart of the newest samples of a few series, scaled to their range. Hand-drawn on a
 * small canvas: it is redrawn many times a second, and allocates nothing when it is.
 */
export class LineChart {
  private readonly ctx: CanvasRenderingContext2D;

  constructor(
    readonly canvas: HTMLCanvasElement,
    private readonly lines: Line[],
    private readonly window = 600,
    /** Keep zero on the axis (times, rates); energies float. */
    private readonly fromZero = true,
  ) {
    const ctx = canvas.getContext('2d', { willReadFrequently: true });
    if (!ctx) throw new Error('this browser gives no canvas 2D context');
    this.ctx = ctx;
  }

  draw(): void {
    const { canvas, ctx } = this;
    const dpr = Math.min(window.devicePixelRatio || 1, 2);
    const w = Math.max(1, Math.round(canvas.clientWidth * dpr));
    const h = Math.max(1, Math.round(canvas.clientHeight * dpr));
    if (canvas.width !== w || canvas.height !== h) {
      canvas.width = w;
      canvas.height = h;
    }
    ctx.clearRect(0, 0, w, h);

    let lo = this.fromZero ? 0 : Infinity;
    let hi = -Infinity;
    let count = 0;
    for (const line of this.lines) {
      const n = Math.min(line.ring.length, this.window);
      count = Math.max(count, n);
      for (let i = line.ring.length - n; i < line.ring.length; i++) {
        const v = line.ring.at(i);
        if (!Number.isFinite(v)) continue;
        if (v < lo) lo = v;
        if (v > hi) hi = v;
      }
    }
    if (count < 2 || !Number.isFinite(hi)) return;
    if (hi - lo < 1e-9 * Math.max(1, Math.abs(hi))) {
      hi += 0.5 * Math.max(1e-6, Math.abs(hi));
      if (!this.fromZero) lo -= 0.5 * Math.max(1e-6, Math.abs(lo));
    }
    const pad = 4 * dpr;
    // A short history fills the chart rather than hugging its right edge; a long one scrolls.
    const span = Math.min(this.window, Math.max(count, 120));
    const sx = (w - 2 * pad) / (span - 1);
    // Room at the top for the scale label, so the highest line never runs through it.
    const top = 14 * dpr;
    const sy = (h - pad - top) / (hi - lo);

    ctx.lineWidth = 1.25 * dpr;
    for (const line of this.lines) {
      const n = Math.min(line.ring.length, this.window);
      const first = line.ring.length - n;
      const x0 = w - pad - (n - 1) * sx;
      ctx.strokeStyle = line.color;
      ctx.beginPath();
      for (let i = 0; i < n; i++) {
        const v = line.ring.at(first + i);
        const px = x0 + i * sx;
        const py = h - pad - (Number.isFinite(v) ? v - lo : 0) * sy;
        if (i === 0) ctx.moveTo(px, py);
        else ctx.lineTo(px, py);
      }
      ctx.stroke();
    }
    ctx.fillStyle = '#8b949e';
    ctx.font = `${10 * dpr}px system-ui, sans-serif`;
    ctx.textBaseline = 'top';
    ctx.fillText(compact(hi), pad, pad);
    ctx.textBaseline = 'bottom';
    ctx.fillText(compact(lo), pad, h - pad);
  }
}

export function compact(v: number): string {
  const a = Math.abs(v);
  if (a >= 1e9) return (v / 1e9).toFixed(2) + 'G';
  if (a >= 1e6) return (v / 1e6).toFixed(2) + 'M';
  if (a >= 1e4) return (v / 1e3).toFixed(1) + 'k';
  if (a >= 100) return v.toFixed(0);
  if (a >= 1) return v.toFixed(2);
  return v.toPrecision(2);
}
