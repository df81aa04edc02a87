import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type { Browser, Page } from 'playwright-core';
import { join } from 'node:path';
import { ARTIFACTS, launchBrowser, openPage, stat } from './browser.js';

// The engine's features in the 2D sandbox (issue 6): scenes with static shapes, the world-option
// toggles, the query tools. Read like a user reads the page: labels, shown counts and pixels.

const POLL = { timeout: 30_000, interval: 100 };
/** Static circles and segments are drawn in this grey (colors.ts STATIC_COLOR). */
const STATIC_RGB = [0xc3, 0xcc, 0xd6];
/** Ray hit markers on the overlay (overlay.ts HIT_COLOR). */
const HIT_RGB = [0xff, 0x7b, 0x72];
/** Rings at bodies hit in a collision (overlay.ts HIT_RING_COLOR). */
const HIT_RING_RGB = [0xd2, 0xa8, 0xff];
/** The Box tool's rectangle and highlights (overlay.ts BOX_COLOR). */
const BOX_RGB = [0x56, 0xd4, 0xdd];

let browser: Browser;

beforeAll(async () => {
  browser = await launchBrowser();
});

afterAll(async () => {
  await browser?.close();
});


async function stepsPass(page: Page, more: number): Promise<void> {
  await page.waitForFunction(
    (target) => Number(document.getElementById('stat-steps')?.textContent?.replace(/\D/g, '')) >= target,
    more,
    { timeout: 30_000 },
  );
}

/**
 * Page coordinates of a world point: the box is fitted into the stage keeping its aspect ratio and
 * centred, as anyone measuring the picture would find. `box` is the scene's box size.
 */
async function toPage(page: Page, box: { width: number; height: number }) {
  const stage = await page.locator('#overlay').boundingBox();
  if (!stage) throw new Error('no stage');
  const scale = Math.min(stage.width / box.width, stage.height / box.height);
  const ox = stage.x + (stage.width - box.width * scale) / 2;
  const oy = stage.y + (stage.height - box.height * scale) / 2;
  return (x: number, y: number) => ({ x: ox + x * scale, y: oy + y * scale });
}

/** RGB of page pixels at the given page points, from one screenshot. */
async function pixelsAt(page: Page, points: { x: number; y: number }[]): Promise<number[][]> {
  const png = await page.screenshot();
  return page.evaluate(
    async ([b64, pts]) => {
      const bitmap = await createImageBitmap(await (await fetch(`data:image/png;base64,${b64}`)).blob());
      const canvas = new OffscreenCanvas(bitmap.width, bitmap.height);
      const ctx = canvas.getContext('2d') as OffscreenCanvasRenderingContext2D;
      ctx.drawImage(bitmap, 0, 0);
      return pts.map((p) => Array.from(ctx.getImageData(Math.round(p.x), Math.round(p.y), 1, 1).data.slice(0, 3)));
    },
    [png.toString('base64'), points] as const,
  );
}

const near = (rgb: number[], want: number[], tolerance = 14) => rgb.every((c, i) => Math.abs(c - want[i]) <= tolerance);

/** Overlay pixels close to a colour: hit markers, which no other overlay drawing uses. */
async function overlayPixelsNear(page: Page, want: number[]): Promise<number> {
  return page.evaluate((w) => {
    const c = document.getElementById('overlay') as HTMLCanvasElement;
    const d = (c.getContext('2d', { willReadFrequently: true }) as CanvasRenderingContext2D).getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) {
      if (d[i + 3] > 200 && Math.abs(d[i] - w[0]) < 20 && Math.abs(d[i + 1] - w[1]) < 20 && Math.abs(d[i + 2] - w[2]) < 20) n++;
    }
    return n;
  }, want);
}

/** Pauses, or resumes when paused: the button reads Pause or Resume. */
function pause(page: Page) {
  return page.locator('#pause').click();
}

describe('2D sandbox: engine features', () => {
  it('draws the funnel scene: segments and pegs in both renderers, and bodies fall', async () => {
    const { page, errors } = await openPage(browser, '/?scene=funnel&n=300');
    await pause(page);
    await stepsPass(page, 1);
    expect(await page.getByLabel('Scene').inputValue()).toBe('funnel');
    // The funnel's own parameters, each with its spec's description as the tooltip.
    for (const name of ['Quantity', 'Gravity', 'Elasticity', 'Size']) {
      const input = page.getByLabel(new RegExp(`^${name} [-\\d]`));
      expect(await input.count(), name).toBe(1);
      expect(await input.locator('..').getAttribute('title'), name).toBeTruthy();
    }
    expect(await page.getByLabel(/^Velocity noise/).count()).toBe(0);
    // 300 falling circles and 51 static pegs.
    expect(await stat(page, 'bodies')).toBe(351);

    const at = await toPage(page, { width: 800, height: 900 });
    // Points along the left funnel wall (20,120)-(360,380) and on the first row of pegs.
    const wall = [0.15, 0.3, 0.45, 0.6, 0.75, 0.9].map((t) => at(20 + 340 * t, 120 + 260 * t));
    const pegs = [0, 2, 4, 6, 8].map((c) => at(120 + c * 70, 470));
    for (const renderer of ['canvas', 'webgl']) {
      await page.getByLabel('Renderer').selectOption(renderer);
      await page.waitForTimeout(300);
      const rgb = await pixelsAt(page, [...wall, ...pegs]);
      expect(rgb.slice(0, wall.length).filter((c) => near(c, STATIC_RGB)).length, `${renderer} wall ${JSON.stringify(rgb)}`).toBe(wall.length);
      expect(rgb.slice(wall.length).filter((c) => near(c, STATIC_RGB)).length, `${renderer} pegs ${JSON.stringify(rgb)}`).toBe(pegs.length);
    }
    await page.locator('#stage').screenshot({ path: join(ARTIFACTS, 'sandbox-funnel-start.png') });

    expect(await stat(page, 'lower-half')).toBe(0);
    await pause(page);
    await expect.poll(() => stat(page, 'lower-half'), POLL).toBeGreaterThan(150);
    expect(await page.locator('#row-segment-contacts').isVisible()).toBe(true);
    await expect.poll(() => stat(page, 'segment-contacts'), POLL).toBeGreaterThan(0);
    await page.locator('#stage').screenshot({ path: join(ARTIFACTS, 'sandbox-funnel.png') });
    expect(errors).toEqual([]);
    await page.close();
  });

  it('shows sleeping bodies with Sleeping on, and none once it is off', async () => {
    // Elasticity 0 and strong gravity: the funnel settles in a few seconds.
    const { page, errors } = await openPage(browser, '/?scene=funnel&n=300&elasticity=0&gravity=1500');
    await stepsPass(page, 2);
    expect(await stat(page, 'sleeping')).toBe(0);
    await page.getByLabel('Sleeping').check();
    await expect.poll(() => new URL(page.url()).searchParams.get('sleeping'), POLL).toBe('1');
    await expect.poll(() => stat(page, 'sleeping'), { timeout: 60_000, interval: 200 }).toBeGreaterThan(0);
    await page.getByLabel('Sleeping').uncheck();
    await expect.poll(() => new URL(page.url()).searchParams.get('sleeping'), POLL).toBeNull();
    await stepsPass(page, 30);
    expect(await stat(page, 'sleeping')).toBe(0);
    expect(errors).toEqual([]);
    await page.close();
  });

  it('with the Pile solver, a settled pile falls asleep as a whole', async () => {
    // The seed box at elasticity 0, with Sleeping: with one solver pass, 1,500 circles keep
    // moving faster than the sleep speed and at most 1 sleeps in 60 s (measured in Node); with
    // the Pile solver 95 % of them sleep 225 steps in.
    const { page, errors } = await openPage(browser, '/?n=1500&elasticity=0&sleeping=1&piles=1');
    expect(await page.getByLabel('Pile solver').isChecked()).toBe(true);
    await expect.poll(() => stat(page, 'sleeping'), { timeout: 90_000, interval: 250 }).toBeGreaterThanOrEqual(1425);
    expect(errors).toEqual([]);
    await page.close();
  });

  it('counts touch events, filtered pairs and swept bodies when their toggles are on', async () => {
    const { page, errors } = await openPage(browser, '/?n=1000');
    await stepsPass(page, 2);
    for (const row of ['begin', 'end', 'filtered']) expect(await page.locator(`#row-${row}`).isVisible(), row).toBe(false);
    // Continuous collision is the engine's default, so its row shows from the start.
    expect(await page.getByLabel('Continuous collision').isChecked()).toBe(true);
    expect(await page.locator('#row-swept').isVisible()).toBe(true);

    await page.getByLabel('Contact events').check();
    await expect.poll(() => page.locator('#row-begin').isVisible(), POLL).toBe(true);
    await expect.poll(() => stat(page, 'begin'), POLL).toBeGreaterThan(0);
    await expect.poll(() => stat(page, 'end'), POLL).toBeGreaterThan(0);
    // Bodies that just began a touch flash on the overlay.
    await expect.poll(() => overlayPixelsNear(page, [255, 255, 255]), POLL).toBeGreaterThan(0);

    await page.getByLabel('Collision layers').check();
    await expect.poll(() => page.locator('#row-filtered').isVisible(), POLL).toBe(true);
    await expect.poll(() => stat(page, 'filtered'), POLL).toBeGreaterThan(0);
    await page.getByLabel('Collision layers').uncheck();
    await expect.poll(() => page.locator('#row-filtered').isVisible(), POLL).toBe(false);

    await page.getByLabel('Continuous collision').uncheck();
    await expect.poll(() => page.locator('#row-swept').isVisible(), POLL).toBe(false);
    // False positives are now measured against the broad-phase's pair tests.
    expect(await stat(page, 'pair-tests')).toBeGreaterThanOrEqual(await stat(page, 'candidates'));
    expect(errors).toEqual([]);
    await page.close();
  });

  it('rings bodies hit in fast collisions and counts hits with Hit events on', async () => {
    // The default seed box is elastic with 1000 bodies at 100 ± 50 px/s: collisions every step.
    const { page, errors } = await openPage(browser, '/?n=1000');
    await stepsPass(page, 2);
    for (const row of ['hits', 'fastest-hit']) expect(await page.locator(`#row-${row}`).isVisible(), row).toBe(false);
    expect(await overlayPixelsNear(page, HIT_RING_RGB)).toBe(0);

    await page.getByLabel('Hit events').check();
    await expect.poll(() => new URL(page.url()).searchParams.get('hits'), POLL).toBe('1');
    await expect.poll(() => page.locator('#row-hits').isVisible(), POLL).toBe(true);
    await expect.poll(() => stat(page, 'hits'), POLL).toBeGreaterThan(0);
    // The fastest hit is at least the threshold, 50 px/s here (8 g·dt = 40 px/s is lower).
    await expect.poll(() => stat(page, 'fastest-hit'), POLL).toBeGreaterThanOrEqual(50);
    expect(await page.locator('#stat-fastest-hit').innerText()).toMatch(/px\/s$/);
    await expect.poll(() => overlayPixelsNear(page, HIT_RING_RGB), POLL).toBeGreaterThan(20);
    await page.locator('#stage').screenshot({ path: join(ARTIFACTS, 'sandbox-hits.png') });

    // Off again: the rows hide and the rings are gone with the rebuilt world.
    await page.getByLabel('Hit events').uncheck();
    await expect.poll(() => page.locator('#row-hits').isVisible(), POLL).toBe(false);
    await expect.poll(() => new URL(page.url()).searchParams.get('hits'), POLL).toBeNull();
    await expect.poll(() => overlayPixelsNear(page, HIT_RING_RGB), POLL).toBe(0);
    expect(errors).toEqual([]);
    await page.close();
  });

  it('casts a ray across the bodies it crosses, and points at the body under the pointer', async () => {
    // An empty, still box; three circles added by clicks on a horizontal line.
    const { page, errors } = await openPage(browser, '/?n=0&gravity=0&velocity=0&size=20');
    await pause(page);
    const at = await toPage(page, { width: 1600, height: 900 });
    for (const x of [400, 800, 1200]) {
      const p = at(x, 450);
      await page.mouse.click(p.x, p.y);
    }
    await expect.poll(() => stat(page, 'bodies'), POLL).toBe(3);

    await page.getByLabel('Tool').selectOption('ray');
    expect(new URL(page.url()).searchParams.get('tool')).toBe('ray');
    const from = at(100, 450);
    const to = at(1500, 450);
    await page.mouse.move(from.x, from.y);
    await page.mouse.down();
    await page.mouse.move((from.x + to.x) / 2, from.y, { steps: 3 });
    await page.mouse.move(to.x, to.y, { steps: 3 });
    await page.mouse.up();
    const readout = page.locator('#query-readout');
    await expect.poll(() => readout.innerText(), POLL).toMatch(/^Ray: 3 hits/);
    // The first body crossed is the first one added (handle 0); the ray enters it at x = 380 of a
    // ray from 100 to 1500, a fraction of 0.2, give or take a pixel of pointer rounding.
    const [, handle, fraction] = /first: body (\d+) at fraction ([\d.]+)/.exec(await readout.innerText()) ?? [];
    expect(Number(handle)).toBe(0);
    expect(Number(fraction)).toBeCloseTo(0.2, 2);
    expect(await overlayPixelsNear(page, HIT_RGB)).toBeGreaterThan(20);
    // Clicks with the Ray tool add nothing.
    expect(await stat(page, 'bodies')).toBe(3);
    // A ray that misses everything.
    const high = at(100, 100);
    await page.mouse.move(high.x, high.y);
    await page.mouse.down();
    await page.mouse.move(at(1500, 100).x, high.y, { steps: 3 });
    await page.mouse.up();
    await expect.poll(() => readout.innerText(), POLL).toBe('Ray: 0 hits');
    await page.locator('#stage').screenshot({ path: join(ARTIFACTS, 'sandbox-ray.png') });

    await page.getByLabel('Tool').selectOption('point');
    const middle = at(805, 445);
    await page.mouse.move(middle.x, middle.y);
    await expect.poll(() => readout.innerText(), POLL).toBe('Point: 1 body under the pointer (1)');
    await page.mouse.move(high.x, high.y);
    await expect.poll(() => readout.innerText(), POLL).toMatch(/^Point: 0 bodies/);

    // A box over all three (radius 20 at x = 400, 800, 1200), then one over empty space.
    await page.getByLabel('Tool').selectOption('box');
    expect(new URL(page.url()).searchParams.get('tool')).toBe('box');
    expect(await readout.innerText()).toMatch(/^Box: drag/);
    const drag = async (x1: number, y1: number, x2: number, y2: number) => {
      const a = at(x1, y1);
      const b = at(x2, y2);
      await page.mouse.move(a.x, a.y);
      await page.mouse.down();
      await page.mouse.move((a.x + b.x) / 2, (a.y + b.y) / 2, { steps: 3 });
      await page.mouse.move(b.x, b.y, { steps: 3 });
      await page.mouse.up();
    };
    await drag(300, 350, 1300, 550);
    await expect.poll(() => readout.innerText(), POLL).toBe('Box: 3 bodies');
    expect(await overlayPixelsNear(page, BOX_RGB)).toBeGreaterThan(100);
    await page.locator('#stage').screenshot({ path: join(ARTIFACTS, 'sandbox-box.png') });
    // Dragged up and to the left, covering only the middle body.
    await drag(900, 520, 700, 380);
    await expect.poll(() => readout.innerText(), POLL).toBe('Box: 1 body');
    await drag(100, 50, 1500, 300);
    await expect.poll(() => readout.innerText(), POLL).toBe('Box: 0 bodies');
    // Drags with the Box tool add nothing.
    expect(await stat(page, 'bodies')).toBe(3);
    expect(errors).toEqual([]);
    await page.close();
  });

  it('finds hits with a ray across a busy scene', async () => {
    const { page, errors } = await openPage(browser, '/?n=1000&tool=ray');
    await stepsPass(page, 2);
    await pause(page);
    const at = await toPage(page, { width: 1600, height: 900 });
    const a = at(50, 300);
    const b = at(1550, 600);
    await page.mouse.move(a.x, a.y);
    await page.mouse.down();
    await page.mouse.move(b.x, b.y, { steps: 4 });
    await page.mouse.up();
    const text = await page.locator('#query-readout').innerText();
    const hits = Number(/^Ray: (\d+) hit/.exec(text)?.[1]);
    expect(hits, text).toBeGreaterThan(0);
    expect(await overlayPixelsNear(page, HIT_RGB)).toBeGreaterThan(0);
    expect(errors).toEqual([]);
    await page.close();
  });

  it('keeps scene, parameters, toggles and tool in the URL; bad values fall back', async () => {
    const { page, errors } = await openPage(browser, '/?n=100');
    await page.getByLabel('Scene').selectOption('uniform');
    await expect.poll(() => new URL(page.url()).searchParams.get('scene'), POLL).toBe('uniform');
    await page.getByLabel(/^Fill /).fill('0.4');
    await page.getByLabel(/^Quantity /).fill('300');
    await page.getByLabel('Sleeping').check();
    await page.getByLabel('Pile solver').check();
    await page.getByLabel('Contact events').check();
    await page.getByLabel('Hit events').check();
    await page.getByLabel('Collision layers').check();
    await page.getByLabel('Continuous collision').uncheck();
    await page.getByLabel('Tool').selectOption('box');
    await expect.poll(() => new URL(page.url()).searchParams.get('tool'), POLL).toBe('box');
    const read = async () => ({
      scene: await page.getByLabel('Scene').inputValue(),
      labels: await page.locator('#scene-controls label').allInnerTexts(),
      toggles: await Promise.all(
        ['Sleeping', 'Pile solver', 'Continuous collision', 'Contact events', 'Hit events', 'Collision layers'].map((n) => page.getByLabel(n).isChecked()),
      ),
      tool: await page.getByLabel('Tool').inputValue(),
      bodies: await stat(page, 'bodies'),
    });
    await stepsPass(page, 2);
    const before = await read();
    expect(before.toggles).toEqual([true, true, false, true, true, true]);
    expect(before.labels.join('|')).toMatch(/Fill\s+40%/);
    const url = new URL(page.url());
    expect(url.searchParams.get('continuous')).toBe('0');
    expect(url.searchParams.get('fill')).toBe('0.4');
    expect(url.searchParams.get('hits')).toBe('1');
    expect(url.searchParams.get('piles')).toBe('1');
    await page.reload({ waitUntil: 'load' });
    await stepsPass(page, 2);
    expect(await read()).toEqual(before);

    // Unknown scene, toggle and tool values fall back to the defaults.
    const bad = page.url().replace('scene=uniform', 'scene=bogus').replace('sleeping=1', 'sleeping=yes').replace('hits=1', 'hits=true');
    await page.goto(bad.replace('tool=box', 'tool=laser'));
    await stepsPass(page, 2);
    expect(await page.getByLabel('Scene').inputValue()).toBe('seed-box');
    expect(await page.getByLabel('Sleeping').isChecked()).toBe(false);
    expect(await page.getByLabel('Hit events').isChecked()).toBe(false);
    expect(new URL(page.url()).searchParams.get('hits')).toBeNull();
    expect(await page.getByLabel('Tool').inputValue()).toBe('drag');
    // A funnel that cannot hold its circles is refused with a notice; its defaults are built instead.
    await page.goto(page.url().replace(/\?.*/, '?scene=funnel&n=5000&size=12'));
    await stepsPass(page, 2);
    expect(await page.locator('#notice').innerText()).toMatch(/fit above the funnel.*; using the scene's defaults\./);
    expect(await stat(page, 'bodies')).toBe(551);
    expect(errors).toEqual([]);
    await page.close();
  });

  it('fits a narrow window: the stage full width above the monitor and controls, no sideways scroll', async () => {
    const { page, errors } = await openPage(browser, '/?n=500');
    await page.setViewportSize({ width: 400, height: 800 });
    await stepsPass(page, 5);
    const layout = await page.evaluate(() => ({
      scrollWidth: document.documentElement.scrollWidth,
      stage: document.getElementById('stage')!.getBoundingClientRect().toJSON() as DOMRect,
      controls: document.querySelector('.controls')!.getBoundingClientRect().toJSON() as DOMRect,
    }));
    expect(layout.scrollWidth).toBeLessThanOrEqual(400);
    expect(layout.stage.width).toBeGreaterThan(350);
    expect(layout.controls.top).toBeGreaterThan(layout.stage.bottom);
    expect(errors).toEqual([]);
    await page.close();
  });

  it('steps on Web Workers with the Threads control, and stops them again', async () => {
    // 40,000 bodies: above the engine's default minBodies, so the workers take part in each step.
    const { page, errors } = await openPage(browser, '/?scene=uniform&n=40000');
    await stepsPass(page, 2);
    expect(page.workers()).toHaveLength(0);
    expect(await page.getByLabel('Threads').locator('option').allInnerTexts()).toContain('2');
    await page.getByLabel('Threads').selectOption('2');
    await expect.poll(() => page.workers().length, POLL).toBe(1);
    const steps = await stat(page, 'steps');
    await stepsPass(page, steps + 5);
    expect(new URL(page.url()).searchParams.get('threads')).toBe('2');
    expect(await stat(page, 'bodies')).toBe(40_000);

    await page.getByLabel('Threads').selectOption('1');
    await expect.poll(() => page.workers().length, POLL).toBe(0);
    await stepsPass(page, (await stat(page, 'steps')) + 2);
    // From the URL too: the link reproduces the choice.
    await page.goto(page.url().replace(/\?.*/, '?scene=uniform&n=40000&threads=2'));
    await expect.poll(() => page.workers().length, POLL).toBe(1);
    expect(await page.getByLabel('Threads').inputValue()).toBe('2');
    // A URL asking for more threads than the machine offers runs the most it offers, and says so in the URL.
    const cores = await page.evaluate(() => navigator.hardwareConcurrency);
    const offered = [8, 4, 2, 1].find((count) => count <= cores) ?? 1;
    await page.goto(page.url().replace(/\?.*/, '?scene=uniform&n=40000&threads=8'));
    await expect.poll(() => page.workers().length, POLL).toBe(offered - 1);
    expect(await page.getByLabel('Threads').inputValue()).toBe(String(offered));
    await expect.poll(() => new URL(page.url()).searchParams.get('threads'), POLL).toBe(offered === 1 ? null : String(offered));
    expect(errors).toEqual([]);
    await page.close();
  });

  it('never freezes: a broad-phase over the pair budget is refused with its reason, and a slow one says it falls behind', async () => {
    // 50,000 circles of the seed box: sap-xy would examine about 19 million pairs a step (4-5 s a step before it swept one axis).
    const { page, errors } = await openPage(browser, '/?n=50000&broadphase=sap-xy');
    await stepsPass(page, 2);
    expect(await page.getByLabel('Broad-phase').inputValue()).toBe('auto');
    expect(await page.locator('#notice').innerText()).toMatch(/sap-xy would examine [\d.]+ million pairs a step/);
    const option = page.locator('#broadphase option[value="sap-xy"]');
    expect(await option.isDisabled()).toBe(true);
    expect(await option.getAttribute('title')).toMatch(/over the page's budget/);
    // The grids are linear whatever the count: always offered.
    for (const name of ['maxgrid', 'hgrid', 'auto']) expect(await page.locator(`#broadphase option[value="${name}"]`).isDisabled()).toBe(false);
    // Fewer bodies: sap-xy is offered again.
    await page.goto(page.url().replace(/n=\d+/, 'n=2000'));
    await stepsPass(page, 2);
    expect(await page.locator('#broadphase option[value="sap-xy"]').isDisabled()).toBe(false);

    // Naive at 3,000 bodies is within the budget (4.5 million pairs) but steps far slower than
    // the frames: the page runs slow, says so, and keeps drawing frames.
    await page.goto(page.url().replace(/\?.*/, '?n=3000&broadphase=naive'));
    await stepsPass(page, 2);
    expect(await page.getByLabel('Broad-phase').inputValue()).toBe('naive');
    await expect.poll(() => page.locator('#pace').innerText(), POLL).toMatch(/Falling behind real time: 0\.\d\d×/);
    const gaps = await page.evaluate(async () => {
      const seen: number[] = [];
      await new Promise<void>((done) => {
        const tick = (t: number) => {
          seen.push(t);
          if (seen.length < 15) requestAnimationFrame(tick);
          else done();
        };
        requestAnimationFrame(tick);
      });
      return seen.slice(1).map((t, i) => t - seen[i]);
    });
    expect(Math.max(...gaps)).toBeLessThan(1000);
    expect(errors).toEqual([]);
    await page.close();
  });
});
