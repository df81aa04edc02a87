import { chromium, type Browser, type Page, type ConsoleMessage } from 'playwright-core';
import { inject } from 'vitest';
import { mkdirSync } from 'node:fs';
import { fileURLToPath } from 'node:url';

/** Debian's Chromium; Playwright never downloads a browser here. Override with CHROMIUM_PATH. */
export const CHROMIUM_PATH = process.env.CHROMIUM_PATH ?? '/usr/bin/chromium';

/** Screenshots and downloads land here: kept as test artefacts, ignored by git. */
export const ARTIFACTS = fileURLToPath(new URL('../../../../artifacts/e2e/', import.meta.url));

export async function launchBrowser(): Promise<Browser> {
  mkdirSync(ARTIFACTS, { recursive: true });
  return chromium.launch({
    executablePath: CHROMIUM_PATH,
    headless: true,
    args: [
      '--no-sandbox',
      '--disable-background-networking',
      '--disable-component-update',
      '--disable-sync',
      '--no-first-run',
      '--disable-quic',
      // Software WebGL, so the WebGL renderer and three.js work on a machine without a GPU.
      '--use-angle=swiftshader',
      '--enable-unsafe-swiftshader',
      '--ignore-gpu-blocklist',
    ],
  });
}

/**
 * A browser whose first page on the dev server, `path`, has been open for two seconds and closed:
 * Vite may reload the first page it serves once it has optimised the dependencies (and warms its
 * transform cache on it), which must happen before a test's page loads, not in the middle of it.
 */
export async function launchWarmedBrowser(path = '/?n=10'): Promise<Browser> {
  const browser = await launchBrowser();
  const { page } = await openPage(browser, path, 'dev');
  await page.waitForTimeout(2000);
  await page.close();
  return browser;
}

/** Where the global setup serves the sandbox: its production build, or the dev server of `npm start`. */
export type Server = 'build' | 'dev';

export function sandboxUrl(path = '/', server: Server = 'build'): string {
  return inject(server === 'dev' ? 'devUrl' : 'sandboxUrl') + path;
}

/** Opens a page and records console errors and uncaught exceptions, for "no console errors" checks. */
export async function openPage(browser: Browser, path = '/', server: Server = 'build'): Promise<{ page: Page; errors: string[] }> {
  const page = await browser.newPage({ viewport: { width: 1400, height: 900 }, acceptDownloads: true });
  const errors: string[] = [];
  page.on('console', (message: ConsoleMessage) => {
    if (message.type() === 'error') errors.push(message.text());
  });
  page.on('pageerror', (error) => errors.push(String(error)));
  await page.goto(sandboxUrl(path, server), { waitUntil: 'load' });
  return { page, errors };
}

/** A number the monitor shows, by its element id (`#stat-<id>`), digits only. */
export async function stat(page: Page, id: string): Promise<number> {
  const text = await page.locator(`#stat-${id}`).innerText();
  return Number(text.replace(/[^\d.-]/g, ''));
}

/** Pixels of the stage's screenshot that are clearly coloured (bodies), not grey or black. */
export async function colourfulPixels(page: Page): Promise<number> {
  const png = await page.locator('#stage').screenshot();
  return page.evaluate(async (b64) => {
    const bitmap = await createImageBitmap(await (await fetch(`data:image/png;base64,${b64}`)).blob());
    const canvas = new OffscreenCanvas(bitmap.width, bitmap.height);
    const ctx = canvas.getContext('2d') as OffscreenCanvasRenderingContext2D;
    ctx.drawImage(bitmap, 0, 0);
    const d = ctx.getImageData(0, 0, bitmap.width, bitmap.height).data;
    let count = 0;
    for (let i = 0; i < d.length; i += 4) if (Math.max(d[i], d[i + 1], d[i + 2]) - Math.min(d[i], d[i + 1], d[i + 2]) > 60) count++;
    return count;
  }, png.toString('base64'));
}

/** Painted pixels on the overlay canvas (grid lines, AABBs, contact points); it is transparent elsewhere. */
export async function overlayPixels(page: Page): Promise<number> {
  return page.evaluate(() => {
    const c = document.getElementById('overlay') as HTMLCanvasElement;
    const d = (c.getContext('2d', { willReadFrequently: true }) as CanvasRenderingContext2D).getImageData(0, 0, c.width, c.height).data;
    let count = 0;
    for (let i = 3; i < d.length; i += 4) if (d[i] > 0) count++;
    return count;
  });
}

/** Pixels of the stage's screenshot within `tolerance` of `rgb` on every channel: one colour's share of the picture. */
export async function pixelsNear(page: Page, rgb: readonly [number, number, number], tolerance = 12): Promise<number> {
  const png = await page.locator('#stage').screenshot();
  return page.evaluate(
    async ({ b64, rgb, tolerance }) => {
      const bitmap = await createImageBitmap(await (await fetch(`data:image/png;base64,${b64}`)).blob());
      const canvas = new OffscreenCanvas(bitmap.width, bitmap.height);
      const ctx = canvas.getContext('2d') as OffscreenCanvasRenderingContext2D;
      ctx.drawImage(bitmap, 0, 0);
      const d = ctx.getImageData(0, 0, bitmap.width, bitmap.height).data;
      let count = 0;
      for (let i = 0; i < d.length; i += 4) {
        if (Math.abs(d[i] - rgb[0]) <= tolerance && Math.abs(d[i + 1] - rgb[1]) <= tolerance && Math.abs(d[i + 2] - rgb[2]) <= tolerance) count++;
      }
      return count;
    },
    { b64: png.toString('base64'), rgb, tolerance },
  );
}
