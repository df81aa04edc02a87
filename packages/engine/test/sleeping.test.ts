import { describe, expect, it } from 'vitest';
import { World } from '../src/index.js';

function restingPile(sleeping: boolean): World {
  const world = new World({ sleeping, gravity: { x: 0, y: 200 }, bounds: { width: 200, height: 100 }, restitution: 0, sleepTime: 0.25 });
  for (let k = 0; k < 10; k++) world.createCircle({ x: 10 + k * 20, y: 90, radius: 9.5 });
  return world;
}

describe('sleeping (report 3.1.4.1, 5.3.3)', () => {
  it('bodies that stay still fall asleep, stop moving, and cost no integration', () => {
    const world = restingPile(true);
    for (let s = 0; s < 120; s++) world.step(1 / 60);
    expect(world.stats.sleepingBodies).toBe(10);
    expect(world.handles().every((h) => !world.isAwake(h))).toBe(true);
    const hash = world.stateHash();
    for (let s = 0; s < 60; s++) world.step(1 / 60);
    expect(world.stateHash()).toBe(hash);
    expect(world.stats.contacts).toBe(0);
  });

  it.each([
    ['setVelocity', (w: World, h: number) => w.setVelocity(h, 1, 0)],
    ['setPosition', (w: World, h: number) => w.setPosition(h, 30, 80)],
    ['applyForce', (w: World, h: number) => w.applyForce(h, 1, 0)],
    ['applyImpulse', (w: World, h: number) => w.applyImpulse(h, 1, 0)],
    ['setGravityScale', (w: World, h: number) => w.setGravityScale(h, 2)],
    ['setLinearDamping', (w: World, h: number) => w.setLinearDamping(h, 2)],
    ['setCollisionFilter', (w: World, h: number) => w.setCollisionFilter(h, 2, 0xffffffff)],
  ])('%s wakes a sleeping body, as every call that changes a body does', (_, change) => {
    const world = restingPile(true);
    for (let s = 0; s < 120; s++) world.step(1 / 60);
    const h = world.handles()[0];
    expect(world.isAwake(h)).toBe(false);
    change(world, h);
    expect(world.isAwake(h)).toBe(true);
  });

  it('is off by default, and a world without it never sleeps', () => {
    const world = restingPile(false);
    for (let s = 0; s < 120; s++) world.step(1 / 60);
    expect(world.stats.sleepingBodies).toBe(0);
  });

  it('a moving body that touches a sleeper wakes it (the Matter.js never-wakes bug, #1112 / #875)', () => {
    const world = restingPile(true);
    for (let s = 0; s < 120; s++) world.step(1 / 60);
    const sleeper = world.handles()[4];
    expect(world.isAwake(sleeper)).toBe(false);
    const ball = world.createCircle({ x: 90, y: 20, vy: 300, radius: 5 });
    let woke = false;
    for (let s = 0; s < 60 && !woke; s++) {
      world.step(1 / 60);
      woke = world.handles().slice(0, 10).some((h) => world.isAwake(h));
    }
    expect(woke).toBe(true);
    // The ball falls straight onto this sleeper (same x): it is the one that must have woken.
    expect(world.isAwake(sleeper)).toBe(true);
    expect(world.isAwake(ball)).toBe(true);
  });

  it('a pile falls asleep as a whole and stays asleep; a slow body landing on it does not wake it', async () => {
    const { buildScene, buildWorld } = await import('@maxgrid/scenes');
    // The sandbox's settings under g = 300 at 60 Hz: sleepSpeed 8 g dt, restitutionThreshold 2 g dt,
    // and the pile solver, with which a settled pile's bodies move at about 1 px/s.
    const world = buildWorld(buildScene('seed-box', { n: 1000, elasticity: 0 }), {
      sleeping: true,
      sleepSpeed: 40,
      restitutionThreshold: 10,
      solverIterations: 4,
      positionCorrection: 0.2,
      contactSlop: 0.05,
    });
    for (let s = 0; s < 600; s++) world.step(1 / 60);
    // Before bodies slept together and only faster bodies woke sleepers, each body slept alone and
    // its neighbours woke it the step after: at most 86 of 2,000 were asleep at once on this scene.
    // Now all of them sleep, in the step the last one comes to rest.
    expect(world.stats.sleepingBodies).toBe(1000);
    const hash = world.stateHash();
    for (let s = 0; s < 60; s++) world.step(1 / 60);
    expect(world.stateHash()).toBe(hash);
    // A ball set down 1 px above the highest sleeper lands at about 25 px/s: slower than
    // sleepSpeed, so the sleepers hold it as static bodies would, and it falls asleep on them.
    const v = world.views();
    let top = 0;
    for (let k = 1; k < v.slotCount; k++) if (v.y[k] - v.radius[k] < v.y[top] - v.radius[top]) top = k;
    const ball = world.createCircle({ x: v.x[top], y: v.y[top] - v.radius[top] - 4 - 1, radius: 4 });
    for (let s = 0; s < 60; s++) {
      world.step(1 / 60);
      expect(world.stats.sleepingBodies).toBeGreaterThanOrEqual(1000);
    }
    expect(world.isAwake(ball)).toBe(false);
  });

  it('a still body falls asleep only together with the awake bodies it touches', () => {
    // B rests on A, A on the floor. Both sleep; then A is woken, and B 10 steps later. A is still
    // for sleepTime (30 steps) first, but it waits for B, and the two fall asleep in one step.
    const world = new World({ sleeping: true, sleepSpeed: 20, gravity: { x: 0, y: 200 }, bounds: { width: 100, height: 100 }, restitution: 0 });
    const a = world.createCircle({ x: 50, y: 90, radius: 10 });
    const b = world.createCircle({ x: 50, y: 70, radius: 10 });
    for (let s = 0; s < 120; s++) world.step(1 / 60);
    expect([world.isAwake(a), world.isAwake(b)]).toEqual([false, false]);
    const fellAsleep: Record<string, number> = {};
    for (let s = 0; s < 120; s++) {
      if (s === 0) world.setAwake(a, true);
      if (s === 10) world.setAwake(b, true);
      world.step(1 / 60);
      for (const [name, h] of [['a', a], ['b', b]] as const) if (!world.isAwake(h) && fellAsleep[name] === undefined && s >= 10) fellAsleep[name] = s;
    }
    expect(fellAsleep.b).toBeGreaterThan(30);
    expect(fellAsleep.a).toBe(fellAsleep.b);
  });

  it('user changes wake a body: velocity, position, type, force, impulse', () => {
    const actions: ((w: World, h: number) => void)[] = [
      (w, h) => w.setVelocity(h, 1, 0),
      (w, h) => w.setPosition(h, 50, 50),
      (w, h) => w.setType(h, 'dynamic'),
      (w, h) => w.applyForce(h, 1, 0),
      (w, h) => w.applyImpulse(h, 1, 0),
      (w, h) => w.setAwake(h, true),
    ];
    for (const action of actions) {
      const world = restingPile(true);
      for (let s = 0; s < 120; s++) world.step(1 / 60);
      const h = world.handles()[3];
      expect(world.isAwake(h)).toBe(false);
      action(world, h);
      expect(world.isAwake(h)).toBe(true);
    }
  });

  it('taking a sleeper\'s support away wakes it: destroy, move, re-filter or re-type what it rests on', () => {
    const dt = 1 / 60;
    const stack = () => {
      const world = new World({
        bounds: { width: 100, height: 100 }, gravity: { x: 0, y: 300 }, restitution: 0, restitutionThreshold: 10,
        sleeping: true, sleepSpeed: 40, solverIterations: 4, positionCorrection: 0.2, contactSlop: 0.05,
      });
      const bottom = world.createCircle({ x: 50, y: 95, radius: 5 });
      const top = world.createCircle({ x: 50, y: 85, radius: 5 });
      const far = world.createCircle({ x: 10, y: 95, radius: 5 });
      for (let s = 0; s < 200; s++) world.step(dt);
      for (const h of [bottom, top, far]) expect(world.isAwake(h)).toBe(false);
      return { world, bottom, top, far };
    };
    // [action, whether the top body then falls]: a kinematic body still holds it up.
    const actions: [(w: World, bottom: number) => void, boolean][] = [
      [(w, bottom) => w.destroyBody(bottom), true],
      [(w, bottom) => w.setPosition(bottom, 80, 95), true],
      [(w, bottom) => w.setCollisionFilter(bottom, 1, 0), true],
      [(w, bottom) => w.setType(bottom, 'kinematic'), false],
    ];
    for (const [action, falls] of actions) {
      const { world, bottom, top, far } = stack();
      const topBefore = world.getCircle(top).y;
      action(world, bottom);
      world.step(dt);
      // The top body wakes and falls; a sleeper touching nothing that changed sleeps on.
      expect(world.isAwake(top)).toBe(true);
      expect(world.isAwake(far)).toBe(false);
      for (let s = 0; s < 60; s++) world.step(dt);
      if (falls) expect(world.getCircle(top).y).toBeGreaterThan(topBefore + 1);
      else expect(Math.abs(world.getCircle(top).y - topBefore)).toBeLessThan(0.5);
    }
    // A static body moved onto a sleeper: the sleeper wakes and is pushed out, not left overlapped.
    const { world, far } = stack();
    const post = world.createCircle({ x: 30, y: 50, radius: 5, type: 'static' });
    world.step(dt);
    world.setPosition(post, 16, 95);
    for (let s = 0; s < 30; s++) world.step(dt);
    const a = world.getCircle(far);
    expect(Math.hypot(a.x - 16, a.y - 95)).toBeGreaterThanOrEqual(10 - 0.05 - 1e-9);
  });

  it('a static circle created overlapping a sleeper wakes it, and it is pushed out; a sleeper it does not touch sleeps on', () => {
    const world = new World({ bounds: { width: 100, height: 100 }, gravity: { x: 0, y: 300 }, restitution: 0, restitutionThreshold: 10, sleeping: true, sleepSpeed: 40 });
    const near = world.createCircle({ x: 20, y: 95, radius: 5 });
    const far = world.createCircle({ x: 80, y: 95, radius: 5 });
    for (let s = 0; s < 200; s++) world.step(1 / 60);
    expect(world.isAwake(near) || world.isAwake(far)).toBe(false);
    world.createCircle({ x: 26, y: 95, radius: 3, type: 'static' });
    world.step(1 / 60);
    expect(world.isAwake(near)).toBe(true);
    expect(world.isAwake(far)).toBe(false);
    for (let s = 0; s < 30; s++) world.step(1 / 60);
    const a = world.getCircle(near);
    expect(Math.hypot(a.x - 26, a.y - 95)).toBeGreaterThanOrEqual(8 - 0.05);
  });

  it('a segment created through a sleeper, or destroyed under one, wakes it; a sleeper elsewhere along the segment sleeps on', () => {
    for (const friction of [0, 0.5]) {
      const setup = () => {
        const world = new World({ gravity: { x: 0, y: 10 }, restitution: 0, sleeping: true, friction });
        const floor = world.createSegment({ x1: -50, y1: 0, x2: 50, y2: 0 });
        const left = world.createCircle({ x: -40, y: -0.5, radius: 0.5 });
        const right = world.createCircle({ x: 40, y: -0.5, radius: 0.5 });
        for (let s = 0; s < 400; s++) world.step(1 / 60);
        expect(world.isAwake(left) || world.isAwake(right), `friction ${friction}`).toBe(false);
        return { world, floor, left, right };
      };
      const created = setup();
      created.world.createSegment({ x1: -39.7, y1: -2, x2: -39.7, y2: 0 });
      created.world.step(1 / 60);
      expect(created.world.isAwake(created.left), `friction ${friction}: crossed`).toBe(true);
      expect(created.world.isAwake(created.right), `friction ${friction}: far along the floor`).toBe(false);
      const destroyed = setup();
      const y = destroyed.world.getBody(destroyed.left).y;
      destroyed.world.destroySegment(destroyed.floor);
      for (let s = 0; s < 30; s++) destroyed.world.step(1 / 60);
      expect(destroyed.world.getBody(destroyed.left).y, `friction ${friction}: falls once its floor is gone`).toBeGreaterThan(y + 1);
      expect(destroyed.world.getBody(destroyed.right).y, `friction ${friction}: falls once its floor is gone`).toBeGreaterThan(y + 1);
    }
  });

  it('sleepTime 0: a still body sleeps after one slow step, a moving one never', () => {
    const world = new World({ sleeping: true, sleepTime: 0 });
    const fast = world.createCircle({ x: 0, y: 0, radius: 1, vx: 300 });
    const slow = world.createCircle({ x: 100, y: 0, radius: 1, vx: 0.5 });
    for (let s = 0; s < 10; s++) {
      world.step(1 / 60);
      expect(world.isAwake(fast)).toBe(true);
      expect(world.getCircle(fast).vx).toBe(300);
      expect(world.isAwake(slow)).toBe(false);
    }
  });

  it('sleeping and waking give the same result with every broad-phase', async () => {
    const { BROADPHASE_NAMES } = await import('../src/index.js');
    const runs = BROADPHASE_NAMES.map((broadphase) => {
      const world = new World({ broadphase, sleeping: true, gravity: { x: 0, y: 300 }, bounds: { width: 320, height: 200 }, restitution: 0, sleepTime: 0.2, sleepSpeed: 8 });
      // Balls fall straight onto row circles: a vertical normal, so nothing slides sideways.
      for (let k = 0; k < 30; k++) world.createCircle({ x: 6 + k * 10.5, y: 196, radius: 4 });
      for (let k = 0; k < 15; k++) world.createCircle({ x: 6 + 2 * k * 10.5, y: 20 + ((k * 37) % 60), radius: 3 });
      let wakeUps = 0;
      let asleep = world.stats.sleepingBodies;
      for (let s = 0; s < 400; s++) {
        world.step(1 / 60);
        if (world.stats.sleepingBodies < asleep) wakeUps++;
        asleep = world.stats.sleepingBodies;
      }
      return { hash: world.stateHash(), asleep, wakeUps };
    });
    expect(new Set(runs.map((r) => r.hash)).size).toBe(1);
    expect(runs[0].asleep).toBeGreaterThan(20);
    expect(runs[0].wakeUps).toBeGreaterThan(0);
  });
});
