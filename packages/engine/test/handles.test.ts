import { describe, expect, it } from 'vitest';
import { World } from '../src/index.js';

describe('handles', () => {
  it('destroying a body leaves every other handle valid and pointing at the same body', () => {
    const world = new World({ bounds: { width: 1000, height: 1000 } });
    const handles = Array.from({ length: 50 }, (_, k) => world.createCircle({ x: 10 + k * 19, y: 500, radius: 1 + (k % 5) }));
    for (let k = 0; k < 50; k += 3) world.destroyBody(handles[k]);
    expect(world.bodyCount).toBe(50 - 17);
    handles.forEach((h, k) => {
      if (k % 3 === 0) {
        expect(world.hasBody(h)).toBe(false);
      } else {
        expect(world.getCircle(h).x).toBe(10 + k * 19);
        expect(world.getCircle(h).radius).toBe(1 + (k % 5));
      }
    });
  });

  it('a reused slot gets a new handle, and the old one stays rejected', () => {
    const world = new World();
    const first = world.createCircle({ x: 0, y: 0, radius: 1 });
    world.destroyBody(first);
    const second = world.createCircle({ x: 5, y: 5, radius: 2 });
    expect(second).not.toBe(first);
    expect(world.hasBody(first)).toBe(false);
    expect(() => world.getCircle(first)).toThrow(/stale/);
    expect(world.getCircle(second).x).toBe(5);
  });

  it('handles are plain non-negative integers, the first ones counting from 0', () => {
    const world = new World();
    expect([0, 1, 2].map(() => world.createCircle({ x: 0, y: 0, radius: 1 }))).toEqual([0, 1, 2]);
  });

  it('destroyed bodies stop taking part: no contacts with them, no energy from them', () => {
    const world = new World();
    const a = world.createCircle({ x: 0, y: 0, vx: 10, radius: 5 });
    const b = world.createCircle({ x: 6, y: 0, radius: 5 });
    world.destroyBody(b);
    world.step(1 / 60);
    expect(world.stats.contacts).toBe(0);
    expect(world.stats.candidatePairs).toBe(0);
    expect(world.kineticEnergy()).toBeCloseTo(0.5 * world.getCircle(a).mass * 100, 9);
  });

  it('handleAtSlot maps the bulk views back to handles', () => {
    const world = new World();
    const a = world.createCircle({ x: 0, y: 0, radius: 1 });
    const b = world.createCircle({ x: 9, y: 0, radius: 1 });
    world.destroyBody(a);
    const c = world.createCircle({ x: 3, y: 0, radius: 1 });
    const v = world.views();
    const found: number[] = [];
    for (let s = 0; s < v.slotCount; s++) if (v.type[s] !== 0) found.push(world.handleAtSlot(s));
    expect(found.sort()).toEqual([b, c].sort());
    expect(world.handleAtSlot(99)).toBe(-1);
  });
});
