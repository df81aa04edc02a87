import type { TestProject } from 'vitest/node';
import { createServer, type ViteDevServer } from 'vite';
import { fileURLToPath } from 'node:url';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { execFileSync } from 'node:child_process';

let server: ViteDevServer | undefined;

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

/** Serves the sandbox once for all browser tests, on a free loopback port. */
export default async function setup(project: TestProject): Promise<() => Promise<void>> {
  project.provide('apiReferenceError', buildApiReference());
  // A private dependency cache and no file watching: a developer's own dev server (or an edit)
  // must not make Vite reload the pages under test.
  const cacheDir = mkdtempSync(join(tmpdir(), 'maxgrid-e2e-vite-'));
  server = await createServer({
    configFile: fileURLToPath(new URL('../../vite.config.ts', import.meta.url)),
    cacheDir,
    server: { host: '127.0.0.1', port: 0, strictPort: false, hmr: false, watch: null },
    logLevel: 'error',
  });
  await server.listen();
  const address = server.httpServer?.address();
  if (!address || typeof address === 'string') throw new Error('vite dev server has no TCP address');
  project.provide('sandboxUrl', `http://127.0.0.1:${address.port}`);
  return async () => {
    await server?.close();
    rmSync(cacheDir, { recursive: true, force: true });
  };
}

declare module 'vitest' {
  export interface ProvidedContext {
    sandboxUrl: string;
    /** Why `npm run docs:api` failed before the server started, or '' when public/api/ holds a fresh reference. */
    apiReferenceError: string;
  }
}
