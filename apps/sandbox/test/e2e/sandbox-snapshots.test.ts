import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type { Browser, Page } from 'playwright-core';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { World } from '@maxgrid/engine';
import { buildScene, buildShapeScene } from '@maxgrid/scenes';
import { ARTIFACTS, launchBrowser, openPage } from './browser.js';
import { decodeSave } from '../../src/save-file.js';
import { isShapeScene, parseSettings, sceneParams } from '../../src/settings.js';
import { buildSandboxShapeWorld, buildSandboxWorld } from '../../src/scene-world.js';
import { DT, Simulation } from '../../src/simulation.js';
import { History, HISTORY_BUDGET_BYTES, HISTORY_SPAN_STEPS, type Mark } from '../../src/history.js';
import { spawnRadius } from '../../src/scene-specs.js';

// Save, Load and the time scrubber (issue 23). Each state the page shows is checked against a
// world built and stepped here, in Node, from the page's own URL: the engine gives the same bits
// in both, so a step the page reached by loading, seeking or replaying must hash as one reached
// by stepping straight there.

const POLL = { timeout: 30_000, interval: 50 };

let browser: Browser;

beforeAll(async () => {
  browser = await launchBrowser();
});

afterAll(async () => {
  await browser?.close();
});

/** The world of the page's settings, stepped here without interruption; hash(n) is its hash at step n. */
class Reference {
  private readonly world: World;
  private readonly hashes: string[] = [];

  constructor(search: string) {
    const s = parseSettings(search);
    this.world = isShapeScene(s.scene) ? buildSandboxShapeWorld(buildShapeScene(s.scene, sceneParams(s)), DT, s, s.substeps) : buildSandboxWorld(buildScene(s.scene, sceneParams(s)), DT, s);
    this.hashes.push(this.world.stateHash());
  }

  hash(step: number): string {
    while (this.hashes.length <= step) {
      this.world.step(DT);
      this.hashes.push(this.world.stateHash());
    }
    return this.hashes[step];
  }
}

const state = (page: Page) => page.evaluate(() => window.__sandboxProbe!.state());
const history = (page: Page) => page.evaluate(() => window.__sandboxProbe!.history());

async function stepsPass(page: Page, target: number): Promise<void> {
  await page.waitForFunction((t) => window.__sandboxProbe!.state().step >= t, target, { timeout: 30_000 });
}

/** Pauses, or resumes when paused: the button reads Pause or Resume. */
const pause = (page: Page) => page.locator('#pause').click();

async function stepTimes(page: Page, n: number): Promise<void> {
  for (let k = 0; k < n; k++) await page.getByRole('button', { name: 'Step', exact: true }).click();
}

/** Clicks Save and returns the file's name and bytes (also kept under artifacts/e2e). */
async function save(page: Page): Promise<{ name: string; path: string; bytes: Uint8Array }> {
  const [download] = await Promise.all([page.waitForEvent('download'), page.locator('#save').click()]);
  const name = download.suggestedFilename();
  const path = join(ARTIFACTS, name);
  await download.saveAs(path);
  return { name, path, bytes: new Uint8Array(readFileSync(path)) };
}

async function load(page: Page, name: string, bytes: Uint8Array): Promise<void> {
  await page.locator('#load-file').setInputFiles({ name, mimeType: 'application/octet-stream', buffer: Buffer.from(bytes) });
}

/** Moves the scrubber to `step`, as dragging it there does, and waits for the page to show it. */
async function scrubTo(page: Page, step: number): Promise<void> {
  await page.locator('#scrubber').fill(String(step));
  await expect.poll(async () => (await state(page)).step, POLL).toBe(step);
}

describe('2D sandbox: save, load and the time scrubber', () => {
  it('saves the world to a file that restores to the same state, here and in another page, which then step alike', async () => {
    const { page, errors } = await openPage(browser, '/?n=400&contacts=1&spawn=box');
    const reference = new Reference(new URL(page.url()).search);
    await stepsPass(page, 20);
    await pause(page);
    const saved = await state(page);
    const file = await save(page);
    expect(file.name).toBe(`maxgrid-seed-box-step${saved.step}.mxgs`);
    const { header, snapshot } = decodeSave(file.bytes);
    expect(header.paused).toBe(true);
    const restored = World.restore(snapshot);
    expect(restored.stats.steps).toBe(saved.step);
    expect(restored.stateHash()).toBe(saved.hash);
    expect(saved.hash).toBe(reference.hash(saved.step));

    // Another page, on another scene, loads it: the scene, its settings and the view come back, paused.
    const other = await openPage(browser, '/?scene=ragdolls');
    await stepsPass(other.page, 2);
    await load(other.page, file.name, file.bytes);
    await expect.poll(() => state(other.page), POLL).toEqual(saved);
    expect(await other.page.getByLabel('Scene').inputValue()).toBe('seed-box');
    expect(await other.page.getByLabel('Contact points').isChecked()).toBe(true);
    expect(await other.page.getByLabel('Click adds').inputValue()).toBe('box');
    expect(new URL(other.page.url()).searchParams.get('n')).toBe('400');
    expect(await other.page.locator('#pause').innerText()).toBe('Resume');
    expect(await other.page.locator('#timeline-status').innerText()).toMatch(new RegExp(`Loaded ${file.name}: seed-box at step ${saved.step.toLocaleString('en-US')}`));
    expect(await history(other.page)).toMatchObject({ oldest: saved.step, head: saved.step, count: 1 });

    // Both pages step on alike, and as the file's world does here.
    await stepTimes(page, 10);
    await stepTimes(other.page, 10);
    for (let k = 0; k < 10; k++) restored.step(DT);
    const a = await state(page);
    const b = await state(other.page);
    expect(a.step).toBe(saved.step + 10);
    expect(b).toEqual(a);
    expect(restored.stateHash()).toBe(a.hash);
    expect(a.hash).toBe(reference.hash(a.step));

    // Saved while running, it loads running, and runs on as the uninterrupted world would.
    await pause(page);
    await stepsPass(page, a.step + 5);
    const running = await save(page);
    expect(decodeSave(running.bytes).header.paused).toBe(false);
    await load(other.page, running.name, running.bytes);
    await expect.poll(() => other.page.locator('#pause').innerText(), POLL).toBe('Pause');
    const from = decodeSave(running.bytes).header.step;
    await stepsPass(other.page, from + 10);
    await pause(other.page);
    const after = await state(other.page);
    expect(after.hash).toBe(reference.hash(after.step));

    expect(errors).toEqual([]);
    expect(other.errors).toEqual([]);
    await other.page.close();
    await page.close();
  });

  it('refuses a corrupt, a cut or a foreign file with the reason in the page, and goes on unchanged', async () => {
    const { page, errors } = await openPage(browser, '/?scene=ragdolls');
    const reference = new Reference(new URL(page.url()).search);
    await stepsPass(page, 10);
    const file = await save(page);
    const { snapshot } = decodeSave(file.bytes);
    const offset = file.bytes.length - snapshot.length;
    const flipped = file.bytes.slice();
    flipped[offset + Math.floor(snapshot.length / 2)] ^= 0x20;
    const cut = file.bytes.slice(0, file.bytes.length - 100);
    const engineSays = (bytes: Uint8Array) => {
      try {
        World.restore(decodeSave(bytes).snapshot);
      } catch (error) {
        return (error as Error).message;
      }
      throw new Error('the engine restored a damaged snapshot');
    };
    const status = page.locator('#timeline-status');
    for (const [name, bytes, says] of [
      ['flipped.mxgs', flipped, engineSays(flipped)],
      ['cut.mxgs', cut, engineSays(cut)],
      ['notes.mxgs', new TextEncoder().encode('not a save at all'), 'not a maxgrid sandbox save'],
    ] as const) {
      const before = (await state(page)).step;
      await load(page, name, bytes);
      await expect.poll(() => status.innerText(), POLL).toContain(`Could not load ${name}: ${says}`);
      expect(await status.getAttribute('class')).toContain('error');
      // Still the same scene, still running.
      await stepsPass(page, before + 5);
      expect(await page.getByLabel('Scene').inputValue()).toBe('ragdolls');
      expect(await page.locator('#pause').innerText()).toBe('Pause');
    }
    // ...and unchanged: where it is now is where the world stepped straight from its start is.
    await pause(page);
    const now = await state(page);
    expect(now.hash).toBe(reference.hash(now.step));
    expect(errors).toEqual([]);
    await page.close();
  });

  it('scrubs back to a step exactly, steps back one, forward again, and resumes on the same path', async () => {
    const { page, errors } = await openPage(browser, '/?scene=ragdolls');
    const reference = new Reference(new URL(page.url()).search);
    await stepsPass(page, 150);
    await pause(page);
    const end = await state(page);
    expect(end.hash).toBe(reference.hash(end.step));
    expect((await history(page)).head).toBe(end.step);

    // Between snapshots, so the page restores one and steps forward to it.
    const back = end.step - 77;
    await scrubTo(page, back);
    expect((await state(page)).hash).toBe(reference.hash(back));
    expect(await page.locator('#scrub-step').innerText()).toBe(`step ${back} of ${end.step}`);
    await page.getByRole('button', { name: 'Step back', exact: true }).click();
    await expect.poll(async () => (await state(page)).step, POLL).toBe(back - 1);
    expect((await state(page)).hash).toBe(reference.hash(back - 1));
    // Forward again, to where it had run to: nothing of the way back was lost.
    await scrubTo(page, end.step);
    expect((await state(page)).hash).toBe(end.hash);

    // Resuming from the past forgets the steps after it and runs on as if never interrupted.
    await scrubTo(page, back);
    expect((await state(page)).paused).toBe(true);
    await pause(page);
    await expect.poll(async () => (await history(page)).head, POLL).toBeLessThan(end.step);
    await stepsPass(page, end.step + 30);
    await pause(page);
    const later = await state(page);
    expect(later.hash).toBe(reference.hash(later.step));
    expect((await history(page)).head).toBe(later.step);

    // An edit in the past (a box added) forgets the future too: the scrubber ends there.
    const edit = later.step - 40;
    await scrubTo(page, edit);
    const bodies = await page.evaluate(() => window.__sandboxProbe!.region());
    const at = await page.evaluate((r) => window.__sandboxProbe!.toCss(r.x + r.width * 0.05, r.y + r.height * 0.05), bodies);
    const stage = await page.locator('#overlay').boundingBox();
    await page.mouse.click(stage!.x + at.x, stage!.y + at.y);
    await expect.poll(async () => (await history(page)).head, POLL).toBe(edit);
    await expect.poll(() => page.locator('#scrubber').getAttribute('max'), POLL).toBe(String(edit));
    expect((await state(page)).hash).not.toBe(reference.hash(edit));

    // A reset starts the history over.
    await page.getByRole('button', { name: 'Reset', exact: true }).click();
    await expect.poll(() => history(page), POLL).toMatchObject({ oldest: 0, head: 0 });
    expect((await state(page)).hash).toBe(reference.hash(0));
    expect(errors).toEqual([]);
    await page.close();
  });

  it.each([
    ['a circle, kinematic while held', '/?n=60&size=20&gravity=0', 0],
    ['a box, pulled by the drag spring', '/?scene=vertical-stack&count=6', 3],
  ])('replays a drag when scrubbing back into it: %s', async (_, path, body) => {
    const { page, errors } = await openPage(browser, path);
    await stepsPass(page, 20);
    await pause(page);
    const stage = (await page.locator('#overlay').boundingBox())!;
    const toPage = async (dx: number, dy: number) => {
      const p = await page.evaluate((h) => window.__sandboxProbe!.pose(h), body);
      const at = await page.evaluate((q) => window.__sandboxProbe!.toCss(q.x, q.y), p);
      return { x: stage.x + at.x + dx, y: stage.y + at.y + dy };
    };
    const start = await toPage(0, 0);
    await page.mouse.move(start.x, start.y);
    await page.mouse.down();
    // The keyboard runs the Pause button, so the pointer stays down on the body all along.
    const toggle = () => page.locator('#pause').press('Enter');
    const during: { hash: string; step: number }[] = [];
    for (const [dx, dy] of [[60, -30], [-40, 50]]) {
      await toggle();
      await page.mouse.move(start.x + dx, start.y + dy, { steps: 8 });
      await stepsPass(page, (await state(page)).step + 20);
      await toggle();
      during.push(await state(page));
      if (body === 0) expect((await page.evaluate((h) => window.__sandboxProbe!.pose(h), body)).type).toBe('kinematic');
    }
    await toggle();
    await stepsPass(page, (await state(page)).step + 10);
    await page.mouse.up();
    await stepsPass(page, (await state(page)).step + 30);
    await pause(page);
    for (const at of during) {
      await scrubTo(page, at.step);
      expect((await state(page)).hash, `step ${at.step}`).toBe(at.hash);
    }
    // Stepping on from a step inside the drag lets the body go: no pointer holds it any more.
    await page.getByRole('button', { name: 'Step', exact: true }).click();
    expect((await page.evaluate((h) => window.__sandboxProbe!.pose(h), body)).type).toBe('dynamic');
    expect(errors).toEqual([]);
    await page.close();
  });
});

describe('the history under edits: the page\'s Simulation and History, in Node', () => {
  const steps = (sim: Simulation, n: number) => {
    for (let k = 0; k < n; k++) sim.stepOnce();
  };

  it('keeps the pin anchor of each step: a pin made after going back before the first holds to a new static body', () => {
    const sim = new Simulation();
    const settings = parseSettings('?scene=vertical-stack&count=6');
    sim.rebuild(settings);
    steps(sim, 40);
    const box3 = sim.world.getBody(3);
    const first = sim.pin(3, box3.x, box3.y);
    const anchor = sim.world.getJoint(first).bodyA as number;
    expect(sim.world.getBody(anchor).type).toBe('static');
    steps(sim, 40);
    sim.seek(20);
    expect(sim.world.jointCount).toBe(0);
    expect(sim.world.hasBody(anchor)).toBe(false);
    // The free handles are those of step 20 again: a box added now takes the anchor's handle.
    const added = sim.spawn(sim.box.x + sim.box.width * 0.1, sim.box.y + sim.box.height * 0.1, spawnRadius(settings.scene, settings.params), 'box');
    expect(added).toBe(anchor);
    const box2 = sim.world.getBody(2);
    const second = sim.pin(2, box2.x, box2.y);
    const holder = sim.world.getJoint(second).bodyA as number;
    expect(holder).not.toBe(added);
    expect(sim.world.getBody(holder).type).toBe('static');
    expect(sim.history.head).toBe(20);
  });

  it('brings back the integrator of the step sought, and the graphs lose the steps undone', () => {
    const sim = new Simulation();
    sim.rebuild(parseSettings('?n=50'));
    steps(sim, 30);
    sim.setIntegrator('explicit-euler');
    steps(sim, 30);
    const end = sim.world.stateHash();
    sim.seek(10);
    expect(sim.world.integrator).toBe('semi-implicit-euler');
    expect(sim.recorder.length).toBe(10);
    expect(sim.time).toBeCloseTo(10 * DT, 12);
    sim.seek(60);
    expect(sim.world.integrator).toBe('explicit-euler');
    expect(sim.world.stateHash()).toBe(end);
    // Switching is an edit: what followed the old choice is forgotten.
    sim.seek(45);
    sim.setIntegrator('semi-implicit-euler');
    expect(sim.history.head).toBe(45);
  });

  it('keeps its snapshots within the budget and the span', () => {
    const mark: Mark = { time: 0, boxX: 0, pinAnchor: -1, held: -1 };
    const history = new History();
    history.reset(0);
    const big = new Uint8Array(20 * 1024 * 1024);
    for (let step = 0; step <= 300; step += 30) history.record(step, big, mark);
    expect(history.bytes).toBeLessThanOrEqual(HISTORY_BUDGET_BYTES);
    expect(history.count).toBe(3);
    expect(history.oldest).toBe(240);
    // One snapshot over the budget is kept alone, so the page can still step back to it.
    history.record(330, new Uint8Array(HISTORY_BUDGET_BYTES + 1), mark);
    expect(history.count).toBe(1);

    history.reset(0);
    const small = new Uint8Array(1000);
    for (let step = 0; step <= 6000; step += 30) history.record(step, small, mark);
    expect(history.head - history.oldest).toBeLessThanOrEqual(HISTORY_SPAN_STEPS);
    expect(history.head - history.oldest).toBeGreaterThan(HISTORY_SPAN_STEPS - 30);
  });
});
