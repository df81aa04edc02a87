// A plain object rather than defineConfig, so that the config loads without importing vite.
// Cross-origin isolation gives the page SharedArrayBuffer, which worker threads need.
const headers = { 'Cross-Origin-Opener-Policy': 'same-origin', 'Cross-Origin-Embedder-Policy': 'require-corp' };

export default {
  server: { headers },
  preview: { headers },
};
