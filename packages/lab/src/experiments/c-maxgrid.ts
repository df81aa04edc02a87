import { buildScene, type Scene } from '@maxgrid/scenes';
import type { Engine } from '../engines/adapter.js';
import { lineChart, type ChartSpec } from '../report/charts.js';
import { csvLine, makeMeta, maxgridOnly, metaSchema, now, spread, spreadSchema, warmUp, warmUpMs, type CBaseline, type Meta, type Profile, type RunContext, type Spread } from './common.js';

/**
 * Issue 5, target 2: maxgrid's step against the same Max Grid algorithm in plain C
 * (packages/lab/native/maxgrid.c, gcc -O3 -march=native -ffp-contract=off). Both run the same
 * scene for the same steps, round by round (C, then JS, then C...; the order alternates), so
 * machine noise hits both alike. The C program prints its final state hash; a timing is reported
 * only when it equals `world.stateHash()` after the same steps, i.e. when C did the same work.
 */
export interface CMaxgridOptions {
  scene: string;
  ns: number[];
  rounds: number;
  /** Timed steps per round, each timed on its own, after `warmupSteps` untimed ones. */
  steps: number;
  warmupSteps: number;
  /** maxgrid's warm-up on twins of each scene before its first round (see warmUp); C is compiled ahead. */
  warmUpMs: number;
  dt: number;
}

export function cMaxgridDefaults(profile: Profile): CMaxgridOptions {
  return profile === 'full'
    ? { scene: 'uniform', ns: [1000, 4000, 16000, 64000, 256000], rounds: 10, steps: 60, warmupSteps: 20, warmUpMs: warmUpMs('full'), dt: 1 / 60 }
    : { scene: 'uniform', ns: [4000, 64000], rounds: 3, steps: 10, warmupSteps: 20, warmUpMs: warmUpMs('quick'), dt: 1 / 60 };
}

export interface CComparison {
  scene: string;
  n: number;
  engine: string;
  /** ok: hashes equal in every round; hash-mismatch: no timing reported. */
  status: 'ok' | 'hash-mismatch';
  cMs: Spread | null;
  jsMs: Spread | null;
  /** JS median / C median. */
  ratio: number | null;
  cHash: string;
  jsHash: string;
  rounds: number;
  stepsPerRound: number;
}

export interface CMaxgridResult {
  meta: Meta;
  /** The compile command and compiler, or why the C side was skipped. */
  compiler: { status: 'ok'; command: string; version: string } | { status: 'skipped'; reason: string };
  rows: CComparison[];
}

/** Resolves the C baseline through the host, or a skip reason (the browser has no host). */
export async function cBaselineOf(ctx: RunContext): Promise<CBaseline | string> {
  if (!ctx.host) return 'no C compiler here (the C baseline runs from Node)';
  return ctx.host.cBaseline();
}

/** C and JS on one scene, `rounds` times each, interleaved; see the file comment. */
export async function compareWithC(
  c: CBaseline,
  engine: Engine,
  scene: Scene,
  o: { rounds: number; steps: number; warmupSteps: number; dt: number; warmUpMs?: number },
  ctx: RunContext,
): Promise<CComparison> {
  warmUp(() => engine.create(scene), o.warmupSteps + o.steps, o.dt, o.warmUpMs ?? 0);
  const cTimes: number[] = [];
  const jsTimes: number[] = [];
  let cHash = '';
  let jsHash = '';
  let same = true;
  const runJs = async () => {
    const sim = engine.create(scene);
    try {
      for (let i = 0; i < o.warmupSteps; i++) sim.step(o.dt);
      for (let i = 0; i < o.steps; i++) {
        const t0 = now();
        sim.step(o.dt);
        jsTimes.push(now() - t0);
      }
      jsHash = sim.stateHash!();
    } finally {
      sim.dispose();
    }
  };
  const runC = async () => {
    const run = await c.run(scene, o.steps, o.warmupSteps, o.dt);
    cTimes.push(...run.stepMs);
    cHash = run.hash;
  };
  for (let round = 0; round < o.rounds; round++) {
    for (const side of round % 2 === 0 ? [runC, runJs] : [runJs, runC]) await side();
    same &&= cHash === jsHash;
    await ctx.yieldToHost?.();
  }
  const ok = same;
  const cMs = ok ? spread(cTimes) : null;
  const jsMs = ok ? spread(jsTimes) : null;
  return {
    scene: scene.name,
    n: scene.count,
    engine: engine.info.id,
    status: ok ? 'ok' : 'hash-mismatch',
    cMs,
    jsMs,
    ratio: cMs && jsMs ? jsMs.median / cMs.median : null,
    cHash,
    jsHash,
    rounds: o.rounds,
    stepsPerRound: o.steps,
  };
}

export async function runCMaxgrid(options: CMaxgridOptions, ctx: RunContext): Promise<CMaxgridResult> {
  const [engine] = maxgridOnly(ctx.engines, 'c-maxgrid').filter((e) => e.info.id === 'maxgrid:maxgrid');
  if (!engine) throw new RangeError(`c-maxgrid compares the C program with maxgrid:maxgrid; got engines ${ctx.engines.map((e) => e.info.id).join(', ')}`);
  const meta = makeMeta('c-maxgrid', { ...ctx, engines: [engine] }, options);
  const c = await cBaselineOf(ctx);
  if (typeof c === 'string') return { meta, compiler: { status: 'skipped', reason: c }, rows: [] };
  const rows: CComparison[] = [];
  for (const [i, n] of options.ns.entries()) {
    ctx.progress?.(i, options.ns.length, `${options.scene} N=${n} C vs JS`);
    rows.push(await compareWithC(c, engine, buildScene(options.scene, { n, seed: 1 }), options, ctx));
  }
  ctx.progress?.(options.ns.length, options.ns.length, 'done');
  return { meta, compiler: { status: 'ok', command: c.command, version: c.compiler }, rows };
}

export function cMaxgridCsv(result: CMaxgridResult): string {
  const lines = [csvLine(['scene', 'n', 'status', 'c_median_ms', 'c_p25_ms', 'c_p75_ms', 'js_median_ms', 'js_p25_ms', 'js_p75_ms', 'js_over_c', 'c_hash', 'js_hash'])];
  for (const r of result.rows) {
    lines.push(csvLine([r.scene, r.n, r.status, r.cMs?.median ?? '', r.cMs?.p25 ?? '', r.cMs?.p75 ?? '', r.jsMs?.median ?? '', r.jsMs?.p25 ?? '', r.jsMs?.p75 ?? '', r.ratio ?? '', r.cHash, r.jsHash]));
  }
  if (result.compiler.status === 'skipped') lines.push(csvLine(['skipped', '', result.compiler.reason, '', '', '', '', '', '', '', '', '']));
  return lines.join('\n') + '\n';
}

export function cMaxgridCharts(result: CMaxgridResult): ChartSpec[] {
  const ok = result.rows.filter((r) => r.status === 'ok');
  if (ok.length === 0) return [];
  return [
    lineChart({
      id: 'c-maxgrid',
      title: `maxgrid (TypeScript) vs the same algorithm in C, scene ${String(result.meta.options.scene)}`,
      xName: 'N (circles)',
      yName: 'median ms per step',
      xLog: true,
      yLog: true,
      series: [
        { name: 'C (gcc -O3 -march=native)', points: ok.map((r) => [r.n, r.cMs!.median]) },
        { name: 'maxgrid:maxgrid (Node)', points: ok.map((r) => [r.n, r.jsMs!.median]) },
      ],
    }),
  ];
}

const nullableSpread = { anyOf: [spreadSchema, { type: 'null' }] };

export const cComparisonSchema = {
  type: 'object',
  required: ['scene', 'n', 'engine', 'status', 'cMs', 'jsMs', 'ratio', 'cHash', 'jsHash', 'rounds', 'stepsPerRound'],
  properties: {
    scene: { type: 'string' },
    n: { type: 'integer', minimum: 1 },
    engine: { const: 'maxgrid:maxgrid' },
    status: { enum: ['ok', 'hash-mismatch'] },
    cMs: nullableSpread,
    jsMs: nullableSpread,
    ratio: { type: ['number', 'null'], exclusiveMinimum: 0 },
    cHash: { type: 'string', pattern: '^[0-9a-f]{16}$' },
    jsHash: { type: 'string', pattern: '^[0-9a-f]{16}$' },
    rounds: { type: 'integer', minimum: 1 },
    stepsPerRound: { type: 'integer', minimum: 1 },
  },
  additionalProperties: false,
} as const;

export const cMaxgridSchema = {
  $id: 'c-maxgrid',
  type: 'object',
  required: ['meta', 'compiler', 'rows'],
  properties: {
    meta: metaSchema,
    compiler: {
      oneOf: [
        { type: 'object', required: ['status', 'command', 'version'], properties: { status: { const: 'ok' }, command: { type: 'string' }, version: { type: 'string' } } },
        { type: 'object', required: ['status', 'reason'], properties: { status: { const: 'skipped' }, reason: { type: 'string', minLength: 1 } } },
      ],
    },
    rows: { type: 'array', items: cComparisonSchema },
  },
  additionalProperties: false,
} as const;
