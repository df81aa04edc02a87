import { buildScene } from '@maxgrid/scenes';
import { lineChart, type ChartSpec } from '../report/charts.js';
import { csvLine, makeMeta, maxgridOnly, metaSchema, now, spread, spreadSchema, type Meta, type Profile, type RunContext, type Spread } from './common.js';

/**
 * maxgrid alone as N grows to a million circles in the constant-density `uniform` scene: cost
 * per body per step (flat means linear scaling) and engine memory per body. Each N runs twice:
 * with the circles created row by row, as they lie (the scene's default, and every other
 * experiment's), and created in a random order (`shuffle`), as a world spawning at random would
 * create them; a grid's build then writes cells and reads bodies at scattered places in memory.
 * Each world is timed fresh and again at each later age (simulated seconds of motion), since
 * moving bodies drift away from their neighbours in memory: the same world, stepped on.
 */
export type ScaleOrder = 'rows' | 'shuffled';

export const SCALE_ORDERS: readonly ScaleOrder[] = ['rows', 'shuffled'];

export interface ScaleOptions {
  ns: number[];
  /** Creation orders to run at each N. */
  orders: ScaleOrder[];
  /** Simulated seconds of motion before each timing, ascending from 0. */
  ages: number[];
  /** Timed steps per N; each is timed on its own, since a large-N step is far above clock resolution. */
  steps: number;
  warmupSteps: number;
  dt: number;
}

export function scaleDefaults(profile: Profile): ScaleOptions {
  return profile === 'full'
    ? { ns: [1000, 4000, 16000, 64000, 256000, 1_000_000], orders: [...SCALE_ORDERS], ages: [0, 10], steps: 30, warmupSteps: 5, dt: 1 / 60 }
    : { ns: [1000, 10_000, 100_000], orders: [...SCALE_ORDERS], ages: [0, 10], steps: 10, warmupSteps: 3, dt: 1 / 60 };
}

export interface ScaleRow {
  n: number;
  engine: string;
  order: ScaleOrder;
  /** Simulated seconds the world had moved before its warm-up steps. */
  ageSeconds: number;
  ms: Spread;
  /** Median step time / N, in nanoseconds. */
  nsPerBody: number;
  memoryBytes: number;
  bytesPerBody: number;
  buildMs: number;
}

export interface ScaleResult {
  meta: Meta;
  rows: ScaleRow[];
}

export async function runScale(options: ScaleOptions, ctx: RunContext): Promise<ScaleResult> {
  const engines = maxgridOnly(ctx.engines, 'scale');
  const rows: ScaleRow[] = [];
  const total = options.ns.length * options.orders.length * engines.length;
  let done = 0;
  for (const n of options.ns) for (const order of options.orders) {
    const scene = buildScene('uniform', { n, seed: 1, shuffle: order === 'shuffled' ? 1 : 0 });
    for (const engine of engines) {
      ctx.progress?.(done++, total, `uniform N=${n} ${order} ${engine.info.id}`);
      const b0 = now();
      const sim = engine.create(scene);
      const buildMs = now() - b0;
      let stepped = 0;
      try {
        for (const ageSeconds of options.ages) {
          // Onward to this age (the steps timed at earlier ages count towards it).
          for (; stepped * options.dt < ageSeconds - 1e-9; stepped++) {
            sim.step(options.dt);
            if (n >= 100_000 && stepped % 16 === 0) await ctx.yieldToHost?.();
          }
          const times: number[] = [];
          for (let i = 0; i < options.warmupSteps; i++, stepped++) sim.step(options.dt);
          for (let i = 0; i < options.steps; i++, stepped++) {
            const t0 = now();
            sim.step(options.dt);
            times.push(now() - t0);
            if (n >= 100_000) await ctx.yieldToHost?.();
          }
          const ms = spread(times);
          const memoryBytes = sim.memoryBytes!();
          rows.push({ n, engine: engine.info.id, order, ageSeconds, ms, nsPerBody: (ms.median * 1e6) / n, memoryBytes, bytesPerBody: memoryBytes / n, buildMs });
        }
      } finally {
        sim.dispose();
      }
      await ctx.yieldToHost?.();
    }
  }
  ctx.progress?.(total, total, 'done');
  return { meta: makeMeta('scale', ctx, options), rows };
}

export function scaleCsv(result: ScaleResult): string {
  const lines = [csvLine(['n', 'engine', 'order', 'age_s', 'median_ms', 'p25_ms', 'p75_ms', 'ns_per_body', 'memory_bytes', 'bytes_per_body', 'build_ms'])];
  for (const r of result.rows) {
    lines.push(csvLine([r.n, r.engine, r.order, r.ageSeconds, r.ms.median, r.ms.p25, r.ms.p75, r.nsPerBody, r.memoryBytes, r.bytesPerBody, r.buildMs]));
  }
  return lines.join('\n') + '\n';
}

export function scaleCharts(result: ScaleResult): ChartSpec[] {
  const lines = [...new Set(result.rows.map((r) => scaleLine(r)))];
  const series = (f: (r: ScaleRow) => number) =>
    lines.map((name) => ({ name, points: result.rows.filter((r) => scaleLine(r) === name).map((r) => [r.n, f(r)] as [number, number]) }));
  return [
    lineChart({ id: 'scale-ns-per-body', title: 'Cost per body per step vs N (uniform)', xName: 'N (circles)', yName: 'ns per body per step', xLog: true, series: series((r) => r.nsPerBody) }),
    lineChart({ id: 'scale-bytes-per-body', title: 'Engine memory per body vs N (uniform)', xName: 'N (circles)', yName: 'bytes per body', xLog: true, series: series((r) => r.bytesPerBody) }),
  ];
}

/** A chart line: the engine, the creation order where it is not the scene's own, and the age where not fresh. */
export function scaleLine(r: ScaleRow): string {
  return `${r.engine}${r.order === 'rows' ? '' : ', shuffled'}${r.ageSeconds > 0 ? `, after ${r.ageSeconds} s` : ''}`;
}

export const scaleSchema = {
  $id: 'scale',
  type: 'object',
  required: ['meta', 'rows'],
  properties: {
    meta: metaSchema,
    rows: {
      type: 'array',
      minItems: 1,
      items: {
        type: 'object',
        required: ['n', 'engine', 'order', 'ageSeconds', 'ms', 'nsPerBody', 'memoryBytes', 'bytesPerBody', 'buildMs'],
        properties: {
          n: { type: 'integer', minimum: 1 },
          engine: { type: 'string', pattern: '^maxgrid:' },
          order: { enum: SCALE_ORDERS },
          ageSeconds: { type: 'number', minimum: 0 },
          ms: spreadSchema,
          nsPerBody: { type: 'number', minimum: 0 },
          memoryBytes: { type: 'integer', minimum: 1 },
          bytesPerBody: { type: 'number', exclusiveMinimum: 0 },
          buildMs: { type: 'number', minimum: 0 },
        },
        additionalProperties: false,
      },
    },
  },
  additionalProperties: false,
} as const;
