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

export function sandboxUrl(path = '/'): string {
  return inject('sandboxUrl') + path;
}

/** Opens a page and records console errors and uncaught exceptions, for "no console errors" checks. */
export async function openPage(browser: Browser, path = '/'): Promise<{ page: Page; errors: string[] }> {
  const page = await browser.newPage({ viewport: { width: 1400, height: 900 }, acceptDownloads: true });
  const errors: string[] = [];
  page.on('console', (message: ConsoleMessage) => {
    if (message.type() === 'error') errors.push(message.text());
  });
  page.on('pageerror', (error) => errors.push(String(error)));
  await page.goto(sandboxUrl(path), { waitUntil: 'load' });
  return { page, errors };
}
