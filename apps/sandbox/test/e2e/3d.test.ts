import { afterAll, afterEach, beforeAll, beforeEach, describe, expect, it } from 'vitest';
import type { Browser, Page } from 'playwright-core';
import { join } from 'node:path';
import { ARTIFACTS, launchBrowser, openPage } from './browser.js';

/**
 * The 3D page renders (issue 3): three.js + cannon-es, the report's early exploration (5.3).
 * Chromium runs software WebGL (swiftshader) here, so frames are slow: waits are generous and
 * the layered-drop experiment is a small version of the page's default.
 */

/** Reads the live simulation's data attributes (see showStats in src/three/main.ts). */
async function simStats(page: Page): Promise<Record<'steps' | 'meanHeight' | 'static' | 'sleeping' | 'cubes', number>> {
  return page.$eval('#sim-stats', (el) => {
    const d = (el as HTMLElement).dataset;
    return {
      steps: Number(d['steps']),
      meanHeight: Number(d['meanHeight']),
      static: Number(d['static']),
      sleeping: Number(d['sleeping']),
      cubes: Number(d['cubes']),
    };
  });
}

async function waitForStat(page: Page, key: 'steps' | 'static' | 'sleeping', test: '>' | '==', value: number): Promise<void> {
  await page.waitForFunction(
    ([k, t, v]) => {
      const n = Number((document.getElementById('sim-stats') as HTMLElement).dataset[k as string]);
      return t === '>' ? n > (v as number) : n === v;
    },
    [key, test, value] as const,
    { timeout: 20_000, polling: 100 },
  );
}

// Each test opens its own page, and a failed test is retried once, because the shared Vite dev
// server may reload the page mid-test when something else in its watched root changes (another
// page's files, re-optimised dependencies); a reload would silently reset the page's state.
describe('the 3D page', { retry: 1 }, () => {
  let browser: Browser;
  let page: Page;
  let errors: string[];

  beforeAll(async () => {
    browser = await launchBrowser();
  });

  beforeEach(async () => {
    ({ page, errors } = await openPage(browser, '/3d.html'));
    // A smaller window than openPage's: software WebGL's frame time grows with the pixel count,
    // and the live simulation advances at most a few fixed steps per frame.
    await page.setViewportSize({ width: 1100, height: 720 });
  });

  afterEach(async () => {
    await page?.close();
  });

  afterAll(async () => {
    await browser?.close();
  });

  it('renders the falling stack on a non-blank WebGL canvas', async () => {
    await waitForStat(page, 'steps', '>', 5);
    const first = await simStats(page);
    expect(first.cubes).toBeGreaterThan(0);
    await waitForStat(page, 'steps', '>', first.steps + 40);
    const later = await simStats(page);
    // The cubes actually fall: steps advance and the stack's mean height drops.
    expect(later.steps).toBeGreaterThan(first.steps);
    expect(later.meanHeight).toBeLessThan(first.meanHeight);

    // Not blank: copy the WebGL canvas (preserveDrawingBuffer) to a 2D canvas and count colours.
    const colours = await page.$eval('#view canvas', (canvas) => {
      const c = canvas as HTMLCanvasElement;
      const copy = document.createElement('canvas');
      copy.width = c.width;
      copy.height = c.height;
      const ctx = copy.getContext('2d', { willReadFrequently: true });
      if (!ctx) return 0;
      ctx.drawImage(c, 0, 0);
      const { data } = ctx.getImageData(0, 0, c.width, c.height);
      const seen = new Set<number>();
      for (let i = 0; i < data.length; i += 4 * 97) seen.add((data[i]! << 16) | (data[i + 1]! << 8) | data[i + 2]!);
      return seen.size;
    });
    // Sky, floor, shadowed floor and lit cube faces at the very least; a blank canvas has one.
    expect(colours).toBeGreaterThan(8);
    await page.screenshot({ path: join(ARTIFACTS, '3d-stack.png') });
    expect(errors).toEqual([]);
  });

  it('toggles sleeping objects and mutable physics object types', async () => {
    // A short stack settles sooner, and both techniques only act on cubes at rest.
    await page.getByLabel('Stack height (cubes)').fill('3');
    await page.getByRole('button', { name: 'Drop the stack again' }).click();
    await page.waitForFunction(() => document.getElementById('sim-stats')?.dataset['cubes'] === '12');
    const sleeping = page.getByLabel('Sleeping objects');
    const mutable = page.getByLabel(/Mutable physics object types/);

    await mutable.check();
    await waitForStat(page, 'static', '>', 0); // landed cubes were made static
    await mutable.uncheck();
    await waitForStat(page, 'static', '==', 0); // and get their mass back

    await sleeping.check();
    await waitForStat(page, 'sleeping', '>', 0);
    await sleeping.uncheck();
    await waitForStat(page, 'sleeping', '==', 0); // turning sleeping off wakes every body
    expect(await sleeping.isChecked()).toBe(false);
    expect(errors).toEqual([]);
  });

  it('runs a short layered-drop experiment and shows three finite, positive averages', async () => {
    await page.getByLabel('Layers', { exact: true }).fill('3');
    await page.getByLabel('Cubes per layer side').fill('3');
    await page.getByLabel('Drop interval (steps)').fill('45');
    await page.getByLabel('Settle steps after the last layer').fill('180');
    // A box tidies an entry it cannot use to the value in use once the edit ends.
    const height = page.getByLabel('Stack height (cubes)');
    await height.fill('1000');
    await height.press('Tab');
    expect(await height.inputValue()).toBe('40');
    await height.fill('');
    await height.press('Tab');
    expect(await height.inputValue()).toBe('10');
    await page.getByRole('button', { name: 'Run the layered-drop experiment' }).click();
    // The live stack's controls are held while the experiment runs, and given back after.
    const drop = page.getByRole('button', { name: 'Drop the stack again' });
    expect(await drop.isDisabled()).toBe(true);
    await page.waitForSelector('#layered-drop-results[data-status="done"]', { state: 'attached', timeout: 30_000 });
    expect(await drop.isDisabled()).toBe(false);

    const cells = await page.$$eval('#layered-drop-results td[data-metric]', (tds) =>
      tds.map((td) => {
        const d = (td as HTMLElement).dataset;
        return { variant: d['variant'], metric: d['metric'], value: Number(d['value']) };
      }),
    );
    const pick = (metric: string) => cells.filter((c) => c.metric === metric);
    const averages = pick('average-ms');
    expect(averages.map((c) => c.variant)).toEqual(['control', 'sleeping', 'mutable']);
    for (const { value } of averages) {
      expect(Number.isFinite(value)).toBe(true);
      expect(value).toBeGreaterThan(0);
    }
    // Medians can round to 0 with the browser's coarse timer, but must be real numbers.
    for (const { value } of pick('median-ms')) expect(value).toBeGreaterThanOrEqual(0);
    // Same fixed setup for every variant: 3 layers × 45 steps + 180, and 27 cubes.
    for (const { value } of pick('steps')) expect(value).toBe(3 * 45 + 180);
    for (const { value } of pick('cubes')) expect(value).toBe(27);
    // Each technique did what it says: only the mutable variant froze cubes, only sleeping slept.
    const at = (metric: string, variant: string) => pick(metric).find((c) => c.variant === variant)?.value;
    expect(at('static-at-end', 'control')).toBe(0);
    expect(at('static-at-end', 'mutable')).toBeGreaterThan(0);
    expect(at('sleeping-at-end', 'control')).toBe(0);
    expect(at('sleeping-at-end', 'sleeping')).toBeGreaterThan(0);

    console.log('layered drop (3 layers of 3×3, 315 steps):', JSON.stringify(averages.concat(pick('median-ms'))));
    await page.locator('#layered-drop-results').scrollIntoViewIfNeeded();
    await page.screenshot({ path: join(ARTIFACTS, '3d-layered-drop.png') });
    expect(errors).toEqual([]);
  });
});
