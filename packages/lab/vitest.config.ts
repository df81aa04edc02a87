import { defineConfig } from 'vitest/config';
import { workspaceAliases } from '../../vitest.shared.js';

export default defineConfig({
  resolve: { alias: workspaceAliases },
  test: { name: 'lab', include: ['test/**/*.test.ts'], testTimeout: 120_000 },
});
