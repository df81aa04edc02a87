import { describe, expect, it } from 'vitest';
import { World } from '../src/index.js';

function pair(options: { ra?: number; rb?: number; ma?: number; mb?: number; ea?: number; eb?: number; gap?: number; typeB?: 'static' | 'kinematic' | 'dynamic' }) {
  const { ra = 5, rb = 5, ma, mb, ea = 1, eb = 1, gap = -1, typeB = 'dynamic' } = options;
  const world = new World({ integrator: 'explicit-euler' });
  const a = world.createCircle({ x: 0, y: 0, vx: 10, radius: ra, mass: ma, restitution: ea });
  const b = world.createCircle({ x: ra + rb + gap, y: 0, vx: typeB === 'static' ? 0 : -10, radius: rb, mass: mb, restitution: eb, type: typeB });
  return { world, a, b };
}

describe('collision response (report 3.1.5, 5.10)', () => {
  it('equal masses, restitution 1, head on: velocities swap', () => {
    const { world, a, b } = pair({});
    world.step(0);
    expect(world.stats.contacts).toBe(1);
    expect(world.getCircle(a).vx).toBeCloseTo(-10, 12);
    expect(world.getCircle(b).vx).toBeCloseTo(10, 12);
  });

  it("matches the report's formula for unequal masses", () => {
    const { world, a, b } = pair({ ma: 1, mb: 3 });
    world.step(0);
    const [ma, mb, va, vb] = [1, 3, 10, -10];
    expect(world.getCircle(a).vx).toBeCloseTo((va * (ma - mb) + 2 * mb * vb) / (ma + mb), 12);
    expect(world.getCircle(b).vx).toBeCloseTo((vb * (mb - ma) + 2 * ma * va) / (ma + mb), 12);
  });

  it('the pair restitution is the larger of the two (two equal values e give e)', () => {
    for (const [ea, eb, expected] of [[0.5, 0.5, 0.5], [0.2, 0.8, 0.8], [0, 1, 1], [0, 0, 0]]) {
      const { world, a, b } = pair({ ea, eb });
      world.step(0);
      const separating = world.getCircle(b).vx - world.getCircle(a).vx;
      expect(separating).toBeCloseTo(expected * 20, 12);
    }
  });

  it('separation leaves the pair tangent, and the heavier body moves less', () => {
    const { world, a, b } = pair({ ma: 1, mb: 4, gap: -2 });
    world.step(0);
    const ca = world.getCircle(a);
    const cb = world.getCircle(b);
    expect(cb.x - ca.x).toBeCloseTo(10, 12);
    expect(-ca.x).toBeCloseTo(2 * (4 / 5), 12);
    expect(cb.x - 8).toBeCloseTo(2 * (1 / 5), 12);
  });

  it('with positionCorrection and contactSlop, separation removes that fraction of the overlap beyond the slop', () => {
    // Overlap 2 (gap -2), slop 0.5: 1.5 beyond it; a quarter of that, 0.375, split 4:1 by inverse mass.
    const world = new World({ positionCorrection: 0.25, contactSlop: 0.5 });
    const a = world.createCircle({ x: 0, y: 0, radius: 5, mass: 1 });
    const b = world.createCircle({ x: 8, y: 0, radius: 5, mass: 4 });
    world.step(0);
    expect(-world.getCircle(a).x).toBeCloseTo(0.375 * (4 / 5), 12);
    expect(world.getCircle(b).x - 8).toBeCloseTo(0.375 * (1 / 5), 12);
    // Within the slop nothing moves, and the impulse still acts.
    const inside = new World({ contactSlop: 0.5 });
    const c = inside.createCircle({ x: 0, y: 0, vx: 3, radius: 5 });
    const d = inside.createCircle({ x: 9.75, y: 0, radius: 5 });
    inside.step(0);
    expect(inside.getCircle(c)).toMatchObject({ x: 0, vx: 0 });
    expect(inside.getCircle(d)).toMatchObject({ x: 9.75, vx: 3 });
  });

  it('a static body is infinitely massive: the dynamic one reflects and takes the whole separation', () => {
    const { world, a, b } = pair({ typeB: 'static', gap: -2 });
    world.step(0);
    expect(world.getCircle(a)).toMatchObject({ vx: -10, x: -2 });
    expect(world.getCircle(b)).toMatchObject({ vx: 0, x: 8 });
  });

  it('separating pairs keep their velocities', () => {
    const world = new World();
    const a = world.createCircle({ x: 0, y: 0, vx: -5, radius: 5 });
    const b = world.createCircle({ x: 9, y: 0, vx: 5, radius: 5 });
    world.step(0);
    expect(world.getCircle(a).vx).toBe(-5);
    expect(world.getCircle(b).vx).toBe(5);
    expect(world.getCircle(b).x - world.getCircle(a).x).toBeCloseTo(10, 12);
  });

  it('concentric circles are pushed apart instead of producing NaN', () => {
    const world = new World();
    const a = world.createCircle({ x: 3, y: 3, radius: 2 });
    const b = world.createCircle({ x: 3, y: 3, radius: 2 });
    world.step(1 / 60);
    const ca = world.getCircle(a);
    const cb = world.getCircle(b);
    expect(Number.isFinite(ca.x) && Number.isFinite(cb.x)).toBe(true);
    expect(Math.hypot(cb.x - ca.x, cb.y - ca.y)).toBeCloseTo(4, 12);
  });
});

describe('box walls (report 5.7)', () => {
  it('a crossing circle is mirrored back by its penetration depth and its normal velocity reversed', () => {
    const world = new World({ bounds: { width: 100, height: 100 }, integrator: 'explicit-euler' });
    const h = world.createCircle({ x: 90, y: 50, vx: 300, vy: 30, radius: 5 });
    world.step(0.1);
    // Unbounded it would reach x = 120, 25 past the wall at 95: mirrored it stands at 70.
    expect(world.getCircle(h)).toMatchObject({ x: 70, y: 53, vx: -300, vy: 30 });
  });

  it('restitution scales the normal velocity and the mirrored distance', () => {
    const world = new World({ bounds: { width: 100, height: 100 }, restitution: 0.5, integrator: 'explicit-euler' });
    const h = world.createCircle({ x: 50, y: 10, vx: 0, vy: -100, radius: 5 });
    world.step(0.1);
    expect(world.getCircle(h)).toMatchObject({ x: 50, y: 7.5, vy: 50 });
  });
});
