import { buildScene } from '@maxgrid/scenes';
import { barChart, lineChart, type ChartSpec } from '../report/charts.js';
import { csvLine, makeMeta, maxgridOnly, metaSchema, type Meta, type Profile, type RunContext } from './common.js';

/**
 * The report's future work (7.4): how many broad-phase candidates are not contacts, measured as
 * it suggests, by the narrow-phase's input (candidate pairs) against its output (contacts), per
 * maxgrid broad-phase. Two sweeps of the `uniform` scene: over N at its default radii (1:2), and
 * over the radius spread minRadius : maxRadius from 1:1 to 1:100 at a fixed N.
 */
export interface FalsePositiveOptions {
  ns: number[];
  /** maxRadius / minRadius values for the spread sweep. */
  ratios: number[];
  /** Smallest radius in the spread sweep; the largest is minRadius * ratio. */
  minRadius: number;
  /** N for the spread sweep. */
  spreadN: number;
  /** Steps averaged per case, after `warmupSteps`. */
  steps: number;
  warmupSteps: number;
  dt: number;
  /** A broad-phase whose step exceeds this (ms) is not run at larger N or ratio. */
  cutoffMs: number;
}

export function falsePositiveDefaults(profile: Profile): FalsePositiveOptions {
  return profile === 'full'
    ? { ns: [1000, 4000, 16000, 64000], ratios: [1, 2, 5, 10, 20, 50, 100], minRadius: 2, spreadN: 8000, steps: 60, warmupSteps: 30, dt: 1 / 60, cutoffMs: 2000 }
    : { ns: [500, 2000, 8000], ratios: [1, 2, 10, 100], minRadius: 2, spreadN: 2000, steps: 10, warmupSteps: 5, dt: 1 / 60, cutoffMs: 200 };
}

export interface FalsePositiveRow {
  sweep: 'n' | 'spread';
  n: number;
  ratio: number;
  engine: string;
  /** Means per step over the measured steps. */
  candidatePairs: number;
  contacts: number;
  /** (candidates - contacts) / candidates, 0 when there are no candidates. */
  falsePositiveFraction: number;
  /** candidates / contacts, null when there are no contacts. */
  candidatesPerContact: number | null;
  broadphaseMs: number;
  narrowphaseMs: number;
}

export interface FalsePositiveResult {
  meta: Meta;
  rows: FalsePositiveRow[];
  skipped: { sweep: 'n' | 'spread'; engine: string; from: number }[];
}

export async function runFalsePositives(options: FalsePositiveOptions, ctx: RunContext): Promise<FalsePositiveResult> {
  const engines = maxgridOnly(ctx.engines, 'false-positives');
  const rows: FalsePositiveRow[] = [];
  const skipped: FalsePositiveResult['skipped'] = [];
  const cases = [
    ...options.ns.map((n) => ({ sweep: 'n' as const, n, ratio: NaN, key: n })),
    ...options.ratios.map((ratio) => ({ sweep: 'spread' as const, n: options.spreadN, ratio, key: ratio })),
  ];
  const total = cases.length * engines.length;
  const dropped = { n: new Set<string>(), spread: new Set<string>() };
  let done = 0;
  for (const c of cases) {
    const params =
      c.sweep === 'n'
        ? { n: c.n, seed: 1 }
        : { n: c.n, seed: 1, minRadius: options.minRadius, maxRadius: options.minRadius * c.ratio };
    const scene = buildScene('uniform', params);
    const ratio = c.sweep === 'n' ? scene.params.maxRadius / scene.params.minRadius : c.ratio;
    for (const engine of engines) {
      const id = engine.info.id;
      ctx.progress?.(done++, total, `${c.sweep} N=${c.n} ratio=${ratio} ${id}`);
      if (dropped[c.sweep].has(id)) continue;
      const sim = engine.create(scene);
      let candidates = 0;
      let contacts = 0;
      let broad = 0;
      let narrow = 0;
      try {
        for (let i = 0; i < options.warmupSteps; i++) sim.step(options.dt);
        for (let i = 0; i < options.steps; i++) {
          sim.step(options.dt);
          const pairs = sim.pairStats!();
          const phases = sim.phaseMs!();
          candidates += pairs.candidatePairs;
          contacts += pairs.contacts;
          broad += phases.broadphaseMs;
          narrow += phases.narrowphaseMs;
        }
      } finally {
        sim.dispose();
      }
      const s = options.steps;
      const row: FalsePositiveRow = {
        sweep: c.sweep,
        n: c.n,
        ratio,
        engine: id,
        candidatePairs: candidates / s,
        contacts: contacts / s,
        falsePositiveFraction: candidates === 0 ? 0 : (candidates - contacts) / candidates,
        candidatesPerContact: contacts === 0 ? null : candidates / contacts,
        broadphaseMs: broad / s,
        narrowphaseMs: narrow / s,
      };
      rows.push(row);
      if (row.broadphaseMs + row.narrowphaseMs > options.cutoffMs) {
        dropped[c.sweep].add(id);
        skipped.push({ sweep: c.sweep, engine: id, from: c.key });
      }
      await ctx.yieldToHost?.();
    }
  }
  ctx.progress?.(total, total, 'done');
  return { meta: makeMeta('false-positives', ctx, options), rows, skipped };
}

export function falsePositiveCsv(result: FalsePositiveResult): string {
  const lines = [
    csvLine(['sweep', 'n', 'radius_ratio', 'engine', 'candidate_pairs', 'contacts', 'false_positive_fraction', 'candidates_per_contact', 'broadphase_ms', 'narrowphase_ms']),
  ];
  for (const r of result.rows) {
    lines.push(
      csvLine([r.sweep, r.n, r.ratio, r.engine, r.candidatePairs, r.contacts, r.falsePositiveFraction, r.candidatesPerContact ?? '', r.broadphaseMs, r.narrowphaseMs]),
    );
  }
  return lines.join('\n') + '\n';
}

export function falsePositiveCharts(result: FalsePositiveResult): ChartSpec[] {
  const engines = [...new Set(result.rows.map((r) => r.engine))];
  const sweep = (kind: 'n' | 'spread', x: (r: FalsePositiveRow) => number) =>
    engines.map((e) => ({
      name: e,
      points: result.rows
        .filter((r) => r.sweep === kind && r.engine === e && r.candidatesPerContact !== null)
        .map((r) => [x(r), r.candidatesPerContact!] as [number, number]),
    }));
  const ratios = [...new Set(result.rows.filter((r) => r.sweep === 'spread').map((r) => r.ratio))];
  return [
    lineChart({
      id: 'false-positives-n',
      title: 'Candidate pairs per true contact vs N (uniform, radii 1:2)',
      xName: 'N (circles)',
      yName: 'candidates / contacts',
      xLog: true,
      yLog: true,
      series: sweep('n', (r) => r.n),
    }),
    barChart({
      id: 'false-positives-spread',
      title: `Candidate pairs per true contact vs radius spread (uniform, N = ${String(result.meta.options.spreadN)})`,
      categories: ratios.map((r) => `1:${r}`),
      yName: 'candidates / contacts',
      yLog: true,
      series: engines.map((e) => ({
        name: e,
        values: ratios.map((ratio) => {
          const row = result.rows.find((r) => r.sweep === 'spread' && r.engine === e && r.ratio === ratio);
          return row?.candidatesPerContact ?? NaN;
        }),
      })),
    }),
  ];
}

export const falsePositiveSchema = {
  $id: 'false-positives',
  type: 'object',
  required: ['meta', 'rows', 'skipped'],
  properties: {
    meta: metaSchema,
    rows: {
      type: 'array',
      minItems: 1,
      items: {
        type: 'object',
        required: ['sweep', 'n', 'ratio', 'engine', 'candidatePairs', 'contacts', 'falsePositiveFraction', 'candidatesPerContact', 'broadphaseMs', 'narrowphaseMs'],
        properties: {
          sweep: { enum: ['n', 'spread'] },
          n: { type: 'integer', minimum: 1 },
          ratio: { type: 'number', minimum: 1 },
          engine: { type: 'string', pattern: '^maxgrid:' },
          candidatePairs: { type: 'number', minimum: 0 },
          contacts: { type: 'number', minimum: 0 },
          falsePositiveFraction: { type: 'number', minimum: 0, maximum: 1 },
          candidatesPerContact: { type: ['number', 'null'], minimum: 1 },
          broadphaseMs: { type: 'number', minimum: 0 },
          narrowphaseMs: { type: 'number', minimum: 0 },
        },
        additionalProperties: false,
      },
    },
    skipped: { type: 'array' },
  },
  additionalProperties: false,
} as const;
