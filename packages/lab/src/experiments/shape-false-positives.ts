import { buildShapeScene } from '@maxgrid/scenes';
import { fmt, type Table } from '../report/tables.js';
import type { StageTimes } from '../shape-engines/adapter.js';
import { csvLine, makeMeta, shapeMetaSchema, now, type Meta, type Profile, type RunContext } from './common.js';

/**
 * The report's false-positive analysis (7.4) for shapes: per maxgrid broad-phase and shape mix,
 * the pairs each broad-phase examines, the pairs it hands the narrow-phase (the grids hand on
 * those whose bounding circles overlap; the sweeps those whose intervals do, which the
 * narrow-phase's own bounding-circle test then thins), the manifolds made of them, and the
 * narrow-phase's share of the step. With polygons every candidate costs a separating-axis test rather than one distance,
 * which is where the report expected Max Grid's advantage to shrink.
 */
export interface ShapeFalsePositiveOptions {
  scenes: { scene: string; n: number }[];
  steps: number;
  warmupSteps: number;
  dt: number;
}

export function shapeFalsePositiveDefaults(profile: Profile): ShapeFalsePositiveOptions {
  const n = profile === 'full' ? 16000 : 4000;
  return { scenes: [{ scene: 'uniform-polygons', n }, { scene: 'polygon-box', n }], steps: profile === 'full' ? 120 : 30, warmupSteps: 30, dt: 1 / 60 };
}

export interface ShapeFalsePositiveRow {
  scene: string;
  n: number;
  engine: string;
  /** Per body per step. */
  examined: number;
  candidates: number;
  manifolds: number;
  /** Candidates per manifold: the narrow-phase tests that found nothing, plus one. */
  candidatesPerManifold: number;
  stepMs: number;
  /** Stage shares of the step, 0..1. */
  broadphaseShare: number;
  narrowphaseShare: number;
  solveShare: number;
}

export interface ShapeFalsePositiveResult {
  meta: Meta;
  rows: ShapeFalsePositiveRow[];
}

export async function runShapeFalsePositives(o: ShapeFalsePositiveOptions, ctx: RunContext): Promise<ShapeFalsePositiveResult> {
  const engines = (ctx.shapeEngines ?? []).filter((e) => e.info.id.startsWith('maxgrid:'));
  if (engines.length === 0) throw new RangeError('shape-false-positives measures maxgrid broad-phases only');
  const rows: ShapeFalsePositiveRow[] = [];
  let done = 0;
  for (const { scene: name, n } of o.scenes) {
    for (const engine of engines) {
      ctx.progress?.(done++, o.scenes.length * engines.length, `${name} N=${n} ${engine.info.id}`);
      const scene = buildShapeScene(name, { n });
      const sim = engine.create(scene, 'defaults');
      try {
        for (let i = 0; i < o.warmupSteps; i++) sim.step(o.dt);
        const sum: StageTimes = { broadphaseMs: 0, narrowphaseMs: 0, solveMs: 0, pairTests: 0, candidatePairs: 0, contacts: 0 };
        let elapsed = 0;
        for (let i = 0; i < o.steps; i++) {
          const t = now();
          sim.step(o.dt);
          elapsed += now() - t;
          const s = sim.stages!();
          for (const key of Object.keys(sum) as (keyof StageTimes)[]) sum[key] += s[key];
        }
        const perBody = (v: number) => v / o.steps / n;
        const staged = sum.broadphaseMs + sum.narrowphaseMs + sum.solveMs;
        rows.push({
          scene: name,
          n,
          engine: engine.info.id,
          examined: perBody(sum.pairTests),
          candidates: perBody(sum.candidatePairs),
          manifolds: perBody(sum.contacts),
          candidatesPerManifold: sum.contacts > 0 ? sum.candidatePairs / sum.contacts : NaN,
          stepMs: elapsed / o.steps,
          broadphaseShare: sum.broadphaseMs / staged,
          narrowphaseShare: sum.narrowphaseMs / staged,
          solveShare: sum.solveMs / staged,
        });
      } finally {
        sim.dispose();
      }
      await ctx.yieldToHost?.();
    }
  }
  return { meta: makeMeta('shape-false-positives', ctx, o), rows };
}

export function shapeFalsePositiveTables(result: ShapeFalsePositiveResult): Table[] {
  return [
    {
      title: 'Broad-phase work on shapes, per body per step, and where the step goes',
      headers: ['scene', 'N', 'broad-phase', 'pairs examined', 'pairs handed on', 'manifolds', 'candidates per manifold', 'ms per step', 'broad %', 'narrow %', 'solve %'],
      rows: result.rows.map((r) => [
        r.scene,
        String(r.n),
        r.engine,
        fmt(r.examined),
        fmt(r.candidates),
        fmt(r.manifolds),
        fmt(r.candidatesPerManifold),
        fmt(r.stepMs),
        fmt(100 * r.broadphaseShare, 2),
        fmt(100 * r.narrowphaseShare, 2),
        fmt(100 * r.solveShare, 2),
      ]),
    },
  ];
}

export function shapeFalsePositiveCsv(result: ShapeFalsePositiveResult): string {
  const lines = [csvLine(['scene', 'n', 'engine', 'examined_per_body', 'candidates_per_body', 'manifolds_per_body', 'candidates_per_manifold', 'step_ms', 'broadphase_share', 'narrowphase_share', 'solve_share'])];
  for (const r of result.rows) lines.push(csvLine([r.scene, r.n, r.engine, r.examined, r.candidates, r.manifolds, r.candidatesPerManifold, r.stepMs, r.broadphaseShare, r.narrowphaseShare, r.solveShare]));
  return lines.join('\n') + '\n';
}

export function shapeFalsePositiveHeadline(result: ShapeFalsePositiveResult): string[] {
  return result.rows
    .filter((r) => r.engine === 'maxgrid:maxgrid')
    .map((r) => `${r.scene}, N = ${r.n}, Max Grid: ${fmt(r.examined)} pairs examined and ${fmt(r.candidates)} handed on per body for ${fmt(r.manifolds)} manifolds (${fmt(r.candidatesPerManifold)} candidates per manifold); the narrow-phase takes ${fmt(100 * r.narrowphaseShare, 2)} % of the step, the broad-phase ${fmt(100 * r.broadphaseShare, 2)} %.`)
    .flatMap((line) => [line, '']);
}

export const shapeFalsePositiveSchema = {
  $id: 'shape-false-positives',
  type: 'object',
  required: ['meta', 'rows'],
  properties: { meta: shapeMetaSchema, rows: { type: 'array', items: { type: 'object' } } },
  additionalProperties: false,
} as const;
