import { beforeAll, describe, expect, it } from 'vitest';
import { existsSync, readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { createRequire } from 'node:module';
import { buildScene, type Scene } from '@maxgrid/scenes';
import { BROADPHASE_NAMES } from '@maxgrid/engine';
import { allocateState, energyOf, sceneMasses, type Engine } from '../src/engines/adapter.js';
import { ENGINE_IDS } from '../src/engines/registry.js';
import { loadEnginesNode } from '../src/node/engines.js';

let engines: Engine[] = [];

beforeAll(async () => {
  engines = await loadEnginesNode(ENGINE_IDS);
});

/** Float32 engines store x / 50 as f32: half an ulp of relative error, scaled back. */
function tolerance(engine: Engine, value: number): number {
  return engine.info.precision === 'f32' ? 2 ** -23 * Math.abs(value) + 1e-9 : 1e-9 * Math.max(1, Math.abs(value));
}

function maxViolation(engine: Engine, got: Float64Array, want: Float64Array): { k: number; got: number; want: number } | null {
  for (let k = 0; k < want.length; k++) {
    if (!(Math.abs(got[k] - want[k]) <= tolerance(engine, want[k]))) return { k, got: got[k], want: want[k] };
  }
  return null;
}

const SCENES: [string, Record<string, number>][] = [
  ['seed-box', { n: 300, seed: 3 }],
  ['uniform', { n: 300, seed: 4 }],
  ['bouncing-ball', {}],
];

/** Walks up from the package's entry point, since some packages do not export package.json. */
function installedVersion(require: NodeJS.Require, name: string): string {
  let dir = dirname(require.resolve(name, { paths: [new URL('..', import.meta.url).pathname] }));
  for (;;) {
    const path = join(dir, 'package.json');
    if (existsSync(path)) {
      const pkg = JSON.parse(readFileSync(path, 'utf8')) as { name?: string; version: string };
      if (pkg.name === name) return pkg.version;
    }
    if (dirname(dir) === dir) throw new Error(`no package.json for ${name}`);
    dir = dirname(dir);
  }
}

describe('engine registry', () => {
  it('has maxgrid once per broad-phase, its pile solver, and the five peer engines', () => {
    expect(ENGINE_IDS).toEqual([...BROADPHASE_NAMES.map((b) => `maxgrid:${b}`), 'maxgrid-piles', 'box2d-wasm', 'planck', 'rapier', 'matter-js', 'p2-es']);
  });

  it("records each engine's installed package version and its settings", () => {
    const require = createRequire(import.meta.url);
    for (const e of engines) {
      if (e.info.package === '@maxgrid/engine') continue;
      expect(e.info.version, e.info.id).toBe(installedVersion(require, e.info.package));
      expect(Object.keys(e.info.settings).length, e.info.id).toBeGreaterThan(3);
    }
  });
});

describe.each(SCENES)('every adapter builds scene %s identically', (name, params) => {
  const scene: Scene = buildScene(name, params);

  it.each(ENGINE_IDS)('%s reads back the scene positions, velocities and radii', (id) => {
    const engine = engines.find((e) => e.info.id === id)!;
    const sim = engine.create(scene);
    try {
      const state = allocateState(scene.count);
      const radii = new Float64Array(scene.count);
      sim.read(state);
      sim.readRadii(radii);
      expect(sim.count).toBe(scene.count);
      for (const [column, got, want] of [
        ['x', state.x, scene.x],
        ['y', state.y, scene.y],
        ['vx', state.vx, scene.vx],
        ['vy', state.vy, scene.vy],
        ['radius', radii, scene.radius],
      ] as const) {
        expect(maxViolation(engine, got, want), `${id} ${column}`).toBeNull();
      }
    } finally {
      sim.dispose();
    }
  });
});

describe('physics sanity per adapter', () => {
  it.each(ENGINE_IDS)('%s: a dropped ball falls g t^2 / 2 in scene units (gravity and velocity scaling)', (id) => {
    const engine = engines.find((e) => e.info.id === id)!;
    const scene = buildScene('bouncing-ball');
    const sim = engine.create(scene);
    const state = allocateState(1);
    try {
      const steps = 30;
      const dt = 1 / 60;
      for (let i = 0; i < steps; i++) sim.step(dt);
      sim.read(state);
      const t = steps * dt;
      const g = scene.gravity.y;
      // Euler variants land between g t^2/2 minus and plus one step's worth; 5% covers them all.
      expect(state.y[0] - scene.y[0]).toBeGreaterThan(0.95 * 0.5 * g * t * t);
      expect(state.y[0] - scene.y[0]).toBeLessThan(1.05 * 0.5 * g * t * t);
      expect(state.vy[0]).toBeCloseTo(g * t, -1);
      expect(Math.abs(state.x[0] - scene.x[0])).toBeLessThan(1e-3);
    } finally {
      sim.dispose();
    }
  });

  it.each(ENGINE_IDS)('%s: the uniform scene stays in its box and keeps its energy bounded over 1 s', (id) => {
    const engine = engines.find((e) => e.info.id === id)!;
    const scene = buildScene('uniform', { n: 200, seed: 5, maxSpeed: 300 });
    const masses = sceneMasses(scene);
    const sim = engine.create(scene);
    const state = allocateState(scene.count);
    try {
      sim.read(state);
      const e0 = energyOf(scene, masses, state).total;
      for (let i = 0; i < 60; i++) sim.step(1 / 60);
      sim.read(state);
      const { width, height } = scene.bounds;
      for (let k = 0; k < scene.count; k++) {
        // Soft-contact engines let circles sink a little into the walls; their centres never leave.
        const r = scene.radius[k];
        expect(state.x[k], `${id} body ${k} x`).toBeGreaterThan(-1e-6);
        expect(state.x[k], `${id} body ${k} x`).toBeLessThan(width + 1e-6);
        expect(state.y[k], `${id} body ${k} y`).toBeGreaterThan(-1e-6);
        expect(state.y[k], `${id} body ${k} y`).toBeLessThan(height + 1e-6);
        expect(r).toBeGreaterThan(0);
      }
      const ratio = energyOf(scene, masses, state).total / e0;
      expect(ratio, id).toBeGreaterThan(0.5);
      expect(ratio, id).toBeLessThan(1.1);
    } finally {
      sim.dispose();
    }
  });
});

describe('scenes with static shapes', () => {
  it('peer adapters refuse them by name; maxgrid builds them', () => {
    const funnel = buildScene('funnel', {});
    for (const engine of engines) {
      if (engine.info.package === '@maxgrid/engine') {
        const sim = engine.create(funnel);
        sim.step(1 / 60);
        expect(sim.count).toBe(funnel.count);
        sim.dispose();
      } else {
        expect(() => engine.create(funnel), engine.info.id).toThrow(new RegExp(`engine '${engine.info.id}' cannot build scene 'funnel'.*static circles.*segments`));
      }
    }
  });
});
