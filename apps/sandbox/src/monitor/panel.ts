import type { Simulation } from '../simulation.js';
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
    pairTests: byId('stat-pair-tests'),
    candidates: byId('stat-candidates'),
    contacts: byId('stat-contacts'),
    falsePositives: byId('stat-false-positives'),
    lowerHalf: byId('stat-lower-half'),
    sleeping: byId('stat-sleeping'),
    joints: byId('stat-joints'),
    segmentContacts: byId('stat-segment-contacts'),
    swept: byId('stat-swept'),
    filtered: byId('stat-filtered'),
    begin: byId('stat-begin'),
    end: byId('stat-end'),
    hits: byId('stat-hits'),
    fastestHit: byId('stat-fastest-hit'),
    stages: byId('stat-stages'),
    route: byId('stat-route'),
  };
  // Rows for features that may not apply: shown only when the scene or a toggle makes them count.
  private readonly rows = {
    lowerHalf: byId('row-lower-half'),
    segmentContacts: byId('row-segment-contacts'),
    swept: byId('row-swept'),
    filtered: byId('row-filtered'),
    begin: byId('row-begin'),
    end: byId('row-end'),
    hits: byId('row-hits'),
    fastestHit: byId('row-fastest-hit'),
    joints: byId('row-joints'),
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
  update(now: number, sim: Simulation, force = false): void {
    if (force || now - this.lastText >= 250) {
      this.lastText = now;
      const world = sim.world;
      const st = world.stats;
      const o = this.out;
      o.bodies.textContent = integer(world.bodyCount);
      o.steps.textContent = integer(st.steps);
      o.time.textContent = `${sim.time.toFixed(2)} s`;
      const stepMs = recentMean(this.recorder.series.step_ms);
      o.stepMs.textContent = Number.isFinite(stepMs) ? `${stepMs.toFixed(2)} ms` : '–';
      const fps = recentRate(this.fps);
      o.fps.textContent = Number.isFinite(fps) ? `${fps.toFixed(0)} fps` : '–';
      o.pairTests.textContent = integer(st.pairTests);
      o.candidates.textContent = integer(st.candidatePairs);
      o.contacts.textContent = integer(st.contacts);
      // Pairs the broad-phase examined that were not touching: the report's measure of its wasted
      // work. Measured on pair tests, since the grids already drop most non-touching pairs before
      // they become candidates.
      o.falsePositives.textContent = st.pairTests > 0 ? `${(100 * (1 - st.contacts / st.pairTests)).toFixed(1)}%` : '–';
      // Where the step went: the broad-phase, the narrow-phase (manifolds with shapes) and the solver.
      o.stages.textContent = `${st.broadphaseMs.toFixed(2)} / ${st.narrowphaseMs.toFixed(2)} / ${st.solveMs.toFixed(2)} ms`;
      const route = world.route;
      o.route.textContent = route.route === 'shapes' ? `shapes, ${route.solver === 'soft' ? 'soft step' : 'elastic pass'}` : 'circles';
      const r = this.rows;
      // Without gravity nothing falls, and where the bodies are says nothing.
      r.lowerHalf.hidden = !sim.falls;
      if (sim.falls) o.lowerHalf.textContent = integer(sim.lowerHalf());
      o.sleeping.textContent = integer(st.sleepingBodies);
      r.joints.hidden = world.jointCount === 0;
      o.joints.textContent = integer(world.jointCount);
      r.segmentContacts.hidden = sim.segments.length === 0;
      o.segmentContacts.textContent = integer(st.segmentContacts);
      r.swept.hidden = !sim.continuous;
      o.swept.textContent = integer(st.sweptBodies);
      r.filtered.hidden = !sim.layers;
      o.filtered.textContent = integer(st.filteredPairs);
      r.begin.hidden = r.end.hidden = !sim.touches.enabled;
      o.begin.textContent = integer(sim.touches.begins);
      o.end.textContent = integer(sim.touches.ends);
      const hits = sim.hits;
      r.hits.hidden = r.fastestHit.hidden = !hits.enabled;
      o.hits.textContent = integer(hits.count);
      // Of the last step, like the count beside it; a dash rather than 0 when nothing hit.
      o.fastestHit.textContent = hits.count > 0 ? `${hits.fastest.toFixed(0)} px/s` : '–';
    }
    if (force || now - this.lastChart >= 100) {
      this.lastChart = now;
      for (const chart of this.charts) chart.draw();
    }
  }
}
