import { describe, expect, it } from 'vitest';
import { execFileSync } from 'node:child_process';
import { existsSync, readFileSync } from 'node:fs';
import { posix } from 'node:path';
import { fileURLToPath } from 'node:url';
import * as sceneModule from '@maxgrid/scenes';

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
    expect(JSON.parse(out)).toEqual({ names: ['naive', 'sap', 'sap-xy', 'sap-persistent', 'maxgrid', 'hgrid', 'hashgrid', 'auto'], bodies: 50, isWorld: true });
    expect(existsSync(`${root}packages/engine/dist/index.d.ts`)).toBe(true);
    // The worker script's own export, imported where it has no worker to serve: it does nothing.
    expect(execFileSync(process.execPath, ['--input-type=module', '-e', "await import('@maxgrid/engine/worker'); console.log('loaded')"], { cwd: root }).toString().trim()).toBe('loaded');
  });

  it('npm pack ships the built JavaScript, its types, a README, a LICENSE and a CHANGELOG, and nothing else', () => {
    const engine = `${root}packages/engine`;
    const [pack] = JSON.parse(execFileSync('npm', ['pack', '--dry-run', '--json', '--ignore-scripts'], { cwd: engine, stdio: ['ignore', 'pipe', 'ignore'] }).toString()) as [{ files: { path: string }[]; size: number }];
    const paths = pack.files.map((f) => f.path);
    for (const needed of ['README.md', 'LICENSE', 'CHANGELOG.md', 'package.json', 'dist/index.js', 'dist/index.d.ts', 'dist/parallel/worker-entry.js']) expect(paths).toContain(needed);
    expect(paths.filter((p) => !/^dist\/.*\.(js|d\.ts)$/.test(p) && !['README.md', 'LICENSE', 'CHANGELOG.md', 'package.json'].includes(p))).toEqual([]);
    // Every module the built entry reaches is shipped: relative imports of each shipped file resolve inside the pack.
    const shipped = new Set(paths);
    for (const file of paths.filter((p) => p.endsWith('.js'))) {
      const text = readFileSync(`${engine}/${file}`, 'utf8');
      for (const [, spec] of text.matchAll(/(?:from|import)\s*\(?\s*['"](\.[^'"]+)['"]/g)) {
        expect(shipped.has(posix.normalize(posix.join(posix.dirname(file), spec))), `${file} imports ${spec}`).toBe(true);
      }
    }
    const manifest = JSON.parse(readFileSync(`${engine}/package.json`, 'utf8')) as { exports: Record<string, Record<string, string>>; engines: { node: string }; type: string };
    expect(Object.keys(manifest.exports['.'])[0]).toBe('types');
    // The worker script, for bundlers that do not emit it by themselves (docs/engine.md, "Workers in your bundler").
    expect(manifest.exports['./worker']).toEqual({ types: './dist/parallel/worker-entry.d.ts', default: './dist/parallel/worker-entry.js' });
    for (const target of Object.values(manifest.exports['./worker'])) expect(paths).toContain(target.slice(2));
    expect(manifest.type).toBe('module');
    expect(manifest.engines.node).toMatch(/>=20\.19/);
  });
  it('npm pack of @maxgrid/scenes ships its built JavaScript and types, a README, a LICENSE and a CHANGELOG, and nothing else', () => {
    const scenes = `${root}packages/scenes`;
    const [pack] = JSON.parse(execFileSync('npm', ['pack', '--dry-run', '--json', '--ignore-scripts'], { cwd: scenes, stdio: ['ignore', 'pipe', 'ignore'] }).toString()) as [{ files: { path: string }[] }];
    const paths = pack.files.map((f) => f.path);
    for (const needed of ['README.md', 'LICENSE', 'CHANGELOG.md', 'package.json', 'dist/index.js', 'dist/index.d.ts']) expect(paths).toContain(needed);
    expect(paths.filter((p) => !/^dist\/.*\.(js|d\.ts)$/.test(p) && !['README.md', 'LICENSE', 'CHANGELOG.md', 'package.json'].includes(p))).toEqual([]);
    const manifest = JSON.parse(readFileSync(`${scenes}/package.json`, 'utf8')) as { exports: Record<string, Record<string, string>>; engines: { node: string } };
    expect(Object.keys(manifest.exports['.'])[0]).toBe('types');
    expect(manifest.engines.node).toMatch(/>=20\.19/);
    // Its README's example, run as written.
    const example = /```ts\n([\s\S]*?)```/.exec(readFileSync(`${scenes}/README.md`, 'utf8'))![1].replace(/^import .*$/m, '');
    const lines: unknown[][] = [];
    new Function('buildShapeScene', 'buildShapeWorld', 'console', example)(sceneModule.buildShapeScene, sceneModule.buildShapeWorld, { log: (...v: unknown[]) => lines.push(v) });
    expect(lines[0][0]).toBe(20);
  });
});
