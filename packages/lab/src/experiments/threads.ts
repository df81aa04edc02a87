import { buildScene, buildWorld } from '@maxgrid/scenes';
import type { Table } from '../report/tables.js';
import { fmt, ratioText } from '../report/tables.js';
import { csvLine, makeMeta, metaSchema, now, spread, spreadSchema, type Meta, type Profile, type RunContext, type Spread } from './common.js';

/**
 * The parallel step across thread counts: one `uniform` world per count, all built from one seeded
 * scene and stepped in turn (so machine noise hits every count alike), medians per step, speed-up
 * against one thread, and each world's state hash against the one-thread world's (the parallel
 * step must give the same bits for any count). T4 measures 2 threads on the project's 2-core
 * machine; this is for machines with more cores, and the moonshot of 1,000,000 circles at 60
 * steps per second.
 */
export interface ThreadsOptions {
  n: number;
  /** null: powers of two up to the machine's cores, and the core count (threadCountsFor). */
  threadCounts: number[] | null;
  dt: number;
  steps: number;
  warmupSteps: number;
}

/** Powers of two up to `cores`, and `cores` itself. */
export function threadCountsFor(cores: number): number[] {
  const counts: number[] = [];
  for (let t = 1; t < cores; t *= 2) counts.push(t);
  counts.push(Math.max(1, cores));
  return counts;
}

export function threadsDefaults(profile: Profile): ThreadsOptions {
  return profile === 'full'
    ? { n: 1_000_000, threadCounts: null, dt: 1 / 60, steps: 60, warmupSteps: 10 }
    : { n: 1_000_000, threadCounts: null, dt: 1 / 60, steps: 20, warmupSteps: 10 };
}

export interface ThreadsRow {
  threads: number;
  ms: Spread;
  speedup: number;
  stepsPerSecond: number;
  sameHashAsOneThread: boolean;
}

export interface ThreadsResult {
  meta: Meta;
  n: number;
  rows: ThreadsRow[];
}

export async function runThreads(o: ThreadsOptions, ctx: RunContext): Promise<ThreadsResult> {
  const meta = makeMeta('threads', ctx, o);
  const counts = o.threadCounts ?? threadCountsFor(Number(ctx.environment.cores) || 1);
  if (counts[0] !== 1) throw new RangeError(`threads: the first thread count must be 1 (the reference), got ${counts.join(',')}`);
  ctx.progress?.(0, o.steps, `building ${counts.length} worlds of N=${o.n}`);
  const scene = buildScene('uniform', { n: o.n, seed: 1 });
  const worlds = counts.map(() => buildWorld(scene, { broadphase: 'maxgrid' }));
  try {
    // minBodies 0: small test sizes measure the parallel path too; adaptive off: the threads themselves are measured (threads-load measures the governor).
    for (const [i, threads] of counts.entries()) if (threads > 1) await worlds[i].startWorkers(threads, { minBodies: 0, adaptive: false });
    for (let s = 0; s < o.warmupSteps; s++) for (const w of worlds) w.step(o.dt);
    const times = worlds.map((): number[] => []);
    for (let s = 0; s < o.steps; s++) {
      ctx.progress?.(s, o.steps, `N=${o.n} step ${s + 1}, ${counts.join('/')} threads`);
      // Each step starts with a different world, so none always follows the same one.
      for (let k = 0; k < worlds.length; k++) {
        const i = (s + k) % worlds.length;
        const t0 = now();
        worlds[i].step(o.dt);
        times[i].push(now() - t0);
      }
      await ctx.yieldToHost?.();
    }
    const reference = worlds[0].stateHash();
    const oneThread = spread(times[0]).median;
    const rows = counts.map((threads, i) => {
      const ms = spread(times[i]);
      return { threads, ms, speedup: oneThread / ms.median, stepsPerSecond: 1000 / ms.median, sameHashAsOneThread: worlds[i].stateHash() === reference };
    });
    return { meta, n: o.n, rows };
  } finally {
    for (const w of worlds) w.stopWorkers();
  }
}

export function threadsCsv(r: ThreadsResult): string {
  return ['threads,n,median_ms,p25_ms,p75_ms,speedup,steps_per_second,same_hash', ...r.rows.map((x) => csvLine([x.threads, r.n, x.ms.median, x.ms.p25, x.ms.p75, x.speedup, x.stepsPerSecond, String(x.sameHashAsOneThread)]))].join('\n') + '\n';
}

export function threadsTables(r: ThreadsResult): Table[] {
  const o = r.meta.options as unknown as ThreadsOptions;
  return [
    {
      title: `Parallel step across thread counts: uniform N = ${r.n.toLocaleString('en-US')} (same bits for every count; moonshot: 1,000,000 at ≥ 60 steps/s)`,
      headers: ['threads', 'median ms [p25–p75]', 'speed-up vs 1', 'steps / s', 'same state hash as 1 thread'],
      rows: r.rows.map((x) => [String(x.threads), `${fmt(x.ms.median)} [${fmt(x.ms.p25)}–${fmt(x.ms.p75)}]`, ratioText(x.speedup), fmt(x.stepsPerSecond), x.sameHashAsOneThread ? 'yes' : 'NO']),
      note: `One world per thread count from one seeded scene, ${o.steps} timed steps each after ${o.warmupSteps} untimed ones, stepped in turn; \`world.startWorkers(threads)\` (worker_threads).`,
    },
  ];
}

export function threadsHeadline(r: ThreadsResult): string[] {
  const best = r.rows.reduce((a, b) => (b.stepsPerSecond > a.stepsPerSecond ? b : a));
  const same = r.rows.every((x) => x.sameHashAsOneThread);
  return [
    `N = ${r.n.toLocaleString('en-US')}: ${r.rows.map((x) => `${x.threads} thread(s) ${fmt(x.ms.median)} ms`).join(', ')}; fastest ${best.threads} threads at ${fmt(best.stepsPerSecond)} steps/s (${ratioText(best.speedup)} one thread); state hashes ${same ? 'equal for every count' : 'DIFFER'}.`,
    '',
  ];
}

export const threadsSchema = {
  type: 'object',
  required: ['meta', 'n', 'rows'],
  properties: {
    meta: metaSchema,
    n: { type: 'integer', minimum: 1 },
    rows: {
      type: 'array',
      minItems: 1,
      items: {
        type: 'object',
        required: ['threads', 'ms', 'speedup', 'stepsPerSecond', 'sameHashAsOneThread'],
        properties: {
          threads: { type: 'integer', minimum: 1 },
          ms: spreadSchema,
          speedup: { type: 'number', exclusiveMinimum: 0 },
          stepsPerSecond: { type: 'number', exclusiveMinimum: 0 },
          sameHashAsOneThread: { type: 'boolean' },
        },
        additionalProperties: false,
      },
    },
  },
  additionalProperties: false,
} as const;
