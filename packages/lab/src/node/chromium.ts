import { existsSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import type { BrowserHost, RemoteWorld } from '../experiments/common.js';

/** Debian's Chromium, as the sandbox's browser tests use; override with CHROMIUM_PATH. */
export const CHROMIUM_PATH = process.env.CHROMIUM_PATH ?? '/usr/bin/chromium';

/** The flags issue 5's browser-parity target measures with (no GPU flags: the step is CPU only). */
export const CHROMIUM_FLAGS = ['--no-sandbox', '--disable-background-networking', '--disable-component-update', '--disable-sync', '--no-first-run', '--disable-quic'];

const VITE_CONFIG = fileURLToPath(new URL('../../../../apps/sandbox/vite.config.ts', import.meta.url));

/** What the lab page (apps/sandbox/src/lab-page) exposes for stepping worlds from outside. */
interface LabWorlds {
  create(scene: string, params: Record<string, number>, broadphase: string): number;
  step(id: number, count: number, dt: number): number[];
  hash(id: number): string;
  dispose(id: number): void;
}
type LabWindow = { __labWorlds?: LabWorlds };

/**
 * Serves the sandbox's lab page with Vite (a private dependency cache, no file watching, so a
 * developer's own dev server is undisturbed) and opens it in headless Chromium. Resolves to a
 * skip reason where Chromium, vite or playwright-core is missing.
 */
export async function chromiumHost(): Promise<BrowserHost | string> {
  if (!existsSync(CHROMIUM_PATH)) return `no Chromium at ${CHROMIUM_PATH} (set CHROMIUM_PATH)`;
  if (!existsSync(VITE_CONFIG)) return `no sandbox app at ${VITE_CONFIG}`;
  let vite: typeof import('vite');
  let playwright: typeof import('playwright-core');
  try {
    vite = await import('vite');
    playwright = await import('playwright-core');
  } catch (error) {
    return `vite or playwright-core cannot be loaded (${error instanceof Error ? error.message : String(error)})`;
  }
  const cacheDir = mkdtempSync(join(tmpdir(), 'maxgrid-lab-vite-'));
  const server = await vite.createServer({
    configFile: VITE_CONFIG,
    cacheDir,
    server: { host: '127.0.0.1', port: 0, strictPort: false, hmr: false, watch: null },
    logLevel: 'error',
  });
  const cleanup: (() => Promise<unknown>)[] = [async () => server.close(), async () => rmSync(cacheDir, { recursive: true, force: true })];
  const close = async () => {
    for (const step of cleanup.reverse()) await step().catch(() => undefined);
  };
  try {
    await server.listen();
    const address = server.httpServer?.address();
    if (!address || typeof address === 'string') throw new Error('vite dev server has no TCP address');
    const browser = await playwright.chromium.launch({ executablePath: CHROMIUM_PATH, headless: true, args: CHROMIUM_FLAGS });
    cleanup.push(async () => browser.close());
    const page = await browser.newPage();
    const errors: string[] = [];
    page.on('pageerror', (error) => errors.push(String(error)));
    await page.goto(`http://127.0.0.1:${address.port}/lab.html`, { waitUntil: 'load', timeout: 120_000 });
    // Vite may optimise dependencies on first load and reload once; wait for the page's hook.
    await page.waitForFunction(() => (window as unknown as LabWindow).__labWorlds !== undefined, undefined, { timeout: 120_000, polling: 200 });
    // Expressions as strings: a serialised TS function could carry transpiler helpers the page
    // lacks. JSON arguments are exact for numbers, so dt and the scene parameters arrive intact.
    const call = async <T>(method: keyof LabWorlds, ...args: unknown[]): Promise<T> => {
      if (errors.length) throw new Error(`lab page error: ${errors.join('; ')}`);
      return page.evaluate(`window.__labWorlds.${method}(...${JSON.stringify(args)})`) as Promise<T>;
    };
    return {
      runtime: `Chromium ${browser.version()} (headless, ${CHROMIUM_PATH})`,
      settings: { flags: CHROMIUM_FLAGS.join(' '), page: '/lab.html of apps/sandbox, served by the Vite dev server' },
      async world(scene, params, broadphase): Promise<RemoteWorld> {
        const id = await call<number>('create', scene, params, broadphase);
        return {
          step: (count, dt) => call<number[]>('step', id, count, dt),
          hash: () => call<string>('hash', id),
          dispose: () => call<void>('dispose', id),
        };
      },
      close,
    };
  } catch (error) {
    await close();
    throw error;
  }
}
