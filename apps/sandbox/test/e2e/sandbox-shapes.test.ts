import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type { Browser, Page } from 'playwright-core';
import { join } from 'node:path';
import { ARTIFACTS, colourfulPixels, launchBrowser, openPage, overlayPixels, stat } from './browser.js';

// The sandbox with shapes: every scene draws without console errors in both renderers, shapes are
// drawn turned, the drag spring pulls a box out of a stack, clicks add shapes, and the contact
// overlay shows points.

const SHAPE_SCENES = ['polygon-box', 'pyramid', 'uniform-polygons', 'many-pyramids', 'tumbler', 'vertical-stack', 'card-house', 'ramp'];
const CIRCLE_SCENES = ['seed-box', 'funnel', 'mixed', 'uniform'];
/** Small versions, so every scene loads quickly on a two-core machine. */
const SMALL: Record<string, string> = {
  'polygon-box': 'n=300',
  pyramid: 'base=12',
  'uniform-polygons': 'n=400',
  'many-pyramids': 'rows=3&columns=3',
  tumbler: 'grid=15',
  'seed-box': 'n=200',
  funnel: 'n=200',
  mixed: 'n=200',
  uniform: 'n=200',
};

let browser: Browser;

beforeAll(async () => {
  browser = await launchBrowser();
});

afterAll(async () => {
  await browser?.close();
});


async function stepsPass(page: Page, target: number): Promise<void> {
  await page.waitForFunction((t) => Number(document.getElementById('stat-steps')?.textContent?.replace(/\D/g, '')) >= t, target, { timeout: 30_000 });
}



describe('sandbox with shapes', () => {
  it('every scene, circles and shapes, steps and draws in canvas 2D and WebGL without console errors', async () => {
    for (const scene of [...SHAPE_SCENES, ...CIRCLE_SCENES]) {
      for (const renderer of ['canvas', 'webgl']) {
        const { page, errors } = await openPage(browser, `/?scene=${scene}&renderer=${renderer}${SMALL[scene] ? `&${SMALL[scene]}` : ''}`);
        await stepsPass(page, 3);
        expect(await colourfulPixels(page), `${scene} ${renderer}`).toBeGreaterThan(200);
        if (SHAPE_SCENES.includes(scene)) expect(await page.evaluate(() => window.__sandboxProbe!.route()), scene).toBe('shapes');
        expect(errors, `${scene} ${renderer}`).toEqual([]);
        await page.close();
      }
    }
  });

  it('draws boxes turned: a spinning box covers different pixels as it turns', async () => {
    for (const renderer of ['canvas', 'webgl']) {
      // One big box spinning in the middle of an empty box: a polygon-box of one body, no gravity.
      const { page, errors } = await openPage(browser, `/?scene=polygon-box&n=1&size=150&sizeNoise=0&velocity=0&gravity=0&spin=30&renderer=${renderer}`);
      await stepsPass(page, 3);
      await page.locator('#pause').click();
      const a = await page.locator('#stage').screenshot();
      const angleA = await page.evaluate(() => window.__sandboxProbe!.pose(0).angle);
      await page.locator('#step').click();
      await page.locator('#step').click();
      await page.locator('#step').click();
      const angleB = await page.evaluate(() => window.__sandboxProbe!.pose(0).angle);
      const b = await page.locator('#stage').screenshot();
      expect(Math.abs(angleB - angleA), renderer).toBeGreaterThan(0.05);
      expect(Buffer.compare(a, b), renderer).not.toBe(0);
      await page.screenshot({ path: join(ARTIFACTS, `sandbox-box-${renderer}.png`) });
      expect(errors).toEqual([]);
      await page.close();
    }
  });

  it('the drag spring pulls a box out of a stack and the stack falls, rather than the box jumping', async () => {
    const { page, errors } = await openPage(browser, '/?scene=vertical-stack&count=6');
    await stepsPass(page, 30);
    const probe = (h: number) => page.evaluate((k) => window.__sandboxProbe!.pose(k), h);
    // Body 3 is the third box from the ground (body 0 is the ground); pull it far to the right.
    const before = await probe(3);
    const top0 = await probe(6);
    const at = await page.evaluate((p) => window.__sandboxProbe!.toCss(p.x, p.y), before);
    const box = await page.locator('#overlay').boundingBox();
    await page.mouse.move(box!.x + at.x, box!.y + at.y);
    await page.mouse.down();
    const far = await page.evaluate((p) => window.__sandboxProbe!.toCss(p.x + 4, p.y), before);
    await page.mouse.move(box!.x + far.x, box!.y + far.y, { steps: 5 });
    // Sampled as it goes: a spring carries the box there over several steps, a teleport in one.
    const path: number[] = [];
    for (let k = 0; k < 40; k++) {
      path.push((await probe(3)).x - before.x);
      await page.waitForTimeout(15);
    }
    await stepsPass(page, (await stat(page, 'steps')) + 60);
    await page.mouse.up();
    const pulled = await probe(3);
    const top = await probe(6);
    expect(pulled.type).toBe('dynamic');
    // It followed the pointer out of the stack...
    expect(pulled.x - before.x).toBeGreaterThan(2);
    // ...but not in one jump: it was seen on its way, between where it was and where it went.
    expect(path.some((dx) => dx > 0.2 && dx < 3)).toBe(true);
    // and the boxes above it fell: the top one is lower (larger y) than it was.
    expect(top.y - top0.y).toBeGreaterThan(0.5);
    expect(errors).toEqual([]);
    await page.close();
  });

  it('a click adds the chosen shape, and the contact overlay shows points', async () => {
    const { page, errors } = await openPage(browser, '/?scene=seed-box&n=50&gravity=0');
    await stepsPass(page, 2);
    expect(await page.evaluate(() => window.__sandboxProbe!.route())).toBe('circles');
    await page.getByLabel('Click adds').selectOption('box');
    const region = await page.evaluate(() => window.__sandboxProbe!.region());
    const at = await page.evaluate((r) => window.__sandboxProbe!.toCss(r.x + r.width / 2, r.y + r.height / 2), region);
    const box = await page.locator('#overlay').boundingBox();
    const bodies = await stat(page, 'bodies');
    await page.mouse.click(box!.x + at.x, box!.y + at.y);
    await page.waitForFunction((n) => Number(document.getElementById('stat-bodies')?.textContent?.replace(/\D/g, '')) === n + 1, bodies, { timeout: 10_000 });
    expect(await page.evaluate(() => window.__sandboxProbe!.route())).toBe('shapes');
    await page.close();
    expect(errors).toEqual([]);

    const second = await openPage(browser, '/?scene=pyramid&base=8');
    await stepsPass(second.page, 5);
    expect(await overlayPixels(second.page)).toBe(0);
    await second.page.getByLabel('Contact points').check();
    await second.page.waitForFunction(() => {
      const c = document.getElementById('overlay') as HTMLCanvasElement;
      const d = (c.getContext('2d', { willReadFrequently: true }) as CanvasRenderingContext2D).getImageData(0, 0, c.width, c.height).data;
      for (let i = 3; i < d.length; i += 4) if (d[i] > 0) return true;
      return false;
    }, undefined, { timeout: 10_000 });
    expect(await overlayPixels(second.page)).toBeGreaterThan(100);
    await second.page.screenshot({ path: join(ARTIFACTS, 'sandbox-pyramid-contacts.png') });
    expect(second.errors).toEqual([]);
    await second.page.close();
  });
});
