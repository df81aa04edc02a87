import { fileURLToPath } from 'node:url';

/**
 * Tests import the workspace packages from source, so that white-box tests of engine internals
 * and tests through the public API see the same classes.
 */
export const workspaceAliases = {
  '@maxgrid/engine': fileURLToPath(new URL('./packages/engine/src/index.ts', import.meta.url)),
  '@maxgrid/scenes': fileURLToPath(new URL('./packages/scenes/src/index.ts', import.meta.url)),
};
