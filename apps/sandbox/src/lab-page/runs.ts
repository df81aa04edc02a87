import { BROADPHASE_NAMES } from '@maxgrid/engine';
import { buildScene, buildWorld, type Scene } from '@maxgrid/scenes';
import type { Environment } from '../../../../packages/lab/src/browser.js';

/**
 * The engine's golden-hash scene, stepped here and in Node by the lab's browser test: equal
 * hashes mean bit-identical physics across runtimes and across broad-phases.
 */
export const DETERMINISM = { scene: 'uniform', params: { n: 2000, seed: 7 }, steps: 300, dt: 1 / 60 } as const;

export interface DeterminismResult {
  scene: string;
  params: Record<string, number>;
  steps: number;
  dt: number;
  /** Digest of the built scene's columns, to tell a scene-builder difference from an engine one. */
  sceneDigest: Record<string, string>;
  hashes: Record<string, string>;
  /** Milliseconds each broad-phase took for all steps in this runtime. */
  ms: Record<string, number>;
}

/** FNV-1a over the exact bits of each scene column. */
export function sceneDigest(scene: Scene): Record<string, string> {
  const out: Record<string, string> = {};
  for (const key of ['x', 'y', 'vx', 'vy', 'radius'] as const) {
    const words = new Uint32Array(scene[key].buffer, scene[key].byteOffset, scene[key].length * 2);
    let h = 0x811c9dc5;
    for (let i = 0; i < words.length; i++) h = Math.imul(h ^ words[i], 0x01000193);
    out[key] = (h >>> 0).toString(16).padStart(8, '0');
  }
  return out;
}

/** Steps `scene` (by default the golden scene built here) with every broad-phase. */
export function determinism(scene: Scene = buildScene(DETERMINISM.scene, DETERMINISM.params)): DeterminismResult {
  const hashes: Record<string, string> = {};
  const ms: Record<string, number> = {};
  for (const broadphase of BROADPHASE_NAMES) {
    const t0 = performance.now();
    const world = buildWorld(scene, { broadphase });
    for (let i = 0; i < DETERMINISM.steps; i++) world.step(DETERMINISM.dt);
    hashes[broadphase] = world.stateHash();
    ms[broadphase] = performance.now() - t0;
  }
  return {
    scene: scene.name,
    params: { ...scene.params },
    steps: DETERMINISM.steps,
    dt: DETERMINISM.dt,
    sceneDigest: sceneDigest(scene),
    hashes,
    ms,
  };
}

/** A scene as JSON-safe plain data (JS numbers survive JSON exactly), for shipping between runtimes. */
export type PlainScene = Omit<Scene, 'x' | 'y' | 'vx' | 'vy' | 'radius'> & Record<'x' | 'y' | 'vx' | 'vy' | 'radius', number[]>;

export function toPlainScene(scene: Scene): PlainScene {
  const { x, y, vx, vy, radius, ...rest } = scene;
  return { ...rest, x: [...x], y: [...y], vx: [...vx], vy: [...vy], radius: [...radius] };
}

export function fromPlainScene(plain: PlainScene): Scene {
  const { x, y, vx, vy, radius, ...rest } = plain;
  const f = (a: number[]) => Float64Array.from(a);
  return { ...rest, x: f(x), y: f(y), vx: f(vx), vy: f(vy), radius: f(radius) };
}

/**
 * The page's quick sizes: smaller than the CLI's quick profile, because a browser tab shares
 * the machine with the test runner and the dev server. Each is merged over the experiment's
 * quick options, so every unlisted setting is the CLI's.
 */
export const BROWSER_QUICK: Record<string, Record<string, unknown>> = {
  'step-time': { ns: [250, 1000], runs: 2, seconds: 0.25, warmupSteps: 5 },
  energy: { n: 300, seconds: 5, samples: 150 },
  'false-positives': { ns: [500, 2000], ratios: [1, 10, 100], spreadN: 1000, steps: 5, warmupSteps: 3 },
  scale: { ns: [1000, 10_000, 100_000], steps: 5, warmupSteps: 2 },
};

export function browserEnvironment(): Environment {
  const chromium = /(?:Chromium|Chrome)\/([\d.]+)/.exec(navigator.userAgent)?.[1];
  return {
    runtime: chromium ? `Chromium ${chromium}` : navigator.userAgent,
    userAgent: navigator.userAgent,
    cores: navigator.hardwareConcurrency,
    crossOriginIsolated: String(globalThis.crossOriginIsolated ?? false),
  };
}
