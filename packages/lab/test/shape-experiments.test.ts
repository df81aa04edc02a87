import { beforeAll, describe, expect, it } from 'vitest';
import { Ajv } from 'ajv';
import type { RunContext } from '../src/experiments/common.js';
import { EXPERIMENTS, shapeEnergy, shapeFalsePositives, shapeStepTime, stability } from '../src/experiments/registry.js';
import type { ShapeEngine } from '../src/shape-engines/adapter.js';
import { SHAPE_ENGINE_IDS } from '../src/shape-engines/registry.js';
import { loadShapeEnginesNode } from '../src/node/engines.js';
import { tablesFor } from '../src/report/html.js';
import { markdownTable } from '../src/report/tables.js';

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
