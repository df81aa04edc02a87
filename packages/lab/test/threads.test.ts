import { describe, expect, it } from 'vitest';
import { Ajv } from 'ajv';
import type { RunContext } from '../src/experiments/common.js';
import { threads } from '../src/experiments/registry.js';
import { runThreads, threadCountsFor, threadsCsv, threadsHeadline, threadsTables } from '../src/experiments/threads.js';
import { loadEnginesNode } from '../src/node/engines.js';

describe('threads experiment', () => {
  it('offers powers of two up to the core count, and the core count', () => {
    expect(threadCountsFor(1)).toEqual([1]);
    expect(threadCountsFor(2)).toEqual([1, 2]);
    expect(threadCountsFor(3)).toEqual([1, 2, 3]);
    expect(threadCountsFor(12)).toEqual([1, 2, 4, 8, 12]);
    expect(threadCountsFor(16)).toEqual([1, 2, 4, 8, 16]);
  });

  it('steps one world per thread count to the same state hash, and its JSON validates', async () => {
    const ctx: RunContext = { engines: await loadEnginesNode(['maxgrid:maxgrid']), environment: { runtime: 'vitest', cores: 3 }, profile: 'custom' };
    const options = { ...threads.options('quick', { ns: [3000], runs: 3 }), warmupSteps: 2 };
    const result = await runThreads(options, ctx);
    expect(result.rows.map((x) => x.threads)).toEqual([1, 2, 3]);
    expect(result.rows.every((x) => x.sameHashAsOneThread)).toBe(true);
    expect(result.rows[0].speedup).toBe(1);
    const validate = new Ajv({ strict: false }).compile(threads.schema);
    expect(validate(JSON.parse(JSON.stringify(result))), JSON.stringify(validate.errors)).toBe(true);
    expect(threadsCsv(result).trim().split('\n')).toHaveLength(4);
    expect(threadsTables(result)[0].rows.map((r) => r[4])).toEqual(['yes', 'yes', 'yes']);
    expect(threadsHeadline(result)[0]).toMatch(/state hashes equal for every count/);
  });

  it('needs one thread first, as the reference', async () => {
    const ctx: RunContext = { engines: [], environment: { runtime: 'vitest' } };
    await expect(runThreads({ ...threads.options('quick', { ns: [100] }), threadCounts: [2, 4] }, ctx)).rejects.toThrow(/first thread count must be 1.*2,4/);
  });
});

describe('threads-load experiment', () => {
  it('starts its busy processes, steps the three worlds to the same bits, stops them again', async () => {
    const { nodeHost } = await import('../src/node/host.js');
    const { threadsLoad } = await import('../src/experiments/registry.js');
    const { runThreadsLoad, threadsLoadTables, threadsLoadHeadline } = await import('../src/experiments/threads-load.js');
    const host = nodeHost();
    let started = 0;
    const counting = { ...host, busyProcesses: async (count: number) => {
      started += count;
      return host.busyProcesses!(count);
    } };
    const ctx: RunContext = { engines: await loadEnginesNode(['maxgrid:maxgrid']), environment: { runtime: 'vitest', cores: 2 }, profile: 'custom', host: counting };
    const options = { ...threadsLoad.options('quick', { ns: [3000], runs: 12 }), loads: [0, 1], warmupSteps: 2 };
    const result = await runThreadsLoad(options, ctx);
    expect(started).toBe(2);
    expect(result.rows.map((r) => `${r.busy} ${r.world}`)).toEqual(['0 one thread', '0 governed', '0 always threads', '2 one thread', '2 governed', '2 always threads']);
    expect(result.rows.every((r) => r.sameHashAsOneThread)).toBe(true);
    for (const r of result.rows) {
      if (r.world === 'one thread') expect(r.threadedShare).toBe(0);
      if (r.world === 'always threads') expect(r.threadedShare).toBe(1);
    }
    const validate = new Ajv({ strict: false }).compile(threadsLoad.schema);
    expect(validate(JSON.parse(JSON.stringify(result))), JSON.stringify(validate.errors)).toBe(true);
    expect(threadsLoadTables(result)[0].rows).toHaveLength(6);
    expect(threadsLoadHeadline(result)[0]).toMatch(/State hashes equal/);
  }, 60_000);

  it('says it was skipped where it cannot start processes', async () => {
    const { runThreadsLoad } = await import('../src/experiments/threads-load.js');
    const { threadsLoad } = await import('../src/experiments/registry.js');
    const result = await runThreadsLoad(threadsLoad.options('quick', {}), { engines: [], environment: { runtime: 'vitest' } });
    expect(result.rows).toEqual([]);
    expect(result.skipped).toMatch(/Node only/);
  });
});
