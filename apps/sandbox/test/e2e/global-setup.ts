import type { TestProject } from 'vitest/node';
import { build, createServer, preview, type PreviewServer, type ViteDevServer } from 'vite';
import { fileURLToPath } from 'node:url';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { execFileSync } from 'node:child_process';

let server: ViteDevServer | undefined;
let built: PreviewServer | undefined;

/**
 * Writes the API reference into public/api/ as `npm run docs:api` does; Vite lists the public
 * files when the server starts (and watches nothing here), so it must exist before. A failure is
 * handed to the API reference's test rather than thrown, so that it fails that test alone.
 */
function buildApiReference(): string {
  const root = fileURLToPath(new URL('../../../../', import.meta.url));
  const typedoc = join(root, 'node_modules', 'typedoc', 'bin', 'typedoc');
  try {
    execFileSync(process.execPath, [typedoc], { cwd: root, stdio: 'pipe', env: { ...process.env, NO_COLOR: '1' } });
    return '';
  } catch (error) {
    const { stdout, stderr } = error as { stdout?: Buffer; stderr?: Buffer };
    return `typedoc failed:\n${stdout?.toString() ?? ''}${stderr?.toString() ?? String(error)}`;
  }
}

/** The server's loopback address, as a URL without a trailing slash. */
function urlOf(address: ReturnType<NonNullable<ViteDevServer['httpServer']>['address']> | undefined, what: string): string {
  if (!address || typeof address === 'string') throw new Error(`${what} has no TCP address`);
  return `http://127.0.0.1:${address.port}`;
}

/**
 * Serves the sandbox twice for all browser tests, each on a free loopback port:
 * - its production build (`vite build`, then `vite preview`), which most tests load: a page is a
 *   few bundled files there, where the dev server answers some 180 module requests per page load,
 *   which took most of the browser tests' time on a two-core machine;
 * - the dev server that `npm start` runs, for the tests of what it serves (dev-server.test.ts,
 *   the API reference) and for Firefox, which loads the engine's sources through it.
 */
export default async function setup(project: TestProject): Promise<() => Promise<void>> {
  project.provide('apiReferenceError', buildApiReference());
  const configFile = fileURLToPath(new URL('../../vite.config.ts', import.meta.url));
  // A private dependency cache and no file watching: a developer's own dev server (or an edit)
  // must not make Vite reload the pages under test.
  const cacheDir = mkdtempSync(join(tmpdir(), 'maxgrid-e2e-vite-'));
  const outDir = mkdtempSync(join(tmpdir(), 'maxgrid-e2e-build-'));
  server = await createServer({
    configFile,
    cacheDir,
    server: { host: '127.0.0.1', port: 0, strictPort: false, hmr: false, watch: null },
    logLevel: 'error',
  });
  await server.listen();
  project.provide('devUrl', urlOf(server.httpServer?.address(), 'vite dev server'));
  await build({ configFile, cacheDir, build: { outDir, emptyOutDir: true }, logLevel: 'error' });
  built = await preview({ configFile, cacheDir, build: { outDir }, preview: { host: '127.0.0.1', port: 0, strictPort: false }, logLevel: 'error' });
  project.provide('sandboxUrl', urlOf(built.httpServer.address(), 'vite preview server'));
  return async () => {
    await built?.close();
    await server?.close();
    rmSync(cacheDir, { recursive: true, force: true });
    rmSync(outDir, { recursive: true, force: true });
  };
}

declare module 'vitest' {
  export interface ProvidedContext {
    /** The sandbox's production build, served by `vite preview`. */
    sandboxUrl: string;
    /** The sandbox as `npm start` serves it: Vite's dev server, the workspace packages from source. */
    devUrl: string;
    /** Why `npm run docs:api` failed before the server started, or '' when public/api/ holds a fresh reference. */
    apiReferenceError: string;
  }
}
