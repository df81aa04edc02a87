import { defineConfig } from 'vitest/config';

// Each workspace keeps its own vitest config; `npm test` runs them all.
export default defineConfig({
  test: {
    projects: ['packages/*/vitest.config.ts', 'apps/*/vitest.config.ts', 'apps/*/vitest.unit.config.ts', 'examples/vitest.config.ts'],
  },
});
