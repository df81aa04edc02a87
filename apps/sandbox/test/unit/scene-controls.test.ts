import { describe, expect, it } from 'vitest';
import { buildShapeScene } from '@maxgrid/scenes';
import { SCENE_CHOICES, sceneSpecs } from '../../src/settings.js';

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
