import { beforeAll, describe, expect, it } from 'vitest';
import { Ajv } from 'ajv';
import type { Engine } from '../src/engines/adapter.js';
import { ENGINE_IDS } from '../src/engines/registry.js';
import type { RunContext } from '../src/experiments/common.js';
import { spread, warmUp } from '../src/experiments/common.js';
import { EXPERIMENTS, cliffs, energy, falsePositives, piles, sapSleep, scale, stepTime, targets } from '../src/experiments/registry.js';
import { cliffsVerdicts } from '../src/experiments/cliffs.js';
import { CLIFF_SCENES } from '@maxgrid/scenes';
import { cBaseline } from '../src/node/native.js';
import { measureHostScaling } from '../src/node/host-scaling.js';
import { renderSvg } from '../src/report/render.js';
import { htmlReport, tablesFor } from '../src/report/html.js';
import { markdownTable } from '../src/report/tables.js';
import { loadEnginesNode } from '../src/node/engines.js';

let engines: Engine[] = [];
const ajv = new Ajv({ allErrors: true, strict: false });

beforeAll(async () => {
  engines = await loadEnginesNode(ENGINE_IDS);
});

function ctx(ids: string[] = ENGINE_IDS): RunContext {
  return { engines: engines.filter((e) => ids.includes(e.info.id)), environment: { runtime: 'vitest' }, profile: 'custom' };
}

/** Validates through a JSON round trip, so NaN (written as null) fails as it would on disk. */
function expectValid(schema: object, result: unknown): void {
  const validate = ajv.compile(schema);
  const ok = validate(JSON.parse(JSON.stringify(result)));
  expect(validate.errors ?? [], JSON.stringify(validate.errors)).toEqual([]);
  expect(ok).toBe(true);
}

function expectPublishable(name: string, result: unknown): void {
  const experiment = EXPERIMENTS[name];
  const csv = experiment.csv(result).trim().split('\n');
  expect(csv.length).toBeGreaterThan(1);
  const columns = csv[0].split(',').length;
  // Quoted fields may hold commas (RFC 4180); count fields outside the quotes.
  for (const line of csv) expect(line.replace(/"(?:[^"]|"")*"/g, 'q').split(',').length).toBe(columns);
  for (const chart of experiment.charts(result)) expect(renderSvg(chart)).toMatch(/^<svg[\s\S]*<\/svg>$/);
  const tables = tablesFor(name, result);
  for (const t of tables) for (const row of t.rows) expect(row).toHaveLength(t.headers.length);
  expect(tables.length).toBeGreaterThan(0);
  for (const t of tables) expect(markdownTable(t)).toContain('| ---');
}

describe('step-time', () => {
  it('measures every engine at every N of both scenes, and its JSON validates', async () => {
    const options = { ...stepTime.options('quick', {}), ns: [40, 80], runs: 2, seconds: 3 / 60, warmupSteps: 1, warmUpMs: 5 };
    const result = await stepTime.run(options, ctx());
    expectValid(stepTime.schema, result);
    expect(result.rows).toHaveLength(2 * 2 * ENGINE_IDS.length);
    for (const row of result.rows) {
      expect(row.runMs).toHaveLength(2);
      expect(row.ms.p25).toBeLessThanOrEqual(row.ms.median);
      expect(row.ms.median).toBeLessThanOrEqual(row.ms.p75);
      expect(row.stepsPerRun).toBe(3);
    }
    expect(new Set(result.rows.map((r) => r.engine))).toEqual(new Set(ENGINE_IDS));
    expect(result.meta.engines.map((e) => e.id)).toEqual(ENGINE_IDS);
    expectPublishable('step-time', result);
  });

  it('drops an engine at larger N once its median passes the cutoff', async () => {
    const options = { ...stepTime.options('quick', {}), scenes: ['uniform'], ns: [30, 60], runs: 1, seconds: 1 / 60, warmupSteps: 0, warmUpMs: 0, cutoffMs: 0 };
    const result = await stepTime.run(options, ctx(['maxgrid:naive']));
    expect(result.rows.map((r) => r.n)).toEqual([30]);
    expect(result.skipped).toEqual([{ scene: 'uniform', engine: 'maxgrid:naive', fromN: 60 }]);
  });

  it("rejects scenes that cannot be swept over N and options it doesn't take", () => {
    expect(() => stepTime.options('quick', { scenes: ['bouncing-ball'] })).toThrow(/bouncing-ball.*sweep/);
    expect(() => stepTime.options('quick', { scenes: ['nowhere'] })).toThrow(/unknown scene 'nowhere'/);
    expect(() => energy.options('quick', { runs: 3 })).toThrow(/--runs does not apply to experiment 'energy'/);
    expect(() => scale.options('quick', { scenes: ['uniform'] })).toThrow(/--scene does not apply/);
  });

  it("expresses the report's full protocol: N from 10 to 4200 by 10, 10 s, 10 runs", () => {
    const full = stepTime.options('full', {});
    expect(full.ns).toHaveLength(420);
    expect([full.ns[0], full.ns[419], full.runs, full.seconds]).toEqual([10, 4200, 10, 10]);
  });
});

describe('energy', () => {
  it('traces every engine; maxgrid broad-phases give identical series; JSON validates', async () => {
    const options = { ...energy.options('quick', {}), ballSeconds: 3, n: 60, seconds: 1, samples: 12 };
    const result = await energy.run(options, ctx());
    expectValid(energy.schema, result);
    expect(result.ball.map((s) => s.engine)).toEqual(ENGINE_IDS);
    for (const s of [...result.ball, ...result.uniform]) {
      expect(s.ratio[0]).toBe(1);
      expect(s.t.length).toBe(s.ratio.length);
    }
    const maxgrid = result.uniform.filter((s) => s.engine.startsWith('maxgrid:'));
    for (const s of maxgrid) expect(s.ratio).toEqual(maxgrid[0].ratio);
    // m g h with h the centre's height above the floor: drop height 700 plus radius 20.
    expect(result.ballInitialEnergy).toBeCloseTo(Math.PI * 20 * 20 * 500 * 720, 6);
    expectPublishable('energy', result);
  });
});

describe('false-positives', () => {
  it('counts pairs examined, candidates and contacts per broad-phase over N, mixed and log-uniform spreads; JSON validates', async () => {
    const options = { ...falsePositives.options('quick', {}), ns: [100, 300], ratios: [1, 10], spreadN: 200, steps: 3, warmupSteps: 2 };
    const result = await falsePositives.run(options, ctx());
    expectValid(falsePositives.schema, result);
    const maxgridIds = ENGINE_IDS.filter((id) => id.startsWith('maxgrid:'));
    expect(result.rows).toHaveLength(6 * maxgridIds.length);
    expect(new Set(result.rows.map((r) => `${r.sweep} ${r.scene}`))).toEqual(new Set(['n uniform', 'mixed mixed', 'log uniform']));
    for (const row of result.rows) {
      expect(row.pairTests).toBeGreaterThanOrEqual(row.candidatePairs);
      expect(row.candidatePairs).toBeGreaterThanOrEqual(row.contacts);
      if (row.engine === 'maxgrid:naive') expect(row.pairTests).toBe((row.n * (row.n - 1)) / 2);
      const same = result.rows.filter((r) => r.sweep === row.sweep && r.n === row.n && r.ratio === row.ratio);
      // Bit-identical worlds find the same contacts whatever the broad-phase.
      for (const other of same) expect(other.contacts).toBe(row.contacts);
    }
    expect(result.rows.filter((r) => r.sweep === 'n').every((r) => r.ratio === 2)).toBe(true);
    expectPublishable('false-positives', result);
  });

  it('refuses engines other than maxgrid', async () => {
    const options = { ...falsePositives.options('quick', {}), ns: [10], ratios: [1], spreadN: 10, steps: 1, warmupSteps: 0 };
    await expect(falsePositives.run(options, ctx(['rapier']))).rejects.toThrow(/maxgrid broad-phases only; got engines rapier/);
  });
});

describe('scale', () => {
  it('reports ns per body and bytes per body; JSON validates', async () => {
    const options = { ...scale.options('quick', {}), ns: [200, 2000], ages: [0, 0.5], steps: 2, warmupSteps: 1 };
    const result = await scale.run(options, ctx(['maxgrid:maxgrid']));
    expectValid(scale.schema, result);
    expect(result.rows.map((r) => `${r.n} ${r.order} ${r.ageSeconds}`)).toEqual(
      ['200 rows 0', '200 rows 0.5', '200 shuffled 0', '200 shuffled 0.5', '2000 rows 0', '2000 rows 0.5', '2000 shuffled 0', '2000 shuffled 0.5'],
    );
    // The same circles in another order: the same memory, and the headline compares the two.
    expect(result.rows[6].memoryBytes).toBe(result.rows[4].memoryBytes);
    expect(scale.headline(result).slice(-2)).toEqual([
      expect.stringMatching(/^At N = 2,000, shuffled \/ row by row = [\d.]+× per step\.$/),
      expect.stringMatching(/^At N = 2,000, after 0\.5 s of motion \/ fresh: row by row [\d.]+×, shuffled [\d.]+× per step\.$/),
    ]);
    expect((scale.charts(result)[0].option.series as { name: string }[]).map((x) => x.name)).toEqual(
      ['maxgrid:maxgrid', 'maxgrid:maxgrid, after 0.5 s', 'maxgrid:maxgrid, shuffled', 'maxgrid:maxgrid, shuffled, after 0.5 s'],
    );
    for (const r of result.rows) {
      expect(r.bytesPerBody).toBeCloseTo(r.memoryBytes / r.n, 9);
      expect(r.nsPerBody).toBeCloseTo((r.ms.median * 1e6) / r.n, 6);
    }
    expectPublishable('scale', result);
  });
});

describe('sap-sleep', () => {
  it('times sap and sap-persistent on moving, pile and field cases with their sleeping fractions; JSON validates', async () => {
    const options = { ...sapSleep.options('quick', {}), n: 300, rounds: 2, steps: 2, warmupSteps: 2, settleSteps: 60 };
    const result = await sapSleep.run(options, ctx(['maxgrid:sap', 'maxgrid:sap-persistent']));
    expectValid(sapSleep.schema, result);
    expect(result.rows.map((r) => `${r.case} ${r.engine}`)).toEqual(
      ['moving', 'pile', 'field'].flatMap((c) => [`${c} maxgrid:sap`, `${c} maxgrid:sap-persistent`]),
    );
    for (const c of ['moving', 'pile', 'field']) {
      const [a, b] = result.rows.filter((r) => r.case === c);
      // Same world, same steps: broad-phases differ only in speed, never in what sleeps or touches.
      expect([b.asleepStart, b.asleepEnd, b.contacts]).toEqual([a.asleepStart, a.asleepEnd, a.contacts]);
    }
    expect(result.rows.find((r) => r.case === 'moving')!.asleepStart).toBe(0);
    expect(result.rows.find((r) => r.case === 'field')!.asleepStart).toBeGreaterThan(0.5);
    expectPublishable('sap-sleep', result);
  });
});

describe('cliffs', () => {
  it('steps every cliff scene with every broad-phase, the same contacts on each, and names the fastest', async () => {
    const options = { ...cliffs.options('quick', {}), scale: 0.05, steps: 2, minSteps: 1 };
    const ids = engines.map((e) => e.info.id).filter((id) => id.startsWith('maxgrid:'));
    const result = await cliffs.run(options, ctx(ids));
    expectValid(cliffs.schema, result);
    expect(result.defaultBroadphase).toBe('maxgrid:auto');
    expect(result.rows).toHaveLength(options.scenes.length * ids.length);
    for (const scene of options.scenes) {
      const rows = result.rows.filter((r) => r.scene === scene);
      expect(rows.map((r) => r.engine).sort()).toEqual([...ids].sort());
      // Same world, same steps: broad-phases differ in work, never in what touches.
      for (const r of rows) expect(r.contactsPerBody).toBe(rows[0].contactsPerBody);
      const naive = rows.find((r) => r.engine === 'maxgrid:naive')!;
      for (const r of rows) expect(naive.pairTestsPerBody).toBeGreaterThanOrEqual(r.pairTestsPerBody);
      // Without static circles, naive examines every pair (statics meet moving bodies through the static tree).
      if (CLIFF_SCENES[scene].build({ n: 10 }).fixed === null) expect(naive.pairTestsPerBody).toBeCloseTo((naive.bodies - 1) / 2, 6);
    }
    for (const v of cliffsVerdicts(result)) {
      const rows = result.rows.filter((r) => r.scene === v.scene);
      const fastest = Math.min(...rows.map((r) => r.ms.median));
      expect(v.best.ms.median).toBe(fastest);
      expect(v.ratio).toBe(rows.find((r) => r.engine === 'maxgrid:auto')!.ms.median / fastest);
    }
    expectPublishable('cliffs', result);
    expect(cliffs.headline(result)[0]).toMatch(/within .*× of its fastest/);
  }, 120_000);
});

describe('piles', () => {
  it('measures a settled pile per engine: the iterated solve holds it up where one pass lets it sink', async () => {
    const options = { ...piles.options('quick', {}), n: 1000, settleSeconds: 6, measureSteps: 10 };
    const result = await piles.run(options, ctx(['maxgrid:maxgrid', 'maxgrid-piles', 'box2d-wasm']));
    expectValid(piles.schema, result);
    const [single, iterated, box2d] = result.rows;
    expect(result.rows.map((r) => r.engine)).toEqual(['maxgrid:maxgrid', 'maxgrid-piles', 'box2d-wasm']);
    // One box of scene data: the same circles, so the same area, in every engine.
    expect(iterated.areaHeight).toBeCloseTo(single.areaHeight, 9);
    expect(box2d.areaHeight).toBeCloseTo(single.areaHeight, 6);
    // Circles that do not overlap cannot pile lower than their area spread over the floor.
    expect(single.pileHeight).toBeLessThan(single.areaHeight);
    expect(iterated.pileHeight).toBeGreaterThan(iterated.areaHeight);
    expect(iterated.meanOverlap).toBeLessThan(single.meanOverlap / 2);
    expect(iterated.motion).toBeLessThan(single.motion / 10);
    expect([single.escaped, iterated.escaped]).toEqual([0, 0]);
    expectPublishable('piles', result);
  });
});

describe('targets', () => {
  it('measures T1, T2, T3, T4, T5 on small sizes, records T6 skipped with its reason; JSON validates', async () => {
    const options = { ...targets.options('quick', {}), n: 1500, bigN: 4000, rounds: 1, stepsPerRound: 1, warmupSteps: 1, bigSteps: 1, bigWarmupSteps: 0, parallelSteps: 3 };
    // The browser is left out here (Chromium start-up is slow); the lab's e2e test drives the page hook T6 uses.
    // A small host-scaling probe: the figures only need to exist and be plausible here.
    const probe = { iterations: 2_000_000, doubles: 1 << 20, passes: 1, rounds: 1 };
    const host = {
      cBaseline,
      browser: async () => 'no browser in this test',
      sandbox: async () => 'no browser in this test',
      hostScaling: () => measureHostScaling(probe),
    };
    const result = await targets.run(options, { ...ctx(targets.defaultEngines), host });
    expectValid(targets.schema, result);
    expect(result.t1.timings.map((t) => t.engine)).toEqual(targets.defaultEngines);
    expect(result.t6).toEqual({ status: 'skipped', reason: 'no browser in this test' });
    expect(['ok', 'skipped']).toContain(result.t2.status);
    expect(result.t3.bytesPerBody).toBeGreaterThan(0);
    // T3's small world is timed alongside the big one, about as long: round(4000 / 1500) steps after each big step.
    expect(result.t3).toMatchObject({ n: 4000, steps: 1, smallN: 1500, smallSteps: 3 });
    expect(result.t3.ratio).toBeCloseTo(result.t3.nsPerBody / result.t3.nsPerBodyAt64k, 12);
    expect(Object.keys(result.t5.mixedOverUniform)).toEqual(['maxgrid:maxgrid', 'maxgrid:hgrid', 'maxgrid:auto']);
    // T4 steps a world on 1 thread and on 2: the bits must agree.
    expect(result.t4).toMatchObject({ status: 'ok', n: 4000, threads: 2, steps: 3, hashesMatch: true });
    // The host probe ran before and after: ratios of timings, so only their presence is checked
    // here (a busy machine can push a tiny probe's ratio anywhere; the lab reports, not asserts).
    for (const scaling of [result.t4.hostScalingBefore!, result.t4.hostScalingAfter!]) {
      for (const ratio of [scaling.compute, scaling.memory]) {
        expect(Number.isFinite(ratio)).toBe(true);
        expect(ratio).toBeGreaterThan(0);
      }
    }
    expect(result.notMeasured.map((x) => x.target.split(' ')[0])).toEqual(['T7']);
    expectPublishable('targets', result);
  });
});

describe('schemas and reports', () => {
  it('a schema rejects a result with a missing field or a non-number', async () => {
    const options = { ...scale.options('quick', {}), ns: [50], steps: 1, warmupSteps: 0 };
    const result = await scale.run(options, ctx(['maxgrid:maxgrid']));
    const validate = ajv.compile(scale.schema);
    const broken = JSON.parse(JSON.stringify(result));
    broken.rows[0].nsPerBody = null;
    expect(validate(broken)).toBe(false);
    delete broken.meta.engines[0].version;
    expect(validate(broken)).toBe(false);
  });

  it('the HTML report is self-contained and carries its data', async () => {
    const options = { ...scale.options('quick', {}), ns: [50], steps: 1, warmupSteps: 0 };
    const result = await scale.run(options, ctx(['maxgrid:maxgrid']));
    const html = htmlReport({
      title: 't',
      command: 'npm run lab -- scale',
      environment: { runtime: 'vitest' },
      engines: result.meta.engines,
      sections: [{ experiment: 'scale', tables: tablesFor('scale', result), svgs: scale.charts(result).map(renderSvg) }],
      results: { scale: result },
    });
    expect(html).not.toMatch(/<(script|link|img)[^>]+(src|href)=/);
    const data = /<script type="application\/json" id="lab-data">([\s\S]*?)<\/script>/.exec(html)![1];
    expect(JSON.parse(data).scale.rows[0].n).toBe(50);
  });

  it('spread gives quantiles of the values', () => {
    expect(spread([4, 1, 3, 2])).toEqual({ median: 2.5, p25: 1.75, p75: 3.25, min: 1, max: 4, mean: 2.5 });
  });
});

describe('warmUp', () => {
  /** A simulation whose step takes `stepMs` of wall time, recording what happened to it. */
  function twins(stepMs: number) {
    const made: { steps: number; disposed: boolean }[] = [];
    const create = () => {
      const twin = { steps: 0, disposed: false };
      made.push(twin);
      return {
        step: () => {
          const t0 = performance.now();
          while (performance.now() - t0 < stepMs);
          twin.steps++;
        },
        dispose: () => {
          twin.disposed = true;
        },
      };
    };
    return { made, create };
  }

  it('steps fresh twins through the timed steps, one after another, until its budget runs out, and disposes each', () => {
    const { made, create } = twins(0.05);
    const t0 = performance.now();
    const taken = warmUp(create, 7, 1 / 60, 60);
    expect(performance.now() - t0).toBeGreaterThanOrEqual(60);
    expect(made.length).toBeGreaterThan(1);
    expect(made.every((t) => t.disposed)).toBe(true);
    // Each twin runs the whole protocol from the start; only the last may be cut short by the budget.
    expect(made.slice(0, -1).every((t) => t.steps === 7)).toBe(true);
    expect(made[made.length - 1].steps).toBeLessThanOrEqual(7);
    expect(taken).toBe(made.reduce((sum, t) => sum + t.steps, 0));
  });

  it('does nothing without a budget or without steps', () => {
    for (const [steps, budget] of [[7, 0], [0, 50], [7, NaN]]) {
      const { made, create } = twins(0);
      expect(warmUp(create, steps, 1 / 60, budget)).toBe(0);
      expect(made).toHaveLength(0);
    }
  });
});
