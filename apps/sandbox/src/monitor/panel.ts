import type { World } from '@maxgrid/engine';
import { LineChart } from './chart.js';
import type { Recorder } from './recorder.js';
import { Ring } from './ring.js';

function byId(id: string): HTMLElement {
  const el = document.getElementById(id);
  if (!el) throw new Error(`sandbox page is missing #${id}`);
  return el;
}

const MEAN_OVER = 30;

function recentMean(ring: Ring): number {
  const n = Math.min(ring.length, MEAN_OVER);
  if (n === 0) return NaN;
  let sum = 0;
  for (let i = ring.length - n; i < ring.length; i++) sum += ring.at(i);
  return sum / n;
}

/** Frames per second over the last frames: frames over their total time, not a mean of rates. */
function recentRate(ring: Ring): number {
  const n = Math.min(ring.length, MEAN_OVER);
  if (n === 0) return NaN;
  let seconds = 0;
  for (let i = ring.length - n; i < ring.length; i++) seconds += 1 / ring.at(i);
  return n / seconds;
}

const integer = (v: number) => v.toLocaleString('en-US');

/**
 * The performance monitor (report 5.3.2) and the energy graph (5.13.1). Text refreshes a few times
 * a second, graphs about ten times: both are for people, and DOM writes every frame cost more
 * than they show.
 */
export class MonitorPanel {
  /** Frame rate of each animation frame, for the fps graph. */
  readonly fps = new Ring(600);
  private readonly charts: LineChart[];
  private readonly out = {
    bodies: byId('stat-bodies'),
    steps: byId('stat-steps'),
    time: byId('stat-time'),
    stepMs: byId('stat-step-ms'),
    fps: byId('stat-fps'),
    candidates: byId('stat-candidates'),
    contacts: byId('stat-contacts'),
    falsePositives: byId('stat-false-positives'),
  };
  private lastText = -Infinity;
  private lastChart = -Infinity;

  constructor(private readonly recorder: Recorder) {
    const s = recorder.series;
    this.charts = [
      new LineChart(byId('chart-step') as HTMLCanvasElement, [{ ring: s.step_ms, color: '#58a6ff' }]),
      new LineChart(byId('chart-fps') as HTMLCanvasElement, [{ ring: this.fps, color: '#3fb950' }]),
      new LineChart(
        byId('chart-energy') as HTMLCanvasElement,
        [
          { ring: s.total, color: '#f0f6fc' },
          { ring: s.kinetic, color: '#f778ba' },
          { ring: s.potential, color: '#d29922' },
        ],
        600,
        false,
      ),
    ];
  }

  /** Call once per frame; `force` refreshes the text now (after a rebuild or a single step). */
  update(now: number, world: World, time: number, force = false): void {
    if (force || now - this.lastText >= 250) {
      this.lastText = now;
      const st = world.stats;
      const o = this.out;
      o.bodies.textContent = integer(world.bodyCount);
      o.steps.textContent = integer(st.steps);
      o.time.textContent = `${time.toFixed(2)} s`;
      const stepMs = recentMean(this.recorder.series.step_ms);
      o.stepMs.textContent = Number.isFinite(stepMs) ? `${stepMs.toFixed(2)} ms` : '–';
      const fps = recentRate(this.fps);
      o.fps.textContent = Number.isFinite(fps) ? `${fps.toFixed(0)} fps` : '–';
      o.candidates.textContent = integer(st.candidatePairs);
      o.contacts.textContent = integer(st.contacts);
      // Candidates the narrow-phase rejected: how much work the broad-phase wasted.
      o.falsePositives.textContent =
        st.candidatePairs > 0 ? `${(100 * (1 - st.contacts / st.candidatePairs)).toFixed(1)}%` : '–';
    }
    if (force || now - this.lastChart >= 100) {
      this.lastChart = now;
      for (const chart of this.charts) chart.draw();
    }
  }
}
