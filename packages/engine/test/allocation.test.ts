import { describe, expect, it } from 'vitest';
import { buildScene, buildWorld } from '@maxgrid/scenes';
import { World } from '../src/index.js';
import { BROADPHASE_NAMES } from './helpers.js';

describe('no buffer reallocation inside step() after warm-up (boxed numbers are not counted here)', () => {
  it.each(BROADPHASE_NAMES)('%s: internal buffer capacities stop changing', (broadphase) => {
    const n = broadphase === 'naive' ? 300 : 3000;
    const world = buildWorld(buildScene('uniform', { n, seed: 4 }), { broadphase });
    for (let s = 0; s < 60; s++) world.step(1 / 60);
    const warm = world.internalCapacities();
    const bodyArrays = world.views().x;
    for (let s = 0; s < 400; s++) {
      world.step(1 / 60);
      expect(world.internalCapacities()).toEqual(warm);
    }
    expect(world.views().x).toBe(bodyArrays);
  });

  it('buffers grow geometrically as bodies are added, not one at a time', () => {
    const world = new World();
    const seen = new Set<number>();
    for (let k = 0; k < 5000; k++) {
      world.createCircle({ x: 0, y: 0, radius: 1 });
      seen.add(world.internalCapacities().bodies);
    }
    expect(seen.size).toBeLessThanOrEqual(10);
  });

  it('reserve() sizes storage up front', () => {
    const world = new World();
    world.reserve(10_000);
    const capacity = world.internalCapacities().bodies;
    for (let k = 0; k < 10_000; k++) world.createCircle({ x: 0, y: 0, radius: 1 });
    expect(world.internalCapacities().bodies).toBe(capacity);
  });
});
