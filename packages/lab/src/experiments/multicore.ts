import { buildScene, buildWorld } from '@maxgrid/scenes';
import { hostScalingSchema, spread, spreadSchema, now, type HostScaling, type RunContext, type Spread } from './common.js';

/**
 * T4: the same world stepped on one thread and on `threads` threads (world.startWorkers), both
 * built from one seeded scene, steps alternating between the two so that machine noise hits both
 * alike; medians per step, their ratio, and the state hashes after equal step counts (the
 * parallel step must give the same bits). Where the host can, its own 2-thread scaling is
 * probed just before and just after (compute-bound and memory-bound kernels, Host.hostScaling):
 * on a shared machine the memory figure moves with other tenants, and so does T4.
 */
export interface MultiCoreOptions {
  n: number;
  threads: number;
  dt: number;
  steps: number;
  warmupSteps: number;
}

export interface MultiCoreResult {
  status: 'ok' | 'skipped';
  reason?: string;
  n?: number;
  threads?: number;
  steps?: number;
  serialMs?: Spread;
  parallelMs?: Spread;
  speedup?: number;
  parallelStepsPerSecond?: number;
  hashesMatch?: boolean;
  hostScalingBefore?: HostScaling;
  hostScalingAfter?: HostScaling;
}

export async function multiCore(o: MultiCoreOptions, ctx: RunContext): Promise<MultiCoreResult> {
  const isNode = typeof (globalThis as { process?: { versions?: { node?: string } } }).process?.versions?.node === 'string';
  if (!isNode) return { status: 'skipped', reason: 'measured from Node (worker_threads); the lab page is not cross-origin isolated' };
  ctx.progress?.(0, 1, 'T4 probing the host: 2-thread scaling of compute and memory');
  const hostScalingBefore = await ctx.host?.hostScaling?.();
  ctx.progress?.(0, 1, `T4 building two worlds of N=${o.n}`);
  const scene = buildScene('uniform', { n: o.n, seed: 1 });
  const serial = buildWorld(scene, { broadphase: 'maxgrid' });
  const parallel = buildWorld(scene, { broadphase: 'maxgrid' });
  // minBodies 0: the lab's small test sizes measure the parallel path too.
  await parallel.startWorkers(o.threads, { minBodies: 0, adaptive: false });
  const serialTimes: number[] = [];
  const parallelTimes: number[] = [];
  let hashesMatch: boolean;
  try {
    for (let s = 0; s < o.warmupSteps; s++) {
      serial.step(o.dt);
      parallel.step(o.dt);
    }
    for (let s = 0; s < o.steps; s++) {
      ctx.progress?.(s, o.steps, `T4 N=${o.n} step ${s + 1}, 1 vs ${o.threads} threads`);
      const t0 = now();
      serial.step(o.dt);
      const t1 = now();
      parallel.step(o.dt);
      const t2 = now();
      serialTimes.push(t1 - t0);
      parallelTimes.push(t2 - t1);
      await ctx.yieldToHost?.();
    }
    hashesMatch = serial.stateHash() === parallel.stateHash();
  } finally {
    // Stopped before the second probe too: idle workers poll for their next command.
    parallel.stopWorkers();
  }
  ctx.progress?.(o.steps, o.steps, 'T4 probing the host again');
  const hostScalingAfter = await ctx.host?.hostScaling?.();
  const serialMs = spread(serialTimes);
  const parallelMs = spread(parallelTimes);
  return {
    status: 'ok',
    n: o.n,
    threads: o.threads,
    steps: o.steps,
    serialMs,
    parallelMs,
    speedup: serialMs.median / parallelMs.median,
    parallelStepsPerSecond: 1000 / parallelMs.median,
    hashesMatch,
    ...(hostScalingBefore && hostScalingAfter ? { hostScalingBefore, hostScalingAfter } : {}),
  };
}

export const multiCoreSchema = {
  type: 'object',
  required: ['status'],
  properties: {
    status: { enum: ['ok', 'skipped'] },
    reason: { type: 'string' },
    n: { type: 'integer', minimum: 1 },
    threads: { type: 'integer', minimum: 1 },
    steps: { type: 'integer', minimum: 1 },
    serialMs: spreadSchema,
    parallelMs: spreadSchema,
    speedup: { type: 'number', exclusiveMinimum: 0 },
    parallelStepsPerSecond: { type: 'number', exclusiveMinimum: 0 },
    hashesMatch: { type: 'boolean' },
    hostScalingBefore: hostScalingSchema,
    hostScalingAfter: hostScalingSchema,
  },
  additionalProperties: false,
} as const;
