import { BROADPHASE_NAMES, type BroadPhaseName, type World } from '@maxgrid/engine';
import { buildScene, buildWorld, type Scene } from '@maxgrid/scenes';
import { maxgridBuildOptions, type Environment } from '../../../../packages/lab/src/browser.js';

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

/** Steps between yields to the page: naive's 300 steps of 2,000 bodies took 7 s in one piece. */
const STEPS_PER_SLICE = 10;

/**
 * Steps `scene` (by default the golden scene built here) with every broad-phase, yielding to the
 * page every few steps (`pause`) so that it stays responsive: in one piece this froze the tab for
 * about 9 s. Times exclude the pauses.
 */
export async function determinism(scene: Scene = buildScene(DETERMINISM.scene, DETERMINISM.params), pause: () => Promise<void> = async () => {}): Promise<DeterminismResult> {
  const hashes: Record<string, string> = {};
  const ms: Record<string, number> = {};
  for (const broadphase of BROADPHASE_NAMES) {
    let t0 = performance.now();
    let busy = 0;
    const world = buildWorld(scene, { broadphase });
    for (let i = 0; i < DETERMINISM.steps; i++) {
      world.step(DETERMINISM.dt);
      if ((i + 1) % STEPS_PER_SLICE === 0) {
        busy += performance.now() - t0;
        await pause();
        t0 = performance.now();
      }
    }
    hashes[broadphase] = world.stateHash();
    ms[broadphase] = busy + performance.now() - t0;
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
  // The CLI's quick cap of 400 settling steps: at 120 the pile had not begun to sleep (0 % asleep).
  'sap-sleep': { n: 1000, rounds: 2, steps: 5, warmupSteps: 5, settleSteps: 400 },
  piles: { n: 500, settleSeconds: 5, measureSteps: 10 },
  integrators: { seconds: 2, dt: 1 / 60, stiffnesses: [10, 100, 1000, 10_000, 100_000] },
  // c-maxgrid and targets are Node-only (a C compiler; they drive this page through __labWorlds).
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

/**
 * Worlds built and stepped on request from outside the page: the lab's browser-parity target
 * (issue 5, T6) drives the same maxgrid step here and in Node, round by round, and compares.
 */
export interface PageWorlds {
  create(scene: string, params: Record<string, number>, broadphase: string): number;
  /** Steps `count` times; each step's time in ms (Chromium's clock is coarse, ~0.1 ms). */
  step(id: number, count: number, dt: number): number[];
  hash(id: number): string;
  /** Runs the world's steps on `threads` threads (Web Workers), even while it is small. */
  startWorkers(id: number, threads: number): Promise<number>;
  dispose(id: number): void;
}

export function pageWorlds(): PageWorlds {
  const worlds = new Map<number, World>();
  let next = 1;
  const get = (id: number): World => {
    const world = worlds.get(id);
    if (!world) throw new RangeError(`no world with id ${id}`);
    return world;
  };
  return {
    create(scene, params, broadphase) {
      if (!(BROADPHASE_NAMES as readonly string[]).includes(broadphase)) throw new RangeError(`unknown broadphase '${broadphase}'`);
      worlds.set(next, buildWorld(buildScene(scene, params), maxgridBuildOptions(broadphase as BroadPhaseName)));
      return next++;
    },
    step(id, count, dt) {
      const world = get(id);
      const times: number[] = [];
      for (let i = 0; i < count; i++) {
        const t0 = performance.now();
        world.step(dt);
        times.push(performance.now() - t0);
      }
      return times;
    },
    hash: (id) => get(id).stateHash(),
    async startWorkers(id, threads) {
      const world = get(id);
      await world.startWorkers(threads, { minBodies: 0 });
      return world.workerCount;
    },
    dispose(id) {
      worlds.get(id)?.stopWorkers();
      worlds.delete(id);
    },
  };
}
