import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import puppeteer, { type Browser } from 'puppeteer-core';
import { fileURLToPath } from 'node:url';
import * as engine from '@maxgrid/engine';
import * as scenes from '@maxgrid/scenes';
import { sandboxUrl } from './browser.js';
// @ts-expect-error: plain JavaScript shared with the engine's runtimes test, which has no types.
import { sceneHashes } from '../../../../packages/engine/test/runtimes/scene-hash-cases.mjs';

/** Debian's Firefox ESR, driven over WebDriver BiDi; nothing downloads a browser. Override with FIREFOX_PATH. */
const FIREFOX_PATH = process.env.FIREFOX_PATH ?? '/usr/bin/firefox-esr';
const ROOT = fileURLToPath(new URL('../../../../', import.meta.url));

type Hashes = Record<string, { hash: string; restored: string; snapshot: string; kernels: boolean }>;

let browser: Browser;

beforeAll(async () => {
  browser = await puppeteer.launch({ browser: 'firefox', executablePath: FIREFOX_PATH, headless: true, protocol: 'webDriverBiDi' });
}, 60_000);

afterAll(async () => {
  await browser?.close();
});

/** The shared scenes stepped in Firefox, the engine loaded from source by the dev server, with or without WebAssembly. */
async function firefoxHashes(wasm: boolean): Promise<Hashes> {
  const page = await browser.newPage();
  try {
    // A same-origin document that loads none of the engine: WebAssembly is removed before it does.
    await page.goto(sandboxUrl('/package.json', 'dev'));
    // A string, not a function: Vitest rewrites import() in this file's functions for Node.
    const json = (await page.evaluate(`(async () => {
      ${wasm ? '' : 'delete globalThis.WebAssembly;'}
      const load = (path) => import('/@fs${ROOT}' + path);
      const { sceneHashes } = await load('packages/engine/test/runtimes/scene-hash-cases.mjs');
      return JSON.stringify(sceneHashes(await load('packages/engine/src/index.ts'), await load('packages/scenes/src/index.ts')));
    })()`)) as string;
    return JSON.parse(json) as Hashes;
  } finally {
    await page.close();
  }
}

describe('the same bits in SpiderMonkey (Firefox ESR) as in V8 (Node)', () => {
  it('steps circles, shapes, joints, blobs and rk4 springs to the same state hashes, with the WebAssembly kernels and without, and restores snapshots to them', async () => {
    const node = sceneHashes(engine, scenes) as Hashes;
    const kernels = await firefoxHashes(true);
    const scalar = await firefoxHashes(false);
    const names = Object.keys(node);
    expect(names.length).toBeGreaterThan(10);
    expect(Object.keys(kernels)).toEqual(names);
    for (const name of names) {
      expect(kernels[name].kernels, `${name}: kernels run in Firefox`).toBe(true);
      expect(scalar[name].kernels, `${name}: none without WebAssembly`).toBe(false);
      expect([kernels[name].hash, scalar[name].hash], name).toEqual([node[name].hash, node[name].hash]);
      // A snapshot taken halfway restores in Firefox to the same bits, and is the same bytes as Node's.
      expect([kernels[name].restored, scalar[name].restored], `${name}, restored`).toEqual([node[name].hash, node[name].hash]);
      expect(kernels[name].snapshot, `${name}, snapshot bytes`).toBe(node[name].snapshot);
    }
  }, 240_000);
});
