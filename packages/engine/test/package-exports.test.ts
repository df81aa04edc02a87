import { describe, expect, it } from 'vitest';
import { execFileSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';

const root = fileURLToPath(new URL('../../../', import.meta.url));

describe('package exports', () => {
  // `npm test` builds first; this checks what a user gets from plain Node ESM, not the sources.
  it('plain Node ESM imports the built package from the repository root', () => {
    const script = `
      import { World, BROADPHASE_NAMES } from '@maxgrid/engine';
      import { buildScene, buildWorld } from '@maxgrid/scenes';
      const w = buildWorld(buildScene('uniform', { n: 50 }));
      w.step(1 / 60);
      console.log(JSON.stringify({ names: BROADPHASE_NAMES, bodies: w.bodyCount, isWorld: w instanceof World }));
    `;
    const out = execFileSync(process.execPath, ['--input-type=module', '-e', script], { cwd: root }).toString();
    expect(JSON.parse(out)).toEqual({ names: ['naive', 'sap', 'sap-xy', 'sap-persistent', 'maxgrid', 'hgrid', 'auto'], bodies: 50, isWorld: true });
    expect(existsSync(`${root}packages/engine/dist/index.d.ts`)).toBe(true);
  });
});
