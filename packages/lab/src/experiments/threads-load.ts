import { buildScene, buildWorld } from '@maxgrid/scenes';
import { fmt, ratioText, type Table } from '../report/tables.js';
import { csvLine, makeMeta, metaSchema, now, spread, spreadSchema, type Meta, type Profile, type RunContext, type Spread } from './common.js';

/**
 * Issue 22, item 6: the parallel step on a machine whose cores are busy with other work. For each
 * load (a number of spinning processes the experiment starts itself), three worlds from one
 * seeded `uniform` scene are stepped in turn, step by step, so that the load hits each alike: one
 * thread, `threads` threads as `startWorkers` gives them (the thread governor on), and the same
 * with the governor off (the threads every step). Medians and means per step, each against one
 * thread; under load, steps swing between quick and preempted, so read both.
 */
export interface ThreadsLoadOptions {
  n: number;
  threads: number;
  /** Busy processes per run, as multiples of the machine's cores (0: idle). */
  loads: number[];
  steps: number;
  warmupSteps: number;
  dt: number;
}

export function threadsLoadDefaults(profile: Profile): ThreadsLoadOptions {
  return profile === 'full'
    ? { n: 40_000, threads: 2, loads: [0, 2, 4], steps: 300, warmupSteps: 30, dt: 1 / 60 }
    : { n: 40_000, threads: 2, loads: [0, 2, 4], steps: 120, warmupSteps: 20, dt: 1 / 60 };
}

export type ThreadsLoadWorld = 'one thread' | 'governed' | 'always threads';
const WORLDS: ThreadsLoadWorld[] = ['one thread', 'governed', 'always threads'];

export interface ThreadsLoadRow {
  /** Busy processes running during the measurement. */
  busy: number;
  world: ThreadsLoadWorld;
  ms: Spread;
  /** Median and mean over the one-thread world's, in the same run. */
  medianRatio: number;
  meanRatio: number;
  /** Share of the timed steps that ran on the threads. */
  threadedShare: number;
  sameHashAsOneThread: boolean;
}

export interface ThreadsLoadResult {
  meta: Meta;
  rows: ThreadsLoadRow[];
  /** Why no load could be started (no Node host), or null. */
  skipped: string | null;
}

export async function runThreadsLoad(o: ThreadsLoadOptions, ctx: RunContext): Promise<ThreadsLoadResult> {
  const meta = makeMeta('threads-load', ctx, o);
  const cores = Number(ctx.environment.cores) || 1;
  const start = ctx.host?.busyProcesses;
  if (!start) return { meta, rows: [], skipped: 'no way to start background processes here (Node only)' };
  const scene = buildScene('uniform', { n: o.n, seed: 1 });
  const rows: ThreadsLoadRow[] = [];
  for (const [run, load] of o.loads.entries()) {
    const busy = Math.round(load * cores);
    const worlds = WORLDS.map(() => buildWorld(scene, { broadphase: 'maxgrid' }));
    const stop = busy > 0 ? await start.call(ctx.host, busy) : () => {};
    try {
      await worlds[1].startWorkers(o.threads, { minBodies: 0 });
      await worlds[2].startWorkers(o.threads, { minBodies: 0, adaptive: false });
      for (let s = 0; s < o.warmupSteps; s++) for (const w of worlds) w.step(o.dt);
      const times = worlds.map((): number[] => []);
      const threaded = worlds.map(() => 0);
      for (let s = 0; s < o.steps; s++) {
        if (s % 10 === 0) ctx.progress?.(run * o.steps + s, o.loads.length * o.steps, `${busy} busy processes, step ${s + 1}`);
        for (let k = 0; k < worlds.length; k++) {
          const i = (s + k) % worlds.length;
          const t0 = now();
          worlds[i].step(o.dt);
          times[i].push(now() - t0);
          if (worlds[i].stats.threads > 1) threaded[i]++;
        }
        await ctx.yieldToHost?.();
      }
      const reference = worlds[0].stateHash();
      const one = spread(times[0]);
      WORLDS.forEach((world, i) => {
        const ms = spread(times[i]);
        rows.push({ busy, world, ms, medianRatio: ms.median / one.median, meanRatio: ms.mean / one.mean, threadedShare: threaded[i] / o.steps, sameHashAsOneThread: worlds[i].stateHash() === reference });
      });
    } finally {
      stop();
      for (const w of worlds) w.stopWorkers();
    }
  }
  ctx.progress?.(1, 1, 'done');
  return { meta, rows, skipped: null };
}

export function threadsLoadTables(r: ThreadsLoadResult): Table[] {
  if (r.skipped) return [{ title: 'Threads under load', headers: ['skipped'], rows: [[r.skipped]] }];
  const o = r.meta.options as unknown as ThreadsLoadOptions;
  return [
    {
      title: `The parallel step under load: uniform N = ${o.n.toLocaleString('en-US')}, ${o.threads} threads against one, background processes spinning`,
      headers: ['busy processes', 'world', 'median ms [p25–p75]', 'mean ms', 'median / one thread', 'mean / one thread', 'steps on threads', 'same bits as one thread'],
      rows: r.rows.map((x) => [String(x.busy), x.world, `${fmt(x.ms.median)} [${fmt(x.ms.p25)}–${fmt(x.ms.p75)}]`, fmt(x.ms.mean), ratioText(x.medianRatio), ratioText(x.meanRatio), `${Math.round(100 * x.threadedShare)}%`, x.sameHashAsOneThread ? 'yes' : 'NO']),
      note: `Three worlds per load, stepped in turn (${o.steps} timed steps each after ${o.warmupSteps}): one thread; \`startWorkers(${o.threads})\` as given (the thread governor on); \`startWorkers(${o.threads}, { adaptive: false })\`. Busy processes: ${o.loads.join(', ')} × the machine's cores.`,
    },
  ];
}

export function threadsLoadHeadline(r: ThreadsLoadResult): string[] {
  if (r.skipped) return [`Skipped: ${r.skipped}.`, ''];
  const loads = [...new Set(r.rows.map((x) => x.busy))];
  const line = loads
    .map((busy) => {
      const governed = r.rows.find((x) => x.busy === busy && x.world === 'governed')!;
      const always = r.rows.find((x) => x.busy === busy && x.world === 'always threads')!;
      return `${busy} busy: governed ${ratioText(governed.medianRatio)} (mean ${ratioText(governed.meanRatio)}), always threads ${ratioText(always.medianRatio)} (mean ${ratioText(always.meanRatio)})`;
    })
    .join('; ');
  const same = r.rows.every((x) => x.sameHashAsOneThread);
  return [`Parallel step against one thread, by median: ${line}. State hashes ${same ? 'equal' : 'DIFFER'}.`, ''];
}

export function threadsLoadCsv(r: ThreadsLoadResult): string {
  const lines = [csvLine(['busy', 'world', 'median_ms', 'p25_ms', 'p75_ms', 'mean_ms', 'median_ratio', 'mean_ratio', 'threaded_share', 'same_hash'])];
  for (const x of r.rows) lines.push(csvLine([x.busy, x.world, x.ms.median, x.ms.p25, x.ms.p75, x.ms.mean, x.medianRatio, x.meanRatio, x.threadedShare, String(x.sameHashAsOneThread)]));
  return lines.join('\n') + '\n';
}

export const threadsLoadSchema = {
  $id: 'threads-load',
  type: 'object',
  required: ['meta', 'rows', 'skipped'],
  properties: {
    meta: metaSchema,
    skipped: { type: ['string', 'null'] },
    rows: {
      type: 'array',
      items: {
        type: 'object',
        required: ['busy', 'world', 'ms', 'medianRatio', 'meanRatio', 'threadedShare', 'sameHashAsOneThread'],
        properties: {
          busy: { type: 'integer', minimum: 0 },
          world: { enum: WORLDS },
          ms: spreadSchema,
          medianRatio: { type: 'number', exclusiveMinimum: 0 },
          meanRatio: { type: 'number', exclusiveMinimum: 0 },
          threadedShare: { type: 'number', minimum: 0, maximum: 1 },
          sameHashAsOneThread: { type: 'boolean' },
        },
        additionalProperties: false,
      },
    },
  },
  additionalProperties: false,
} as const;
