import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type { Browser, Page } from 'playwright-core';
import { BROADPHASE_NAMES } from '@maxgrid/engine';
import { buildScene, buildWorld, type Scene } from '@maxgrid/scenes';
import { Ajv } from 'ajv';
import { ARTIFACTS, launchBrowser, openPage } from './browser.js';
import { DETERMINISM, sceneDigest, toPlainScene } from '../../src/lab-page/runs.js';
import type { LabPageResults } from '../../src/lab-page/main.js';
import { EXPERIMENTS, ENGINE_IDS, maxgridBuildOptions } from '../../../../packages/lab/src/browser.js';

let browser: Browser;
let page: Page;
let errors: string[];
let results: LabPageResults;

/** A scene stepped in Node with every broad-phase, the same way the page steps it in Chromium. */
function nodeHashes(scene: Scene): Record<string, string> {
  const hashes: Record<string, string> = {};
  for (const broadphase of BROADPHASE_NAMES) {
    const world = buildWorld(scene, { broadphase });
    for (let i = 0; i < DETERMINISM.steps; i++) world.step(DETERMINISM.dt);
    hashes[broadphase] = world.stateHash();
  }
  return hashes;
}

const golden = buildScene(DETERMINISM.scene, DETERMINISM.params);
let goldenHashes: Record<string, string>;

describe('lab page in Chromium', () => {
  beforeAll(async () => {
    goldenHashes = nodeHashes(golden);
    browser = await launchBrowser();
    ({ page, errors } = await openPage(browser, '/lab.html?auto=1'));
    await page.waitForFunction(() => window.__labResults?.done === true, undefined, { timeout: 170_000, polling: 500 });
    results = (await page.evaluate(() => window.__labResults)) as LabPageResults;
    await page.screenshot({ path: `${ARTIFACTS}lab.png`, fullPage: true });
  }, 180_000);

  afterAll(async () => {
    await browser?.close();
  });

  it('runs every quick experiment without errors', () => {
    expect(results.errors).toEqual([]);
    expect(errors).toEqual([]);
    // Node-only experiments (C baseline, targets) are not run by the page.
    const inBrowser = Object.entries(EXPERIMENTS).filter(([, e]) => !e.nodeOnly).map(([name]) => name);
    expect(Object.keys(results.experiments).sort()).toEqual(inBrowser.sort());
    expect(results.environment.runtime).toMatch(/^Chromium \d+/);
  });

  it("produces results that validate against each experiment's schema", () => {
    const ajv = new Ajv({ strict: false });
    for (const [name, result] of Object.entries(results.experiments)) {
      const validate = ajv.compile(EXPERIMENTS[name].schema);
      expect(validate(result), `${name}: ${JSON.stringify(validate.errors)}`).toBe(true);
    }
  });

  it("sap-sleep's pile case sleeps in the page as in Node (it settled too briefly to sleep at all)", () => {
    const rows = (results.experiments['sap-sleep'] as { rows: { case: string; asleepStart: number }[] }).rows.filter((r) => r.case === 'pile');
    expect(rows.length).toBeGreaterThan(0);
    for (const row of rows) expect(row.asleepStart).toBeGreaterThanOrEqual(0.9);
  });

  it('loads and measures every engine, the WASM ones included', () => {
    const stepTime = results.experiments['step-time'] as { rows: { engine: string }[] };
    expect(new Set(stepTime.rows.map((r) => r.engine))).toEqual(new Set(ENGINE_IDS));
  });

  it('shows charts and tables on the page', async () => {
    expect(await page.locator('#experiments figure svg').count()).toBeGreaterThanOrEqual(7);
    expect(await page.locator('#experiments table').count()).toBeGreaterThanOrEqual(6);
    const json = JSON.parse((await page.locator('#lab-json').textContent()) ?? '{}');
    expect(json.done).toBe(true);
  });

  it('steps worlds on request through __labWorlds (the browser-parity target) to the same hash as Node', async () => {
    const params = { n: 3000, seed: 2 };
    const id = await page.evaluate((p) => window.__labWorlds!.create('uniform', p, 'maxgrid'), params);
    const times = await page.evaluate((i) => window.__labWorlds!.step(i, 20, 1 / 60), id);
    expect(times).toHaveLength(20);
    const world = buildWorld(buildScene('uniform', params), maxgridBuildOptions('maxgrid'));
    for (let s = 0; s < 20; s++) world.step(1 / 60);
    expect(await page.evaluate((i) => window.__labWorlds!.hash(i), id)).toBe(world.stateHash());
    await page.evaluate((i) => window.__labWorlds!.dispose(i), id);
  });

  it('bins a large shuffled world in bands on Web Workers to the same hash as Node on one thread', async () => {
    // 140,000 circles listed in a random order: past the banded bin's 131,072 bodies and scattered,
    // so from the second step the workers count, partition and sort bands (parallel/banded-bin.ts)
    // and Node's single thread bins in bands too.
    await expectWorkersMatchNode({ n: 140_000, seed: 6, shuffle: 1 }, 12);
  });

  /** Steps `uniform` with `params` in the page on 2 Web Workers and in Node on one thread, and compares their hashes. */
  async function expectWorkersMatchNode(params: Record<string, number>, steps: number): Promise<void> {
    const id = await page.evaluate((p) => window.__labWorlds!.create('uniform', p, 'maxgrid'), params);
    expect(await page.evaluate((i) => window.__labWorlds!.startWorkers(i, 2), id)).toBe(2);
    await page.evaluate(([i, n]) => window.__labWorlds!.step(i, n, 1 / 60), [id, steps] as const);
    const world = buildWorld(buildScene('uniform', params), maxgridBuildOptions('maxgrid'));
    for (let s = 0; s < steps; s++) world.step(1 / 60);
    expect(await page.evaluate((i) => window.__labWorlds!.hash(i), id)).toBe(world.stateHash());
    await page.evaluate((i) => window.__labWorlds!.dispose(i), id);
  }

  it('runs the parallel step on Web Workers (the page is cross-origin isolated) to the same hash as Node on one thread', async () => {
    expect(await page.evaluate(() => globalThis.crossOriginIsolated)).toBe(true);
    await expectWorkersMatchNode({ n: 3000, seed: 4 }, 30);
  });

  // Determinism across runtimes, in three steps so that a failure says where bits diverge.
  it('builds the golden scene to the same bits in Node and in Chromium', () => {
    // Differing vx/vy here means the scene builder's Math.cos/Math.sin round differently in the
    // two V8 versions: the scene, not the engine, breaks cross-runtime determinism.
    expect(results.determinism?.sceneDigest).toEqual(sceneDigest(golden));
  });

  it('steps identical scene data to the same state hash in Node and in Chromium, with every broad-phase', async () => {
    const inBrowser = await page.evaluate((scene) => window.__labDeterminismOf!(scene), toPlainScene(golden));
    expect(inBrowser.sceneDigest).toEqual(sceneDigest(golden));
    expect(inBrowser.hashes).toEqual(goldenHashes);
  });

  it('steps the golden scene (built in each runtime) to the same state hash in Node and in Chromium, with every broad-phase', () => {
    expect(new Set(Object.values(goldenHashes)).size).toBe(1);
    expect(Object.keys(goldenHashes)).toEqual([...BROADPHASE_NAMES]);
    expect(results.determinism?.hashes).toEqual(goldenHashes);
  });
});
