import { beforeAll, describe, expect, it } from 'vitest';
import { Ajv } from 'ajv';
import { buildShapeScene } from '@maxgrid/scenes';
import { allocatePoses, UnsupportedSceneError, type ShapeEngine } from '../src/shape-engines/adapter.js';
import { loadShapeEnginesNode } from '../src/node/engines.js';
import { joints, jointSanity, type JointsOptions } from '../src/experiments/joints.js';
import { EXPERIMENTS } from '../src/experiments/registry.js';
import { tablesFor } from '../src/report/html.js';
import { markdownTable } from '../src/report/tables.js';
import { hookedEngine, withClock } from './step-hooks.js';

const IDS = ['maxgrid:maxgrid', 'box2d-wasm', 'planck', 'rapier', 'matter-js', 'p2-es'];
let engines: ShapeEngine[] = [];

beforeAll(async () => {
  engines = await loadShapeEnginesNode(IDS);
});

/** Small enough for every engine in a test; long enough (about 0.8 s) for a joint that was left out to show. */
const TINY: JointsOptions = {
  ...joints.options('quick', {}),
  cases: [
    { scene: 'chain', params: { links: 10, horizontal: 1 } },
    { scene: 'joint-grid', params: { size: 10 } },
    { scene: 'bridge', params: { planks: 6, load: 2 } },
    { scene: 'ragdolls', params: { count: 2, columns: 2 } },
  ],
  warmupSteps: 5,
  warmUpMs: 5,
  steps: 45,
  minSteps: 45,
  budgetMs: 60_000,
};

/** Which engines build which scene: Rapier cannot cap a joint motor and Matter has no limits or motors, so neither builds the bridge (joint friction) or the ragdolls. */
const EXPECTED: Record<string, string[]> = {
  chain: IDS,
  'joint-grid': IDS,
  bridge: ['maxgrid:maxgrid', 'box2d-wasm', 'planck', 'p2-es'],
  ragdolls: ['maxgrid:maxgrid', 'box2d-wasm', 'planck', 'p2-es'],
};

describe('joints', () => {
  it('steps every joint scene with every engine that has its joints, each within its physical bounds, and says why the others were not built', async () => {
    const result = await joints.run(TINY, { engines: [], shapeEngines: engines, environment: { runtime: 'vitest' }, profile: 'custom' });
    const validate = new Ajv({ allErrors: true, strict: false }).compile(joints.schema);
    expect(validate(JSON.parse(JSON.stringify(result))), JSON.stringify(validate.errors)).toBe(true);
    for (const [scene, ids] of Object.entries(EXPECTED)) {
      const rows = result.rows.filter((r) => r.scene === scene);
      expect(rows.map((r) => r.engine), scene).toEqual(ids);
      for (const r of rows) {
        expect(r.steps, `${scene} ${r.engine}`).toBe(TINY.steps);
        expect(r.sanity.ok, `${scene} ${r.engine}: ${r.sanity.label} ${r.sanity.value}, pin gap ${r.sanity.pinGap}`).toBe(true);
      }
      const skipped = result.skipped.filter((s) => s.scene === scene).map((s) => s.engine);
      expect([...ids, ...skipped].sort(), scene).toEqual([...IDS].sort());
    }
    // The chain stays a chain: its tip within a few per cent of its length from the pivot, every pin within a quarter link.
    for (const r of result.rows.filter((x) => x.scene === 'chain')) {
      expect(r.sanity.value, r.engine).toBeGreaterThan(0.9);
      expect(r.sanity.value, r.engine).toBeLessThan(1.05);
      expect(r.sanity.pinGap, r.engine).toBeLessThan(0.25);
    }
    for (const s of result.skipped) expect(s.reason, `${s.scene} ${s.engine}`).toMatch(/motor|limit/);
    expect(EXPERIMENTS.joints).toBe(joints);
    const csv = joints.csv(result).trim().split('\n');
    expect(csv).toHaveLength(result.rows.length + 1);
    for (const t of tablesFor('joints', result)) {
      for (const row of t.rows) expect(row).toHaveLength(t.headers.length);
      expect(markdownTable(t)).toContain('| ---');
    }
    expect(joints.headline(result).join(' ')).toContain('Every engine that ran kept its joints within the plausible range');
  });

  it('the sanity figures tell a scene whose joints were left out: each engine on the chain and the joint grid without them is implausible', () => {
    for (const [name, params] of [['chain', { links: 10, horizontal: 1 }], ['joint-grid', { size: 10 }]] as const) {
      const scene = buildShapeScene(name, params);
      const loose = { ...scene, joints: [] };
      for (const engine of engines) {
        const sim = engine.create(loose, 'defaults');
        try {
          for (let s = 0; s < 50; s++) sim.step(1 / 60);
          const p = allocatePoses(sim.count);
          sim.read(p);
          // Judged against the scene with its joints, as the experiment judges every engine.
          expect(jointSanity(scene, p, 50 / 60).ok, `${engine.info.id} ${name}`).toBe(false);
        } finally {
          sim.dispose();
        }
      }
    }
  });

  it("the blobs' figure tells rings without their gas: they fold below the plausible area, and hold it with the gas", () => {
    const scene = buildShapeScene('blobs', { count: 2 });
    const maxgrid = engines.find((e) => e.info.id === 'maxgrid:maxgrid')!;
    const figure = (given: typeof scene) => {
      const sim = maxgrid.create(given, 'defaults');
      try {
        for (let s = 0; s < 180; s++) sim.step(1 / 60);
        const p = allocatePoses(sim.count);
        sim.read(p);
        return jointSanity(scene, p, 3);
      } finally {
        sim.dispose();
      }
    };
    const held = figure(scene);
    expect(held.ok, JSON.stringify(held)).toBe(true);
    const empty = figure({ ...scene, joints: scene.joints!.filter((j) => j.kind !== 'pressure') });
    expect(empty.ok).toBe(false);
    expect(empty.value).toBeLessThan(0.6);
  });

  it('an adapter refuses a joint it cannot build rather than leaving it out', () => {
    const byId = (id: string) => engines.find((e) => e.info.id === id)!;
    const refusals: [string, string, Record<string, number>, RegExp][] = [
      ['rapier', 'bridge', { planks: 3, load: 0 }, /motor/],
      ['matter-js', 'ragdolls', { count: 1 }, /limits/],
      ['planck', 'car', { bumps: 1 }, /wheel joint's translation limits/],
      ['rapier', 'car', { bumps: 1 }, /wheel/],
      ['p2-es', 'jellies', { count: 1, side: 2 }, /distance/],
    ];
    for (const [id, name, params, reason] of refusals) {
      const create = () => byId(id).create(buildShapeScene(name as 'chain', params), 'defaults');
      expect(create, `${id} ${name}`).toThrow(UnsupportedSceneError);
      expect(create, `${id} ${name}`).toThrow(reason);
    }
  });
});

describe('joints: timing', () => {
  const CHAIN: JointsOptions = { ...TINY, cases: [{ scene: 'chain', params: { links: 4, horizontal: 1 } }], warmupSteps: 1, warmUpMs: 0, baseline: 'a' };
  const ctx = (shapeEngines: ShapeEngine[]) => ({ engines: [], shapeEngines, environment: { runtime: 'vitest' }, profile: 'custom' as const });
  /** maxgrid's simulation under another id, with a hook on each step. */
  const wrapped = (id: string, onStep: () => void): ShapeEngine => hookedEngine(engines.find((e) => e.info.id === 'maxgrid:maxgrid')!, id, onStep);

  it('steps all engines side by side in turns of turnSteps steps, the order rotated each turn', async () => {
    const log: string[] = [];
    const logging = (id: string) => wrapped(id, () => log.push(id));
    await joints.run({ ...CHAIN, steps: 4, minSteps: 4, turnSteps: 3 }, ctx([logging('a'), logging('b'), logging('c')]));
    // The warm-up step, then turns of three steps, the first of each untimed: 2 timed, then the last 2.
    expect(log.join(' ')).toBe('a b c' + ' a a a b b b c c c' + ' b b b c c c a a a');
  });

  it("times the steps after the first of each turn, which finds the caches holding another engine's data, and reads the figures after every step taken", async () => {
    const clock = { t: 0 };
    const last = { id: '' };
    // A step that costs 5 ms at the start of a turn (after the other engine's) and 1 ms after one of its own.
    const cold = (id: string) =>
      wrapped(id, () => {
        clock.t += last.id === id ? 1 : 5;
        last.id = id;
      });
    const result = await withClock(clock, () => joints.run({ ...CHAIN, warmupSteps: 0, steps: 18, minSteps: 18, turnSteps: 10 }, ctx([cold('a'), cold('b')])));
    for (const r of result.rows) {
      expect(r.steps, r.engine).toBe(18);
      expect(r.ms.median, r.engine).toBe(1);
      expect(r.ms.p75, r.engine).toBe(1);
      // Two turns of 10 steps each.
      expect(r.seconds, r.engine).toBeCloseTo(20 / 60, 12);
    }
    expect(joints.tables(result)[0].note).toContain('in turns of 10 steps each, the order rotated each turn, the first step of each turn');
  });

  it('stops timing an engine once its steps, untimed ones included, have spent its budget, and no sooner than minSteps', async () => {
    const clock = { t: 0 };
    const result = await withClock(clock, () =>
      joints.run(
        { ...CHAIN, warmupSteps: 0, steps: 18, minSteps: 2, budgetMs: 250, turnSteps: 10 },
        ctx([wrapped('a', () => (clock.t += 1)), wrapped('slow', () => (clock.t += 100))]),
      ),
    );
    const row = (id: string) => result.rows.find((r) => r.engine === id)!;
    expect(row('a').steps).toBe(18);
    // Untimed 100, timed 200, timed 300: two timed steps (the minimum), then the budget is spent.
    expect(row('slow').steps).toBe(2);
    expect(row('slow').seconds).toBeCloseTo(3 / 60, 12);
    expect(joints.tables(result)[0].rows[0]).toContain('100 (100×), 2 steps');
  });
});
