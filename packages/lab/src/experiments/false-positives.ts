import { buildScene, type Scene } from '@maxgrid/scenes';
import { lineChart, type ChartSpec } from '../report/charts.js';
import { csvLine, makeMeta, maxgridOnly, metaSchema, type Meta, type Profile, type RunContext } from './common.js';

/**
 * The report's future work (7.4): how much work a broad-phase does per true contact. Three
 * numbers per step, from the engine's own counters: pairs the broad-phase examined (pairTests,
 * its real work: n(n-1)/2 for naive, every 3x3-neighbourhood pair for maxgrid), pairs it passed to
 * the narrow-phase (candidatePairs; the grids already filter these by a padded circle test, so
 * they sit near the contact count) and contacts. The headline is pairs examined per contact.
 * Three sweeps: over N (`uniform`, radii 4..8), and over the radius spread 1:1..1:100 at a fixed N
 * with two size distributions: `mixed` (many small circles and 0.1% `ratio` times larger, the
 * report's worst case for Max Grid) and `uniform` with log-uniform radii (as many circles per
 * size octave).
 */
export interface FalsePositiveOptions {
  ns: number[];
  /** Largest radius over smallest, for the two spread sweeps. */
  ratios: number[];
  /** Smallest radius in the spread sweeps (mixed: small circles in [minRadius, 2 minRadius]). */
  minRadius: number;
  /** N for the spread sweeps. */
  spreadN: number;
  /** Steps averaged per case, after `warmupSteps`. */
  steps: number;
  warmupSteps: number;
  dt: number;
  /** A broad-phase whose step exceeds this (ms) is not run at larger N or ratio of that sweep. */
  cutoffMs: number;
}

export function falsePositiveDefaults(profile: Profile): FalsePositiveOptions {
  return profile === 'full'
    ? { ns: [1000, 4000, 16000, 64000], ratios: [1, 2, 5, 10, 20, 50, 100], minRadius: 4, spreadN: 16000, steps: 60, warmupSteps: 30, dt: 1 / 60, cutoffMs: 2000 }
    : { ns: [500, 2000, 8000], ratios: [1, 2, 10, 100], minRadius: 4, spreadN: 2000, steps: 10, warmupSteps: 5, dt: 1 / 60, cutoffMs: 200 };
}

export type FalsePositiveSweep = 'n' | 'mixed' | 'log';
export const FALSE_POSITIVE_SWEEPS: Record<FalsePositiveSweep, string> = {
  n: 'uniform, radii 4..8, over N',
  mixed: 'mixed (0.1% of circles ratio times larger), over radius ratio',
  log: 'uniform with log-uniform radii, over radius ratio',
};

export interface FalsePositiveRow {
  sweep: FalsePositiveSweep;
  scene: string;
  n: number;
  ratio: number;
  engine: string;
  /** Means per step over the measured steps. */
  pairTests: number;
  candidatePairs: number;
  contacts: number;
  /** pairTests / contacts, null when there are no contacts: the headline. */
  testsPerContact: number | null;
  /** candidatePairs / contacts, null when there are no contacts. */
  candidatesPerContact: number | null;
  /** (pairTests - contacts) / pairTests, 0 when nothing was examined. */
  falsePositiveFraction: number;
  broadphaseMs: number;
  narrowphaseMs: number;
}

export interface FalsePositiveResult {
  meta: Meta;
  rows: FalsePositiveRow[];
  skipped: { sweep: FalsePositiveSweep; engine: string; from: number }[];
}

function sceneFor(sweep: FalsePositiveSweep, n: number, ratio: number, o: FalsePositiveOptions): Scene {
  if (sweep === 'n') return buildScene('uniform', { n, seed: 1 });
  if (sweep === 'mixed') return buildScene('mixed', { n, seed: 1, minRadius: o.minRadius, ratio });
  return buildScene('uniform', { n, seed: 1, minRadius: o.minRadius, maxRadius: o.minRadius * ratio, logRadius: 1 });
}

export async function runFalsePositives(options: FalsePositiveOptions, ctx: RunContext): Promise<FalsePositiveResult> {
  const engines = maxgridOnly(ctx.engines, 'false-positives');
  const rows: FalsePositiveRow[] = [];
  const skipped: FalsePositiveResult['skipped'] = [];
  const cases = [
    ...options.ns.map((n) => ({ sweep: 'n' as const, n, ratio: 2, key: n })),
    ...(['mixed', 'log'] as const).flatMap((sweep) => options.ratios.map((ratio) => ({ sweep, n: options.spreadN, ratio, key: ratio }))),
  ];
  const total = cases.length * engines.length;
  const dropped = new Set<string>();
  let done = 0;
  for (const c of cases) {
    const scene = sceneFor(c.sweep, c.n, c.ratio, options);
    for (const engine of engines) {
      const id = engine.info.id;
      ctx.progress?.(done++, total, `${c.sweep} N=${c.n} ratio=${c.ratio} ${id}`);
      if (dropped.has(`${c.sweep} ${id}`)) continue;
      const sim = engine.create(scene);
      const sum = { tests: 0, candidates: 0, contacts: 0, broad: 0, narrow: 0 };
      try {
        for (let i = 0; i < options.warmupSteps; i++) sim.step(options.dt);
        for (let i = 0; i < options.steps; i++) {
          sim.step(options.dt);
          const pairs = sim.pairStats!();
          const phases = sim.phaseMs!();
          sum.tests += pairs.pairTests;
          sum.candidates += pairs.candidatePairs;
          sum.contacts += pairs.contacts;
          sum.broad += phases.broadphaseMs;
          sum.narrow += phases.narrowphaseMs;
        }
      } finally {
        sim.dispose();
      }
      const s = options.steps;
      const row: FalsePositiveRow = {
        sweep: c.sweep,
        scene: scene.name,
        n: c.n,
        // The n sweep's ratio is the scene's own maxRadius / minRadius (8 / 4).
        ratio: c.sweep === 'n' ? scene.params.maxRadius / scene.params.minRadius : c.ratio,
        engine: id,
        pairTests: sum.tests / s,
        candidatePairs: sum.candidates / s,
        contacts: sum.contacts / s,
        testsPerContact: sum.contacts === 0 ? null : sum.tests / sum.contacts,
        candidatesPerContact: sum.contacts === 0 ? null : sum.candidates / sum.contacts,
        falsePositiveFraction: sum.tests === 0 ? 0 : Math.max(0, sum.tests - sum.contacts) / sum.tests,
        broadphaseMs: sum.broad / s,
        narrowphaseMs: sum.narrow / s,
      };
      rows.push(row);
      if (row.broadphaseMs + row.narrowphaseMs > options.cutoffMs) {
        dropped.add(`${c.sweep} ${id}`);
        const next = cases.find((d) => d.sweep === c.sweep && d.key > c.key);
        if (next) skipped.push({ sweep: c.sweep, engine: id, from: next.key });
      }
      await ctx.yieldToHost?.();
    }
  }
  ctx.progress?.(total, total, 'done');
  return { meta: makeMeta('false-positives', ctx, options), rows, skipped };
}

export function falsePositiveCsv(result: FalsePositiveResult): string {
  const lines = [
    csvLine(['sweep', 'scene', 'n', 'radius_ratio', 'engine', 'pair_tests', 'candidate_pairs', 'contacts', 'tests_per_contact', 'candidates_per_contact', 'false_positive_fraction', 'broadphase_ms', 'narrowphase_ms']),
  ];
  for (const r of result.rows) {
    lines.push(
      csvLine([r.sweep, r.scene, r.n, r.ratio, r.engine, r.pairTests, r.candidatePairs, r.contacts, r.testsPerContact ?? '', r.candidatesPerContact ?? '', r.falsePositiveFraction, r.broadphaseMs, r.narrowphaseMs]),
    );
  }
  return lines.join('\n') + '\n';
}

export function falsePositiveCharts(result: FalsePositiveResult): ChartSpec[] {
  const engines = [...new Set(result.rows.map((r) => r.engine))];
  const series = (sweep: FalsePositiveSweep, x: (r: FalsePositiveRow) => number) =>
    engines.map((e) => ({
      name: e,
      points: result.rows
        .filter((r) => r.sweep === sweep && r.engine === e && r.testsPerContact !== null)
        .map((r) => [x(r), r.testsPerContact!] as [number, number]),
    }));
  const spreadN = String(result.meta.options.spreadN);
  return [
    lineChart({
      id: 'false-positives-n',
      title: 'Pairs examined per true contact vs N (uniform, radii 4..8)',
      xName: 'N (circles)',
      yName: 'pair tests / contacts',
      xLog: true,
      yLog: true,
      series: series('n', (r) => r.n),
    }),
    lineChart({
      id: 'false-positives-spread',
      title: `Pairs examined per true contact vs radius ratio (mixed, N = ${spreadN})`,
      xName: 'largest / smallest radius',
      yName: 'pair tests / contacts',
      xLog: true,
      yLog: true,
      series: series('mixed', (r) => r.ratio),
    }),
    lineChart({
      id: 'false-positives-log',
      title: `Pairs examined per true contact vs radius ratio (uniform, log-uniform radii, N = ${spreadN})`,
      xName: 'largest / smallest radius',
      yName: 'pair tests / contacts',
      xLog: true,
      yLog: true,
      series: series('log', (r) => r.ratio),
    }),
  ];
}

const count = { type: 'number', minimum: 0 } as const;
const perContact = { type: ['number', 'null'], minimum: 0 } as const;

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
        required: ['sweep', 'scene', 'n', 'ratio', 'engine', 'pairTests', 'candidatePairs', 'contacts', 'testsPerContact', 'candidatesPerContact', 'falsePositiveFraction', 'broadphaseMs', 'narrowphaseMs'],
        properties: {
          sweep: { enum: ['n', 'mixed', 'log'] },
          scene: { enum: ['uniform', 'mixed'] },
          n: { type: 'integer', minimum: 1 },
          ratio: { type: 'number', minimum: 1 },
          engine: { type: 'string', pattern: '^maxgrid:' },
          pairTests: count,
          candidatePairs: count,
          contacts: count,
          testsPerContact: perContact,
          candidatesPerContact: perContact,
          falsePositiveFraction: { type: 'number', minimum: 0, maximum: 1 },
          broadphaseMs: count,
          narrowphaseMs: count,
        },
        additionalProperties: false,
      },
    },
    skipped: {
      type: 'array',
      items: {
        type: 'object',
        required: ['sweep', 'engine', 'from'],
        properties: { sweep: { enum: ['n', 'mixed', 'log'] }, engine: { type: 'string' }, from: { type: 'number' } },
      },
    },
  },
  additionalProperties: false,
} as const;
