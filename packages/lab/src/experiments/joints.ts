import { buildShapeScene, type ShapeScene, type ShapeSceneName } from '@maxgrid/scenes';
import { engineLabel, fmt, ratioText, warmUpNote, type Table } from '../report/tables.js';
import { allocatePoses, resolveSceneJoints, scenePoint, UnsupportedSceneError, type PoseState, type ShapeProfile, type ShapeSimulation } from '../shape-engines/adapter.js';
import { SHAPE_ENGINE_IDS } from '../shape-engines/registry.js';
import { csvLine, makeMeta, shapeMetaSchema, now, spread, spreadSchema, stepInTurns, warmUp, warmUpMs, type Meta, type Profile, type RunContext, type Spread } from './common.js';
// Types only: registry.ts imports this file, and a value imported back would be read before it is defined.
import type { Experiment, Overrides } from './registry.js';

/**
 * Issue 21: step times on joint scenes against the peers that have the scene's joints (Box2D
 * 2.4, planck, Rapier, Matter, p2), with a physical figure beside each time so that an engine
 * that is fast because its joints give way shows it. Per scene, one simulation per engine, the
 * engines stepped side by side in turns of a few steps each, the order rotated each turn, so that
 * the host's noise hits them alike; the first step of a turn, which finds the caches full of the
 * engine before's data, is stepped but not timed (see stepInTurns). An engine leaves the rotation
 * once it has its timed steps or has spent its budget. An engine that lacks one of the scene's
 * joint kinds or features is skipped there, with its reason.
 */
export interface JointsOptions {
  cases: { scene: JointSceneName; params: Record<string, number> }[];
  /** The peers' settings profile: joints need their engines' iterations, not the report's one. */
  profile: ShapeProfile;
  /** Untimed steps first, each engine in turn. */
  warmupSteps: number;
  /** Each engine's warm-up on throwaway twins of a case before it is timed, so that the timed steps run compiled code (see warmUp). */
  warmUpMs: number;
  /** Timed steps per engine, unless the budget runs out first. */
  steps: number;
  /** Steps an engine takes at a turn; the first of each is stepped but not timed (see stepInTurns). */
  turnSteps: number;
  minSteps: number;
  budgetMs: number;
  dt: number;
  /** The engine the ratios divide by. */
  baseline: string;
}

export const JOINT_SCENES = ['joint-grid', 'chain', 'bridge', 'ragdolls', 'car', 'jellies', 'blobs'] as const satisfies readonly ShapeSceneName[];
export type JointSceneName = (typeof JOINT_SCENES)[number];

export function jointsDefaults(profile: Profile): JointsOptions {
  const common = { profile: 'defaults' as const, dt: 1 / 60, baseline: 'maxgrid:maxgrid' };
  return profile === 'full'
    ? {
        ...common,
        cases: [
          { scene: 'joint-grid', params: { size: 100 } },
          { scene: 'chain', params: { links: 100, horizontal: 1 } },
          { scene: 'bridge', params: {} },
          { scene: 'ragdolls', params: {} },
          { scene: 'car', params: {} },
          { scene: 'jellies', params: {} },
          // Soft bodies at scale (issue 21): hundreds of them, ten to twenty thousand particles.
          { scene: 'jellies', params: { count: 400 } },
          { scene: 'blobs', params: { count: 625 } },
          { scene: 'blobs', params: { count: 625, segments: 3 } },
        ],
        warmupSteps: 30,
        warmUpMs: warmUpMs('full'),
        steps: 300,
        turnSteps: 10,
        minSteps: 10,
        budgetMs: 20_000,
      }
    : {
        ...common,
        cases: [
          { scene: 'joint-grid', params: { size: 40 } },
          { scene: 'chain', params: { links: 100, horizontal: 1 } },
          { scene: 'bridge', params: {} },
          { scene: 'ragdolls', params: { count: 20 } },
          { scene: 'car', params: {} },
          { scene: 'jellies', params: { count: 8 } },
          { scene: 'blobs', params: { count: 12 } },
        ],
        warmupSteps: 10,
        warmUpMs: warmUpMs('quick'),
        steps: 60,
        turnSteps: 10,
        minSteps: 5,
        budgetMs: 3000,
      };
}

/** What the sanity column reads for a scene, and the range a physical answer falls in. */
export interface SanityFigure {
  /** What was measured, with its unit. */
  label: string;
  value: number;
  /** Where a plausible answer lies; an engine whose joints gave way lands outside it. */
  lower: number;
  upper: number;
  /** The largest distance between a revolute joint's two anchors, scene units (0 without revolute joints). */
  pinGap: number;
  /** The largest plausible pin gap (a fraction of the parts' size), or null where the scene has no pins. */
  pinGapLimit: number | null;
  /** The figure within its range and the pin gap within its limit. */
  ok: boolean;
}

export interface JointsRow {
  scene: string;
  params: Record<string, number>;
  bodies: number;
  joints: number;
  engine: string;
  /** Timed steps (fewer than the option's where the budget ran out). */
  steps: number;
  /** Simulated time at which the sanity figures were read. */
  seconds: number;
  ms: Spread;
  sanity: SanityFigure;
}

export interface JointsResult {
  meta: Meta;
  rows: JointsRow[];
  skipped: { scene: string; engine: string; reason: string }[];
}

function pose(p: PoseState, k: number) {
  return { x: p.x[k], y: p.y[k], angle: p.angle[k], shapes: [] };
}

/** The largest gap between the anchors of a revolute joint. */
export function pinGap(scene: ShapeScene, p: PoseState): number {
  let gap = 0;
  // Only revolute pins are measured; a scene with kinds the peers lack (a blob's gas) has none to resolve.
  if (!(scene.joints ?? []).some((j) => j.kind === 'revolute')) return 0;
  for (const j of resolveSceneJoints(scene, 'lab')) {
    if (j.kind !== 'revolute') continue;
    const a = scenePoint(pose(p, j.bodyA), j.anchorA);
    const b = scenePoint(pose(p, j.bodyB), j.anchorB);
    gap = Math.max(gap, Math.hypot(b.x - a.x, b.y - a.y));
  }
  return gap;
}

/**
 * The scene's physical figure after `seconds` from its start, and its pins' largest gap. The
 * bounds are loose (a few times what Box2D 2.4 and maxgrid give) but each sits far inside what
 * the scene does once its joints give way: bodies let go fall g t^2 / 2, and pins come apart by
 * a good part of the parts' size (Matter's joint grid, p2's bridge).
 */
export function jointSanity(scene: ShapeScene, p: PoseState, seconds: number): SanityFigure {
  const g = Math.hypot(scene.gravity.x, scene.gravity.y);
  const freeFall = (g * seconds * seconds) / 2;
  const gap = pinGap(scene, p);
  const figure = (label: string, value: number, lower: number, upper: number, gapLimit: number | null): SanityFigure => ({
    label,
    value,
    lower,
    upper,
    pinGap: gap,
    pinGapLimit: gapLimit,
    ok: value >= lower && value <= upper && (gapLimit === null || gap <= gapLimit),
  });
  switch (scene.name) {
    case 'chain': {
      // The far end of the last link, against the pinned end at the origin, over the chain's length.
      const links = scene.params.links;
      const L = scene.params.linkLength;
      const tip = scenePoint(pose(p, links), { x: L / 2, y: 0 });
      return figure('tip to pivot / chain length', Math.hypot(tip.x, tip.y) / (links * L), 0.8, 1.05, L / 4);
    }
    case 'joint-grid': {
      // The bottom of the middle column hangs from the pins straight above it: it drops only by
      // what the grid stretches, where a grid without joints falls freely.
      const n = scene.params.size;
      const k = Math.floor(n / 2) * n + n - 1;
      // Pins at half the spacing apart: Box2D 2.4's grid stretches to 0.4 at its worst pin without coming apart.
      return figure('drop below the pins, m', p.y[k] - scene.bodies[k].y, -0.5, 0.2 * freeFall + 0.5, 0.5);
    }
    case 'bridge': {
      // The deck starts taut between the posts, so it sags only as far as its pins stretch: a
      // quarter of the span would take a sixth more length.
      const k = 2 + Math.floor(scene.params.planks / 2);
      return figure('midspan sag, m', p.y[k] - scene.bodies[k].y, -0.5, Math.min(0.5 * freeFall + 0.5, scene.params.planks / 4), 0.25);
    }
    case 'ragdolls': {
      // The mean over the limited joints: one limb's overshoot as a body lands is brief, and would make the figure a coin toss.
      let sum = 0;
      let count = 0;
      for (const j of resolveSceneJoints(scene, 'lab')) {
        if (j.kind !== 'revolute' || !j.limits) continue;
        const turn = p.angle[j.bodyB] - p.angle[j.bodyA] - j.referenceAngle;
        const angle = Math.atan2(Math.sin(turn), Math.cos(turn));
        sum += Math.max(0, j.limits.lower - angle, angle - j.limits.upper);
        count++;
      }
      return figure('mean angle past a limit, rad', sum / Math.max(count, 1), 0, 0.1, 0.1);
    }
    case 'car':
      // The wheels' motors drive the chassis forward only through the wheel joints.
      return figure('chassis travel, m', p.x[0] - scene.bodies[0].x, 0.25 * seconds, 8 * seconds, null);
    case 'jellies': {
      let worst = 0;
      for (const j of resolveSceneJoints(scene, 'lab')) {
        if (j.kind !== 'distance') continue;
        const a = scenePoint(pose(p, j.bodyA), j.anchorA);
        const b = scenePoint(pose(p, j.bodyB), j.anchorB);
        worst = Math.max(worst, Math.abs(Math.hypot(b.x - a.x, b.y - a.y) - j.length) / j.length);
      }
      return figure('largest spring stretch / rest length', worst, 0, 1, null);
    }
    case 'blobs': {
      // The gas holds each ring's area near its rest area (it inflates them a fifth past their
      // start), where an empty ring folds to a third; the median, since a ring landing under
      // another is squashed for a moment.
      const ratios: number[] = [];
      for (const j of scene.joints ?? []) {
        if (j.kind !== 'pressure') continue;
        const ring = j.bodies;
        let now = 0;
        let start = 0;
        for (let i = 0; i < ring.length; i++) {
          const a = ring[i];
          const b = ring[(i + 1) % ring.length];
          now += p.x[a] * p.y[b] - p.x[b] * p.y[a];
          start += scene.bodies[a].x * scene.bodies[b].y - scene.bodies[b].x * scene.bodies[a].y;
        }
        ratios.push(now / start);
      }
      ratios.sort((x, y) => x - y);
      const median = ratios.length === 0 ? NaN : ratios[ratios.length >> 1];
      return figure("median ring's area / its area at the start", median, 0.6, 1.5, null);
    }
    default:
      throw new RangeError(`joints: no sanity figure for scene '${scene.name}'`);
  }
}

/** The steps an engine takes, in turns of `turnSteps` (see stepInTurns), to time `timed` of them. */
export function stepsForTimed(timed: number, turnSteps: number): number {
  const turn = Math.max(1, Math.round(turnSteps));
  return turn === 1 ? timed : timed + Math.ceil(timed / (turn - 1));
}

export async function runJoints(o: JointsOptions, ctx: RunContext): Promise<JointsResult> {
  const engines = ctx.shapeEngines ?? [];
  if (engines.length === 0) throw new RangeError('joints needs shape engines');
  const rows: JointsRow[] = [];
  const skipped: JointsResult['skipped'] = [];
  let done = 0;
  for (const c of o.cases) {
    const scene = buildShapeScene(c.scene, c.params);
    const running: { id: string; sim: ShapeSimulation }[] = [];
    try {
      for (const engine of engines) {
        try {
          warmUp(() => engine.create(scene, o.profile), o.warmupSteps + stepsForTimed(o.steps, o.turnSteps), o.dt, o.warmUpMs);
          running.push({ id: engine.info.id, sim: engine.create(scene, o.profile) });
        } catch (error) {
          if (!(error instanceof UnsupportedSceneError)) throw error;
          skipped.push({ scene: c.scene, engine: engine.info.id, reason: error.reason });
        }
      }
      for (let s = 0; s < o.warmupSteps; s++) for (const r of running) r.sim.step(o.dt);
      const times = running.map((): number[] => []);
      // Every step's time, the untimed first of each turn's included, counts against the budget.
      const spent = running.map(() => 0);
      const taken = running.map(() => 0);
      const active = (i: number) => times[i].length < o.steps && (times[i].length < o.minSteps || spent[i] < o.budgetMs);
      const progress = () => ctx.progress?.(done + Math.min(1, Math.max(0, ...times.map((t) => t.length)) / o.steps), o.cases.length, `${c.scene} step ${Math.max(0, ...taken) + 1}`);
      progress();
      await stepInTurns(
        running.length,
        o.turnSteps,
        0,
        // The timed steps still wanted, and the untimed first of the turn.
        (i) => (active(i) ? o.steps - times[i].length + 1 : 0),
        (i, timed) => {
          const t0 = now();
          running[i].sim.step(o.dt);
          const ms = now() - t0;
          taken[i]++;
          spent[i] += ms;
          if (timed) times[i].push(ms);
        },
        active,
        () => {
          progress();
          return ctx.yieldToHost?.();
        },
      );
      running.forEach((r, i) => {
        const p = allocatePoses(r.sim.count);
        r.sim.read(p);
        const seconds = (o.warmupSteps + taken[i]) * o.dt;
        rows.push({
          scene: c.scene,
          params: { ...scene.params },
          bodies: scene.bodies.length,
          joints: scene.joints?.length ?? 0,
          engine: r.id,
          steps: times[i].length,
          seconds,
          ms: spread(times[i]),
          sanity: jointSanity(scene, p, seconds),
        });
      });
    } finally {
      for (const r of running) r.sim.dispose();
    }
    done++;
  }
  ctx.progress?.(1, 1, 'done');
  return { meta: makeMeta('joints', ctx, o), rows, skipped };
}

function enginesOf(result: JointsResult): string[] {
  const ids = (result.meta.engines ?? []).map((e) => e.id.replace(/ \(shapes\)$/, ''));
  const seen = new Set([...result.rows.map((r) => r.engine), ...result.skipped.map((s) => s.engine)]);
  return ids.filter((id) => seen.has(id));
}

/** A case's label: its scene and parameters, since a profile may run one scene at several sizes. */
function caseOf(r: JointsRow): string {
  return `${r.scene} (${Object.entries(r.params).map(([k, v]) => `${k} ${v}`).join(', ')})`;
}

/** Each case that ran, in order, then each scene that only has refusals. */
function casesOf(result: JointsResult): string[] {
  const ran = new Set(result.rows.map((r) => r.scene));
  return [...new Set([...result.rows.map(caseOf), ...result.skipped.filter((s) => !ran.has(s.scene)).map((s) => s.scene)])];
}

/** How the steps were taken and timed, from a result's options (results from before turns stepped the engines in turn a step at a time, every step timed). */
function stepsText(options: Record<string, unknown>): string {
  const warmup = String(options.warmupSteps);
  if (!(Number(options.turnSteps) > 0)) return `One simulation per engine, stepped in turn after ${warmup} untimed steps`;
  const turn = Math.max(1, Math.round(Number(options.turnSteps)));
  const how =
    turn === 1
      ? 'stepped in turn a step at a time, the order rotated each step, every step timed'
      : `in turns of ${turn} steps each, the order rotated each turn, the first step of each turn (which finds the caches holding the engine before's data) stepped but not timed`;
  return `One simulation per engine: ${warmup} untimed steps, then all engines' simulations side by side, ${how}`;
}

export function jointsTables(result: JointsResult): Table[] {
  const engines = enginesOf(result);
  const cases = casesOf(result);
  const baseline = String(result.meta.options.baseline);
  const steps = Number(result.meta.options.steps);
  const row = (key: string, engine: string) => result.rows.find((r) => caseOf(r) === key && r.engine === engine);
  const first = (key: string) => result.rows.find((r) => caseOf(r) === key);
  const times: Table = {
    title: `Joint scenes: median ms per step, and its ratio to ${baseline}'s (above 1: maxgrid is faster)`,
    headers: ['scene', 'bodies', 'joints', ...engines.map(engineLabel)],
    rows: cases.map((key) => {
      const b = row(key, baseline);
      return [
        key,
        String(first(key)?.bodies ?? ''),
        String(first(key)?.joints ?? ''),
        ...engines.map((e) => {
          const r = row(key, e);
          if (!r) return 'not built';
          const ratio = e === baseline || !b ? '' : ` (${ratioText(r.ms.median / b.ms.median)})`;
          const cut = r.steps < steps ? `, ${r.steps} steps` : '';
          return `${fmt(r.ms.median)}${ratio}${cut}`;
        }),
      ];
    }),
    note: `${stepsText(result.meta.options)}; ${steps} timed steps each, fewer where an engine spent its budget of ${fmt(Number(result.meta.options.budgetMs) / 1000)} s${Number(result.meta.options.turnSteps) > 0 ? ' on its steps' : ''}.${warmUpNote('Before that', result.meta.options.warmUpMs)} Peers with their recommended settings ('${String(result.meta.options.profile)}'), sleeping off. "not built": the engine lacks one of the scene's joint kinds or features (see below).`,
  };
  const sanity: Table = {
    title: 'Joint scenes: a physical figure after the run (and the largest revolute pin gap, m); "implausible" where the joints gave way',
    headers: ['scene', 'figure', 'plausible (pin gap)', 'after', ...engines.map(engineLabel)],
    rows: cases
      .filter((key) => first(key))
      .map((key) => {
        const f = first(key)!;
        return [
          f.scene + (cases.filter((k) => first(k)?.scene === f.scene).length > 1 ? `, ${f.bodies} bodies` : ''),
          f.sanity.label,
          `${fmt(f.sanity.lower)} to ${fmt(f.sanity.upper)}${f.sanity.pinGapLimit === null ? '' : ` (≤ ${fmt(f.sanity.pinGapLimit)})`}`,
          `${fmt(f.seconds)} s`,
          ...engines.map((e) => {
            const r = row(key, e);
            if (!r) return '–';
            const gap = r.sanity.pinGapLimit === null ? '' : ` (${fmt(r.sanity.pinGap)})`;
            return `${fmt(r.sanity.value)}${gap}${r.sanity.ok ? '' : ' implausible'}`;
          }),
        ];
      }),
    note: 'Bounds are per scene, loose, and read at the simulated time shown (later or earlier for an engine cut short by its budget; its own figure is judged at its own time).',
  };
  const out = [times, sanity];
  if (result.skipped.length > 0) {
    out.push({ title: 'Engines not built on a joint scene, and why', headers: ['scene', 'engine', 'reason'], rows: result.skipped.map((s) => [s.scene, engineLabel(s.engine), s.reason]) });
  }
  return out;
}

export function jointsHeadline(result: JointsResult): string[] {
  const baseline = String(result.meta.options.baseline);
  const out: string[] = [];
  for (const key of casesOf(result)) {
    const b = result.rows.find((r) => caseOf(r) === key && r.engine === baseline);
    if (!b) continue;
    const scene = b.scene;
    const peers = result.rows.filter((r) => caseOf(r) === key && r.engine !== baseline).map((r) => `${engineLabel(r.engine)} ${ratioText(r.ms.median / b.ms.median)}${r.sanity.ok ? '' : ' (implausible)'}`);
    out.push(`${scene} (${b.bodies} bodies, ${b.joints} joints): ${baseline} ${fmt(b.ms.median)} ms a step; ${peers.length > 0 ? `${peers.join(', ')} as slow` : 'no peer has its joints'}.`);
  }
  const bad = result.rows.filter((r) => !r.sanity.ok);
  out.push(bad.length === 0 ? 'Every engine that ran kept its joints within the plausible range.' : `Outside the plausible range: ${bad.map((r) => `${engineLabel(r.engine)} on ${r.scene} of ${r.bodies} bodies (${r.sanity.label} ${fmt(r.sanity.value)}, pin gap ${fmt(r.sanity.pinGap)})`).join(', ')}.`, '');
  return out;
}

export function jointsCsv(result: JointsResult): string {
  const lines = [csvLine(['scene', 'bodies', 'joints', 'engine', 'steps', 'seconds', 'median_ms', 'p25_ms', 'p75_ms', 'sanity_figure', 'sanity_value', 'sanity_ok', 'pin_gap'])];
  for (const r of result.rows) lines.push(csvLine([r.scene, r.bodies, r.joints, r.engine, r.steps, r.seconds, r.ms.median, r.ms.p25, r.ms.p75, r.sanity.label, r.sanity.value, r.sanity.ok ? 1 : 0, r.sanity.pinGap]));
  return lines.join('\n') + '\n';
}

export const jointsSchema = {
  $id: 'joints',
  type: 'object',
  required: ['meta', 'rows', 'skipped'],
  properties: {
    meta: shapeMetaSchema,
    rows: {
      type: 'array',
      minItems: 1,
      items: {
        type: 'object',
        required: ['scene', 'params', 'bodies', 'joints', 'engine', 'steps', 'seconds', 'ms', 'sanity'],
        properties: {
          scene: { enum: [...JOINT_SCENES] },
          params: { type: 'object' },
          bodies: { type: 'integer', minimum: 1 },
          joints: { type: 'integer', minimum: 1 },
          engine: { type: 'string' },
          steps: { type: 'integer', minimum: 1 },
          seconds: { type: 'number', exclusiveMinimum: 0 },
          ms: spreadSchema,
          sanity: {
            type: 'object',
            required: ['label', 'value', 'lower', 'upper', 'pinGap', 'pinGapLimit', 'ok'],
            properties: {
              label: { type: 'string' },
              value: { type: 'number' },
              lower: { type: 'number' },
              upper: { type: 'number' },
              pinGap: { type: 'number', minimum: 0 },
              pinGapLimit: { type: ['number', 'null'] },
              ok: { type: 'boolean' },
            },
            additionalProperties: false,
          },
        },
        additionalProperties: false,
      },
    },
    skipped: {
      type: 'array',
      items: {
        type: 'object',
        required: ['scene', 'engine', 'reason'],
        properties: { scene: { enum: [...JOINT_SCENES] }, engine: { type: 'string' }, reason: { type: 'string', minLength: 1 } },
        additionalProperties: false,
      },
    },
  },
  additionalProperties: false,
} as const;

/** --runs sets the timed steps, --dt the step; the cases are fixed (the CLI's --scene names circle scenes). */
function jointsOptions(profile: Profile, o: Overrides): JointsOptions {
  const flags: Record<keyof Overrides, string> = { ns: '--n', runs: '--runs', seconds: '--seconds', scenes: '--scene', dt: '--dt' };
  for (const key of Object.keys(o) as (keyof Overrides)[]) {
    if (o[key] !== undefined && key !== 'runs' && key !== 'dt') throw new RangeError(`option ${flags[key]} does not apply to experiment 'joints' (it takes --runs, --dt)`);
  }
  const d = jointsDefaults(profile);
  return { ...d, steps: o.runs ?? d.steps, dt: o.dt ?? d.dt };
}

export const joints: Experiment<JointsOptions, JointsResult> = {
  name: 'joints',
  description: "Step time on joint scenes (Box2D v3's joint_grid, a 100-link chain, a bridge, ragdolls, a car, jellies, pressure blobs) against every peer that has their joints, with a physical figure per engine (issue 21)",
  schema: jointsSchema,
  defaultEngines: ['maxgrid:maxgrid', ...SHAPE_ENGINE_IDS.filter((id) => !id.startsWith('maxgrid:'))],
  // Seconds of Matter and p2 on the 10,000-body joint grid: too long for the lab page.
  nodeOnly: true,
  shapes: true,
  options: jointsOptions,
  run: runJoints,
  csv: jointsCsv,
  charts: () => [],
  tables: jointsTables,
  headline: jointsHeadline,
};
