import { describe, expect, it } from 'vitest';
import { buildShapeScene } from '@maxgrid/scenes';
import { SCENE_CHOICES, defaultSettings, refusedTools, sceneSpecs, type SceneChoice } from '../../src/settings.js';
import { Simulation } from '../../src/simulation.js';

/** Each scene at a size that builds in milliseconds. */
const SMALL: Partial<Record<SceneChoice, Record<string, number>>> = {
  'seed-box': { n: 50 },
  funnel: { n: 50 },
  mixed: { n: 200 },
  uniform: { n: 50 },
  'polygon-box': { n: 50 },
  pyramid: { base: 5 },
  'uniform-polygons': { n: 50 },
  'many-pyramids': { rows: 2, columns: 2 },
  tumbler: { grid: 5 },
  'vertical-stack': { count: 3 },
  'card-house': { levels: 2 },
  chain: { links: 5 },
  bridge: { planks: 5, load: 2 },
  'joint-grid': { size: 4 },
  ragdolls: { count: 2 },
  car: { bumps: 3 },
  jellies: { count: 2 },
  blobs: { count: 2 },
};

describe('scene sliders', () => {
  it.each(SCENE_CHOICES)('%s: every slider has a label of its own, not its parameter\'s name', (scene) => {
    for (const spec of sceneSpecs(scene)) expect(spec.label, `${scene}.${spec.key}`).not.toBe(spec.key);
  });

  it("polygon-box, the seed box with shapes, has the seed box's sliders, and builds at every corner of its size and box sliders", () => {
    const seedBox = Object.fromEntries(sceneSpecs('seed-box').map((s) => [s.key, s]));
    const shapes = Object.fromEntries(sceneSpecs('polygon-box').map((s) => [s.key, s]));
    for (const key of ['gravity', 'elasticity', 'size', 'sizeNoise', 'velocity', 'velocityNoise']) {
      const pick = ({ label, min, max, step }: (typeof shapes)[string]) => ({ label, min, max, step });
      expect(pick(shapes[key]), key).toEqual(pick(seedBox[key]));
    }
    const ends = (key: string) => [shapes[key].min, shapes[key].max];
    for (const size of ends('size')) {
      for (const sizeNoise of ends('sizeNoise')) {
        for (const width of ends('width')) {
          for (const height of ends('height')) {
            const params = { n: 50, size, sizeNoise, width, height };
            expect(() => buildShapeScene('polygon-box', params), JSON.stringify(params)).not.toThrow();
          }
        }
      }
    }
  });
});

describe('tools', () => {
  it.each(SCENE_CHOICES)('%s offers Pin and Cut exactly where its world takes a pin', (scene) => {
    const settings = defaultSettings(scene);
    Object.assign(settings.params, SMALL[scene]);
    const sim = new Simulation();
    sim.rebuild(settings);
    const body = sim.world.handles().find((h) => sim.world.getBody(h).type === 'dynamic');
    expect(body, 'a dynamic body to pin').toBeDefined();
    const b = sim.world.getBody(body!);
    let pinned = true;
    try {
      sim.pin(body!, b.x, b.y);
    } catch {
      pinned = false;
    }
    const refused = refusedTools(sim.acceptsJoints);
    expect({ pin: refused.pin === undefined, cut: refused.cut === undefined }).toEqual({ pin: pinned, cut: pinned });
  });
});
