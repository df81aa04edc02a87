/**
 * The performance monitor of 5.3.2 ("a graph of framerate according to time"), plus the physics
 * step time, which is what the optimisations of 5.3.3 actually change: frame rate alone is capped
 * by the display and mixes in rendering cost.
 *
 * A small canvas 2D graph: a ring of the last HISTORY frames, redrawn at most ~10 times a second
 * so the monitor itself stays cheap.
 */
const HISTORY = 180;
const REDRAW_MS = 100;

export class PerfMonitor {
  private readonly fps = new Float64Array(HISTORY);
  private readonly stepMs = new Float64Array(HISTORY);
  private head = 0;
  private filled = 0;
  private lastFrame = -1;
  private lastDraw = -Infinity;
  private readonly ctx: CanvasRenderingContext2D;

  constructor(
    private readonly canvas: HTMLCanvasElement,
    private readonly readout: HTMLElement,
  ) {
    const ctx = canvas.getContext('2d');
    if (!ctx) throw new Error('2D canvas unavailable for the performance monitor');
    this.ctx = ctx;
  }

  /** One animation frame: its timestamp and the physics time spent in it (0 if no step ran). */
  frame(now: number, physicsMs: number): void {
    if (this.lastFrame >= 0 && now > this.lastFrame) {
      this.fps[this.head] = 1000 / (now - this.lastFrame);
      this.stepMs[this.head] = physicsMs;
      this.head = (this.head + 1) % HISTORY;
      this.filled = Math.min(HISTORY, this.filled + 1);
    }
    this.lastFrame = now;
    if (now - this.lastDraw >= REDRAW_MS) {
      this.lastDraw = now;
      this.draw();
    }
  }

  /** Forget the previous frame time, e.g. after a pause, so the gap does not show as a dip. */
  restart(): void {
    this.lastFrame = -1;
  }

  private mean(series: Float64Array, count: number): number {
    let sum = 0;
    for (let i = 1; i <= count; i++) sum += series[(this.head - i + HISTORY) % HISTORY]!;
    return count > 0 ? sum / count : 0;
  }

  private draw(): void {
    const { ctx, canvas } = this;
    const w = canvas.width;
    const h = canvas.height;
    ctx.fillStyle = '#101820';
    ctx.fillRect(0, 0, w, h);
    // Scales: 0..75 FPS (above the usual 60 Hz), 0..max(4 ms, peak) for the step time.
    let peak = 4;
    for (let i = 0; i < this.filled; i++) peak = Math.max(peak, this.stepMs[i]!);
    this.plot(this.fps, 75, '#4fd18b');
    this.plot(this.stepMs, peak, '#f2c12e');
    const recent = Math.min(this.filled, 30);
    const fps = this.mean(this.fps, recent);
    const ms = this.mean(this.stepMs, recent);
    ctx.font = '11px system-ui, sans-serif';
    ctx.fillStyle = '#4fd18b';
    ctx.fillText(`${fps.toFixed(0)} FPS`, 6, 13);
    ctx.fillStyle = '#f2c12e';
    ctx.fillText(`physics ${ms.toFixed(2)} ms/frame (scale ${peak.toFixed(1)} ms)`, 60, 13);
    this.readout.textContent = `${fps.toFixed(0)} FPS, physics ${ms.toFixed(2)} ms per frame`;
  }

  private plot(series: Float64Array, max: number, colour: string): void {
    const { ctx, canvas } = this;
    const top = 18;
    const span = canvas.height - top - 2;
    ctx.strokeStyle = colour;
    ctx.lineWidth = 1.5;
    ctx.beginPath();
    for (let i = 0; i < this.filled; i++) {
      const value = series[(this.head - this.filled + i + HISTORY) % HISTORY]!;
      const x = (i / (HISTORY - 1)) * canvas.width;
      const y = top + span * (1 - Math.min(1, value / max));
      if (i === 0) ctx.moveTo(x, y);
      else ctx.lineTo(x, y);
    }
    ctx.stroke();
  }
}
