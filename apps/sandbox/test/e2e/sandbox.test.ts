import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type { Browser, Page } from 'playwright-core';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { ARTIFACTS, colourfulPixels, launchBrowser, openPage, overlayPixels, stat } from './browser.js';

// The 2D sandbox, driven like a user would: through labelled controls, the visible statistics and
// the pixels on screen. Small scenes keep each test quick on a two-core machine.

const COLUMNS = ['time', 'step_ms', 'kinetic', 'potential', 'total', 'candidate_pairs', 'contacts'];
/** Frames can take a second on a busy two-core machine; polls wait for behaviour, not for speed. */
const POLL = { timeout: 30_000, interval: 100 };
const SLIDERS = ['Gravity', 'Elasticity', 'Quantity', 'Size', 'Size noise', 'Velocity', 'Velocity noise'];

let browser: Browser;

beforeAll(async () => {
  browser = await launchBrowser();
});

afterAll(async () => {
  await browser?.close();
});

/** A slider by its label. The label also shows the value ("Size 6.0 px"), hence the pattern. */
function slider(page: Page, name: string) {
  return page.getByLabel(new RegExp(`^${name} [-\\d]`));
}

async function labelText(page: Page, name: string): Promise<string> {
  const id = await slider(page, name).getAttribute('id');
  return page.locator(`label[for="${id}"]`).innerText();
}


/** Waits until the visible step counter passes `after` + `more`: the simulation is running. */
async function stepsPass(page: Page, after: number, more = 3): Promise<void> {
  await page.waitForFunction(
    (target) => Number(document.getElementById('stat-steps')?.textContent?.replace(/\D/g, '')) >= target,
    after + more,
    { timeout: 30_000 },
  );
}

/**
 * Waits for `more` steps after `from` while checking that the counter never went below `from`: a
 * live switch keeps the world, a rebuild would restart the count at zero.
 */
async function stepsContinue(page: Page, from: number, more = 3): Promise<void> {
  const deadline = Date.now() + POLL.timeout;
  for (;;) {
    const steps = await stat(page, 'steps');
    expect(steps).toBeGreaterThanOrEqual(from);
    if (steps >= from + more) return;
    if (Date.now() > deadline) throw new Error(`steps stuck at ${steps}, expected ${from + more}`);
    await page.waitForTimeout(50);
  }
}



describe('2D sandbox', () => {
  it('loads without console errors and draws circles', async () => {
    const { page, errors } = await openPage(browser, '/');
    await stepsPass(page, 0);
    expect(await stat(page, 'bodies')).toBe(1000);
    for (const name of SLIDERS) expect(await slider(page, name).count(), name).toBe(1);
    for (const name of ['Seed', 'Broad-phase', 'Integrator', 'Renderer', 'Max Grid cells', 'AABBs']) {
      expect(await page.getByLabel(name).count(), name).toBe(1);
    }
    for (const name of ['Pause', 'Step', 'Reset', 'Download data']) {
      expect(await page.getByRole('button', { name, exact: true }).count()).toBe(1);
    }
    expect(await colourfulPixels(page)).toBeGreaterThan(2000);
    // The graphs have something on them by now.
    const charted = await page.evaluate(() =>
      ['chart-step', 'chart-fps', 'chart-energy'].map((id) => {
        const c = document.getElementById(id) as HTMLCanvasElement;
        const d = (c.getContext('2d', { willReadFrequently: true }) as CanvasRenderingContext2D).getImageData(0, 0, c.width, c.height).data;
        let n = 0;
        for (let i = 3; i < d.length; i += 4) if (d[i] > 0) n++;
        return n;
      }),
    );
    for (const n of charted) expect(n).toBeGreaterThan(50);
    await page.screenshot({ path: join(ARTIFACTS, 'sandbox-load.png'), timeout: 60_000 });
    expect(errors).toEqual([]);
    await page.close();
  });

  it('each slider changes what its label shows and rebuilds the scene', async () => {
    const { page, errors } = await openPage(browser, '/?n=200');
    await stepsPass(page, 0, 2);
    for (const name of SLIDERS) {
      const input = slider(page, name);
      const before = await labelText(page, name);
      const max = Number(await input.getAttribute('max'));
      const min = Number(await input.getAttribute('min'));
      const current = Number(await input.inputValue());
      // Somewhere clearly different from where the slider is now (Quantity: a scene that stays quick).
      let target = current - min > (max - min) / 2 ? min + (max - min) * 0.2 : min + (max - min) * 0.8;
      if (name === 'Quantity') target = Math.round((max - min) * 0.55);
      const step = Number(await input.getAttribute('step'));
      await input.fill(String(min + Math.round((target - min) / step) * step));
      const after = await labelText(page, name);
      expect(after, name).not.toBe(before);
      expect(after.startsWith(name)).toBe(true);
      if (name === 'Quantity') {
        const shown = Number(after.replace(/\D/g, ''));
        expect(shown).not.toBe(200);
        await page.waitForFunction(
          (n) => Number(document.getElementById('stat-bodies')?.textContent?.replace(/\D/g, '')) === n,
          shown,
        );
        // Keep the remaining rebuilds small.
        await input.fill(String(current));
      }
    }
    const seed = page.getByLabel('Seed');
    await seed.fill('12345');
    await seed.press('Enter');
    await expect.poll(() => new URL(page.url()).searchParams.get('seed'), POLL).toBe('12345');
    const bodies = await stat(page, 'bodies');
    expect(Number((await labelText(page, 'Quantity')).replace(/\D/g, ''))).toBe(bodies);
    expect(errors).toEqual([]);
    await page.close();
  });

  it('keeps running across every broad-phase, integrator and renderer', async () => {
    const { page, errors } = await openPage(browser, '/?n=500&grid=1');
    await stepsPass(page, 0, 5);
    const broadphases = await page.getByLabel('Broad-phase').locator('option').evaluateAll((os) => os.map((o) => (o as HTMLOptionElement).value));
    expect(broadphases).toEqual(expect.arrayContaining(['naive', 'sap', 'sap-xy', 'maxgrid']));
    for (const name of broadphases) {
      const steps = await stat(page, 'steps');
      await page.getByLabel('Broad-phase').selectOption(name);
      await stepsContinue(page, steps);
      expect(new URL(page.url()).searchParams.get('broadphase')).toBe(name);
    }
    // The Max Grid overlay draws the grid of the last step, so it shows only while a Max Grid is built.
    await page.getByLabel('Broad-phase').selectOption('maxgrid');
    await expect.poll(() => overlayPixels(page), POLL).toBeGreaterThan(1000);
    await page.getByLabel('Broad-phase').selectOption('sap');
    await expect.poll(() => overlayPixels(page), POLL).toBe(0);
    const beforeIntegrator = await stat(page, 'steps');
    await page.getByLabel('Integrator').selectOption('explicit-euler');
    await stepsContinue(page, beforeIntegrator);

    for (const renderer of ['webgl', 'canvas']) {
      const steps = await stat(page, 'steps');
      await page.getByLabel('Renderer').selectOption(renderer);
      expect(await page.getByLabel('Renderer').inputValue()).toBe(renderer);
      await stepsContinue(page, steps);
      expect(await colourfulPixels(page), renderer).toBeGreaterThan(1000);
      await page.locator('#stage').screenshot({ path: join(ARTIFACTS, `sandbox-${renderer}.png`) });
    }
    expect(await stat(page, 'bodies')).toBe(500);
    expect(errors).toEqual([]);
    await page.close();
  });

  it("logs every frame for the lab: the frame log's steps add up to the world's, and it names the WebGL device", async () => {
    const { page, errors } = await openPage(browser, '/?scene=uniform&n=300&renderer=webgl');
    await stepsPass(page, 0, 20);
    // Paused, the log and the world's clock are read at the same moment.
    await page.getByRole('button', { name: 'Pause', exact: true }).click();
    const log = await page.evaluate(() => window.__sandboxFrames!.read());
    expect(log).toMatchObject({ renderer: 'webgl', bodies: 300, threads: 1 });
    const steps = log.steps.reduce((a, b) => a + b, 0);
    expect(steps).toBeGreaterThanOrEqual(20);
    expect(steps).toBe(Math.round(log.simulatedSeconds * 60));
    for (let i = 1; i < log.start.length; i++) expect(log.start[i]).toBeGreaterThan(log.start[i - 1]);
    expect(log.stepMs.length).toBe(log.start.length);
    expect(Math.min(...log.stepMs, ...log.drawMs)).toBeGreaterThanOrEqual(0);
    expect(await page.evaluate(() => window.__sandboxFrames!.webglDevice())).toMatch(/\S/);
    // A rebuilt world starts a new log.
    await page.getByRole('button', { name: 'Reset', exact: true }).click();
    await expect.poll(() => stat(page, 'steps'), POLL).toBe(0);
    const rebuilt = await page.evaluate(() => window.__sandboxFrames!.read());
    expect(rebuilt.steps.reduce((a, b) => a + b, 0)).toBe(0);
    expect(errors).toEqual([]);
    await page.close();
  });

  it('pauses, steps once and resets', async () => {
    const { page, errors } = await openPage(browser, '/?n=100');
    await stepsPass(page, 0, 5);
    const pause = page.locator('#pause');
    await page.getByRole('button', { name: 'Pause', exact: true }).click();
    expect(await pause.getAttribute('aria-pressed')).toBe('true');
    const paused = await stat(page, 'steps');
    await page.waitForTimeout(400);
    expect(await stat(page, 'steps')).toBe(paused);
    await page.getByRole('button', { name: 'Step', exact: true }).click();
    await expect.poll(() => stat(page, 'steps'), POLL).toBe(paused + 1);
    await page.getByRole('button', { name: 'Reset', exact: true }).click();
    await expect.poll(() => stat(page, 'steps'), POLL).toBe(0);
    expect(await page.locator('#stat-time').innerText()).toBe('0.00 s');
    // Still paused after a reset: the button says what a click does now.
    await page.getByRole('button', { name: 'Resume', exact: true }).click();
    await stepsPass(page, 0, 5);
    expect(errors).toEqual([]);
    await page.close();
  });

  it('adds a circle on a click in empty space and drags one with the pointer', async () => {
    // No bodies, no gravity, no initial speed: whatever is on screen is what the pointer did.
    const { page, errors } = await openPage(browser, '/?n=0&gravity=0&velocity=0&size=20');
    await page.getByRole('button', { name: 'Pause', exact: true }).click();
    const box = await page.locator('#overlay').boundingBox();
    if (!box) throw new Error('overlay has no box');
    const at = (fx: number, fy: number) => ({ x: box.x + box.width * fx, y: box.y + box.height * fy });
    const a = at(0.3, 0.5);
    const b = at(0.7, 0.5);
    await page.mouse.click(a.x, a.y);
    await expect.poll(() => stat(page, 'bodies'), POLL).toBe(1);
    // Drag the new circle from a to b.
    await page.mouse.move(a.x, a.y);
    await page.mouse.down();
    await page.mouse.move((a.x + b.x) / 2, a.y, { steps: 4 });
    await page.mouse.move(b.x, b.y, { steps: 4 });
    await page.mouse.up();
    // a is empty now, so a click there adds a circle; b holds the dragged one, so a click there does not.
    await page.mouse.click(a.x, a.y);
    await expect.poll(() => stat(page, 'bodies'), POLL).toBe(2);
    await page.mouse.click(b.x, b.y);
    await page.waitForTimeout(200);
    expect(await stat(page, 'bodies')).toBe(2);
    expect(await colourfulPixels(page)).toBeGreaterThan(500);
    expect(errors).toEqual([]);
    await page.close();
  });

  it('downloads the recorded series as CSV and JSON', async () => {
    const { page, errors } = await openPage(browser, '/?n=300&seed=5');
    await stepsPass(page, 0, 20);
    await page.getByRole('button', { name: 'Pause', exact: true }).click();
    const steps = await stat(page, 'steps');

    await page.getByLabel('Format').selectOption('csv');
    const [csvDownload] = await Promise.all([page.waitForEvent('download'), page.getByRole('button', { name: 'Download data' }).click()]);
    expect(csvDownload.suggestedFilename()).toMatch(/\.csv$/);
    const csvPath = join(ARTIFACTS, 'sandbox-data.csv');
    await csvDownload.saveAs(csvPath);
    const lines = readFileSync(csvPath, 'utf8').trim().split('\n');
    expect(lines[0].split(',')).toEqual(COLUMNS);
    const rows = lines.slice(1).map((line) => line.split(',').map(Number));
    expect(rows.length).toBe(steps);
    for (const [i, row] of rows.entries()) {
      expect(row.length).toBe(COLUMNS.length);
      for (const v of row) expect(Number.isFinite(v)).toBe(true);
      expect(row[0]).toBeCloseTo((i + 1) / 60, 9);
      expect(row[4]).toBeCloseTo(row[2] + row[3], 3);
      expect(row[6]).toBeLessThanOrEqual(row[5]);
    }
    expect(rows.some((row) => row[5] > 0)).toBe(true);

    await page.getByLabel('Format').selectOption('json');
    const [jsonDownload] = await Promise.all([page.waitForEvent('download'), page.getByRole('button', { name: 'Download data' }).click()]);
    expect(jsonDownload.suggestedFilename()).toMatch(/\.json$/);
    const jsonPath = join(ARTIFACTS, 'sandbox-data.json');
    await jsonDownload.saveAs(jsonPath);
    const data = JSON.parse(readFileSync(jsonPath, 'utf8'));
    expect(data.columns).toEqual(COLUMNS);
    expect(data.settings.n).toBe(300);
    expect(data.settings.seed).toBe(5);
    for (const c of COLUMNS) expect(data.series[c]).toHaveLength(steps);
    expect(data.series.contacts).toEqual(rows.map((row) => row[6]));
    expect(errors).toEqual([]);
    await page.close();
  });

  it('keeps the settings in the URL, so a reload shows the same view', async () => {
    const { page, errors } = await openPage(browser, '/?n=150');
    await slider(page, 'Gravity').fill('-500');
    await slider(page, 'Elasticity').fill('0.7');
    await slider(page, 'Size').fill('3.5');
    await slider(page, 'Quantity').fill('400');
    await page.getByLabel('Seed').fill('99');
    await page.getByLabel('Seed').press('Enter');
    await page.getByLabel('Broad-phase').selectOption('sap-xy');
    await page.getByLabel('Integrator').selectOption('explicit-euler');
    await page.getByLabel('Renderer').selectOption('webgl');
    await page.getByLabel('AABBs').check();
    await expect.poll(() => new URL(page.url()).searchParams.get('aabb'), POLL).toBe('1');

    const read = async () => ({
      labels: await Promise.all(SLIDERS.map((name) => labelText(page, name))),
      seed: await page.getByLabel('Seed').inputValue(),
      broadphase: await page.getByLabel('Broad-phase').inputValue(),
      integrator: await page.getByLabel('Integrator').inputValue(),
      renderer: await page.getByLabel('Renderer').inputValue(),
      aabb: await page.getByLabel('AABBs').isChecked(),
      bodies: await stat(page, 'bodies'),
    });
    await stepsPass(page, 0, 2);
    const before = await read();
    expect(before.labels[0]).toContain('-500');
    expect(before.seed).toBe('99');
    expect(before.bodies).toBe(Number(before.labels[2].replace(/\D/g, '')));

    await page.reload({ waitUntil: 'load' });
    await stepsPass(page, 0, 2);
    expect(await read()).toEqual(before);
    await page.screenshot({ path: join(ARTIFACTS, 'sandbox-url.png') });
    const shared = new URL(page.url()).search;
    expect(errors).toEqual([]);
    await page.close();

    // The shared link, opened afresh, shows the same thing too.
    const fresh = await openPage(browser, `/${shared}`);
    await stepsPass(fresh.page, 0, 2);
    const { labels, seed, broadphase, bodies } = before;
    expect({
      labels: await Promise.all(SLIDERS.map((name) => labelText(fresh.page, name))),
      seed: await fresh.page.getByLabel('Seed').inputValue(),
      broadphase: await fresh.page.getByLabel('Broad-phase').inputValue(),
      bodies: await stat(fresh.page, 'bodies'),
    }).toEqual({ labels, seed, broadphase, bodies });
    expect(fresh.errors).toEqual([]);
    await fresh.page.close();
  });

  it('falls back to clamped defaults on bad URL parameters', async () => {
    const { page, errors } = await openPage(browser, '/?n=banana&gravity=1e9&size=-4&elasticity=&broadphase=bogus&renderer=vr&seed=-7&velocityNoise=NaN');
    await stepsPass(page, 0, 2);
    expect(await stat(page, 'bodies')).toBe(1000);
    expect(await labelText(page, 'Gravity')).toContain('2000');
    expect(await labelText(page, 'Size')).toMatch(/^Size\s+0\.5/);
    expect(await labelText(page, 'Elasticity')).toContain('1.00');
    expect(await page.getByLabel('Broad-phase').inputValue()).toBe('auto');
    expect(await page.getByLabel('Renderer').inputValue()).toBe('canvas');
    expect(await page.getByLabel('Seed').inputValue()).toBe('0');
    // O(n²) naive on a large scene would stall the page: it is refused with a visible notice.
    await page.goto(page.url().replace(/n=\d+/, 'n=20000').replace(/broadphase=\w+/, 'broadphase=naive'));
    await stepsPass(page, 0, 2);
    expect(await page.getByLabel('Broad-phase').inputValue()).toBe('auto');
    expect(await page.locator('#notice').innerText()).toMatch(/naive/);
    expect(errors).toEqual([]);
    await page.close();
  });
});
