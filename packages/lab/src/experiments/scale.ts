import { buildScene } from '@maxgrid/scenes';
import { lineChart, type ChartSpec } from '../report/charts.js';
import { csvLine, makeMeta, maxgridOnly, metaSchema, now, spread, spreadSchema, type Meta, type Profile, type RunContext, type Spread } from './common.js';

/**
 * maxgrid alone as N grows to a million circles in the constant-density `uniform` scene: cost
 * per body per step (flat means linear scaling) and engine memory per body.
 */
export interface ScaleOptions {
  ns: number[];
  /** Timed steps per N; each is timed on its own, since a large-N step is far above clock resolution. */
  steps: number;
  warmupSteps: number;
  dt: number;
}

export function scaleDefaults(profile: Profile): ScaleOptions {
  return profile === 'full'
    ? { ns: [1000, 4000, 16000, 64000, 256000, 1_000_000], steps: 30, warmupSteps: 5, dt: 1 / 60 }
    : { ns: [1000, 10_000, 100_000], steps: 10, warmupSteps: 3, dt: 1 / 60 };
}

export interface ScaleRow {
  n: number;
  engine: string;
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
  const total = options.ns.length * engines.length;
  let done = 0;
  for (const n of options.ns) {
    const scene = buildScene('uniform', { n, seed: 1 });
    for (const engine of engines) {
      ctx.progress?.(done++, total, `uniform N=${n} ${engine.info.id}`);
      const b0 = now();
      const sim = engine.create(scene);
      const buildMs = now() - b0;
      const times: number[] = [];
      try {
        for (let i = 0; i < options.warmupSteps; i++) sim.step(options.dt);
        for (let i = 0; i < options.steps; i++) {
          const t0 = now();
          sim.step(options.dt);
          times.push(now() - t0);
          if (n >= 100_000) await ctx.yieldToHost?.();
        }
        const ms = spread(times);
        const memoryBytes = sim.memoryBytes!();
        rows.push({ n, engine: engine.info.id, ms, nsPerBody: (ms.median * 1e6) / n, memoryBytes, bytesPerBody: memoryBytes / n, buildMs });
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
  const lines = [csvLine(['n', 'engine', 'median_ms', 'p25_ms', 'p75_ms', 'ns_per_body', 'memory_bytes', 'bytes_per_body', 'build_ms'])];
  for (const r of result.rows) {
    lines.push(csvLine([r.n, r.engine, r.ms.median, r.ms.p25, r.ms.p75, r.nsPerBody, r.memoryBytes, r.bytesPerBody, r.buildMs]));
  }
  return lines.join('\n') + '\n';
}

export function scaleCharts(result: ScaleResult): ChartSpec[] {
  const engines = [...new Set(result.rows.map((r) => r.engine))];
  const series = (f: (r: ScaleRow) => number) =>
    engines.map((e) => ({ name: e, points: result.rows.filter((r) => r.engine === e).map((r) => [r.n, f(r)] as [number, number]) }));
  return [
    lineChart({ id: 'scale-ns-per-body', title: 'Cost per body per step vs N (uniform)', xName: 'N (circles)', yName: 'ns per body per step', xLog: true, series: series((r) => r.nsPerBody) }),
    lineChart({ id: 'scale-bytes-per-body', title: 'Engine memory per body vs N (uniform)', xName: 'N (circles)', yName: 'bytes per body', xLog: true, series: series((r) => r.bytesPerBody) }),
  ];
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
        required: ['n', 'engine', 'ms', 'nsPerBody', 'memoryBytes', 'bytesPerBody', 'buildMs'],
        properties: {
          n: { type: 'integer', minimum: 1 },
          engine: { type: 'string', pattern: '^maxgrid:' },
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
