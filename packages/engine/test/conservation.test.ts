import { describe, expect, it } from 'vitest';
import { World } from '../src/index.js';
import { buildScene, buildWorld } from '@maxgrid/scenes';
import { randomWorld } from './helpers.js';

describe('conservation', () => {
  it('momentum is conserved by collisions (no walls, no gravity), at any restitution', () => {
    for (const restitution of [1, 0.5, 0]) {
      const world = randomWorld(400, 5, { restitution }, 150);
      const before = world.momentum();
      let contacts = 0;
      for (let s = 0; s < 300; s++) {
        world.step(1 / 60);
        contacts += world.stats.contacts;
      }
      const after = world.momentum();
      expect(contacts).toBeGreaterThan(100);
      // Summing 400 terms of magnitude ~1e4 each: round-off is ~1e-9, any real leak is far larger.
      const scale = 1e4 * 400;
      expect(Math.abs(after.x - before.x)).toBeLessThan(scale * 1e-12);
      expect(Math.abs(after.y - before.y)).toBeLessThan(scale * 1e-12);
    }
  });

  it('kinetic energy stays constant to round-off with restitution 1 and no gravity, over a long run', () => {
    const world = buildWorld(buildScene('uniform', { n: 2000, seed: 9 }));
    const before = world.kineticEnergy();
    let contacts = 0;
    for (let s = 0; s < 3000; s++) {
      world.step(1 / 60);
      contacts += world.stats.contacts;
    }
    expect(contacts).toBeGreaterThan(10_000);
    expect(Math.abs(world.kineticEnergy() / before - 1)).toBeLessThan(1e-10);
  });

  it('kinetic energy drops with restitution below 1 (so the test above can fail)', () => {
    const world = randomWorld(500, 9, { bounds: { width: 600, height: 400 }, restitution: 0.5 });
    const before = world.kineticEnergy();
    for (let s = 0; s < 600; s++) world.step(1 / 60);
    expect(world.kineticEnergy()).toBeLessThan(0.5 * before);
  });

  it('potential energy is -m g.p, zero without gravity, and total energy of a falling body is near constant', () => {
    const flat = new World({ bounds: { width: 100, height: 100 } });
    flat.createCircle({ x: 50, y: 20, radius: 5 });
    expect(flat.potentialEnergy()).toBe(0);

    const world = new World({ gravity: { x: 0, y: 100 }, integrator: 'semi-implicit-euler' });
    const h = world.createCircle({ x: 0, y: 0, radius: 1, mass: 2 });
    world.step(0.001);
    const start = world.kineticEnergy() + world.potentialEnergy();
    for (let s = 0; s < 1000; s++) world.step(0.001);
    const c = world.getCircle(h);
    expect(world.potentialEnergy()).toBeCloseTo(-2 * 100 * c.y, 9);
    const end = world.kineticEnergy() + world.potentialEnergy();
    // Semi-implicit Euler under constant gravity errs by m g^2 dt t / 2 at most: 2*1e4*1e-3*1/2 = 10.
    expect(Math.abs(end - start)).toBeLessThan(11);
  });
});
