/**
 * Worker threads in each bundler's production build, in Vite's dev server and on a plain page,
 * in Chromium: each example builds from a temporary copy whose node_modules/@maxgrid/engine is
 * what `npm pack` of the engine ships (a real directory, not the workspace link, which Vite would
 * serve as source instead of pre-bundling it), and its page reports what ran. Then the sandbox's
 * own production build, with threads.
 */
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { execFileSync } from 'node:child_process';
import { cpSync, existsSync, mkdirSync, mkdtempSync, readdirSync, rmSync, statSync } from 'node:fs';
import type { Server } from 'node:http';
import type { AddressInfo } from 'node:net';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { chromium, type Browser } from 'playwright-core';
import { build, createServer, type Logger } from 'vite';
import webpack, { type Configuration, type Stats } from 'webpack';
import { serve } from '../serve.mjs';

const ROOT = fileURLToPath(new URL('../../', import.meta.url));
const ENGINE = join(ROOT, 'packages/engine');
const EXAMPLES = join(ROOT, 'examples');
const CHROMIUM_PATH = process.env.CHROMIUM_PATH ?? '/usr/bin/chromium';

/** What an example's page writes into #result. */
interface Result {
  threads?: number;
  lastStepThreads?: number;
  stateHash?: string;
  sameAsOneThread?: boolean;
  error?: string;
}

/** Two threads ran the steps, and gave the bits of one. */
const RAN_ON_TWO_THREADS = { threads: 2, lastStepThreads: 2, sameAsOneThread: true };

let browser: Browser;
let shipped: string[];
let scratch: string;
const servers: Server[] = [];

/** Newest modification time under `dir`, in ms. */
function newest(dir: string): number {
  let time = 0;
  for (const entry of readdirSync(dir, { withFileTypes: true, recursive: true })) {
    if (entry.isFile()) time = Math.max(time, statSync(join(entry.parentPath, entry.name)).mtimeMs);
  }
  return time;
}

beforeAll(() => {
  // `npm test` type-checks, which builds, first; run alone, this test builds what it needs. tsc
  // writes its build info on every build, and only the outputs that changed.
  const built = join(ENGINE, 'dist/.tsbuildinfo');
  if (!existsSync(built) || statSync(built).mtimeMs < newest(join(ENGINE, 'src'))) execFileSync('npm', ['run', 'build'], { cwd: ROOT, stdio: 'pipe' });
  const [pack] = JSON.parse(execFileSync('npm', ['pack', '--dry-run', '--json', '--ignore-scripts'], { cwd: ENGINE, stdio: ['ignore', 'pipe', 'pipe'] }).toString()) as [{ files: { path: string }[] }];
  shipped = pack.files.map((file) => file.path);
  scratch = mkdtempSync(join(tmpdir(), 'maxgrid-examples-'));
});

beforeAll(async () => {
  browser = await chromium.launch({
    executablePath: CHROMIUM_PATH,
    headless: true,
    args: ['--no-sandbox', '--disable-background-networking', '--disable-component-update', '--disable-sync', '--no-first-run', '--disable-quic'],
  });
});

afterAll(async () => {
  await browser?.close();
  for (const server of servers) server.close();
  if (scratch) rmSync(scratch, { recursive: true, force: true });
});

/** A copy of examples/<name> with the packed engine installed in it, as a user's project has it. */
function project(name: string): string {
  const dir = join(scratch, name);
  cpSync(join(EXAMPLES, name), dir, { recursive: true, filter: (from) => !/[/\\](node_modules|dist)$/.test(from) });
  const installed = join(dir, 'node_modules/@maxgrid/engine');
  for (const file of shipped) {
    mkdirSync(dirname(join(installed, file)), { recursive: true });
    cpSync(join(ENGINE, file), join(installed, file));
  }
  return dir;
}

/** Serves `dir` cross-origin isolated, as serve.mjs does for a reader of the examples. */
async function served(dir: string): Promise<string> {
  const server = (await serve(dir)) as Server;
  servers.push(server);
  return `http://127.0.0.1:${(server.address() as AddressInfo).port}/`;
}

/** Opens `url`, waits for the page's result and returns it with the page's console errors. */
async function run(url: string): Promise<{ result: Result; errors: string[] }> {
  const page = await browser.newPage();
  const errors: string[] = [];
  page.on('console', (message) => {
    if (message.type() === 'error') errors.push(message.text());
  });
  page.on('pageerror', (error) => errors.push(String(error)));
  try {
    await page.goto(url);
    await page.waitForFunction(() => !document.getElementById('result')?.textContent?.startsWith('running'), null, { timeout: 60_000 });
    return { result: JSON.parse((await page.locator('#result').textContent()) ?? '') as Result, errors };
  } finally {
    await page.close();
  }
}

/** A Vite logger that keeps warnings and errors, so that a test can say the build was clean. */
function recordingLogger(said: string[]): Logger {
  const keep = (message: string) => void said.push(message);
  return { info: () => {}, warn: keep, warnOnce: keep, error: keep, clearScreen: () => {}, hasErrorLogged: () => said.length > 0, hasWarned: false };
}

describe('worker threads in a bundled page', () => {
  it('Vite: the production build emits the worker, and two threads step the same bits as one', async () => {
    const dir = project('vite');
    const said: string[] = [];
    await build({ root: dir, configFile: join(dir, 'vite.config.js'), logLevel: 'warn', customLogger: recordingLogger(said) });
    expect(said).toEqual([]);
    expect(readdirSync(join(dir, 'dist/assets')).some((file) => file.startsWith('worker-entry'))).toBe(true);
    const { result, errors } = await run(await served(join(dir, 'dist')));
    expect(result).toMatchObject(RAN_ON_TWO_THREADS);
    expect(errors).toEqual([]);
  });

  it("Vite: the dev server, with the engine pre-bundled by the dependency optimizer", async () => {
    const dir = project('vite');
    const server = await createServer({
      root: dir,
      configFile: join(dir, 'vite.config.js'),
      logLevel: 'error',
      server: { host: '127.0.0.1', port: 0, hmr: false, watch: null },
    });
    try {
      await server.listen();
      const { result, errors } = await run(`http://127.0.0.1:${(server.httpServer!.address() as AddressInfo).port}/`);
      expect(result).toMatchObject(RAN_ON_TWO_THREADS);
      expect(errors).toEqual([]);
      // The case that needs the optimizer to carry the worker's URL: the engine ran from its cache.
      expect(existsSync(join(dir, 'node_modules/.vite/deps/@maxgrid_engine.js'))).toBe(true);
    } finally {
      await server.close();
    }
  });

  it('webpack 5: the production build emits the worker as a chunk, without warnings', async () => {
    const dir = project('webpack');
    const config = ((await import(pathToFileURL(join(dir, 'webpack.config.js')).href)) as { default: Configuration }).default;
    const stats = await new Promise<Stats>((resolve, reject) => webpack(config, (error, out) => (error || !out ? reject(error) : resolve(out))));
    const { errors, warnings } = stats.toJson({ all: false, errors: true, warnings: true });
    expect({ errors: errors?.map((e) => e.message), warnings: warnings?.map((w) => w.message) }).toEqual({ errors: [], warnings: [] });
    const { result, errors: pageErrors } = await run(await served(join(dir, 'dist')));
    expect(result).toMatchObject(RAN_ON_TWO_THREADS);
    expect(pageErrors).toEqual([]);
  });

  it('esbuild: the worker built from @maxgrid/engine/worker and named by workerUrl; without it, the error names the URL', async () => {
    const dir = project('esbuild');
    // The example's own build script, with esbuild from the repository's node_modules.
    execFileSync('npm', ['run', 'build', '--silent'], { cwd: dir, stdio: 'pipe', env: { ...process.env, PATH: `${join(ROOT, 'node_modules/.bin')}:${process.env.PATH}` } });
    const url = await served(join(dir, 'dist'));
    const { result, errors } = await run(url);
    expect(result).toMatchObject(RAN_ON_TWO_THREADS);
    expect(errors).toEqual([]);
    rmSync(join(dir, 'dist/worker.js'));
    const missing = await run(url);
    expect(missing.result.error).toContain(`worker thread failed to start: the browser could not load or run the worker script ${url}worker.js`);
    expect(missing.result.error).toContain('startWorkers(n, { workerUrl })');
  });

  it('a plain <script type="module"> page: the worker beside the engine; without it, the error names the URL and the fix', async () => {
    const dir = project('plain');
    const url = await served(dir);
    const { result, errors } = await run(url);
    expect(result).toMatchObject(RAN_ON_TWO_THREADS);
    expect(errors).toEqual([]);
    rmSync(join(dir, 'node_modules/@maxgrid/engine/dist/parallel/worker-entry.js'));
    const missing = await run(url);
    expect(missing.result.error).toContain(`the engine's worker script ${url}node_modules/@maxgrid/engine/dist/parallel/worker-entry.js`);
    expect(missing.result.error).toContain('build @maxgrid/engine/worker as an entry point of its own and pass its URL: startWorkers(n, { workerUrl })');
  });
});

describe('the sandbox', () => {
  it('its production build starts worker threads', async () => {
    const out = join(scratch, 'sandbox-dist');
    // Its warnings (the peer engines' Node fallbacks, chunk sizes) are the sandbox's own business.
    await build({ configFile: join(ROOT, 'apps/sandbox/vite.config.ts'), cacheDir: join(scratch, 'sandbox-vite-cache'), logLevel: 'error', build: { outDir: out, emptyOutDir: true } });
    expect(readdirSync(join(out, 'assets')).some((file) => file.startsWith('worker-entry'))).toBe(true);
    const page = await browser.newPage();
    // The Threads choice offers counts up to the cores; 4 makes 2 available on any machine.
    await page.addInitScript(() => Object.defineProperty(navigator, 'hardwareConcurrency', { get: () => 4 }));
    try {
      await page.goto(`${await served(out)}?threads=2`);
      await page.waitForFunction(() => window.__sandboxFrames?.read().threads === 2 || /did not start/.test(document.getElementById('notice')?.textContent ?? ''), null, { timeout: 60_000 });
      const state = await page.evaluate(() => ({ threads: window.__sandboxFrames?.read().threads, notice: document.getElementById('notice')?.textContent }));
      expect(state).toEqual({ threads: 2, notice: '' });
    } finally {
      await page.close();
    }
  });
});

declare global {
  interface Window {
    __sandboxFrames?: { read(): { threads: number } };
  }
}
