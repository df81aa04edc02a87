import { World, type BroadPhaseName } from '@maxgrid/engine';
import { CLIFF_SCENES, CLIFF_SCENE_NAMES, buildWorld, type CliffSceneName } from '@maxgrid/scenes';
import { fmt, ratioText, type Table } from '../report/tables.js';
import { csvLine, makeMeta, maxgridOnly, metaSchema, now, spread, spreadSchema, type Meta, type Profile, type RunContext, type Spread } from './common.js';

/**
 * Issue 22, item 8: the scenes where a broad-phase or the continuous sweep used to fall off a
 * cliff (packages/scenes/src/cliffs.ts), each stepped with every maxgrid broad-phase and
 * otherwise the engine's default options (continuous collision on), as a new user would run
 * them. Per scene, one world per broad-phase, stepped in turn round by round (after a throwaway
 * world and one warm-up step each); per broad-phase the median step, the pairs examined
 * and contacts per body, and the default broad-phase's time over the fastest one's. A
 * broad-phase is timed for at most `budgetMs` (at least `minSteps` steps), so `naive` at 20,000
 * bodies costs seconds, not minutes.
 */
export interface CliffsOptions {
  scenes: CliffSceneName[];
  /** Each scene's body count over its default (1: the sizes the issue measured). */
  scale: number;
  /** Timed steps per broad-phase, unless the budget runs out first. */
  steps: number;
  minSteps: number;
  budgetMs: number;
  dt: number;
}

export function cliffsDefaults(profile: Profile): CliffsOptions {
  return profile === 'full'
    ? { scenes: [...CLIFF_SCENE_NAMES], scale: 1, steps: 30, minSteps: 3, budgetMs: 6000, dt: 1 / 60 }
    : { scenes: [...CLIFF_SCENE_NAMES], scale: 1, steps: 16, minSteps: 2, budgetMs: 2500, dt: 1 / 60 };
}

export interface CliffsRow {
  scene: string;
  bodies: number;
  engine: string;
  steps: number;
  ms: Spread;
  /** Means over the timed steps, per body. */
  pairTestsPerBody: number;
  contactsPerBody: number;
}

export interface CliffsResult {
  meta: Meta;
  /** The broad-phase a World gets when none is given. */
  defaultBroadphase: string;
  rows: CliffsRow[];
}

export async function runCliffs(options: CliffsOptions, ctx: RunContext): Promise<CliffsResult> {
  const engines = maxgridOnly(ctx.engines, 'cliffs');
  const rows: CliffsRow[] = [];
  const total = options.scenes.length;
  let done = 0;
  for (const name of options.scenes) {
    const definition = CLIFF_SCENES[name];
    const scene = definition.build({ n: Math.max(1, Math.round(definition.params.n.default * options.scale)) });
    // A throwaway world first, so that the first broad-phase timed does not pay for compiling the scene's code paths.
    const warm = buildWorld(scene);
    for (let s = 0; s < 3; s++) warm.step(options.dt);
    // Every broad-phase's world stepped in turn, round by round, so that the host's noise hits
    // them alike; a world leaves the rotation once it has its steps, or has spent its budget.
    const worlds = engines.map((engine) => buildWorld(scene, { broadphase: engine.info.id.slice('maxgrid:'.length) as BroadPhaseName }));
    for (const world of worlds) world.step(options.dt);
    const times = worlds.map((): number[] => []);
    const spent = worlds.map(() => 0);
    const pairTests = worlds.map(() => 0);
    const contacts = worlds.map(() => 0);
    const active = (i: number) => times[i].length < options.steps && (times[i].length < options.minSteps || spent[i] < options.budgetMs);
    for (let round = 0; worlds.some((_, i) => active(i)); round++) {
      ctx.progress?.(done + Math.min(round, options.steps) / options.steps, total, `${name} round ${round + 1}`);
      for (let k = 0; k < worlds.length; k++) {
        const i = (round + k) % worlds.length;
        if (!active(i)) continue;
        const t0 = now();
        worlds[i].step(options.dt);
        const ms = now() - t0;
        times[i].push(ms);
        spent[i] += ms;
        pairTests[i] += worlds[i].stats.pairTests;
        contacts[i] += worlds[i].stats.contacts;
      }
      await ctx.yieldToHost?.();
    }
    worlds.forEach((world, i) => {
      const perBody = times[i].length * world.bodyCount;
      rows.push({ scene: name, bodies: world.bodyCount, engine: engines[i].info.id, steps: times[i].length, ms: spread(times[i]), pairTestsPerBody: pairTests[i] / perBody, contactsPerBody: contacts[i] / perBody });
    });
    done++;
  }
  ctx.progress?.(1, 1, 'done');
  return { meta: makeMeta('cliffs', ctx, options), defaultBroadphase: `maxgrid:${new World().broadphase}`, rows };
}

/** Per scene: the fastest broad-phase and the default's median over its median (null when the default was not run). */
export function cliffsVerdicts(result: CliffsResult): { scene: string; best: CliffsRow; ratio: number | null }[] {
  const scenes = [...new Set(result.rows.map((r) => r.scene))];
  return scenes.map((scene) => {
    const rows = result.rows.filter((r) => r.scene === scene);
    const best = rows.reduce((a, b) => (b.ms.median < a.ms.median ? b : a));
    const fallback = rows.find((r) => r.engine === result.defaultBroadphase);
    return { scene, best, ratio: fallback ? fallback.ms.median / best.ms.median : null };
  });
}

export function cliffsTables(result: CliffsResult): Table[] {
  const engines = [...new Set(result.rows.map((r) => r.engine))];
  const verdicts = cliffsVerdicts(result);
  const cell = (scene: string, engine: string) => {
    const r = result.rows.find((x) => x.scene === scene && x.engine === engine);
    return r ? `${fmt(r.ms.median)} (${fmt(r.pairTestsPerBody)})` : '–';
  };
  return [
    {
      title: 'Cliff scenes: median ms per step (pairs examined per body), every broad-phase with the default options otherwise',
      headers: ['scene', 'bodies', ...engines, 'fastest', `${result.defaultBroadphase} / fastest`],
      rows: verdicts.map((v) => [v.scene, String(v.best.bodies), ...engines.map((e) => cell(v.scene, e)), v.best.engine, v.ratio === null ? '–' : ratioText(v.ratio)]),
      note: `One world per broad-phase, stepped in turn. Timed steps per broad-phase: up to ${String(result.meta.options.steps)}, fewer where a step takes long (a budget of ${fmt(Number(result.meta.options.budgetMs) / 1000)} s, at least ${String(result.meta.options.minSteps)}). Continuous collision is on, as by default: in segment-floor and static-wall its sweep is part of every step.`,
    },
  ];
}

export function cliffsHeadline(result: CliffsResult): string[] {
  const verdicts = cliffsVerdicts(result).filter((v) => v.ratio !== null);
  if (verdicts.length === 0) return [`The default broad-phase (${result.defaultBroadphase}) was not among those run.`];
  const worst = verdicts.reduce((a, b) => (b.ratio! > a.ratio! ? b : a));
  return [
    `With the default options (${result.defaultBroadphase}), every cliff scene steps within ${ratioText(worst.ratio!)} of its fastest broad-phase (worst: ${worst.scene}, fastest there ${worst.best.engine}): ${verdicts
      .map((v) => `${v.scene} ${ratioText(v.ratio!)}`)
      .join(', ')}.`,
    '',
  ];
}

export function cliffsCsv(result: CliffsResult): string {
  const lines = [csvLine(['scene', 'bodies', 'engine', 'steps', 'median_ms', 'p25_ms', 'p75_ms', 'pair_tests_per_body', 'contacts_per_body'])];
  for (const r of result.rows) lines.push(csvLine([r.scene, r.bodies, r.engine, r.steps, r.ms.median, r.ms.p25, r.ms.p75, r.pairTestsPerBody, r.contactsPerBody]));
  return lines.join('\n') + '\n';
}

export const cliffsSchema = {
  $id: 'cliffs',
  type: 'object',
  required: ['meta', 'defaultBroadphase', 'rows'],
  properties: {
    meta: metaSchema,
    defaultBroadphase: { type: 'string', pattern: '^maxgrid:' },
    rows: {
      type: 'array',
      minItems: 1,
      items: {
        type: 'object',
        required: ['scene', 'bodies', 'engine', 'steps', 'ms', 'pairTestsPerBody', 'contactsPerBody'],
        properties: {
          scene: { enum: [...CLIFF_SCENE_NAMES] },
          bodies: { type: 'integer', minimum: 1 },
          engine: { type: 'string', pattern: '^maxgrid:' },
          steps: { type: 'integer', minimum: 1 },
          ms: spreadSchema,
          pairTestsPerBody: { type: 'number', minimum: 0 },
          contactsPerBody: { type: 'number', minimum: 0 },
        },
        additionalProperties: false,
      },
    },
  },
  additionalProperties: false,
} as const;
