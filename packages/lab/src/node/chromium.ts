import { existsSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import type { BrowserHost, FrameSample, RemoteWorld, SandboxHost, SandboxRun } from '../experiments/common.js';

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

/**
 * Extra flags from CHROMIUM_ARGS (split on spaces), appended to CHROMIUM_FLAGS, for example
 * `--disable-gpu-vsync --disable-frame-rate-limit` to time frames past the display's 60 Hz. The
 * run records them with its results.
 */
export function chromiumArgs(): string[] {
  return [...CHROMIUM_FLAGS, ...(process.env.CHROMIUM_ARGS ?? '').split(/\s+/).filter((a) => a !== '')];
}

interface OpenPage {
  page: import('playwright-core').Page;
  origin: string;
  version: string;
  args: string[];
  errors: string[];
  close(): Promise<void>;
}

/**
 * Serves the sandbox app with Vite (a private dependency cache, no file watching, so a developer's
 * own dev server is undisturbed) and opens one tab in headless Chromium. Resolves to a skip reason
 * where Chromium, vite or playwright-core is missing.
 */
async function openSandbox(args: string[]): Promise<OpenPage | string> {
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
    const browser = await playwright.chromium.launch({ executablePath: CHROMIUM_PATH, headless: true, args });
    cleanup.push(async () => browser.close());
    const page = await browser.newPage();
    const errors: string[] = [];
    page.on('pageerror', (error) => errors.push(String(error)));
    return { page, origin: `http://127.0.0.1:${address.port}`, version: browser.version(), args, errors, close };
  } catch (error) {
    await close();
    throw error;
  }
}

/** Opens `path` and waits for `hook` on window; Vite may optimise dependencies on first load and reload once. */
async function load(open: OpenPage, path: string, hook: string): Promise<void> {
  await open.page.goto(`${open.origin}${path}`, { waitUntil: 'load', timeout: 120_000 });
  await open.page.waitForFunction(`window.${hook} !== undefined`, undefined, { timeout: 120_000, polling: 200 });
}

/** The lab page (`/lab.html`) in headless Chromium, stepping worlds on request (T6). */
export async function chromiumHost(): Promise<BrowserHost | string> {
  const open = await openSandbox(CHROMIUM_FLAGS);
  if (typeof open === 'string') return open;
  try {
    await load(open, '/lab.html', '__labWorlds');
    // Expressions as strings: a serialised TS function could carry transpiler helpers the page
    // lacks. JSON arguments are exact for numbers, so dt and the scene parameters arrive intact.
    const call = async <T>(method: keyof LabWorlds, ...args: unknown[]): Promise<T> => {
      if (open.errors.length) throw new Error(`lab page error: ${open.errors.join('; ')}`);
      return open.page.evaluate(`window.__labWorlds.${method}(...${JSON.stringify(args)})`) as Promise<T>;
    };
    return {
      runtime: `Chromium ${open.version} (headless, ${CHROMIUM_PATH})`,
      settings: { flags: CHROMIUM_FLAGS.join(' '), page: '/lab.html of apps/sandbox, served by the Vite dev server' },
      async world(scene, params, broadphase): Promise<RemoteWorld> {
        const id = await call<number>('create', scene, params, broadphase);
        return {
          step: (count, dt) => call<number[]>('step', id, count, dt),
          hash: () => call<string>('hash', id),
          dispose: () => call<void>('dispose', id),
        };
      },
      close: open.close,
    };
  } catch (error) {
    await open.close();
    throw error;
  }
}

/** Environment that decides which GPU driver Chromium finds (and whether it has fonts): recorded where set. */
const DRIVER_ENV = ['VK_DRIVER_FILES', 'VK_ICD_FILENAMES', '__EGL_VENDOR_LIBRARY_FILENAMES', 'LD_LIBRARY_PATH', 'FONTCONFIG_FILE'];

/** The fewest frames a timed stretch should hold, and how much longer than asked it may run to get them. */
const MIN_FRAMES = 6;
const MAX_WAIT_FACTOR = 5;

/** The sandbox page itself (`/index.html`) in headless Chromium, timed frame by frame (T7). */
export async function sandboxHost(): Promise<SandboxHost | string> {
  const open = await openSandbox(chromiumArgs());
  if (typeof open === 'string') return open;
  const viewport = open.page.viewportSize();
  return {
    runtime: `Chromium ${open.version} (headless, ${CHROMIUM_PATH})`,
    settings: {
      flags: open.args.join(' '),
      page: '/ (the sandbox) of apps/sandbox, served by the Vite dev server',
      viewport: viewport ? `${viewport.width}x${viewport.height} CSS px` : 'default',
      env: DRIVER_ENV.filter((k) => process.env[k]).map((k) => `${k}=${process.env[k]}`).join(' ') || 'none of ' + DRIVER_ENV.join(', '),
    },
    async measure(query, warmupSeconds, seconds): Promise<SandboxRun> {
      await load(open, `/?${query}`, '__sandboxFrames');
      const page = open.page;
      await page.waitForTimeout(warmupSeconds * 1000);
      await page.evaluate('window.__sandboxFrames.clear()');
      const before = (await page.evaluate('window.__sandboxFrames.read()')) as FrameSample;
      await page.waitForTimeout(seconds * 1000);
      let frames = (await page.evaluate('window.__sandboxFrames.read()')) as FrameSample;
      // A software rasteriser can take seconds a frame at 100k circles: wait for enough frames
      // to time, up to a bound, rather than report two.
      for (let waited = seconds; frames.start.length < MIN_FRAMES && waited < MAX_WAIT_FACTOR * seconds; waited++) {
        await page.waitForTimeout(1000);
        frames = (await page.evaluate('window.__sandboxFrames.read()')) as FrameSample;
      }
      if (open.errors.length) throw new Error(`sandbox page error: ${open.errors.join('; ')}`);
      return {
        frames,
        droppedSteps: frames.droppedSteps - before.droppedSteps,
        webglDevice: (await page.evaluate('window.__sandboxFrames.webglDevice()')) as string | null,
        notice: ((await page.textContent('#notice')) ?? '').trim(),
        devicePixelRatio: (await page.evaluate('window.devicePixelRatio')) as number,
      };
    },
    close: open.close,
  };
}
