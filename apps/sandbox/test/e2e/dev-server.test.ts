import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type { Browser, Page } from 'playwright-core';
import { colourfulPixels, launchWarmedBrowser, openPage, stat } from './browser.js';

// The other sandbox tests load its production build. This one loads the dev server that `npm
// start` runs, which serves the workspace packages from source, module by module: a shape scene
// and a circle scene on two threads step and draw there without console errors.

let browser: Browser;

beforeAll(async () => {
  browser = await launchWarmedBrowser('/?scene=pyramid&base=4');
});

afterAll(async () => {
  await browser?.close();
});

async function stepsPass(page: Page, target: number): Promise<void> {
  await page.waitForFunction((t) => Number(document.getElementById('stat-steps')?.textContent?.replace(/\D/g, '')) >= t, target, { timeout: 30_000 });
}

describe("the sandbox on npm start's dev server", () => {
  it('steps and draws a pyramid of boxes, on the shape route', async () => {
    const { page, errors } = await openPage(browser, '/?scene=pyramid&base=8', 'dev');
    await stepsPass(page, 5);
    expect(await page.evaluate(() => window.__sandboxProbe!.route())).toBe('shapes');
    expect(await colourfulPixels(page)).toBeGreaterThan(200);
    expect(errors).toEqual([]);
    await page.close();
  });

  it('steps circles on two threads, the second a Web Worker started from source', async () => {
    const { page, errors } = await openPage(browser, '/?scene=uniform&n=40000&threads=2', 'dev');
    await expect.poll(() => page.workers().length, { timeout: 30_000, interval: 100 }).toBe(1);
    await stepsPass(page, (await stat(page, 'steps')) + 5);
    expect(await stat(page, 'bodies')).toBe(40_000);
    expect(errors).toEqual([]);
    await page.close();
  });
});
