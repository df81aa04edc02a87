import { defineConfig } from 'vitest/config';
import { workspaceAliases } from '../../vitest.shared.js';

// The page's logic that needs no browser (URL settings, sliders, tools): no server to start, no
// Chromium, so these run in a second where the end-to-end tests take minutes.
export default defineConfig({
  resolve: { alias: workspaceAliases },
  test: { name: 'sandbox-unit', include: ['test/unit/**/*.test.ts'] },
});
