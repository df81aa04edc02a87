import { buildScene, type Scene } from '@maxgrid/scenes';
import type { Engine, Simulation } from '../engines/adapter.js';
import { maxgridBuildOptions } from '../engines/maxgrid.js';
import { cBaselineOf, cComparisonSchema, compareWithC, type CComparison } from './c-maxgrid.js';
import { multiCore, multiCoreSchema, type MultiCoreResult } from './multicore.js';
import { makeMeta, metaSchema, now, spread, spreadSchema, type Meta, type Profile, type RunContext, type Spread } from './common.js';

/**
 * Issue 5's targets, each as one measurement from this one run (ratios only between numbers taken
 * here, engines interleaved round by round so machine noise hits all of them):
 * T1 maxgrid vs Rapier and box2d-wasm at 64k `uniform`; T2 maxgrid vs the C baseline at 64k;
 * T3 a million bodies: bytes per body and ns per body against 64k; T5 `mixed` at ratio 100 with
 * maxgrid:auto, hgrid and maxgrid against their `uniform` cost, and against Rapier; T6 the same
 * maxgrid step in headless Chromium against Node; T4 the million-body world on 1 thread against
 * `threads` threads. T7 (the sandbox page with WebGL) is the `sandbox-render` experiment's; this one points there.
 */
export interface TargetsOptions {
  n: number;
  bigN: number;
  mixedRatio: number;
  dt: number;
  rounds: number;
  /** Timed steps per engine per round, each timed on its own; peers take 100+ ms at 64k. */
  stepsPerRound: number;
  warmupSteps: number;
  /** Steps for the million-body world (about 0.3 s each). */
  bigSteps: number;
  /**
   * Untimed steps first. At least 10: the uniform scene starts with its circles apart, and at
   * 1,000,000 bodies its contacts climb from about 3,000 in the first step to about 48,000 by the
   * tenth, then stay there; T3 and T4 are about the steady state, not that climb.
   */
  bigWarmupSteps: number;
  /** Threads for T4's parallel step. */
  threads: number;
  /** Steps of each world for T4 (alternating). */
  parallelSteps: number;
  /**
   * T6's rounds, each `stepsPerRound * 2` steps in Node then as many in Chromium (or the other way
   * round). More than the peers' rounds because a 64k step takes a few ms: with 3 rounds of 10 steps
   * the ratio ranged over 0.82-1.3x in five runs of one afternoon.
   */
  parityRounds: number;
}

export function targetsDefaults(profile: Profile): TargetsOptions {
  return profile === 'full'
    ? { n: 64_000, bigN: 1_000_000, mixedRatio: 100, dt: 1 / 60, rounds: 6, stepsPerRound: 10, warmupSteps: 20, bigSteps: 30, bigWarmupSteps: 10, threads: 2, parallelSteps: 30, parityRounds: 20 }
    : { n: 64_000, bigN: 1_000_000, mixedRatio: 100, dt: 1 / 60, rounds: 3, stepsPerRound: 5, warmupSteps: 20, bigSteps: 5, bigWarmupSteps: 10, threads: 2, parallelSteps: 15, parityRounds: 12 };
}

export interface Timing {
  engine: string;
  scene: string;
  n: number;
  ms: Spread;
  steps: number;
  nsPerBody: number;
}

export interface TargetsResult {
  meta: Meta;
  t1: { timings: Timing[]; rapierOverMaxgrid: number | null; box2dOverMaxgrid: number | null };
  t2: { status: 'ok' | 'hash-mismatch' | 'skipped'; reason?: string; compile?: string; comparison?: CComparison };
  t3: {
    n: number; ms: Spread; steps: number; memoryBytes: number; bytesPerBody: number; nsPerBody: number;
    /** The o.n-body world timed alongside (see `million`). */
    smallN: number; smallMs: Spread; smallSteps: number; nsPerBodyAt64k: number;
    ratio: number; buildMs: number;
  };
  t4: MultiCoreResult;
  t5: { timings: Timing[]; mixedOverUniform: Record<string, number>; rapierOverAuto: number | null };
  t6: { status: 'ok' | 'skipped'; reason?: string; runtime?: string; settings?: Record<string, string>; node?: Spread; browser?: Spread; ratio?: number; hashesMatch?: boolean };
  notMeasured: { target: string; reason: string }[];
}

const PEERS = ['rapier', 'box2d-wasm'];
const MAXGRIDS = ['maxgrid:maxgrid', 'maxgrid:hgrid', 'maxgrid:auto'];

function pick(engines: Engine[], ids: string[]): Engine[] {
  const missing = ids.filter((id) => !engines.some((e) => e.info.id === id));
  if (missing.length) throw new RangeError(`targets needs engines ${ids.join(', ')}; missing ${missing.join(', ')}`);
  return ids.map((id) => engines.find((e) => e.info.id === id)!);
}

/** Every engine on one scene, kept alive, stepped `stepsPerRound` times each in rotating order. */
async function interleaved(engines: Engine[], scene: Scene, o: TargetsOptions, ctx: RunContext, label: string): Promise<Timing[]> {
  const sims: Simulation[] = [];
  try {
    for (const e of engines) {
      ctx.progress?.(0, 1, `${label}: building ${e.info.id}`);
      sims.push(e.create(scene));
    }
    const times = sims.map(() => [] as number[]);
    sims.forEach((sim, i) => {
      ctx.progress?.(0, 1, `${label}: warm-up ${engines[i].info.id}`);
      for (let s = 0; s < o.warmupSteps; s++) sim.step(o.dt);
    });
    for (let round = 0; round < o.rounds; round++) {
      for (let k = 0; k < sims.length; k++) {
        const i = (k + round) % sims.length;
        ctx.progress?.(round, o.rounds, `${label}: round ${round + 1} ${engines[i].info.id}`);
        for (let s = 0; s < o.stepsPerRound; s++) {
          const t0 = now();
          sims[i].step(o.dt);
          times[i].push(now() - t0);
        }
        await ctx.yieldToHost?.();
      }
    }
    return engines.map((e, i) => {
      const ms = spread(times[i]);
      return { engine: e.info.id, scene: scene.name, n: scene.count, ms, steps: times[i].length, nsPerBody: (ms.median * 1e6) / scene.count };
    });
  } finally {
    for (const sim of sims) sim.dispose();
  }
}

const median = (timings: Timing[], id: string) => timings.find((t) => t.engine === id)?.ms.median;
const over = (a: number | undefined, b: number | undefined) => (a !== undefined && b !== undefined && b > 0 ? a / b : null);

export async function runTargets(o: TargetsOptions, ctx: RunContext): Promise<TargetsResult> {
  const maxgrids = pick(ctx.engines, MAXGRIDS);
  const peers = pick(ctx.engines, PEERS);
  const meta = makeMeta('targets', ctx, o);
  const uniform = buildScene('uniform', { n: o.n, seed: 1 });

  // T1 (and T5's uniform reference): every maxgrid broad-phase and both peers on uniform 64k.
  const t1Timings = await interleaved([...maxgrids, ...peers], uniform, o, ctx, `T1 uniform N=${o.n}`);
  const base = median(t1Timings, 'maxgrid:maxgrid');
  const t1 = { timings: t1Timings, rapierOverMaxgrid: over(median(t1Timings, 'rapier'), base), box2dOverMaxgrid: over(median(t1Timings, 'box2d-wasm'), base) };

  // T2: the C baseline, hash-checked, interleaved with maxgrid run by run.
  let t2: TargetsResult['t2'];
  const c = await cBaselineOf(ctx);
  if (typeof c === 'string') t2 = { status: 'skipped', reason: c };
  else {
    ctx.progress?.(0, 1, `T2 C vs maxgrid N=${o.n}`);
    const comparison = await compareWithC(c, maxgrids[0], uniform, { rounds: o.rounds, steps: o.stepsPerRound * 2, warmupSteps: o.warmupSteps, dt: o.dt }, ctx);
    t2 = { status: comparison.status, compile: c.command, comparison };
  }

  // T5: the mixed scene, every maxgrid broad-phase and Rapier.
  const mixed = buildScene('mixed', { n: o.n, seed: 1, ratio: o.mixedRatio });
  const t5Timings = await interleaved([...maxgrids, peers[0]], mixed, o, ctx, `T5 mixed 1:${o.mixedRatio} N=${o.n}`);
  const mixedOverUniform: Record<string, number> = {};
  for (const id of MAXGRIDS) mixedOverUniform[id] = over(median(t5Timings, id), median(t1Timings, id)) ?? NaN;
  const t5 = { timings: t5Timings, mixedOverUniform, rapierOverAuto: over(median(t5Timings, 'rapier'), median(t5Timings, 'maxgrid:auto')) };

  // T6: the maxgrid step in Chromium (the lab page) and in Node, round by round.
  const t6 = await browserParity(o, ctx);

  // T3 last: a million bodies hold about 200 MB, freed before anything else runs.
  const t3 = await million(maxgrids[0], o, ctx);

  // T4 after T3, for the same reason; two million-body worlds.
  const t4 = await multiCore({ n: o.bigN, threads: o.threads, dt: o.dt, steps: o.parallelSteps, warmupSteps: o.bigWarmupSteps }, ctx);

  const notMeasured = [
    {
      target: 'T7 sandbox 100k with WebGL',
      reason:
        'measured by its own experiment, `npm run lab -- sandbox-render`, which times the live sandbox page frame by frame; where Chromium has no GPU it renders WebGL with SwiftShader (CPU) and says so',
    },
  ];
  return { meta, t1, t2, t3, t4, t5, t6, notMeasured };
}

/**
 * The million-body world, timed step by step alternating with a world of o.n bodies (enough of
 * its steps after each big one to take about as long), so that the per-body ratio compares two
 * numbers taken side by side. T1's 64k median, taken minutes earlier, would fold the host's drift
 * into the ratio: on this 2-core machine memory-bound steps of 1M bodies slow down by half or more
 * from one minute to the next (41 to 65 ms within one run of 40 steps), and the 64k step drifts on
 * its own schedule (its median alongside ranged over 2.27-3.35 ms in one day's runs). With T1's
 * median, T3 gave 0.886x to 1.63x in four runs of one afternoon.
 */
async function million(engine: Engine, o: TargetsOptions, ctx: RunContext): Promise<TargetsResult['t3']> {
  ctx.progress?.(0, 1, `T3 building N=${o.bigN}`);
  const b0 = now();
  const sim = engine.create(buildScene('uniform', { n: o.bigN, seed: 1 }));
  const buildMs = now() - b0;
  const small = engine.create(buildScene('uniform', { n: o.n, seed: 1 }));
  try {
    for (let s = 0; s < o.bigWarmupSteps; s++) sim.step(o.dt);
    for (let s = 0; s < o.warmupSteps; s++) small.step(o.dt);
    const smallPerBig = Math.max(1, Math.round(o.bigN / o.n));
    const times: number[] = [];
    const smallTimes: number[] = [];
    for (let s = 0; s < o.bigSteps; s++) {
      ctx.progress?.(s, o.bigSteps, `T3 N=${o.bigN} step ${s + 1}`);
      const t0 = now();
      sim.step(o.dt);
      times.push(now() - t0);
      for (let k = 0; k < smallPerBig; k++) {
        const t1 = now();
        small.step(o.dt);
        smallTimes.push(now() - t1);
      }
      await ctx.yieldToHost?.();
    }
    const ms = spread(times);
    const smallMs = spread(smallTimes);
    const memoryBytes = sim.memoryBytes!();
    const nsPerBody = (ms.median * 1e6) / o.bigN;
    const nsPerBodyAt64k = (smallMs.median * 1e6) / o.n;
    return {
      n: o.bigN, ms, steps: times.length, memoryBytes, bytesPerBody: memoryBytes / o.bigN, nsPerBody,
      smallN: o.n, smallMs, smallSteps: smallTimes.length, nsPerBodyAt64k, ratio: nsPerBody / nsPerBodyAt64k, buildMs,
    };
  } finally {
    sim.dispose();
    small.dispose();
  }
}

async function browserParity(o: TargetsOptions, ctx: RunContext): Promise<TargetsResult['t6']> {
  if (!ctx.host) return { status: 'skipped', reason: 'runs from Node, which drives a headless Chromium' };
  ctx.progress?.(0, 1, 'T6 starting Vite and Chromium');
  const host = await ctx.host.browser();
  if (typeof host === 'string') return { status: 'skipped', reason: host };
  const params = { n: o.n, seed: 1 };
  try {
    const engine = ctx.engines.find((e) => e.info.id === 'maxgrid:maxgrid')!;
    const remote = await host.world('uniform', params, maxgridBuildOptions('maxgrid').broadphase!);
    const local = engine.create(buildScene('uniform', params));
    const nodeTimes: number[] = [];
    const browserTimes: number[] = [];
    await remote.step(o.warmupSteps, o.dt);
    for (let s = 0; s < o.warmupSteps; s++) local.step(o.dt);
    const steps = o.stepsPerRound * 2;
    for (let round = 0; round < o.parityRounds; round++) {
      ctx.progress?.(round, o.parityRounds, `T6 round ${round + 1}`);
      const runNode = async () => {
        for (let s = 0; s < steps; s++) {
          const t0 = now();
          local.step(o.dt);
          nodeTimes.push(now() - t0);
        }
      };
      const runBrowser = async () => void browserTimes.push(...(await remote.step(steps, o.dt)));
      for (const side of round % 2 === 0 ? [runNode, runBrowser] : [runBrowser, runNode]) await side();
    }
    const hashesMatch = (await remote.hash()) === local.stateHash!();
    await remote.dispose();
    local.dispose();
    const node = spread(nodeTimes);
    const browser = spread(browserTimes);
    return { status: 'ok', runtime: host.runtime, settings: host.settings, node, browser, ratio: browser.median / node.median, hashesMatch };
  } finally {
    await host.close();
  }
}

const timing = {
  type: 'object',
  required: ['engine', 'scene', 'n', 'ms', 'steps', 'nsPerBody'],
  properties: { engine: { type: 'string' }, scene: { type: 'string' }, n: { type: 'integer' }, ms: spreadSchema, steps: { type: 'integer', minimum: 1 }, nsPerBody: { type: 'number', minimum: 0 } },
  additionalProperties: false,
} as const;
const ratio = { type: ['number', 'null'] } as const;

export const targetsSchema = {
  $id: 'targets',
  type: 'object',
  required: ['meta', 't1', 't2', 't3', 't4', 't5', 't6', 'notMeasured'],
  properties: {
    meta: metaSchema,
    t1: {
      type: 'object',
      required: ['timings', 'rapierOverMaxgrid', 'box2dOverMaxgrid'],
      properties: { timings: { type: 'array', minItems: 5, items: timing }, rapierOverMaxgrid: ratio, box2dOverMaxgrid: ratio },
    },
    t2: {
      type: 'object',
      required: ['status'],
      properties: { status: { enum: ['ok', 'hash-mismatch', 'skipped'] }, reason: { type: 'string' }, compile: { type: 'string' }, comparison: cComparisonSchema },
    },
    t3: {
      type: 'object',
      required: ['n', 'ms', 'steps', 'memoryBytes', 'bytesPerBody', 'nsPerBody', 'smallN', 'smallMs', 'smallSteps', 'nsPerBodyAt64k', 'ratio', 'buildMs'],
      properties: {
        n: { type: 'integer', minimum: 1 },
        ms: spreadSchema,
        steps: { type: 'integer', minimum: 1 },
        memoryBytes: { type: 'integer', minimum: 1 },
        bytesPerBody: { type: 'number', exclusiveMinimum: 0 },
        nsPerBody: { type: 'number', minimum: 0 },
        smallN: { type: 'integer', minimum: 1 },
        smallMs: spreadSchema,
        smallSteps: { type: 'integer', minimum: 1 },
        nsPerBodyAt64k: { type: 'number', minimum: 0 },
        ratio: { type: 'number', minimum: 0 },
        buildMs: { type: 'number', minimum: 0 },
      },
    },
    t4: multiCoreSchema,
    t5: {
      type: 'object',
      required: ['timings', 'mixedOverUniform', 'rapierOverAuto'],
      properties: { timings: { type: 'array', minItems: 4, items: timing }, mixedOverUniform: { type: 'object', additionalProperties: { type: 'number' } }, rapierOverAuto: ratio },
    },
    t6: {
      type: 'object',
      required: ['status'],
      properties: {
        status: { enum: ['ok', 'skipped'] },
        reason: { type: 'string' },
        runtime: { type: 'string' },
        settings: { type: 'object' },
        node: spreadSchema,
        browser: spreadSchema,
        ratio: { type: 'number', exclusiveMinimum: 0 },
        hashesMatch: { type: 'boolean' },
      },
    },
    notMeasured: { type: 'array', items: { type: 'object', required: ['target', 'reason'] } },
  },
  additionalProperties: false,
} as const;
