import { describe, expect, it } from 'vitest';
import { execFileSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';

const ROOT = fileURLToPath(new URL('../../..', import.meta.url));
const SCRIPT = fileURLToPath(new URL('./runtimes/scene-hashes.mjs', import.meta.url));
/** Bun's npm package for this machine ships the binary: JavaScriptCore, the engine of Safari. */
const BUN = `${ROOT}/node_modules/@oven/bun-${process.platform}-${process.arch}/bin/bun`;

type Hashes = Record<string, { hash: string; restored: string; snapshot: string; kernels: boolean }>;

function run(runtime: string, ...args: string[]): Hashes {
  return JSON.parse(execFileSync(runtime, [SCRIPT, ...args], { encoding: 'utf8', timeout: 120_000 })) as Hashes;
}

describe('the same bits in every JavaScript engine', () => {
  it('V8 (Node) and JavaScriptCore (Bun) step circles, shapes, joints and springs to the same state hashes, with and without the WebAssembly kernels, and take and restore the same snapshots', () => {
    expect(existsSync(BUN), `no Bun binary at ${BUN}: npm install -O @oven/bun-${process.platform}-${process.arch}`).toBe(true);
    const node = run(process.execPath);
    const nodeScalar = run(process.execPath, '--no-wasm');
    const bun = run(BUN);
    const bunScalar = run(BUN, '--no-wasm');
    const names = Object.keys(node);
    expect(names.length).toBeGreaterThan(10);
    for (const name of names) {
      expect(node[name].kernels, `${name}: kernels run in Node`).toBe(true);
      expect(nodeScalar[name].kernels, `${name}: no kernels without WebAssembly`).toBe(false);
      expect(bun[name].kernels, `${name}: kernels run in Bun`).toBe(true);
      expect(bunScalar[name].kernels).toBe(false);
      expect([nodeScalar[name].hash, bun[name].hash, bunScalar[name].hash], name).toEqual([node[name].hash, node[name].hash, node[name].hash]);
      // A snapshot taken halfway restores to the same bits in each, and is the same bytes in both
      // runtimes: one taken in either restores in the other.
      expect([node, nodeScalar, bun, bunScalar].map((run) => run[name].restored), `${name}, restored`).toEqual([1, 2, 3, 4].map(() => node[name].hash));
      expect([bun[name].snapshot, bunScalar[name].snapshot], `${name}, snapshot bytes`).toEqual([node[name].snapshot, nodeScalar[name].snapshot]);
    }
  }, 300_000);
});
