import type { BroadPhaseName, World } from '@maxgrid/engine';
import { buildScene, buildWorld, type BuildOptions, type Scene } from '@maxgrid/scenes';
import { barChart, type ChartSpec } from '../report/charts.js';
import { MAXGRID_PILES_OPTIONS } from '../engines/maxgrid.js';
import { csvLine, makeMeta, maxgridOnly, metaSchema, now, spread, spreadSchema, type Meta, type Profile, type RunContext, type Spread } from './common.js';

/**
 * Issue 6, item 2: persistent sweep-and-prune (sorted endpoints kept between steps, restored by
 * insertion sort, sleeping pairs skipped) against `sap` (sorted from scratch each step), on
 * three scenes:
 * - moving: `uniform`, elastic, no sleeping: every body moves every step;
 * - pile: `seed-box` with gravity, elasticity 0 and sleeping, restitutionThreshold and sleepSpeed
 *   above g dt and the pile solver, settled first until `targetAsleep` of the bodies sleep (or
 *   `settleSteps` pass);
 * - field: `uniform` at rest except every 50th body, inelastic, with sleeping: most bodies sleep
 *   at once and moving ones wake a few neighbours. This one reaches a mostly-sleeping state
 *   whether or not piles settle in the engine.
 * The sleeping fraction is reported at the start and end of the timed steps: read each speed-up
 * together with it. Both worlds of a case are stepped in alternating rounds.
 */
export interface SapSleepOptions {
  n: number;
  /** Timed rounds; each engine steps `steps` times per round, each step timed. */
  rounds: number;
  steps: number;
  warmupSteps: number;
  /** Most steps spent settling the pile before timing. */
  settleSteps: number;
  /** Settling stops once this fraction of bodies sleeps. */
  targetAsleep: number;
  dt: number;
}

export function sapSleepDefaults(profile: Profile): SapSleepOptions {
  return profile === 'full'
    ? { n: 8000, rounds: 10, steps: 30, warmupSteps: 30, settleSteps: 3000, targetAsleep: 0.9, dt: 1 / 60 }
    : { n: 2000, rounds: 3, steps: 10, warmupSteps: 10, settleSteps: 400, targetAsleep: 0.9, dt: 1 / 60 };
}

export type SapSleepCase = 'moving' | 'pile' | 'field';

interface CaseSetup {
  scene: Scene;
  /** World options beyond the broad-phase, as recorded in the output. */
  world: BuildOptions & { sleepSpeed?: number };
  settle: boolean;
}

function setup(kind: SapSleepCase, n: number, dt: number): CaseSetup {
  if (kind === 'moving') return { scene: buildScene('uniform', { n, seed: 1 }), world: { sleeping: false, continuous: false }, settle: false };
  if (kind === 'pile') {
    const g = 300;
    const scene = buildScene('seed-box', { n, seed: 1, gravity: g, elasticity: 0 });
    // Resting contacts under gravity bounce and creep at about g dt per step; thresholds above it.
    // The pile solver: with the single pass a pile keeps moving too fast to sleep.
    const slack = 4 * g * dt;
    return { scene, world: { sleeping: true, continuous: false, restitutionThreshold: slack, sleepSpeed: slack, ...MAXGRID_PILES_OPTIONS }, settle: true };
  }
  const moving = buildScene('uniform', { n, seed: 1 });
  const vx = new Float64Array(n);
  const vy = new Float64Array(n);
  for (let k = 0; k < n; k += 50) {
    vx[k] = moving.vx[k];
    vy[k] = moving.vy[k];
  }
  // Inelastic collisions conserve momentum, so struck clusters drift at a few px/s until a wall
  // stops them: sleepSpeed 5 lets them sleep, keeping roughly 90% of the field asleep.
  return { scene: { ...moving, vx, vy, restitution: 0 }, world: { sleeping: true, continuous: false, sleepSpeed: 5 }, settle: true };
}

export interface SapSleepRow {
  case: SapSleepCase;
  scene: string;
  n: number;
  engine: string;
  settings: Record<string, number | boolean>;
  settleSteps: number;
  /** Sleeping bodies / N at the start and at the end of the timed steps. */
  asleepStart: number;
  asleepEnd: number;
  ms: Spread;
  /** Mean pairs examined and contacts per timed step. */
  pairTests: number;
  contacts: number;
}

export interface SapSleepResult {
  meta: Meta;
  rows: SapSleepRow[];
}

function asleepFraction(world: World, n: number): number {
  return n === 0 ? 0 : world.stats.sleepingBodies / n;
}

export async function runSapSleep(options: SapSleepOptions, ctx: RunContext): Promise<SapSleepResult> {
  const engines = maxgridOnly(ctx.engines, 'sap-sleep');
  const rows: SapSleepRow[] = [];
  const cases: SapSleepCase[] = ['moving', 'pile', 'field'];
  let done = 0;
  for (const kind of cases) {
    const { scene, world: settings, settle } = setup(kind, options.n, options.dt);
    // sleepSpeed is a World option that BuildOptions does not list yet; buildWorld passes every
    // option through to the World constructor.
    const worlds = engines.map((e) => buildWorld(scene, { ...settings, broadphase: e.info.id.slice('maxgrid:'.length) as BroadPhaseName }));
    let settled = 0;
    if (settle) {
      // Bit-identical across broad-phases: settle the first until enough sleep, the rest as far.
      while (settled < options.settleSteps && asleepFraction(worlds[0], scene.count) < options.targetAsleep) {
        worlds[0].step(options.dt);
        settled++;
      }
      for (const w of worlds.slice(1)) for (let i = 0; i < settled; i++) w.step(options.dt);
    }
    for (const w of worlds) for (let i = 0; i < options.warmupSteps; i++) w.step(options.dt);
    const start = worlds.map((w) => asleepFraction(w, scene.count));
    const times = worlds.map(() => [] as number[]);
    const tests = worlds.map(() => 0);
    const contacts = worlds.map(() => 0);
    for (let round = 0; round < options.rounds; round++) {
      const order = round % 2 === 0 ? worlds.map((_, i) => i) : worlds.map((_, i) => worlds.length - 1 - i);
      for (const i of order) {
        ctx.progress?.(done++, cases.length * options.rounds * engines.length, `${kind} round ${round + 1} ${engines[i].info.id}`);
        for (let s = 0; s < options.steps; s++) {
          const t0 = now();
          worlds[i].step(options.dt);
          times[i].push(now() - t0);
          tests[i] += worlds[i].stats.pairTests;
          contacts[i] += worlds[i].stats.contacts;
        }
        await ctx.yieldToHost?.();
      }
    }
    const timed = options.rounds * options.steps;
    worlds.forEach((w, i) =>
      rows.push({
        case: kind,
        scene: scene.name,
        n: scene.count,
        engine: engines[i].info.id,
        settings: { ...(settings as Record<string, number | boolean>), restitution: scene.restitution },
        settleSteps: settled,
        asleepStart: start[i],
        asleepEnd: asleepFraction(w, scene.count),
        ms: spread(times[i]),
        pairTests: tests[i] / timed,
        contacts: contacts[i] / timed,
      }),
    );
  }
  ctx.progress?.(1, 1, 'done');
  return { meta: makeMeta('sap-sleep', ctx, options), rows };
}

export function sapSleepCsv(result: SapSleepResult): string {
  const lines = [csvLine(['case', 'scene', 'n', 'engine', 'settle_steps', 'asleep_start', 'asleep_end', 'median_ms', 'p25_ms', 'p75_ms', 'pair_tests', 'contacts'])];
  for (const r of result.rows) {
    lines.push(csvLine([r.case, r.scene, r.n, r.engine, r.settleSteps, r.asleepStart, r.asleepEnd, r.ms.median, r.ms.p25, r.ms.p75, r.pairTests, r.contacts]));
  }
  return lines.join('\n') + '\n';
}

export function sapSleepCharts(result: SapSleepResult): ChartSpec[] {
  const cases = [...new Set(result.rows.map((r) => r.case))];
  const engines = [...new Set(result.rows.map((r) => r.engine))];
  return [
    barChart({
      id: 'sap-sleep',
      title: `sap vs sap-persistent: median step (N = ${String(result.meta.options.n)})`,
      categories: cases.map((c) => {
        const r = result.rows.find((x) => x.case === c)!;
        return `${c} (${Math.round(r.asleepStart * 100)}% asleep)`;
      }),
      yName: 'median ms per step',
      series: engines.map((e) => ({ name: e, values: cases.map((c) => result.rows.find((r) => r.case === c && r.engine === e)?.ms.median ?? NaN) })),
    }),
  ];
}

const fraction = { type: 'number', minimum: 0, maximum: 1 } as const;

export const sapSleepSchema = {
  $id: 'sap-sleep',
  type: 'object',
  required: ['meta', 'rows'],
  properties: {
    meta: metaSchema,
    rows: {
      type: 'array',
      minItems: 1,
      items: {
        type: 'object',
        required: ['case', 'scene', 'n', 'engine', 'settings', 'settleSteps', 'asleepStart', 'asleepEnd', 'ms', 'pairTests', 'contacts'],
        properties: {
          case: { enum: ['moving', 'pile', 'field'] },
          scene: { type: 'string' },
          n: { type: 'integer', minimum: 1 },
          engine: { type: 'string', pattern: '^maxgrid:' },
          settings: { type: 'object' },
          settleSteps: { type: 'integer', minimum: 0 },
          asleepStart: fraction,
          asleepEnd: fraction,
          ms: spreadSchema,
          pairTests: { type: 'number', minimum: 0 },
          contacts: { type: 'number', minimum: 0 },
        },
        additionalProperties: false,
      },
    },
  },
  additionalProperties: false,
} as const;
