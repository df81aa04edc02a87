import { describe, expect, it } from 'vitest';
import { World } from '../src/index.js';

describe('integrators', () => {
  it('explicit Euler: position advances with the old velocity, then velocity with gravity', () => {
    const world = new World({ gravity: { x: 2, y: -10 }, integrator: 'explicit-euler' });
    const h = world.createCircle({ x: 1, y: 2, vx: 3, vy: 4, radius: 1 });
    world.step(0.5);
    expect(world.getCircle(h)).toMatchObject({ x: 1 + 3 * 0.5, y: 2 + 4 * 0.5, vx: 3 + 2 * 0.5, vy: 4 - 10 * 0.5 });
  });

  it('semi-implicit Euler: velocity first, then position with the new velocity', () => {
    const world = new World({ gravity: { x: 2, y: -10 }, integrator: 'semi-implicit-euler' });
    const h = world.createCircle({ x: 1, y: 2, vx: 3, vy: 4, radius: 1 });
    world.step(0.5);
    expect(world.getCircle(h)).toMatchObject({ x: 1 + 4 * 0.5, y: 2 + -1 * 0.5, vx: 4, vy: -1 });
  });

  it('zero gravity is allowed and leaves velocities alone', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const h = world.createCircle({ x: 0, y: 0, vx: 1, vy: -1, radius: 1 });
    for (let s = 0; s < 10; s++) world.step(0.1);
    expect(world.getCircle(h).vx).toBe(1);
    expect(world.getCircle(h).x).toBeCloseTo(1, 12);
  });

  it('switching integrator at run time takes effect on the next step', () => {
    const world = new World({ gravity: { x: 0, y: 10 }, integrator: 'explicit-euler' });
    const h = world.createCircle({ x: 0, y: 0, radius: 1 });
    world.step(1);
    expect(world.getCircle(h).y).toBe(0);
    world.setIntegrator('semi-implicit-euler');
    world.step(1);
    expect(world.getCircle(h).y).toBe(20);
  });

  it('dt = 0 moves nothing', () => {
    const world = new World({ gravity: { x: 0, y: 10 } });
    const h = world.createCircle({ x: 0, y: 0, vx: 5, radius: 1 });
    world.step(0);
    expect(world.getCircle(h)).toMatchObject({ x: 0, y: 0, vx: 5, vy: 0 });
  });
});

describe('body types (report 3.1.2)', () => {
  it('a static body never moves, even when hit', () => {
    const world = new World({ gravity: { x: 0, y: 100 } });
    const wall = world.createCircle({ x: 0, y: 0, radius: 10, type: 'static' });
    world.createCircle({ x: -25, y: 0, vx: 500, radius: 5 });
    for (let s = 0; s < 60; s++) world.step(1 / 60);
    expect(world.getCircle(wall)).toMatchObject({ x: 0, y: 0, vx: 0, vy: 0 });
  });

  it('a kinematic body moves with its velocity, ignores gravity and collisions, and pushes dynamic bodies', () => {
    const world = new World({ gravity: { x: 0, y: 100 } });
    const pusher = world.createCircle({ x: 0, y: 0, vx: 60, radius: 10, type: 'kinematic' });
    const ball = world.createCircle({ x: 25, y: 0, radius: 5 });
    for (let s = 0; s < 60; s++) world.step(1 / 60);
    const p = world.getCircle(pusher);
    expect(p.x).toBeCloseTo(60, 9);
    expect(p).toMatchObject({ y: 0, vx: 60, vy: 0 });
    expect(world.getCircle(ball).x).toBeGreaterThan(p.x + 14.99);
  });

  it('types change at run time (mutable object types, report 3.2)', () => {
    const world = new World({ gravity: { x: 0, y: 10 } });
    const h = world.createCircle({ x: 0, y: 0, vx: 5, radius: 1 });
    world.setType(h, 'static');
    world.step(1);
    expect(world.getCircle(h)).toMatchObject({ x: 0, y: 0, vx: 0, vy: 0, type: 'static' });
    world.setType(h, 'kinematic');
    world.setVelocity(h, 1, 0);
    world.step(1);
    expect(world.getCircle(h)).toMatchObject({ x: 1, y: 0, type: 'kinematic' });
    world.setType(h, 'dynamic');
    world.step(1);
    expect(world.getCircle(h).vy).toBeGreaterThan(0);
  });
});
