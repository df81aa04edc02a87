import { beforeAll, describe, expect, it } from 'vitest';
import { execFileSync } from 'node:child_process';
import { Ajv } from 'ajv';
import { buildScene } from '@maxgrid/scenes';
import type { Engine } from '../src/engines/adapter.js';
import type { RunContext } from '../src/experiments/common.js';
import { compareWithC } from '../src/experiments/c-maxgrid.js';
import { cMaxgrid } from '../src/experiments/registry.js';
import { loadEnginesNode } from '../src/node/engines.js';
import { nodeHost } from '../src/node/host.js';
import { cBaseline, cSceneBytes } from '../src/node/native.js';

// CI has gcc; a machine without one skips the C runs, and says so in the test names.
const compiler = process.env.CC ?? 'gcc';
const hasCompiler = (() => {
  try {
    execFileSync(compiler, ['--version'], { stdio: 'ignore' });
    return compiler !== 'none';
  } catch {
    return false;
  }
})();
const needsC = hasCompiler ? '' : ` [SKIPPED: no C compiler '${compiler}']`;
if (!hasCompiler) console.warn(`native.test: no C compiler '${compiler}'; the C baseline tests are skipped`);

let engine: Engine;
beforeAll(async () => {
  [engine] = await loadEnginesNode(['maxgrid:maxgrid']);
});

const ctx = (host = nodeHost()): RunContext => ({ engines: [engine], environment: { runtime: 'vitest' }, profile: 'custom', host });

describe('C baseline (native/maxgrid.c)', () => {
  it.skipIf(!hasCompiler)(`reaches the same state hash as world.stateHash() on small uniform, seed-box and mixed scenes${needsC}`, async () => {
    const c = await cBaseline();
    if (typeof c === 'string') throw new Error(c);
    for (const [name, n] of [['uniform', 300], ['seed-box', 200], ['mixed', 400]] as const) {
      const row = await compareWithC(c, engine, buildScene(name, { n, seed: 3 }), { rounds: 2, steps: 4, warmupSteps: 3, dt: 1 / 60 }, ctx());
      expect(row.cHash, name).toBe(row.jsHash);
      expect(row.status).toBe('ok');
      expect(row.ratio).toBeGreaterThan(0);
    }
  });

  it.skipIf(!hasCompiler)(`c-maxgrid quick run: JSON validates against its schema${needsC}`, async () => {
    const options = { ...cMaxgrid.options('quick', {}), ns: [200, 500], rounds: 2, steps: 3, warmupSteps: 1, warmUpMs: 5 };
    const result = await cMaxgrid.run(options, ctx());
    const validate = new Ajv({ strict: false }).compile(cMaxgrid.schema);
    expect(validate(JSON.parse(JSON.stringify(result))), JSON.stringify(validate.errors)).toBe(true);
    expect(result.compiler.status).toBe('ok');
    expect(result.rows.map((r) => r.status)).toEqual(['ok', 'ok']);
    expect(cMaxgrid.csv(result).split('\n')[0]).toMatch(/^scene,n,status,c_median_ms/);
  });

  it('records "skipped" with the reason when there is no C compiler, and its JSON still validates', async () => {
    const host = { cBaseline: async () => 'no C compiler (test)', browser: async () => 'no browser (test)', sandbox: async () => 'no browser (test)' };
    const result = await cMaxgrid.run({ ...cMaxgrid.options('quick', {}), ns: [100] }, ctx(host));
    expect(result.compiler).toEqual({ status: 'skipped', reason: 'no C compiler (test)' });
    expect(result.rows).toEqual([]);
    expect(new Ajv({ strict: false }).compile(cMaxgrid.schema)(JSON.parse(JSON.stringify(result)))).toBe(true);
    expect(cMaxgrid.csv(result)).toContain('no C compiler (test)');
  });

  it('refuses scenes the C program does not implement, naming what it lacks', () => {
    expect(() => cSceneBytes(buildScene('funnel', {}))).toThrow(/c-maxgrid cannot run this scene: scene 'funnel' has \d+ (static circles|segments)/);
    expect(() => cMaxgrid.options('quick', { scenes: ['funnel'] })).toThrow(/--scene for experiment 'c-maxgrid' takes one of uniform, seed-box, mixed/);
  });
});
