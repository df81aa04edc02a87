import { describe, expect, it } from 'vitest';
import { World } from '../src/index.js';

describe('forces, impulses, gravity scale, damping', () => {
  it('a force acts for one step as F/m, then is cleared', () => {
    const world = new World({ integrator: 'semi-implicit-euler' });
    const h = world.createCircle({ x: 0, y: 0, radius: 1, mass: 2 });
    world.applyForce(h, 10, -4);
    world.applyForce(h, 10, 0);
    world.step(0.5);
    expect(world.getCircle(h)).toMatchObject({ vx: 5, vy: -1, x: 2.5, y: -0.5 });
    world.step(0.5);
    expect(world.getCircle(h)).toMatchObject({ vx: 5, vy: -1 });
  });

  it('a force and a torque act for one step, on the circle route and with shapes, and a pause (step(0)) keeps them for the next', () => {
    for (const shapes of [false, true]) {
      const world = new World({ gravity: { x: 0, y: 0 } });
      const h = shapes ? world.createBox({ x: 0, y: 0, width: 2, height: 2, mass: 2 }) : world.createCircle({ x: 0, y: 0, radius: 1, mass: 2 });
      const { mass, inertia } = world.getBody(h);
      world.applyForce(h, 4, 0);
      world.applyTorque(h, 1);
      world.step(0);
      world.step(0);
      for (let s = 0; s < 3; s++) {
        world.step(0.5);
        const b = world.getBody(h);
        const label = `${shapes ? 'shapes' : 'circles'}, step ${s}`;
        expect(b.vx, label).toBeCloseTo((4 / mass) * 0.5, 12);
        expect(b.angularVelocity, label).toBeCloseTo((1 / inertia) * 0.5, 12);
      }
    }
  });

  it('a force or an impulse at a point adds its moment about the centre of mass', () => {
    // An L of two boxes, its centre of mass off its origin, turned and far out: the arm is from the centre of mass.
    const make = (world: World, x: number): number => {
      const h = world.createBody({ x, y: -3, angle: 0.7 });
      world.addShape(h, { kind: 'box', width: 2, height: 0.5, offsetX: 1 });
      world.addShape(h, { kind: 'box', width: 0.5, height: 1.5, offsetY: 1 });
      return h;
    };
    const world = new World({ gravity: { x: 0, y: 0 } });
    const a = make(world, 1e4);
    const b = make(world, 2e4);
    const body = world.getBody(a);
    const px = body.centerX + 0.75;
    const py = body.centerY - 1.25;
    world.applyForceAtPoint(a, 30, -12, px, py);
    world.applyForce(b, 30, -12);
    world.applyTorque(b, (px - body.centerX) * -12 - (py - body.centerY) * 30);
    world.step(1 / 60);
    const [fa, fb] = [world.getBody(a), world.getBody(b)];
    expect([fa.vx, fa.vy, fa.angularVelocity]).toEqual([fb.vx, fb.vy, fb.angularVelocity]);
    expect(fa.angularVelocity).toBeCloseTo((0.75 * -12 + 1.25 * 30) / body.inertia / 60, 12);

    const before = world.getBody(a);
    world.applyImpulseAtPoint(a, 4, 5, before.centerX - 2, before.centerY + 0.5);
    const after = world.getBody(a);
    expect(after.vx - before.vx).toBeCloseTo(4 / before.mass, 14);
    expect(after.vy - before.vy).toBeCloseTo(5 / before.mass, 14);
    expect(after.angularVelocity - before.angularVelocity).toBeCloseTo((-2 * 5 - 0.5 * 4) / before.inertia, 12);

    // A body that cannot turn takes the linear part alone; a sleeper wakes.
    const fixed = world.createBox({ x: 0, y: 0, width: 1, height: 1, fixedRotation: true });
    world.applyImpulseAtPoint(fixed, 0, 3, 0.5, 0);
    expect(world.getBody(fixed)).toMatchObject({ vy: 3, angularVelocity: 0 });
    const sleepy = new World({ sleeping: true });
    const s = sleepy.createBox({ x: 0, y: 0, width: 1, height: 1 });
    sleepy.setAwake(s, false);
    sleepy.applyForceAtPoint(s, 1, 0, 0, 0.5);
    expect(sleepy.isAwake(s)).toBe(true);
  });

  it('a force or an impulse at a point is refused whole, naming the field, where a part of it is bad', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const h = world.createBox({ x: 0, y: 0, width: 1, height: 1, density: 1e-6 });
    const twin = world.createBox({ x: 5, y: 0, width: 1, height: 1, density: 1e-6 });
    expect(() => world.applyForceAtPoint(h, 1, 0, Number.NaN, 0)).toThrow(TypeError);
    expect(() => world.applyForceAtPoint(h, 1, 0, Number.NaN, 0)).toThrow(/\bx\b/);
    expect(() => world.applyImpulseAtPoint(h, 1, 0, 0, Infinity)).toThrow(/\by\b/);
    // A linear part within bounds, a moment past them: nothing is added.
    expect(() => world.applyForceAtPoint(h, 1e90, 0, 0, 1e90)).toThrow(RangeError);
    expect(() => world.applyImpulseAtPoint(h, 1e90, 0, 0, 1e90)).toThrow(/angular velocity/);
    const ground = world.createBox({ x: 0, y: 9, width: 1, height: 1, type: 'static' });
    expect(() => world.applyForceAtPoint(ground, 1, 0, 0, 0)).toThrow(/only dynamic bodies/);
    world.step(1 / 60);
    const [a, b] = [world.getBody(h), world.getBody(twin)];
    expect([a.vx, a.vy, a.angularVelocity]).toEqual([b.vx, b.vy, b.angularVelocity]);
  });

  it('an impulse changes velocity by I/m at once', () => {
    const world = new World();
    const h = world.createCircle({ x: 0, y: 0, vx: 1, radius: 1, mass: 4 });
    world.applyImpulse(h, 8, -2);
    expect(world.getCircle(h)).toMatchObject({ vx: 3, vy: -0.5 });
  });

  it('gravity scale multiplies gravity per body; 0 floats, -1 rises', () => {
    const world = new World({ gravity: { x: 0, y: 10 } });
    const normal = world.createCircle({ x: 0, y: 0, radius: 1 });
    const floating = world.createCircle({ x: 10, y: 0, radius: 1, gravityScale: 0 });
    const rising = world.createCircle({ x: 20, y: 0, radius: 1 });
    world.setGravityScale(rising, -1);
    world.step(1);
    expect(world.getCircle(normal).vy).toBe(10);
    expect(world.getCircle(floating).vy).toBe(0);
    expect(world.getCircle(rising).vy).toBe(-10);
  });

  it('linear damping decays velocity as v / (1 + dt c)', () => {
    const world = new World();
    const h = world.createCircle({ x: 0, y: 0, vx: 12, radius: 1, linearDamping: 2 });
    world.step(0.5);
    expect(world.getCircle(h).vx).toBe(6);
    world.setLinearDamping(h, 0);
    world.step(0.5);
    expect(world.getCircle(h).vx).toBe(6);
  });

  it('the general integrator gives the same bits as the plain one when nothing is customised', () => {
    const build = () => {
      const world = new World({ gravity: { x: 0, y: 9 }, bounds: { width: 200, height: 200 } });
      for (let k = 0; k < 50; k++) world.createCircle({ x: 10 + (k % 10) * 18, y: 10 + Math.floor(k / 10) * 18, vx: k - 25, vy: 25 - k, radius: 5 });
      return world;
    };
    const plain = build();
    const general = build();
    // A zero force on one body forces the general loop for that step without changing physics.
    for (let s = 0; s < 100; s++) {
      general.applyForce(0, 0, 0);
      plain.step(1 / 60);
      general.step(1 / 60);
    }
    expect(general.stateHash()).toBe(plain.stateHash());
  });
});

describe('collision layers (report 3.1.4.2)', () => {
  it('a pair collides only if each category is in the other mask, and filtered pairs are counted', () => {
    const world = new World();
    const a = world.createCircle({ x: 0, y: 0, vx: 10, radius: 5, category: 0b01, mask: 0b10 });
    const ghost = world.createCircle({ x: 8, y: 0, radius: 5, category: 0b01, mask: 0b11 });
    world.step(0);
    expect(world.stats.contacts).toBe(0);
    expect(world.stats.filteredPairs).toBe(1);
    expect(world.getCircle(a).vx).toBe(10);
    world.setCollisionFilter(ghost, 0b10, 0b01);
    world.step(0);
    expect(world.stats.contacts).toBe(1);
    expect(world.stats.filteredPairs).toBe(0);
  });

  it('filtering does not depend on the broad-phase', async () => {
    const { BROADPHASE_NAMES } = await import('../src/index.js');
    const hashes = BROADPHASE_NAMES.map((broadphase) => {
      const world = new World({ broadphase, bounds: { width: 300, height: 300 } });
      for (let k = 0; k < 200; k++) {
        world.createCircle({ x: 10 + (k % 20) * 14, y: 10 + Math.floor(k / 20) * 28, vx: (k * 37) % 50 - 25, vy: (k * 53) % 50 - 25, radius: 6, category: 1 << (k % 3), mask: k % 2 ? 0b011 : 0b110 });
      }
      for (let s = 0; s < 120; s++) world.step(1 / 60);
      return world.stateHash();
    });
    expect(new Set(hashes).size).toBe(1);
  });
});

describe('setTargetTransform', () => {
  it('moves a kinematic body onto each target pose in a step, and what rests on it rides along', () => {
    // A dynamic body in free flight takes the velocities as well: its centre of mass lies off its origin, which a kinematic body's does not.
    for (const [solver, turning, type] of [['elastic', true, 'kinematic'], ['elastic', true, 'dynamic'], ['soft', true, 'kinematic'], ['soft', false, 'kinematic']] as const) {
      const world = new World({ gravity: { x: 0, y: solver === 'soft' ? 10 : 0 }, friction: 0.8, restitution: 0, solver });
      // A platform of two boxes, turned at the start.
      const platform = world.createBody({ x: 0, y: 0, angle: 0.3, type });
      world.addShape(platform, { kind: 'box', width: 4, height: 0.5, offsetX: 1 });
      world.addShape(platform, { kind: 'box', width: 0.5, height: 0.5, offsetX: -1.5, offsetY: -0.5 });
      const riding = solver === 'soft' && !turning;
      const rider = riding ? world.createBox({ x: 1, y: -0.5, width: 0.5, height: 0.5 }) : -1;
      if (solver === 'soft') world.setTransform(platform, 0, 0, 0);
      const dt = 1 / 60;
      for (let s = 1; s <= 120; s++) {
        const t = s * dt;
        // Sideways and up from rest (within what friction holds), and turning; the elastic pass's turn crosses +-pi.
        const x = 1.5 * (1 - Math.cos(t));
        const y = -0.25 * t * t;
        const angle = !turning ? 0 : solver === 'soft' ? 0.2 * (1 - Math.cos(2 * t)) : 1.5 * t;
        world.setTargetTransform(platform, x, y, angle, dt);
        world.step(dt);
        const body = world.getBody(platform);
        const label = `${solver}, ${type}${turning ? ', turning' : ''}, step ${s}`;
        expect(body.x, label).toBeCloseTo(x, 9);
        expect(body.y, label).toBeCloseTo(y, 9);
        const turn = Math.atan2(Math.sin(body.angle - angle), Math.cos(body.angle - angle));
        expect(Math.abs(turn), label).toBeLessThan(solver === 'soft' ? 1e-4 : 1e-12);
      }
      if (riding) {
        // The rider kept its place on the platform: in the platform's frame it moved less than a centimetre.
        const p = world.getBody(platform);
        const r = world.getBody(rider);
        const dx = r.x - p.x;
        const dy = r.y - p.y;
        const localX = Math.cos(p.angle) * dx + Math.sin(p.angle) * dy;
        expect(Math.abs(localX - 1)).toBeLessThan(0.01);
      }
    }
  });

  it('refuses a static body, a bad dt or pose, and a velocity past the largest allowed, by name, leaving the body as it was', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const wall = world.createBox({ x: 0, y: 0, width: 1, height: 1, type: 'static' });
    const lift = world.createBox({ x: 5, y: 0, width: 1, height: 1, type: 'kinematic' });
    expect(() => world.setTargetTransform(wall, 1, 0, 0, 1 / 60)).toThrow(/static/);
    expect(() => world.setTargetTransform(lift, 1, 0, 0, 0)).toThrow(RangeError);
    expect(() => world.setTargetTransform(lift, 1, 0, 0, NaN)).toThrow(/dt.*NaN/);
    expect(() => world.setTargetTransform(lift, 1, 0, NaN, 1 / 60)).toThrow(/angle.*NaN/);
    expect(() => world.setTargetTransform(lift, 1e100, 0, 0, 1e-10)).toThrow(/beyond/);
    expect(world.getBody(lift)).toMatchObject({ x: 5, y: 0, vx: 0, vy: 0, angularVelocity: 0 });
  });
});
