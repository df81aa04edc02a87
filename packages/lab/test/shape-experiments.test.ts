import { beforeAll, describe, expect, it } from 'vitest';
import { Ajv } from 'ajv';
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { buildShapeScene } from '@maxgrid/scenes';
import { sceneScale, type RunContext } from '../src/experiments/common.js';
import { EXPERIMENTS, shapeEnergy, shapeFalsePositives, shapeStepTime, stability } from '../src/experiments/registry.js';
import { allocatePoses, type ShapeEngine } from '../src/shape-engines/adapter.js';
import { rampJudge } from '../src/experiments/stability.js';
import { crossing, sceneBroken } from '../src/experiments/shape-step-time.js';
import { BOX2D_WASM_CORE } from '../src/engines/versions.js';
import { SHAPE_ENGINE_IDS } from '../src/shape-engines/registry.js';
import { loadShapeEnginesNode } from '../src/node/engines.js';
import { tablesFor } from '../src/report/html.js';
import { markdownTable } from '../src/report/tables.js';
import { hookedEngine, withClock } from './step-hooks.js';

let engines: ShapeEngine[] = [];
const ajv = new Ajv({ allErrors: true, strict: false });

beforeAll(async () => {
  engines = await loadShapeEnginesNode(SHAPE_ENGINE_IDS);
});

function ctx(ids: string[]): RunContext {
  return { engines: [], shapeEngines: engines.filter((e) => ids.includes(e.info.id)), environment: { runtime: 'vitest' }, profile: 'custom' };
}

/** Validates through a JSON round trip, as the file on disk is read. */
function expectValid(schema: object, result: unknown): void {
  const validate = ajv.compile(schema);
  validate(JSON.parse(JSON.stringify(result)));
  expect(validate.errors ?? [], JSON.stringify(validate.errors)).toEqual([]);
}

function expectTables(name: string, result: unknown): void {
  const tables = tablesFor(name, result);
  expect(tables.length).toBeGreaterThan(0);
  for (const t of tables) {
    for (const row of t.rows) expect(row).toHaveLength(t.headers.length);
    expect(markdownTable(t)).toContain('| ---');
  }
  expect(EXPERIMENTS[name].csv(result).trim().split('\n').length).toBeGreaterThan(1);
}

const PEERS = ['maxgrid:maxgrid', 'box2d-wasm', 'planck', 'rapier', 'matter-js', 'p2-es'];

describe('shape experiments write what their schemas accept', () => {
  it('shape-step-time', async () => {
    const options = {
      ...shapeStepTime.options('quick', {}),
      fixed: [{ scene: 'pyramid', params: { base: 4 } }],
      sweeps: [{ scene: 'uniform-polygons', ns: [40], profile: 'report' as const }],
      runs: 1,
      steps: 2,
      warmupSteps: 1,
      warmUpMs: 0,
    };
    const result = await shapeStepTime.run(options, ctx(PEERS));
    expectValid(shapeStepTime.schema, result);
    expectTables('shape-step-time', result);
  });

  it('stability', async () => {
    const result = await stability.run({ ...stability.options('quick', {}), pyramidBase: 4, seconds: 0.1, rampSeconds: 0.1, profiles: ['defaults'] }, ctx(PEERS));
    expectValid(stability.schema, result);
    expectTables('stability', result);
  });

  it('shape-energy', async () => {
    const result = await shapeEnergy.run({ ...shapeEnergy.options('quick', {}), n: 40, seconds: 0.2, samples: 4 }, ctx(PEERS));
    expectValid(shapeEnergy.schema, result);
    expectTables('shape-energy', result);
  });

  it('shape-false-positives', async () => {
    const result = await shapeFalsePositives.run({ ...shapeFalsePositives.options('quick', {}), scenes: [{ scene: 'polygon-box', n: 60 }], steps: 2, warmupSteps: 1 }, ctx(['maxgrid:maxgrid', 'maxgrid:hgrid']));
    expectValid(shapeFalsePositives.schema, result);
    expectTables('shape-false-positives', result);
  });
});

describe('stability: the ramp judge', () => {
  const angle = 20;
  const scene = buildShapeScene('ramp', { angle, friction: 0.5 });
  const theta = (angle * Math.PI) / 180;
  const posesOf = (dx: number, dy: number, turn: number) => {
    const p = allocatePoses(2);
    scene.bodies.forEach((b, k) => {
      p.x[k] = b.x;
      p.y[k] = b.y;
      p.angle[k] = b.angle ?? 0;
    });
    p.x[1] += dx;
    p.y[1] += dy;
    p.angle[1] += turn;
    return p;
  };
  const start = posesOf(0, 0, 0);

  it('does not count settling across the slope as sliding: a box pushed 1.5 cm out of the ramp sticks', () => {
    // Out of the ramp: against its normal, which points into the ramp at (-sin, cos) with y down.
    const out = posesOf(0.015 * Math.sin(theta), -0.015 * Math.cos(theta), 0);
    const verdict = rampJudge(angle, 0.5)(start, out, scene, 2);
    expect(Math.abs(verdict.value)).toBeLessThan(1e-12);
    expect(verdict.pass).toBe(true);
  });

  it("follows the box, not the body's origin 18 m away: a body turned a milliradian about the box's centre has not slid", () => {
    // The body turns about the box's centre: its origin swings 1.8 cm, the box stays.
    const box = scene.bodies[1].shapes[0];
    const c0 = { x: Math.cos(theta) * box.offsetX! - Math.sin(theta) * box.offsetY!, y: Math.sin(theta) * box.offsetX! + Math.cos(theta) * box.offsetY! };
    const turned = theta + 0.001;
    const c1 = { x: Math.cos(turned) * box.offsetX! - Math.sin(turned) * box.offsetY!, y: Math.sin(turned) * box.offsetX! + Math.cos(turned) * box.offsetY! };
    const verdict = rampJudge(angle, 0.5)(start, posesOf(c0.x - c1.x, c0.y - c1.y, 0.001), scene, 2);
    expect(Math.abs(verdict.value)).toBeLessThan(1e-9);
    expect(verdict.pass).toBe(true);
  });

  it('measures a slide down the slope at its length, and passes it within 2 % of theory', () => {
    const slides = rampJudge(30, 0.3);
    const a = 10 * (Math.sin(Math.PI / 6) - 0.3 * Math.cos(Math.PI / 6));
    const d = 0.5 * a * 4;
    const ramp30 = buildShapeScene('ramp', { angle: 30, friction: 0.3 });
    const p0 = allocatePoses(2);
    const p1 = allocatePoses(2);
    p0.angle[1] = p1.angle[1] = Math.PI / 6;
    p1.x[1] = d * Math.cos(Math.PI / 6);
    p1.y[1] = d * Math.sin(Math.PI / 6);
    const verdict = slides(p0, p1, ramp30, 2);
    expect(verdict.value).toBeCloseTo(d, 12);
    expect(verdict.pass).toBe(true);
  });
});

describe('stability: checks outside an engine range', () => {
  it("marks the card house and the 5 cm stack as outside Box2D 2.4's range for box2d-wasm and planck, and leaves them out of the headline's count", async () => {
    const result = await stability.run({ ...stability.options('quick', {}), pyramidBase: 4, seconds: 0.1, rampSeconds: 0.1, profiles: ['defaults'] }, ctx(['box2d-wasm', 'planck', 'rapier']));
    const outside = result.rows.filter((r) => r.outsideRange).map((r) => `${r.check} ${r.engine}`);
    expect(outside.sort()).toEqual(['card house box2d-wasm', 'card house planck', 'vertical stack (15), 5 cm boxes box2d-wasm', 'vertical stack (15), 5 cm boxes planck']);
    for (const r of result.rows.filter((x) => x.outsideRange)) expect(r.outsideRange).toMatch(/outside Box2D 2\.4's documented range/);
    const [table] = stability.tables(result);
    const card = table.rows.find((row) => row[0] === 'card house')!;
    expect(card[table.headers.indexOf('Box2D 2.4.1 (WASM)')]).toMatch(/\(outside its range\)$/);
    expect(card[table.headers.indexOf('rapier')]).toMatch(/\((pass|FAIL)\)$/);
    expect(table.note).toMatch(/card house with Box2D 2\.4\.1 \(WASM\) and planck/);
    const headline = stability.headline(result).join(' ');
    expect(headline).toMatch(/Box2D 2\.4\.1 \(WASM\) \d\/5 \(2 outside its documented range\)/);
    expect(headline).toMatch(/rapier \d\/7[,;.]/);
  });
});

describe('engine labels', () => {
  it("name box2d-wasm by the Box2D it compiles, 2.4.1, in every table, headline and chart of the shape experiments, so that it is not read as Box2D v3", async () => {
    const readme = readFileSync(createRequire(import.meta.url).resolve('box2d-wasm/README.md'), 'utf8');
    expect(readme).toContain(`Compatibility: Box2D [v${BOX2D_WASM_CORE}]`);
    const ids = ['maxgrid:maxgrid', 'box2d-wasm'];
    const results: [string, unknown][] = [
      ['shape-step-time', await shapeStepTime.run({ ...shapeStepTime.options('quick', {}), fixed: [{ scene: 'pyramid', params: { base: 4 } }], sweeps: [{ scene: 'uniform-polygons', ns: [40], profile: 'report' }], runs: 1, steps: 2, warmupSteps: 1, warmUpMs: 0 }, ctx(ids))],
      ['stability', await stability.run({ ...stability.options('quick', {}), pyramidBase: 4, seconds: 0.05, rampSeconds: 0.05, profiles: ['defaults'] }, ctx(ids))],
      ['shape-energy', await shapeEnergy.run({ ...shapeEnergy.options('quick', {}), n: 40, seconds: 0.1, samples: 2 }, ctx(ids))],
    ];
    for (const [name, result] of results) {
      const experiment = EXPERIMENTS[name];
      const text = [...experiment.headline(result), ...tablesFor(name, result).flatMap((t) => [...t.headers, ...t.rows.flat(), t.note ?? '']), ...experiment.charts(result).map((c) => JSON.stringify(c))].join('\n');
      expect(text, name).toContain('Box2D 2.4.1 (WASM)');
      expect(text, name).not.toMatch(/box2d-wasm/);
    }
  });
});

describe('shape-step-time: broken simulations', () => {
  it('sceneBroken: bodies that end over a metre outside the scene (through a floor) are named, bodies that settle are not', () => {
    const scene = buildShapeScene('many-pyramids', { rows: 1, columns: 2, base: 3 });
    const p = allocatePoses(scene.bodies.length);
    scene.bodies.forEach((b, k) => {
      p.x[k] = b.x;
      p.y[k] = b.y + 0.05;
    });
    expect(sceneBroken(scene, p)).toBeNull();
    p.y[3] += 5;
    p.x[5] = NaN;
    expect(sceneBroken(scene, p)).toBe('2 of 12 bodies ended over 1 m outside the scene (through a floor or a wall)');
  });

  it("marks a peer whose pyramids fall through their floors invalid, and gives it no ratio, crossing or chart point", async () => {
    const real = engines.find((e) => e.info.id === 'box2d-wasm')!;
    // A peer that builds no floors or walls: its bodies fall freely, as p2-es's pyramids did through floors it could not collide with.
    const floorless: ShapeEngine = { info: { ...real.info, id: 'floorless' }, create: (scene, profile) => real.create({ ...scene, segments: [], bounds: null }, profile) };
    const result = await shapeStepTime.run(
      {
        ...shapeStepTime.options('quick', {}),
        fixed: [{ scene: 'many-pyramids', params: { rows: 1, columns: 2, base: 3 } }],
        sweeps: [{ scene: 'polygon-box', ns: [250], profile: 'defaults' }],
        runs: 1,
        steps: 30,
        warmupSteps: 30,
        warmUpMs: 0,
        baseline: 'box2d-wasm',
      },
      { ...ctx(['box2d-wasm']), shapeEngines: [real, floorless] },
    );
    expectValid(shapeStepTime.schema, result);
    const row = (id: string) => result.rows.find((r) => r.engine === id)!;
    for (const r of result.rows) {
      if (r.engine === 'box2d-wasm') expect(r.invalid, r.scene).toBeNull();
      else expect(r.invalid, r.scene).toMatch(/^run 1: \d+ of \d+ bodies ended over 1 m outside the scene/);
    }
    const [times, answer] = shapeStepTime.tables(result);
    for (let i = 0; i < 2; i++) {
      expect(times.rows[i][times.headers.indexOf('floorless')]).toMatch(/ \(invalid\)$/);
      expect(answer.rows[i][answer.headers.indexOf('floorless')]).toBe('invalid');
    }
    expect(times.note).toMatch(/"invalid": the engine's simulation of the scene was broken/);
    // Stepping nothing, the floorless peer is faster than Box2D: without the check it would overtake it.
    expect(crossing(result, 'polygon-box', 'floorless')).toBeNull();
    for (const chart of shapeStepTime.charts(result)) {
      const series = (chart.option as { series: { name: string; data: unknown[] }[] }).series.find((x) => x.name === 'floorless');
      expect(series?.data ?? [], chart.id).toEqual([]);
    }
    expect(shapeStepTime.headline(result).join(' ')).toMatch(/invalid, a broken simulation: floorless/);
  });
});

describe('shape-step-time: timing', () => {
  it('steps all engines side by side in turns of turnSteps steps, the order rotated each turn', async () => {
    const log: string[] = [];
    const real = engines.find((e) => e.info.id === 'maxgrid:maxgrid')!;
    const logging = (id: string): ShapeEngine => hookedEngine(real, id, () => log.push(id));
    await shapeStepTime.run(
      { ...shapeStepTime.options('quick', {}), fixed: [{ scene: 'pyramid', params: { base: 3 } }], sweeps: [], runs: 1, steps: 5, turnSteps: 2, warmupSteps: 1, warmUpMs: 0, baseline: 'a' },
      { ...ctx([]), shapeEngines: [logging('a'), logging('b'), logging('c')] },
    );
    // The warm-up step, then turns of two steps (the last of one), the order rotated each turn.
    expect(log.join(' ')).toBe('a b c' + ' a a b b c c' + ' b b c c a a' + ' c a b');
  });

  it('times the steps after the first of each turn, which finds the caches holding another engine\'s data', async () => {
    const real = engines.find((e) => e.info.id === 'maxgrid:maxgrid')!;
    const clock = { t: 0 };
    const last = { id: '' };
    let stepsTaken = 0;
    // A step that costs 5 ms at the start of a turn (after the other engine's) and 1 ms after one of its own.
    const cold = (id: string): ShapeEngine =>
      hookedEngine(real, id, () => {
        clock.t += last.id === id ? 1 : 5;
        last.id = id;
        stepsTaken++;
      });
    const result = await withClock(clock, () =>
      shapeStepTime.run(
        { ...shapeStepTime.options('quick', {}), fixed: [{ scene: 'pyramid', params: { base: 3 } }], sweeps: [], runs: 1, steps: 20, turnSteps: 10, warmupSteps: 0, warmUpMs: 0, baseline: 'a' },
        { ...ctx([]), shapeEngines: [cold('a'), cold('b')] },
      ),
    );
    expect(stepsTaken).toBe(40);
    for (const r of result.rows) expect(r.ms.median, r.engine).toBe(1);
    expect(shapeStepTime.tables(result)[0].note).toContain('the mean of the 18 steps after the first of each turn');
  });

});

describe('units', () => {
  it("shape-step-time's and shape-energy's notes say what each peer took a scene unit for, and that Box2D 2.4's and planck's results depend on it", async () => {
    expect(sceneScale(buildShapeScene('pyramid', { base: 3 }))).toEqual({ lengthUnit: 1, smallestM: Math.SQRT1_2, largestM: Math.SQRT1_2 });
    const ids = ['maxgrid:maxgrid', 'box2d-wasm'];
    const steps = await shapeStepTime.run({ ...shapeStepTime.options('quick', {}), fixed: [{ scene: 'pyramid', params: { base: 3 } }], sweeps: [{ scene: 'uniform-polygons', ns: [40], profile: 'report' }], runs: 1, steps: 1, warmupSteps: 0, warmUpMs: 0 }, ctx(ids));
    const energy = await shapeEnergy.run({ ...shapeEnergy.options('quick', {}), n: 40, seconds: 0.05, samples: 1 }, ctx(ids));
    const notes = [shapeStepTime.tables(steps)[0].note!, shapeEnergy.tables(energy)[0].note!];
    expect(notes[0]).toMatch(/pyramid at lengthUnit 1 \([^)]*\): Box2D 2\.4\.1 \(WASM\), planck, Rapier and p2-es ran 1 scene unit as 1 m, Matter\.js as 50 px/);
    for (const note of notes) {
      expect(note).toMatch(/uniform-polygons at lengthUnit 50 \(bodies [\d.]+ to [\d.]+ m from centre to rim\): Box2D 2\.4\.1 \(WASM\), planck, Rapier and p2-es ran 1 scene unit as 0\.02 m, Matter\.js as 1 px/);
      expect(note).toContain("Box2D 2.4's and planck's results depend on that scale");
    }
  });
});
