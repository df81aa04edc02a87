import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type { Browser, Page } from 'playwright-core';
import { launchBrowser, openPage, overlayPixels, stat } from './browser.js';

// What the page tells a user and where it puts it: the overfill warning, the pause button's name,
// the controls at a common laptop size, and the grid overlay's extent.

const POLL = { timeout: 30_000, interval: 100 };

let browser: Browser;

beforeAll(async () => {
  browser = await launchBrowser();
});

afterAll(async () => {
  await browser?.close();
});

async function stepsPass(page: Page, after: number, more = 3): Promise<void> {
  await page.waitForFunction(
    (target) => Number(document.getElementById('stat-steps')?.textContent?.replace(/\D/g, '')) >= target,
    after + more,
    { timeout: 30_000 },
  );
}

/**
 * Painted overlay pixels more than `margin` device pixels outside the box's drawn rectangle, which
 * is found through the page's own mapping from the world to CSS pixels.
 */
async function overlayPixelsOutsideBox(page: Page, margin = 1): Promise<number> {
  return page.evaluate((margin) => {
    const probe = window.__sandboxProbe!;
    const r = probe.region();
    const a = probe.toCss(r.x, r.y);
    const b = probe.toCss(r.x + r.width, r.y + r.height);
    const c = document.getElementById('overlay') as HTMLCanvasElement;
    const k = c.width / c.clientWidth;
    const [x0, y0, x1, y1] = [a.x * k - margin, a.y * k - margin, b.x * k + margin, b.y * k + margin];
    const d = (c.getContext('2d', { willReadFrequently: true }) as CanvasRenderingContext2D).getImageData(0, 0, c.width, c.height).data;
    let count = 0;
    for (let y = 0; y < c.height; y++) {
      for (let x = 0; x < c.width; x++) {
        if (d[(y * c.width + x) * 4 + 3] === 0) continue;
        if (x + 1 < x0 || x > x1 || y + 1 < y0 || y > y1) count++;
      }
    }
    return count;
  }, margin);
}

describe('2D sandbox: warnings and layout', () => {
  it('warns when the circles cover more than the box, and says by how much', async () => {
    // The case: 50,000 default circles cover 4.3 times the box.
    const { page, errors } = await openPage(browser, '/?n=50000');
    await page.locator('#pause').click();
    const warning = page.locator('#overfill');
    await expect.poll(() => warning.isVisible(), POLL).toBe(true);
    expect(await warning.innerText()).toMatch(/4\.3x the box's area/);
    // Down to the fewest circles the slider allows: they fit, and the warning goes.
    const quantity = page.getByLabel(/^Quantity [\d]/);
    await quantity.fill(await quantity.getAttribute('min') as string);
    await expect.poll(() => stat(page, 'bodies'), POLL).toBeLessThan(1000);
    await expect.poll(() => warning.isVisible(), POLL).toBe(false);
    expect(await warning.innerText()).toBe('');
    expect(errors).toEqual([]);
    await page.close();
  });

  it('shows no warning for the default scene, which fits', async () => {
    const { page, errors } = await openPage(browser, '/');
    await stepsPass(page, 0);
    expect(await page.locator('#overfill').isVisible()).toBe(false);
    expect(errors).toEqual([]);
    await page.close();
  });

  it('names the pause button after what a click does: Resume while paused, Pause while running', async () => {
    const { page, errors } = await openPage(browser, '/?n=100');
    await stepsPass(page, 0);
    const button = page.locator('#pause');
    expect(await button.innerText()).toBe('Pause');
    expect(await button.getAttribute('aria-pressed')).toBe('false');
    await button.click();
    expect(await button.innerText()).toBe('Resume');
    expect(await button.getAttribute('aria-pressed')).toBe('true');
    expect(await page.getByRole('button', { name: 'Resume', exact: true }).count()).toBe(1);
    expect(await page.getByRole('button', { name: 'Pause', exact: true }).count()).toBe(0);
    const paused = await stat(page, 'steps');
    await page.waitForTimeout(300);
    expect(await stat(page, 'steps')).toBe(paused);
    await page.getByRole('button', { name: 'Resume', exact: true }).click();
    expect(await button.innerText()).toBe('Pause');
    expect(await button.getAttribute('aria-pressed')).toBe('false');
    await stepsPass(page, paused);
    expect(errors).toEqual([]);
    await page.close();
  });

  it('at 1400 x 900 shows the Pause, Step and Reset buttons and the View section without scrolling', async () => {
    const { page, errors } = await openPage(browser, '/');
    await page.setViewportSize({ width: 1400, height: 900 });
    await stepsPass(page, 0);
    const scrolled = await page.evaluate(() => ({ page: window.scrollY, controls: document.querySelector('.controls')!.scrollTop }));
    expect(scrolled).toEqual({ page: 0, controls: 0 });
    const view = page.locator('fieldset', { has: page.locator('legend', { hasText: /^View$/ }) });
    for (const [name, target] of [
      ['Pause', page.locator('#pause')],
      ['Step', page.getByRole('button', { name: 'Step', exact: true })],
      ['Reset', page.getByRole('button', { name: 'Reset', exact: true })],
      ['View', view],
    ] as const) {
      const box = await target.boundingBox();
      if (!box) throw new Error(`${name} has no box`);
      expect(box.y, name).toBeGreaterThanOrEqual(0);
      expect(box.y + box.height, name).toBeLessThanOrEqual(900);
      expect(box.x + box.width, name).toBeLessThanOrEqual(1400);
    }
    // Within the viewport and also not clipped by the controls' own scrolling box.
    const controls = await page.locator('.controls').boundingBox();
    const viewBox = await view.boundingBox();
    expect(viewBox!.y + viewBox!.height).toBeLessThanOrEqual(controls!.y + controls!.height);
    expect(errors).toEqual([]);
    await page.close();
  });

  it('at 1400 x 900 puts the timeline bar between the stage and the monitor, all in the window, with a load message too', async () => {
    const { page, errors } = await openPage(browser, '/');
    await page.setViewportSize({ width: 1400, height: 900 });
    await stepsPass(page, 0);
    const boxes = async () => {
      const out: Record<string, { x: number; y: number; width: number; height: number }> = {};
      for (const id of ['stage', 'timeline', 'step-back', 'scrubber', 'scrub-step', 'save', 'load']) {
        const box = await page.locator(`#${id}`).boundingBox();
        if (!box) throw new Error(`#${id} has no box`);
        out[id] = box;
      }
      const monitor = await page.locator('.monitor').boundingBox();
      if (!monitor) throw new Error('the monitor has no box');
      out.monitor = monitor;
      return out;
    };
    const check = async (label: string) => {
      const b = await boxes();
      expect(b.timeline.y, label).toBeGreaterThanOrEqual(b.stage.y + b.stage.height);
      expect(b.monitor.y, label).toBeGreaterThanOrEqual(b.timeline.y + b.timeline.height);
      expect(b.monitor.y + b.monitor.height, label).toBeLessThanOrEqual(900);
      for (const id of ['step-back', 'scrubber', 'scrub-step', 'save', 'load']) {
        expect(b[id].y, `${label} ${id}`).toBeGreaterThanOrEqual(b.timeline.y);
        expect(b[id].y + b[id].height, `${label} ${id}`).toBeLessThanOrEqual(b.timeline.y + b.timeline.height);
        expect(b[id].x + b[id].width, `${label} ${id}`).toBeLessThanOrEqual(1400);
      }
      // One row: the scrubber keeps most of the width.
      expect(b.scrubber.width, label).toBeGreaterThan(b.timeline.width / 2);
    };
    await check('bar');
    // A refused file's message shows under the bar, and the monitor still fits.
    await page.locator('#load-file').setInputFiles({ name: 'junk.mxgs', mimeType: 'application/octet-stream', buffer: Buffer.from('junk') });
    await expect.poll(() => page.locator('#timeline-status').isVisible(), POLL).toBe(true);
    await check('with a message');
    expect(await page.evaluate(() => window.scrollY)).toBe(0);
    expect(errors).toEqual([]);
    await page.close();
  });

  it('draws the Max Grid overlay inside the box only', async () => {
    const { page, errors } = await openPage(browser, '/?n=500&grid=1&broadphase=maxgrid');
    // A taller window leaves room below the box, where the grid's last row would show.
    await page.setViewportSize({ width: 1400, height: 1150 });
    await stepsPass(page, 0, 30);
    await expect.poll(() => overlayPixels(page), POLL).toBeGreaterThan(1000);
    // The grid covers the circles' extent, so whether it would reach past the walls changes from
    // step to step as they move: look at many frames, over two seconds of falling and spreading.
    let outside = 0;
    for (let k = 0; k < 12; k++) {
      outside = Math.max(outside, await overlayPixelsOutsideBox(page));
      await page.waitForTimeout(150);
    }
    expect(outside).toBe(0);
    // Clipped at the walls, not shrunk away from them: lines still run up to the box's edges.
    await page.locator('#pause').click();
    expect(await overlayPixelsOutsideBox(page, -3)).toBeGreaterThan(0);
    expect(errors).toEqual([]);
    await page.close();
  });
});
