import { afterAll, afterEach, beforeAll, describe, expect, it } from 'vitest';
import type { Browser, Page } from 'playwright-core';
import { join } from 'node:path';
import { ARTIFACTS, launchBrowser, openPage } from './browser.js';
// For its window.__example declaration.
import type {} from '../../examples/test-hook.js';

/**
 * The debug-draw examples (apps/sandbox/examples) draw what world.debugRender() describes. Each
 * check pauses the page's world, reads the canvas from a screenshot (the same for Canvas 2D and
 * WebGL), and compares it with the lines the world gives, mapped through the transform the page
 * exposes: the lines' pixels must be drawn, in their colours, the pixels far from every line must
 * be background, and the outline of a known body, placed from world.getBody, must be drawn.
 * A renderer that draws nothing, flips y, draws at another scale or leaves lines out fails.
 */

const PAGES = [
  ['Canvas 2D', '/examples/debug-canvas.html'],
  ['PixiJS', '/examples/debug-pixi.html'],
  ['three.js', '/examples/debug-three.html'],
] as const;

interface Check {
  steps: number;
  lineCount: number;
  drawnLines: number;
  /** Points along the lines, about 2 px apart, inside the canvas, and those with a drawn pixel within one pixel. */
  linePoints: number;
  linePointsDrawn: number;
  /** Of the drawn line points, those whose brightest nearby pixel has the line's hue. */
  linePointsInColour: number;
  /** Grid points at least 4 px from every line, and those that are drawn. */
  emptyPoints: number;
  emptyPointsDrawn: number;
  /** Points on the outline of the first ragdoll's head (body 1), and those drawn. */
  headPoints: number;
  headPointsDrawn: number;
  headY: number;
  /** Drawn pixels, one flag per pixel, for comparing two pictures. */
  drawn: string;
}

async function hookValue(page: Page, key: 'steps' | 'frames'): Promise<number> {
  return page.evaluate((k) => window.__example?.[k] ?? -1, key);
}

async function waitFor(page: Page, key: 'steps' | 'frames', above: number): Promise<void> {
  await page.waitForFunction(([k, v]) => (window.__example?.[k as 'steps' | 'frames'] ?? -1) > (v as number), [key, above] as const, { timeout: 30_000, polling: 50 });
}

/** Pauses the world, waits for two frames drawn after it, and checks the canvas against the world. */
async function pausedCheck(page: Page, shot: string): Promise<Check> {
  await page.evaluate(() => {
    window.__example!.paused = true;
  });
  await waitFor(page, 'frames', (await hookValue(page, 'frames')) + 1);
  const png = await page.locator('#view').screenshot({ path: join(ARTIFACTS, shot) });
  return page.evaluate(async (b64) => {
    const hook = window.__example!;
    const bitmap = await createImageBitmap(await (await fetch(`data:image/png;base64,${b64}`)).blob());
    const w = bitmap.width;
    const h = bitmap.height;
    const canvas = new OffscreenCanvas(w, h);
    const ctx = canvas.getContext('2d') as OffscreenCanvasRenderingContext2D;
    ctx.drawImage(bitmap, 0, 0);
    const d = ctx.getImageData(0, 0, w, h).data;
    // The examples' background, #11161c; drawn means clearly brighter.
    const isDrawn = (x: number, y: number) => {
      const i = 4 * (y * w + x);
      return Math.abs(d[i] - 0x11) + Math.abs(d[i + 1] - 0x16) + Math.abs(d[i + 2] - 0x1c) > 60;
    };
    const inside = (sx: number, sy: number) => sx >= 2 && sy >= 2 && sx < w - 2 && sy < h - 2;
    /** The brightest pixel within one pixel of (sx, sy), or -1 when none is drawn. */
    const brightestNear = (sx: number, sy: number) => {
      let best = -1;
      let bestSum = -1;
      for (let y = Math.floor(sy) - 1; y <= Math.floor(sy) + 1; y++) {
        for (let x = Math.floor(sx) - 1; x <= Math.floor(sx) + 1; x++) {
          if (!isDrawn(x, y)) continue;
          const i = 4 * (y * w + x);
          const sum = d[i] + d[i + 1] + d[i + 2];
          if (sum > bestSum) [best, bestSum] = [i, sum];
        }
      }
      return best;
    };
    const { world, view } = hook;
    const toX = (x: number) => (x - view.left) * view.scale;
    const toY = (y: number) => (y - view.top) * view.scale;

    const { lineCount, vertices, colors } = world.debugRender();
    const screen = new Float64Array(4 * lineCount);
    for (let k = 0; k < 4 * lineCount; k += 2) [screen[k], screen[k + 1]] = [toX(vertices[k]), toY(vertices[k + 1])];

    let linePoints = 0;
    let linePointsDrawn = 0;
    let linePointsInColour = 0;
    for (let k = 0; k < lineCount; k++) {
      // A point every two pixels or so, so that each line counts by its length on screen: the
      // ground's one edge across the canvas weighs as much as a ragdoll's many short ones.
      const n = Math.max(1, Math.round(Math.hypot(screen[4 * k + 2] - screen[4 * k], screen[4 * k + 3] - screen[4 * k + 1]) / 2));
      for (let j = 0; j < n; j++) {
        const t = (j + 0.5) / n;
        const sx = screen[4 * k] + t * (screen[4 * k + 2] - screen[4 * k]);
        const sy = screen[4 * k + 1] + t * (screen[4 * k + 3] - screen[4 * k + 1]);
        if (!inside(sx, sy)) continue;
        linePoints++;
        const i = brightestNear(sx, sy);
        if (i < 0) continue;
        linePointsDrawn++;
        // Blended with the near-black background a colour keeps its hue: compare both scaled to
        // their brightest channel.
        const seen = [d[i], d[i + 1], d[i + 2]];
        const want = [colors[8 * k], colors[8 * k + 1], colors[8 * k + 2]];
        const seenMax = Math.max(...seen);
        const wantMax = Math.max(...want);
        if (seen.every((c, j) => Math.abs(c / seenMax - want[j] / wantMax) < 0.2)) linePointsInColour++;
      }
    }

    const distanceToLines = (px: number, py: number) => {
      let best = Infinity;
      for (let k = 0; k < lineCount; k++) {
        const ax = screen[4 * k];
        const ay = screen[4 * k + 1];
        const dx = screen[4 * k + 2] - ax;
        const dy = screen[4 * k + 3] - ay;
        const length2 = dx * dx + dy * dy;
        const t = length2 > 0 ? Math.max(0, Math.min(1, ((px - ax) * dx + (py - ay) * dy) / length2)) : 0;
        best = Math.min(best, Math.hypot(px - ax - t * dx, py - ay - t * dy));
      }
      return best;
    };
    let emptyPoints = 0;
    let emptyPointsDrawn = 0;
    for (let y = 3; y < h - 3; y += 7) {
      for (let x = 3; x < w - 3; x += 7) {
        if (distanceToLines(x + 0.5, y + 0.5) < 4) continue;
        emptyPoints++;
        if (isDrawn(x, y)) emptyPointsDrawn++;
      }
    }

    // Body 1 is the first ragdoll's head (the ground is body 0), a circle: its outline, from the
    // body's pose, not from the lines.
    const head = world.getBody(1);
    const circle = world.getShape(head.shapes[0]);
    if (circle.kind !== 'circle') throw new Error(`body 1 is a ${circle.kind}, not the head`);
    const [c, s] = [Math.cos(head.angle), Math.sin(head.angle)];
    const cx = head.x + c * circle.vertices[0].x - s * circle.vertices[0].y;
    const cy = head.y + s * circle.vertices[0].x + c * circle.vertices[0].y;
    let headPoints = 0;
    let headPointsDrawn = 0;
    for (let k = 0; k < 8; k++) {
      const sx = toX(cx + circle.radius * Math.cos((k * Math.PI) / 4));
      const sy = toY(cy + circle.radius * Math.sin((k * Math.PI) / 4));
      if (!inside(sx, sy)) continue;
      headPoints++;
      if (brightestNear(sx, sy) >= 0) headPointsDrawn++;
    }

    let drawn = '';
    for (let y = 0; y < h; y++) for (let x = 0; x < w; x++) drawn += isDrawn(x, y) ? '1' : '0';
    return {
      steps: hook.steps,
      lineCount,
      drawnLines: hook.drawnLines,
      linePoints,
      linePointsDrawn,
      linePointsInColour,
      emptyPoints,
      emptyPointsDrawn,
      headPoints,
      headPointsDrawn,
      headY: cy,
      drawn,
    };
  }, png.toString('base64'));
}

function expectPictureOfWorld(check: Check): void {
  const { drawn, ...numbers } = check;
  void drawn;
  // The ragdolls' capsules, circles and joints, and the ground: well over a thousand lines.
  expect(check.lineCount, JSON.stringify(numbers)).toBeGreaterThan(1000);
  expect(check.drawnLines).toBe(check.lineCount);
  expect(check.linePoints).toBeGreaterThan(1500);
  expect(check.linePointsDrawn / check.linePoints, JSON.stringify(numbers)).toBeGreaterThan(0.95);
  expect(check.linePointsInColour / check.linePointsDrawn, JSON.stringify(numbers)).toBeGreaterThan(0.8);
  // Most of the canvas is far from every line, and stays background.
  expect(check.emptyPoints).toBeGreaterThan(5000);
  expect(check.emptyPointsDrawn / check.emptyPoints, JSON.stringify(numbers)).toBeLessThan(0.01);
  expect(check.headPoints).toBe(8);
  expect(check.headPointsDrawn, JSON.stringify(numbers)).toBe(8);
}

// A failed test is retried once: the shared Vite dev server may reload a page mid-test (see 3d.test.ts).
describe.each(PAGES)('the %s debug-draw example', { retry: 1 }, (_name, path) => {
  let browser: Browser;
  let page: Page | undefined;

  beforeAll(async () => {
    browser = await launchBrowser();
  });

  afterEach(async () => {
    await page?.close();
  });

  afterAll(async () => {
    await browser?.close();
  });

  it('steps the world and draws it where it is, and again after the bodies move', async () => {
    const opened = await openPage(browser, path);
    page = opened.page;
    const name = path.slice(path.lastIndexOf('/') + 1, -'.html'.length);

    await waitFor(page, 'steps', 10);
    const first = await pausedCheck(page, `${name}-first.png`);
    expectPictureOfWorld(first);

    // Paused, the world holds still.
    expect(await hookValue(page, 'steps')).toBe(first.steps);

    await page.evaluate(() => {
      window.__example!.paused = false;
    });
    await waitFor(page, 'steps', first.steps + 40);
    const later = await pausedCheck(page, `${name}-later.png`);
    expectPictureOfWorld(later);

    // The head fell, and the picture changed with it.
    expect(later.headY - first.headY).toBeGreaterThan(0.5);
    let changed = 0;
    for (let i = 0; i < first.drawn.length; i++) if (first.drawn[i] !== later.drawn[i]) changed++;
    expect(changed).toBeGreaterThan(500);

    expect(opened.errors).toEqual([]);
  });
});
