import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { dirname, join } from 'node:path';
import type { Engine } from '../engines/adapter.js';
import { box2dUsesSimd } from '../engines/box2d.js';
import { loadEngines } from '../engines/registry.js';
import type { ShapeEngine } from '../shape-engines/adapter.js';
import { loadShapeEngines } from '../shape-engines/registry.js';

const require = createRequire(import.meta.url);

/** The bytes of the box2d-wasm build that its Node entry will pick on this runtime. */
export function box2dWasmBinary(): Uint8Array {
  const dir = join(dirname(require.resolve('box2d-wasm')), '..', 'umd');
  return readFileSync(join(dir, box2dUsesSimd() ? 'Box2D.simd.wasm' : 'Box2D.wasm'));
}

/** `loadEngines` with the Node-only hooks filled in. */
export function loadEnginesNode(ids: readonly string[]): Promise<Engine[]> {
  return loadEngines(ids, ids.includes('box2d-wasm') ? { box2dWasmBinary: box2dWasmBinary() } : {});
}

/** `loadShapeEngines` with box2d-wasm's bytes. */
export function loadShapeEnginesNode(ids: readonly string[]): Promise<ShapeEngine[]> {
  return loadShapeEngines(ids, ids.includes('box2d-wasm') ? { box2dWasmBinary: box2dWasmBinary() } : {});
}
