import type { TestProject } from 'vitest/node';
import { createServer, type ViteDevServer } from 'vite';
import { fileURLToPath } from 'node:url';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

let server: ViteDevServer | undefined;

/** Serves the sandbox once for all browser tests, on a free loopback port. */
export default async function setup(project: TestProject): Promise<() => Promise<void>> {
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
  }
}
