import { buildShapeScene, type ShapeScene } from '@maxgrid/scenes';
import { lineChart, type ChartSpec } from '../report/charts.js';
import { engineLabel, fmt, ratioText, warmUpNote, type Table } from '../report/tables.js';
import { allocatePoses, bodyCentroid, type PoseState, type ShapeProfile, type ShapeSimulation, type StageTimes } from '../shape-engines/adapter.js';
import { csvLine, makeMeta, scaleNote, sceneScale, sceneScaleSchema, shapeMetaSchema, now, spread, spreadSchema, stepInTurns, timedInTurns, warmUp, warmUpMs, type Meta, type Profile, type RunContext, type SceneScale, type Spread } from './common.js';

/**
 * Step time on scenes of shapes, every engine on the same scene: Box2D v3's fixed benchmarks
 * (pyramid, many pyramids, tumbler) and two scenes swept over N (the report's noisy scene with
 * squares and hexagons, elastic; the seed box with mixed shapes under gravity), so that the
 * report's question 7.4 (where does Max Grid stop winning once shapes are general polygons?) is
 * answered by ratios measured side by side. maxgrid also reports its stage times, which say why.
 */
export interface ShapeStepTimeOptions {
  /** Scenes at one size each. */
  fixed: { scene: string; params: Record<string, number> }[];
  /** Scenes swept over N (their `n` parameter). */
  sweeps: { scene: string; ns: number[]; profile: ShapeProfile }[];
  /** The settings profile of the fixed scenes (see ShapeProfile). */
  fixedProfile: ShapeProfile;
  runs: number;
  /** Steps each engine takes per run after its warm-up steps, in turns of `turnSteps` (see runShapeStepTime). */
  steps: number;
  /** Steps an engine takes at a turn; the first of each turn is not timed. */
  turnSteps: number;
  warmupSteps: number;
  /** Each engine's warm-up on twins of a case before its first timed run (see warmUp). */
  warmUpMs: number;
  dt: number;
  /** An engine whose median exceeds this on a sweep is not run at larger N of it. */
  cutoffMs: number;
  /** The maxgrid engine the 7.4 table measures peers against. */
  baseline: string;
}

export function shapeStepTimeDefaults(profile: Profile): ShapeStepTimeOptions {
  const common = { fixedProfile: 'defaults' as const, dt: 1 / 60, baseline: 'maxgrid:maxgrid' };
  return profile === 'full'
    ? {
        ...common,
        fixed: [
          { scene: 'pyramid', params: { base: 100 } },
          { scene: 'many-pyramids', params: {} },
          { scene: 'tumbler', params: {} },
        ],
        sweeps: [
          { scene: 'uniform-polygons', ns: [1000, 4000, 16000, 64000], profile: 'report' },
          { scene: 'polygon-box', ns: [250, 1000, 4000, 16000], profile: 'defaults' },
        ],
        runs: 3,
        steps: 300,
        turnSteps: 10,
        warmupSteps: 60,
        warmUpMs: warmUpMs('full'),
        cutoffMs: 1000,
      }
    : {
        ...common,
        fixed: [
          { scene: 'pyramid', params: { base: 100 } },
          { scene: 'many-pyramids', params: { rows: 5, columns: 5 } },
          { scene: 'tumbler', params: {} },
        ],
        sweeps: [
          { scene: 'uniform-polygons', ns: [1000, 4000, 16000, 64000], profile: 'report' },
          { scene: 'polygon-box', ns: [250, 1000, 4000], profile: 'defaults' },
        ],
        runs: 1,
        steps: 60,
        turnSteps: 10,
        warmupSteps: 30,
        warmUpMs: warmUpMs('quick'),
        cutoffMs: 150,
      };
}

export interface ShapeStepTimeRow {
  scene: string;
  /** The scene's size: N for sweeps, its body count for fixed scenes. */
  n: number;
  params: Record<string, number>;
  profile: ShapeProfile;
  engine: string;
  /** Mean step time of each run, ms. */
  runMs: number[];
  ms: Spread;
  /** maxgrid only: mean stage times and counts over the timed steps of the last run. */
  stages: StageTimes | null;
  /** Why the engine's simulation of the scene was broken in a run (sceneBroken), or null: its time is not compared. */
  invalid: string | null;
  /** The scene's lengthUnit and body sizes in metres, which the Box2D family's tolerances depend on. */
  scale: SceneScale;
}

export interface ShapeStepTimeResult {
  meta: Meta;
  options: ShapeStepTimeOptions;
  rows: ShapeStepTimeRow[];
  skipped: { scene: string; engine: string; fromN: number }[];
}

/**
 * Whether a simulation of the scene is broken rather than slow: a body that ends more than a
 * metre outside the scene's box (its walls, or the view it is drawn in where it has none), or at
 * no finite place, has fallen through a floor or out through a wall, which no engine's stacking
 * or settling does. Such an engine's time is for another scene (p2-es's pyramids falling through
 * floors it could not collide with stepped as free fall), so its row is marked and given no
 * ratio. Static and kinematic bodies are not judged. Returns why, or null.
 */
export function sceneBroken(scene: ShapeScene, p: PoseState): string | null {
  const margin = scene.world.lengthUnit ?? 1;
  const box = scene.bounds ? { minX: 0, minY: 0, maxX: scene.bounds.width, maxY: scene.bounds.height } : scene.view;
  let out = 0;
  let dynamic = 0;
  scene.bodies.forEach((b, k) => {
    if ((b.type ?? 'dynamic') !== 'dynamic') return;
    dynamic++;
    const c = bodyCentroid(b);
    const cos = Math.cos(p.angle[k]);
    const sin = Math.sin(p.angle[k]);
    const x = p.x[k] + cos * c.x - sin * c.y;
    const y = p.y[k] + sin * c.x + cos * c.y;
    const inside = x >= box.minX - margin && x <= box.maxX + margin && y >= box.minY - margin && y <= box.maxY + margin;
    if (!inside) out++;
  });
  return out === 0 ? null : `${out} of ${dynamic} bodies ended over 1 m outside the scene (through a floor or a wall)`;
}

export async function runShapeStepTime(o: ShapeStepTimeOptions, ctx: RunContext): Promise<ShapeStepTimeResult> {
  const engines = ctx.shapeEngines ?? [];
  if (engines.length === 0) throw new RangeError('shape-step-time needs shape engines');
  const rows: ShapeStepTimeRow[] = [];
  const skipped: ShapeStepTimeResult['skipped'] = [];
  const cases: { scene: string; params: Record<string, number>; profile: ShapeProfile; sweep: boolean }[] = [
    ...o.fixed.map((f) => ({ scene: f.scene, params: f.params, profile: o.fixedProfile, sweep: false })),
    ...o.sweeps.flatMap((s) => s.ns.map((n) => ({ scene: s.scene, params: { n }, profile: s.profile, sweep: true }))),
  ];
  const total = cases.length * o.runs;
  let done = 0;
  const dropped = new Map<string, Set<string>>();
  const zero = (): StageTimes => ({ broadphaseMs: 0, narrowphaseMs: 0, solveMs: 0, pairTests: 0, candidatePairs: 0, contacts: 0 });
  for (const c of cases) {
    const out = dropped.get(c.scene) ?? new Set<string>();
    dropped.set(c.scene, out);
    const runMs = new Map<string, number[]>(engines.map((e) => [e.info.id, []]));
    const stages = new Map<string, StageTimes>();
    const invalid = new Map<string, string>();
    let size = 0;
    let scale: SceneScale | undefined;
    for (let run = 0; run < o.runs; run++) {
      ctx.progress?.(done++, total, `${c.scene} ${JSON.stringify(c.params)} run ${run + 1}`);
      const params = c.sweep ? { ...c.params, seed: run + 1 } : c.params;
      const scene = buildShapeScene(c.scene, params);
      size = scene.bodies.length;
      scale = sceneScale(scene);
      // Every engine's simulation side by side, stepped in turns of a few steps each, so that the
      // machine's noise falls on all engines alike rather than on whichever ran then; the first
      // step of a turn, which finds the caches full of the engine before's data, is stepped, not
      // timed (see stepInTurns).
      const running: { id: string; sim: ShapeSimulation; elapsed: number; timed: number; sum: StageTimes }[] = [];
      try {
        for (const engine of engines) {
          if (out.has(engine.info.id)) continue;
          if (run === 0) warmUp(() => engine.create(scene, c.profile), o.warmupSteps + o.steps, o.dt, o.warmUpMs);
          running.push({ id: engine.info.id, sim: engine.create(scene, c.profile), elapsed: 0, timed: 0, sum: zero() });
        }
        for (let i = 0; i < o.warmupSteps; i++) for (const r of running) r.sim.step(o.dt);
        // The order rotates each turn (from a run's own start), so that no engine always steps right after another.
        const taken = running.map(() => 0);
        await stepInTurns(
          running.length,
          o.turnSteps,
          run,
          (i) => o.steps - taken[i],
          (i, timed) => {
            const r = running[i];
            taken[i]++;
            if (!timed) {
              r.sim.step(o.dt);
              return;
            }
            // A clock pair per step, so that stage times can be read between steps; steps take
            // milliseconds here, far above the clock's resolution.
            const t0 = now();
            r.sim.step(o.dt);
            r.elapsed += now() - t0;
            r.timed++;
            const s = r.sim.stages?.();
            if (s) for (const key of Object.keys(r.sum) as (keyof StageTimes)[]) r.sum[key] += s[key];
          },
          undefined,
          () => ctx.yieldToHost?.(),
        );
        for (const r of running) {
          runMs.get(r.id)!.push(r.elapsed / r.timed);
          if (r.sim.stages) {
            for (const key of Object.keys(r.sum) as (keyof StageTimes)[]) r.sum[key] /= r.timed;
            stages.set(r.id, r.sum);
          }
          const poses = allocatePoses(r.sim.count);
          r.sim.read(poses);
          const broken = sceneBroken(scene, poses);
          if (broken && !invalid.has(r.id)) invalid.set(r.id, `run ${run + 1}: ${broken}`);
        }
      } finally {
        for (const r of running) r.sim.dispose();
      }
      await ctx.yieldToHost?.();
    }
    for (const engine of engines) {
      const id = engine.info.id;
      const values = runMs.get(id)!;
      if (values.length === 0) continue;
      const row: ShapeStepTimeRow = { scene: c.scene, n: c.sweep ? c.params.n : size, params: c.params, profile: c.profile, engine: id, runMs: values, ms: spread(values), stages: stages.get(id) ?? null, invalid: invalid.get(id) ?? null, scale: scale! };
      rows.push(row);
      if (c.sweep && row.ms.median > o.cutoffMs && !out.has(id)) {
        out.add(id);
        const sweep = o.sweeps.find((s) => s.scene === c.scene)!;
        const next = sweep.ns.find((m) => m > c.params.n);
        if (next !== undefined) skipped.push({ scene: c.scene, engine: id, fromN: next });
      }
    }
  }
  ctx.progress?.(total, total, 'done');
  return { meta: makeMeta('shape-step-time', ctx, o), options: o, rows, skipped };
}

/** The stage that took most of maxgrid's step, and its share. */
export function dominantStage(s: StageTimes | null): string {
  if (!s) return '';
  const stages: [string, number][] = [
    ['broad-phase', s.broadphaseMs],
    ['narrow-phase', s.narrowphaseMs],
    ['solver', s.solveMs],
  ];
  const total = stages.reduce((a, [, v]) => a + v, 0);
  const [name, ms] = stages.reduce((a, b) => (b[1] > a[1] ? b : a));
  return total > 0 ? `${name} ${Math.round((100 * ms) / total)} %` : '';
}

function peersOf(result: ShapeStepTimeResult): string[] {
  return [...new Set(result.rows.map((r) => r.engine))].filter((e) => !e.startsWith('maxgrid:'));
}

function find(result: ShapeStepTimeResult, scene: string, n: number, engine: string): ShapeStepTimeRow | undefined {
  return result.rows.find((r) => r.scene === scene && r.n === n && r.engine === engine);
}

/** A peer's time over the baseline's, or 'invalid' where either's simulation was broken (results from before the check have no `invalid`). */
function ratioCell(r: ShapeStepTimeRow | undefined, b: ShapeStepTimeRow | undefined): string {
  if (!r || !b) return '';
  return r.invalid || b.invalid ? 'invalid' : ratioText(r.ms.median / b.ms.median);
}

/** Where a peer first steps faster than the baseline along a sweep, or null. */
export function crossing(result: ShapeStepTimeResult, scene: string, peer: string): number | null {
  const baseline = result.options.baseline;
  const ns = [...new Set(result.rows.filter((r) => r.scene === scene).map((r) => r.n))].sort((a, b) => a - b);
  for (const n of ns) {
    const a = find(result, scene, n, peer);
    const b = find(result, scene, n, baseline);
    if (a && b && !a.invalid && !b.invalid && a.ms.median < b.ms.median) return n;
  }
  return null;
}

/** How a run's steps were taken and timed, from its options (results from before turns stepped each engine's run at once). */
function turnsText(o: ShapeStepTimeOptions): string {
  if (!(o.turnSteps > 0)) return `the mean of ${o.steps} timed ones; engines in turn, the order rotated per run`;
  const turn = Math.max(1, Math.round(o.turnSteps));
  return `${o.steps} more, all engines' simulations side by side in turns of ${turn} steps each, the order rotated each turn; the mean of the ${timedInTurns(o.steps, turn)} steps after the first of each turn, which finds the caches holding the engine before's data`;
}

/** The times table's note on rows whose simulation was broken, where there are any. */
function invalidNote(result: ShapeStepTimeResult): string {
  const bad = result.rows.filter((r) => r.invalid);
  if (bad.length === 0) return '';
  return `"invalid": the engine's simulation of the scene was broken, so its time is for another scene and is given no ratio (${bad.map((r) => `${engineLabel(r.engine)} on ${r.scene} ${r.n}, ${r.invalid}`).join('; ')}). `;
}

export function shapeStepTimeTables(result: ShapeStepTimeResult): Table[] {
  const engines = [...new Set(result.rows.map((r) => r.engine))];
  const cases = [...new Map(result.rows.map((r) => [`${r.scene} ${r.n}`, r])).values()];
  const times: Table = {
    title: 'Step time on shape scenes (median of runs, ms)',
    headers: ['scene', 'N', 'profile', ...engines.map(engineLabel)],
    rows: cases.map((c) => [
      c.scene,
      String(c.n),
      c.profile,
      ...engines.map((e) => {
        const r = find(result, c.scene, c.n, e);
        return r?.invalid ? `${fmt(r.ms.median)} (invalid)` : fmt(r?.ms.median);
      }),
    ]),
    note: `${invalidNote(result)}${scaleNote(cases)}${scaleNote(cases) ? ' ' : ''}Per run, each engine's own simulation of the scene: ${result.options.warmupSteps} untimed steps, then ${turnsText(result.options)}.${warmUpNote('Before its first run of a case', result.options.warmUpMs)}`,
  };
  const baseline = result.options.baseline;
  const peers = peersOf(result);
  const answer: Table = {
    title: `Report 7.4: each peer's step time over ${baseline}'s (above 1: maxgrid is faster), and what takes maxgrid's step`,
    headers: ['scene', 'N', `${baseline} ms`, ...peers.map(engineLabel), 'maxgrid pairs per body', 'maxgrid contacts per body', 'maxgrid stage that dominates'],
    rows: cases.map((c) => {
      const b = find(result, c.scene, c.n, baseline);
      const s = b?.stages ?? null;
      return [
        c.scene,
        String(c.n),
        fmt(b?.ms.median),
        ...peers.map((p) => ratioCell(find(result, c.scene, c.n, p), b)),
        s ? fmt(s.candidatePairs / c.n) : '',
        s ? fmt(s.contacts / c.n) : '',
        dominantStage(s),
      ];
    }),
  };
  const sweeps = [...new Set(result.options.sweeps.map((s) => s.scene))];
  const crossings: Table = {
    title: 'Where a peer overtakes Max Grid along N (the first N at which it steps faster), if it does',
    headers: ['scene', ...peers.map(engineLabel)],
    rows: sweeps.map((scene) => {
      const largest = Math.max(...result.rows.filter((r) => r.scene === scene).map((r) => r.n));
      return [scene, ...peers.map((p) => {
        const n = crossing(result, scene, p);
        return n === null ? `not up to N = ${largest}` : `N = ${n}`;
      })];
    }),
  };
  return [times, answer, crossings];
}

export function shapeStepTimeCharts(result: ShapeStepTimeResult): ChartSpec[] {
  const baseline = result.options.baseline;
  const charts: ChartSpec[] = [];
  for (const sweep of result.options.sweeps) {
    const rows = result.rows.filter((r) => r.scene === sweep.scene);
    const engines = [...new Set(rows.map((r) => r.engine))];
    charts.push(
      lineChart({
        id: `shape-step-time-${sweep.scene}`,
        title: `Step time vs N, scene ${sweep.scene} (${sweep.profile} settings)`,
        xName: 'N (bodies)',
        yName: 'ms per step',
        xLog: true,
        yLog: true,
        series: engines.map((e) => ({ name: engineLabel(e), points: rows.filter((r) => r.engine === e && !r.invalid).map((r) => [r.n, r.ms.median] as [number, number]) })),
      }),
    );
    const peers = peersOf(result);
    charts.push(
      lineChart({
        id: `seven-four-${sweep.scene}`,
        title: `Report 7.4, ${sweep.scene}: peer step time over ${baseline}'s (below 1: the peer is faster)`,
        xName: 'N (bodies)',
        yName: 'ratio',
        xLog: true,
        yLog: true,
        series: [
          ...peers.map((p) => ({
            name: engineLabel(p),
            points: rows
              .filter((r) => r.engine === p && !r.invalid)
              .flatMap((r) => {
                const b = find(result, sweep.scene, r.n, baseline);
                return b && !b.invalid ? [[r.n, r.ms.median / b.ms.median] as [number, number]] : [];
              }),
          })),
          { name: 'parity', points: [...new Set(rows.map((r) => r.n))].sort((a, b) => a - b).map((n) => [n, 1] as [number, number]) },
        ],
      }),
    );
  }
  return charts;
}

export function shapeStepTimeCsv(result: ShapeStepTimeResult): string {
  const lines = [csvLine(['scene', 'n', 'profile', 'engine', 'median_ms', 'p25_ms', 'p75_ms', 'runs', 'broadphase_ms', 'narrowphase_ms', 'solve_ms', 'candidate_pairs', 'contacts', 'invalid'])];
  for (const r of result.rows) {
    const s = r.stages;
    lines.push(csvLine([r.scene, r.n, r.profile, r.engine, r.ms.median, r.ms.p25, r.ms.p75, r.runMs.length, s?.broadphaseMs ?? '', s?.narrowphaseMs ?? '', s?.solveMs ?? '', s?.candidatePairs ?? '', s?.contacts ?? '', r.invalid ?? '']));
  }
  return lines.join('\n') + '\n';
}

export function shapeStepTimeHeadline(result: ShapeStepTimeResult): string[] {
  const baseline = result.options.baseline;
  const out: string[] = [];
  const pyramid = result.rows.filter((r) => r.scene === 'pyramid');
  const b = pyramid.find((r) => r.engine === baseline);
  if (b) {
    const others = pyramid.filter((r) => !r.engine.startsWith('maxgrid:')).map((r) => `${engineLabel(r.engine)} ${fmt(r.ms.median)} ms (${ratioCell(r, b)})`);
    out.push(`Box2D v3's large pyramid (${b.n} bodies): ${baseline} ${fmt(b.ms.median)} ms a step; ${others.join(', ')}.`, '');
  }
  for (const sweep of result.options.sweeps) {
    const largest = Math.max(...result.rows.filter((r) => r.scene === sweep.scene).map((r) => r.n));
    const top = find(result, sweep.scene, largest, baseline);
    if (!top) continue;
    const at = peersOf(result)
      .map((p) => find(result, sweep.scene, largest, p))
      .filter((r): r is ShapeStepTimeRow => r !== undefined);
    const peers = at.filter((r) => ratioCell(r, top) !== 'invalid').map((r) => `${engineLabel(r.engine)} ${ratioCell(r, top)}`);
    const broken = at.filter((r) => ratioCell(r, top) === 'invalid').map((r) => engineLabel(r.engine));
    const overtaken = peersOf(result).filter((p) => crossing(result, sweep.scene, p) !== null);
    out.push(
      `${sweep.scene} at N = ${largest}: ${baseline} ${fmt(top.ms.median)} ms a step (${dominantStage(top.stages)}); ${peers.length > 0 ? `${peers.join(', ')} as slow` : 'no peer compared'}${broken.length > 0 ? ` (invalid, a broken simulation: ${broken.join(', ')})` : ''}. ` +
        (overtaken.length === 0 ? 'No peer overtakes it at any N measured.' : `Overtaken by ${overtaken.map((p) => `${engineLabel(p)} from N = ${crossing(result, sweep.scene, p)}`).join(', ')}.`),
      '',
    );
  }
  return out;
}

const stagesSchema = {
  type: ['object', 'null'],
  required: ['broadphaseMs', 'narrowphaseMs', 'solveMs', 'pairTests', 'candidatePairs', 'contacts'],
  properties: {
    broadphaseMs: { type: 'number' },
    narrowphaseMs: { type: 'number' },
    solveMs: { type: 'number' },
    pairTests: { type: 'number' },
    candidatePairs: { type: 'number' },
    contacts: { type: 'number' },
  },
  additionalProperties: false,
} as const;

export const shapeStepTimeSchema = {
  $id: 'shape-step-time',
  type: 'object',
  required: ['meta', 'options', 'rows', 'skipped'],
  properties: {
    meta: shapeMetaSchema,
    options: { type: 'object' },
    rows: {
      type: 'array',
      items: {
        type: 'object',
        required: ['scene', 'n', 'params', 'profile', 'engine', 'runMs', 'ms', 'stages', 'invalid', 'scale'],
        properties: {
          scene: { type: 'string' },
          n: { type: 'integer', minimum: 0 },
          params: { type: 'object' },
          profile: { enum: ['report', 'defaults'] },
          engine: { type: 'string' },
          runMs: { type: 'array', minItems: 1, items: { type: 'number', minimum: 0 } },
          ms: spreadSchema,
          stages: stagesSchema,
          invalid: { type: ['string', 'null'] },
          scale: sceneScaleSchema,
        },
        additionalProperties: false,
      },
    },
    skipped: { type: 'array' },
  },
  additionalProperties: false,
} as const;
