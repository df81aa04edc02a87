import { defineConfig, type Connect, type Plugin } from 'vite';
import { fileURLToPath } from 'node:url';
import { workspaceAliases } from '../../vitest.shared.js';

const ISOLATION = { 'Cross-Origin-Opener-Policy': 'same-origin', 'Cross-Origin-Embedder-Policy': 'require-corp' };

const page = (name: string) => fileURLToPath(new URL(`./${name}`, import.meta.url));

/**
 * The API reference (`npm run docs:api`) is written to public/api/. Vite serves a public file by
 * its exact name only and answers /api/ with the sandbox's own page, so the folder's index is
 * named for it; /api gets the slash its pages' relative links need.
 */
function apiReferenceIndex(): Plugin {
  const rewrite: Connect.NextHandleFunction = (req, res, next) => {
    const [path, query] = (req.url ?? '').split('?', 2);
    const search = query === undefined ? '' : `?${query}`;
    if (path === '/api') {
      res.statusCode = 301;
      res.setHeader('Location', `/api/${search}`);
      res.end();
      return;
    }
    if (path === '/api/') req.url = `/api/index.html${search}`;
    next();
  };
  return {
    name: 'maxgrid-api-reference-index',
    configureServer: (server) => void server.middlewares.use(rewrite),
    configurePreviewServer: (server) => void server.middlewares.use(rewrite),
  };
}

// The pages: the 2D sandbox (index), the report's three.js + cannon-es exploration (3d), the lab's
// browser runner (lab), and the debug-draw examples (examples/). The workspace packages are served
// from source, so edits to the engine show up without a rebuild.
export default defineConfig({
  root: fileURLToPath(new URL('.', import.meta.url)),
  resolve: { alias: workspaceAliases },
  plugins: [apiReferenceIndex()],
  // Pre-bundle every third-party module the pages load, including the lab's lazily imported peer
  // engines: otherwise Vite discovers them on first use, re-optimises and reloads the page, which
  // cuts a running experiment (or a test) short. planck is named through the lab, under whose
  // node_modules npm installs it: from the sandbox alone Vite could not resolve it, and warned.
  optimizeDeps: {
    include: ['three', 'cannon-es', 'echarts', 'matter-js', '@maxgrid/lab > planck', 'p2-es', '@dimforge/rapier2d-simd-compat'],
  },
  // Cross-origin isolation, so that pages get SharedArrayBuffer and world.startWorkers can run
  // the engine on Web Workers. Every resource the pages load is same-origin.
  server: { host: '127.0.0.1', port: 5173, headers: ISOLATION },
  preview: { host: '127.0.0.1', port: 4173, headers: ISOLATION },
  build: {
    target: 'es2022',
    rollupOptions: {
      input: {
        index: page('index.html'),
        '3d': page('3d.html'),
        lab: page('lab.html'),
        'debug-canvas': page('examples/debug-canvas.html'),
        'debug-pixi': page('examples/debug-pixi.html'),
        'debug-three': page('examples/debug-three.html'),
      },
    },
  },
});
