import { describe, expect, it } from 'vitest';
import { World, type WorldOptions } from '../src/index.js';

const DT = 1 / 60;
const CAP = 100;

/** The worlds a body can move in: the circle engine, the shape route's elastic pass (asked for, or picked by auto for a frictionless box), and the soft step. */
const ROUTES: { label: string; options: WorldOptions; body: (world: World) => number }[] = [
  { label: 'circle engine', options: {}, body: (w) => w.createCircle({ x: 0, y: 0, radius: 0.5 }) },
  { label: "elastic pass, 'elastic'", options: { solver: 'elastic' }, body: (w) => w.createBox({ x: 0, y: 0, width: 1, height: 1 }) },
  { label: "elastic pass, 'auto'", options: {}, body: (w) => w.createBox({ x: 0, y: 0, width: 1, height: 1 }) },
  { label: 'soft step', options: { solver: 'soft' }, body: (w) => w.createBox({ x: 0, y: 0, width: 1, height: 1 }) },
];

/** What the step is given: a velocity set between steps, an impulse, a force, strong gravity. */
const PUSHES: { label: string; gravity: number; push: (world: World, h: number) => void }[] = [
  { label: 'setVelocity 1e6', gravity: 0, push: (w, h) => w.setVelocity(h, 6e5, -8e5) },
  { label: 'applyImpulse 1e9', gravity: 0, push: (w, h) => w.applyImpulse(h, -1e9, 0) },
  { label: 'applyForce 1e9', gravity: 0, push: (w, h) => w.applyForce(h, 0, 1e9) },
  { label: 'gravity 1e8', gravity: 1e8, push: () => {} },
];

describe('maxLinearSpeed', () => {
  it('no dynamic body moves faster within a step, whatever set its velocity, on every route and integrator', () => {
    for (const route of ROUTES) {
      // rk4 moves a world to the shape route, so the circle engine has the two Euler methods.
      const integrators = route.label === 'circle engine' ? (['explicit-euler', 'semi-implicit-euler'] as const) : (['explicit-euler', 'semi-implicit-euler', 'rk4'] as const);
      for (const integrator of integrators) {
        for (const { label, gravity, push } of PUSHES) {
          const world = new World({ ...route.options, integrator, gravity: { x: 0, y: gravity }, maxLinearSpeed: CAP });
          const h = route.body(world);
          for (let s = 0; s < 3; s++) {
            if (s === 0) push(world, h);
            const before = world.getBody(h);
            world.step(DT);
            const after = world.getBody(h);
            const moved = Math.hypot(after.x - before.x, after.y - before.y);
            const what = `${route.label}, ${integrator}, ${label}, step ${s + 1}: moved ${moved}`;
            expect(moved, what).toBeLessThanOrEqual(CAP * DT * (1 + 1e-12));
            expect(Math.hypot(after.vx, after.vy), what).toBeLessThanOrEqual(CAP * (1 + 1e-12));
          }
        }
      }
    }
  });

  it('under the limit, bodies move as they would without one (the same bits)', () => {
    for (const route of ROUTES) {
      const hashes = [CAP, undefined].map((maxLinearSpeed) => {
        const world = new World({ ...route.options, gravity: { x: 3, y: 10 }, maxLinearSpeed });
        const h = route.body(world);
        world.setVelocity(h, 40, -30);
        for (let s = 0; s < 30; s++) {
          if (s === 10) world.applyForce(h, 50, 20);
          world.step(DT);
        }
        return world.stateHash();
      });
      expect(hashes[0], route.label).toBe(hashes[1]);
    }
  });
});
