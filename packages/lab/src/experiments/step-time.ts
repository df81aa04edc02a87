import { buildScene } from '@maxgrid/scenes';
import { lineChart, type ChartSpec } from '../report/charts.js';
import {
  csvLine,
  makeMeta,
  metaSchema,
  now,
  nRange,
  rotate,
  spread,
  spreadSchema,
  warmUp,
  warmUpMs,
  type Meta,
  type Profile,
  type RunContext,
  type Spread,
} from './common.js';

/** The report's performance test (5.13.2, 6.2): mean physics step time against N. */
export interface StepTimeOptions {
  scenes: string[];
  ns: number[];
  runs: number;
  /** Simulated seconds per run; steps per run = round(seconds / dt), the same for every engine. */
  seconds: number;
  dt: number;
  /** Untimed steps before each run, so JIT tiers and buffers settle first. */
  warmupSteps: number;
  /**
   * Each engine's warm-up on twins of a scene's first N before its first run (see warmUp); the
   * larger N that follow run the same code, already warm.
   */
  warmUpMs: number;
  /** An engine whose median exceeds this at some N is not run at larger N of that scene. */
  cutoffMs: number;
}

export function stepTimeDefaults(profile: Profile): StepTimeOptions {
  return profile === 'full'
    ? { scenes: ['seed-box', 'uniform'], ns: nRange(10, 4200, 10), runs: 10, seconds: 10, dt: 1 / 60, warmupSteps: 30, warmUpMs: warmUpMs('full'), cutoffMs: 1000 }
    : { scenes: ['seed-box', 'uniform'], ns: [250, 1000, 4000], runs: 3, seconds: 0.5, dt: 1 / 60, warmupSteps: 10, warmUpMs: warmUpMs('quick'), cutoffMs: 100 };
}

export interface StepTimeRow {
  scene: string;
  n: number;
  engine: string;
  /** Mean step time of each run, ms; the spread is over runs, as the report's 10 runs. */
  runMs: number[];
  ms: Spread;
  stepsPerRun: number;
}

export interface StepTimeResult {
  meta: Meta;
  rows: StepTimeRow[];
  /** Engines dropped for larger N once too slow: scene, engine, first N not run. */
  skipped: { scene: string; engine: string; fromN: number }[];
}

export async function runStepTime(options: StepTimeOptions, ctx: RunContext): Promise<StepTimeResult> {
  const { engines } = ctx;
  const steps = Math.max(1, Math.round(options.seconds / options.dt));
  const rows: StepTimeRow[] = [];
  const skipped: StepTimeResult['skipped'] = [];
  const total = options.scenes.length * options.ns.length * options.runs * engines.length;
  let done = 0;
  for (const sceneName of options.scenes) {
    const dropped = new Set<string>();
    for (const n of options.ns) {
      const runMs = new Map<string, number[]>(engines.map((e) => [e.info.id, []]));
      for (let run = 0; run < options.runs; run++) {
        // One seeded scene per run, shared by every engine; rotating the order per run spreads
        // machine noise (and any order effect) over all engines alike.
        const scene = buildScene(sceneName, { n, seed: run + 1 });
        for (const engine of rotate(engines, run)) {
          const id = engine.info.id;
          ctx.progress?.(done++, total, `${sceneName} N=${n} run ${run + 1} ${id}`);
          if (dropped.has(id)) continue;
          if (run === 0 && n === options.ns[0]) warmUp(() => engine.create(scene), options.warmupSteps + steps, options.dt, options.warmUpMs);
          const sim = engine.create(scene);
          try {
            for (let i = 0; i < options.warmupSteps; i++) sim.step(options.dt);
            // The timed loop holds nothing but step calls: one clock pair around all of them
            // keeps coarse browser clocks (100 us in Chromium) from quantising fast steps.
            const t0 = now();
            for (let i = 0; i < steps; i++) sim.step(options.dt);
            runMs.get(id)!.push((now() - t0) / steps);
          } finally {
            sim.dispose();
          }
          await ctx.yieldToHost?.();
        }
      }
      for (const engine of engines) {
        const id = engine.info.id;
        const values = runMs.get(id)!;
        if (values.length === 0) continue;
        const row = { scene: sceneName, n, engine: id, runMs: values, ms: spread(values), stepsPerRun: steps };
        rows.push(row);
        if (row.ms.median > options.cutoffMs && !dropped.has(id)) {
          dropped.add(id);
          const next = options.ns.find((m) => m > n);
          if (next !== undefined) skipped.push({ scene: sceneName, engine: id, fromN: next });
        }
      }
    }
  }
  ctx.progress?.(total, total, 'done');
  return { meta: makeMeta('step-time', ctx, options), rows, skipped };
}

export function stepTimeCsv(result: StepTimeResult): string {
  const lines = [csvLine(['scene', 'n', 'engine', 'median_ms', 'p25_ms', 'p75_ms', 'min_ms', 'max_ms', 'runs', 'steps_per_run'])];
  for (const r of result.rows) {
    lines.push(csvLine([r.scene, r.n, r.engine, r.ms.median, r.ms.p25, r.ms.p75, r.ms.min, r.ms.max, r.runMs.length, r.stepsPerRun]));
  }
  return lines.join('\n') + '\n';
}

export function stepTimeCharts(result: StepTimeResult): ChartSpec[] {
  const scenes = [...new Set(result.rows.map((r) => r.scene))];
  return scenes.map((scene) => {
    const rows = result.rows.filter((r) => r.scene === scene);
    const engines = [...new Set(rows.map((r) => r.engine))];
    const pick = (engine: string, f: (r: StepTimeRow) => number): [number, number][] =>
      rows.filter((r) => r.engine === engine).map((r) => [r.n, f(r)]);
    return lineChart({
      id: `step-time-${scene}`,
      title: `Step time vs N, scene ${scene} (median of runs; dashed: p25 and p75)`,
      xName: 'N (circles)',
      yName: 'ms per step',
      yLog: true,
      series: engines.map((e) => ({ name: e, points: pick(e, (r) => r.ms.median) })),
      bands: engines.map((e) => ({ name: e, low: pick(e, (r) => r.ms.p25), high: pick(e, (r) => r.ms.p75) })),
    });
  });
}

/** Median of `engine` over the median of `baseline` at the same scene and N, or NaN. */
export function stepTimeRatio(result: StepTimeResult, scene: string, n: number, engine: string, baseline: string): number {
  const find = (id: string) => result.rows.find((r) => r.scene === scene && r.n === n && r.engine === id);
  const a = find(engine);
  const b = find(baseline);
  return a && b ? a.ms.median / b.ms.median : NaN;
}

export const stepTimeSchema = {
  $id: 'step-time',
  type: 'object',
  required: ['meta', 'rows', 'skipped'],
  properties: {
    meta: metaSchema,
    rows: {
      type: 'array',
      items: {
        type: 'object',
        required: ['scene', 'n', 'engine', 'runMs', 'ms', 'stepsPerRun'],
        properties: {
          scene: { type: 'string' },
          n: { type: 'integer', minimum: 1 },
          engine: { type: 'string' },
          runMs: { type: 'array', minItems: 1, items: { type: 'number', minimum: 0 } },
          ms: spreadSchema,
          stepsPerRun: { type: 'integer', minimum: 1 },
        },
        additionalProperties: false,
      },
    },
    skipped: {
      type: 'array',
      items: {
        type: 'object',
        required: ['scene', 'engine', 'fromN'],
        properties: { scene: { type: 'string' }, engine: { type: 'string' }, fromN: { type: 'integer' } },
      },
    },
  },
  additionalProperties: false,
} as const;
