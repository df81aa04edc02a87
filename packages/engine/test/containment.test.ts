import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { World, type World as WorldType } from '../src/index.js';
import { BROADPHASE_NAMES, buildSpec, sceneArbitrary } from './helpers.js';

function assertInside(world: WorldType, width: number, height: number): void {
  const v = world.views();
  for (let i = 0; i < v.slotCount; i++) {
    if (v.type[i] === 0) continue;
    const r = v.radius[i];
    if (!(v.x[i] >= r && v.x[i] <= width - r && v.y[i] >= r && v.y[i] <= height - r)) {
      throw new Error(`slot ${i} at (${v.x[i]}, ${v.y[i]}) radius ${r} is outside ${width} x ${height}`);
    }
  }
}

describe('containment: no circle ends a step outside the box', () => {
  it('at extreme speeds that cross the box many times per step, for any restitution', () => {
    for (const speed of [1e3, 1e6, 1e9, 1e15, 1e100]) {
      for (const restitution of [1, 0.9, 0.5, 0]) {
        const world = new World({ bounds: { width: 300, height: 200 }, restitution });
        world.createCircle({ x: 150, y: 100, vx: speed, vy: -speed / 3, radius: 10 });
        world.createCircle({ x: 40, y: 40, vx: -speed / 7, vy: speed, radius: 5 });
        for (let s = 0; s < 20; s++) {
          world.step(1 / 60);
          assertInside(world, 300, 200);
        }
        for (const h of world.handles()) {
          const c = world.getCircle(h);
          expect(Number.isFinite(c.vx) && Number.isFinite(c.vy)).toBe(true);
        }
      }
    }
  });

  it('on random crowded scenes with every broad-phase', () => {
    fc.assert(
      fc.property(sceneArbitrary, fc.constantFrom(...BROADPHASE_NAMES), (spec, broadphase) => {
        const world = buildSpec(spec, { broadphase });
        for (let s = 0; s < 30; s++) {
          world.step(1 / 30);
          assertInside(world, spec.width, spec.height);
        }
      }),
      { numRuns: 40, seed: 7 },
    );
  });

  it('kinematic bodies are contained too and keep their speed', () => {
    const world = new World({ bounds: { width: 100, height: 100 }, restitution: 0.2 });
    const k = world.createCircle({ x: 50, y: 50, vx: 1e5, vy: 0, radius: 5, type: 'kinematic' });
    for (let s = 0; s < 10; s++) {
      world.step(1 / 60);
      assertInside(world, 100, 100);
    }
    expect(Math.abs(world.getCircle(k).vx)).toBe(1e5);
  });

  it('at the largest speed and step the engine takes (1e100 and 1e6 s), a circle stays in the box and finite', () => {
    const world = new World({ bounds: { width: 100, height: 100 }, restitution: 1000 });
    world.createCircle({ x: 50, y: 50, vx: 1e100, vy: -1e100, radius: 5 });
    world.createCircle({ x: 20, y: 20, vx: -1e100, vy: 1e100, radius: 5 });
    for (let s = 0; s < 5; s++) {
      world.step(1e6);
      assertInside(world, 100, 100);
    }
    const v = world.views();
    for (let k = 0; k < 2; k++) expect([v.x[k], v.y[k], v.vx[k], v.vy[k]].every(Number.isFinite)).toBe(true);
    // Beyond those, the input is refused by name rather than left to overflow.
    expect(() => world.createCircle({ x: 50, y: 50, vx: 1.7e308, vy: 0, radius: 5 })).toThrow(/vx must be within ±1e\+100/);
    expect(() => world.step(1e7)).toThrow(/dt must be at most 1000000/);
  });

  it("a pile of boxes in the box settles and sleeps, as between static walls: containment leaves the walls' contacts their slop", () => {
    // Moved out of the slop the wall contacts rest in, boxes along a wall were pushed into their
    // neighbours every step, and 198 of 200 were still awake after 15 s.
    const cols = 16;
    const cell = 1.9;
    const width = cols * cell + 2;
    const height = Math.ceil(200 / cols) * cell + 6;
    const world = new World({ gravity: { x: 0, y: 10 }, friction: 0.6, restitution: 0, sleeping: true, bounds: { width, height } });
    let seed = 12345;
    const random = (): number => (seed = (seed * 16807) % 2147483647) / 2147483647;
    for (let k = 0; k < 200; k++) {
      const x = 1 + cell * ((k % cols) + 0.5);
      const y = height - 2 - cell * (Math.floor(k / cols) + 0.5);
      world.createBox({ x, y, width: 2 * (0.15 + 0.45 * random()), height: 2 * (0.15 + 0.45 * random()), angle: 6 * random() - 3 });
    }
    for (let s = 0; s < 12 * 60; s++) world.step(1 / 60);
    expect(world.stats.sleepingBodies).toBe(200);
  });

  it('a box thrown far past a wall in one step lands inside, against the wall it crossed', () => {
    const cases = [
      // The speed limit lifted to the largest allowed: with the default one no body moves that far.
      { solver: 'elastic', gravity: 1e100, vy: 0, options: { maxLinearSpeed: 1e100 } },
      { solver: 'elastic', gravity: 1e20, vy: 0, options: { maxLinearSpeed: 1e100 } },
      { solver: 'elastic', gravity: 0, vy: 1e20, options: { maxLinearSpeed: 1e100 } },
      { solver: 'elastic', gravity: 0, vy: -1e20, options: { maxLinearSpeed: 1e100 } },
      { solver: 'soft', gravity: 0, vy: 1e20, options: { maxLinearSpeed: 1e100 } },
    ] as const;
    for (const { solver, gravity, vy, options } of cases) {
      const world = new World({ bounds: { width: 100, height: 100 }, restitution: 0, solver, gravity: { x: 0, y: gravity }, ...options });
      const box = world.createBox({ x: 50, y: 50, width: 3, height: 1.8, vy });
      for (let s = 0; s < 3; s++) {
        world.step(1 / 60);
        const { x, y } = world.getBody(box);
        const label = `${solver}, gravity ${gravity}, vy ${vy}, step ${s + 1}: at (${x}, ${y})`;
        // The soft step's wall contacts rest up to a slop (5 mm) deep, and containment leaves
        // that much: moved out of it, bodies along a wall were pushed into their neighbours.
        const allowance = solver === 'soft' ? 0.005 : 0;
        expect(x, label).toBeGreaterThanOrEqual(1.5 - allowance);
        expect(x, label).toBeLessThanOrEqual(98.5 + allowance);
        expect(y, label).toBeGreaterThanOrEqual(0.9 - allowance - 1e-9);
        expect(y, label).toBeLessThanOrEqual(99.1 + allowance + 1e-9);
        // y grows downwards: the first step ends at the floor (y = 100) when it was thrown or
        // pulled that way. (What the solver makes of 1e20 m/s into a wall after that is not asked.)
        if (s === 0) expect(y, label).toBeCloseTo(gravity > 0 || vy > 0 ? 99.1 + allowance : 0.9 - allowance, 6);
      }
    }
  });
});
