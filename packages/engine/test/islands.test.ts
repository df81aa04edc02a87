import { describe, expect, it } from 'vitest';
import { World } from '../src/index.js';
import { buildShapeScene, buildShapeWorld } from '@maxgrid/scenes';

const DT = 1 / 60;

function sleeping(world: World): number {
  return world.stats.sleepingBodies;
}

describe('island sleeping with shapes', () => {
  it('a settled pyramid falls asleep as a whole, in one step', () => {
    const world = buildShapeWorld(buildShapeScene('pyramid', { base: 20 }), { sleeping: true });
    const boxes = world.bodyCount - 1;
    let first = -1;
    for (let s = 0; s < 600 && first < 0; s++) {
      world.step(DT);
      if (sleeping(world) > 0) first = s;
    }
    expect(first).toBeGreaterThan(0);
    expect(sleeping(world)).toBe(boxes);
  });

  it('wakes as a whole when something hits it, and falls asleep again', () => {
    const world = buildShapeWorld(buildShapeScene('pyramid', { base: 20 }), { sleeping: true });
    const boxes = world.bodyCount - 1;
    for (let s = 0; s < 300; s++) world.step(DT);
    expect(sleeping(world)).toBe(boxes);
    // A ball dropped on the top box (at y = -19.5, x = 0).
    world.createCircle({ x: 0, y: -30, radius: 0.5, vy: 20, density: 5, friction: 0.6 });
    const counts: number[] = [];
    for (let s = 0; s < 60; s++) {
      world.step(DT);
      counts.push(sleeping(world));
    }
    // From all asleep to none in one step: never part of the pyramid.
    const woke = counts.indexOf(0);
    expect(woke).toBeGreaterThan(0);
    expect(counts.slice(0, woke).every((c) => c === boxes)).toBe(true);
    for (let s = 0; s < 900; s++) world.step(DT);
    // The boxes sleep again (the ball may still be rolling away on the long ground).
    expect(world.handles().slice(1, boxes + 1).every((h) => !world.isAwake(h))).toBe(true);
  });

  it('a sleeping island wakes whole when one of its bodies is disturbed through the API', () => {
    const world = buildShapeWorld(buildShapeScene('vertical-stack', { count: 5 }), { sleeping: true });
    for (let s = 0; s < 300; s++) world.step(DT);
    expect(sleeping(world)).toBe(5);
    world.applyImpulse(world.handles()[3], 0.1, 0);
    expect(sleeping(world)).toBe(5);
    expect(world.handles().slice(1).every((h) => world.isAwake(h))).toBe(true);
  });

  it('two piles apart are two islands: hitting one leaves the other asleep', () => {
    const world = new World({ gravity: { x: 0, y: 10 }, friction: 0.6, restitution: 0, sleeping: true });
    world.createBox({ x: 0, y: 1, width: 100, height: 2, type: 'static' });
    const left = [0, 1, 2].map((k) => world.createBox({ x: -10, y: -0.5 - k, width: 1, height: 1 }));
    const right = [0, 1, 2].map((k) => world.createBox({ x: 10, y: -0.5 - k, width: 1, height: 1 }));
    for (let s = 0; s < 300; s++) world.step(DT);
    expect(sleeping(world)).toBe(6);
    world.setVelocity(left[2], 1, 0);
    expect(left.every((h) => world.isAwake(h))).toBe(true);
    expect(right.every((h) => !world.isAwake(h))).toBe(true);
  });

  it('a static shape added into a sleeping pile wakes that pile, whether a new body or a shape on the ground', () => {
    for (const how of ['addShape', 'addCircle', 'createBox', 'createCapsule'] as const) {
      const world = new World({ gravity: { x: 0, y: 10 }, friction: 0.6, restitution: 0, sleeping: true });
      const ground = world.createBox({ x: 0, y: 1, width: 100, height: 2, type: 'static' });
      const left = [0, 1, 2].map((k) => world.createBox({ x: -10, y: -0.5 - k, width: 1, height: 1 }));
      const right = [0, 1, 2].map((k) => world.createBox({ x: 10, y: -0.5 - k, width: 1, height: 1 }));
      for (let s = 0; s < 300; s++) world.step(DT);
      expect(sleeping(world), how).toBe(6);
      // A post pushed into the left pile's middle box, from the side (0.2 of overlap).
      if (how === 'addShape') world.addShape(ground, { kind: 'box', width: 0.4, height: 1, offsetX: -10.5, offsetY: -2.5 });
      else if (how === 'addCircle') world.addShape(ground, { kind: 'circle', radius: 0.2, offsetX: -10.6, offsetY: -2.5 });
      else if (how === 'createBox') world.createBox({ x: -10.5, y: -1.5, width: 0.4, height: 1, type: 'static' });
      else world.createCapsule({ x: -10.5, y: -1.5, length: 0.6, radius: 0.1, angle: Math.PI / 2, type: 'static' });
      const before = world.getBody(left[1]).x;
      world.step(DT);
      expect(left.every((h) => world.isAwake(h)), how).toBe(true);
      expect(right.every((h) => !world.isAwake(h)), how).toBe(true);
      for (let s = 0; s < 30; s++) world.step(DT);
      // and the post pushes the box it overlaps away, to the right
      expect(world.getBody(left[1]).x, how).toBeGreaterThan(before + 0.01);
    }
  });

  it('a sleeper takes its share of the hit that wakes it, in that step, as an awake body would', () => {
    // The hit arrives within one step from beyond the speculative margin: the sleeper wakes
    // before the solve, not after it, or it meets the hit as a wall would.
    for (const v of [1, 2, 6, 20])
      for (const gap of [0.3, 0.337, 0.71]) {
        const run = (sleeping: boolean): number[] => {
          const world = new World({ gravity: { x: 0, y: 0 }, friction: 0, restitution: 0, sleeping });
          const b = world.createBox({ x: 0, y: 0, width: 1, height: 1 });
          const a = world.createBox({ x: -1 - gap, y: 0, width: 1, height: 1 });
          for (let s = 0; s < 60; s++) world.step(DT);
          expect(world.isAwake(b)).toBe(!sleeping);
          world.setVelocity(a, v, 0);
          const out: number[] = [];
          for (let s = 0; s < 30; s++) {
            world.step(DT);
            out.push(world.getBody(a).vx, world.getBody(b).vx);
          }
          return out;
        };
        const asleep = run(true);
        const awake = run(false);
        for (let k = 0; k < asleep.length; k += 2) {
          expect(asleep[k] + asleep[k + 1], `${v} ${gap} ${k}`).toBeCloseTo(v, 9);
          expect(asleep[k + 1], `${v} ${gap} ${k}`).toBeCloseTo(awake[k + 1], 9);
        }
      }
    // A kinematic pusher does not sink into a sleeper; a platform set moving carries a box asleep on it from the first step.
    const world = new World({ gravity: { x: 0, y: 10 }, friction: 0.6, sleeping: true });
    world.createBox({ x: 0, y: 1, width: 100, height: 2, type: 'static' });
    const box = world.createBox({ x: 0, y: -0.5, width: 1, height: 1 });
    const pusher = world.createBox({ x: -2, y: -0.5, width: 1, height: 1, type: 'kinematic' });
    const platform = world.createBox({ x: 20, y: -0.25, width: 6, height: 0.5, type: 'kinematic' });
    const rider = world.createBox({ x: 20, y: -1, width: 1, height: 1 });
    for (let s = 0; s < 120; s++) world.step(DT);
    expect(world.isAwake(box)).toBe(false);
    expect(world.isAwake(rider)).toBe(false);
    world.setVelocity(pusher, 6, 0);
    world.setVelocity(platform, 2, 0);
    world.step(DT);
    expect(world.getBody(rider).vx).toBeGreaterThan(0.09);
    for (let s = 0; s < 30; s++) {
      world.step(DT);
      expect(world.getBody(box).x - world.getBody(pusher).x, `${s}`).toBeGreaterThan(1 - 0.005);
    }
  });

  it('a sleeper hit right after it fell asleep, its contacts the same as the first pass found, is solved as an awake one', () => {
    // The second pass's list equals the first pass's, which no solve saw: taken as unchanged, it
    // kept the colouring of the step before (no lanes), and the hit went through, then NaN.
    const run = (sleep: boolean): number[] => {
      const world = new World({ friction: 0.6 });
      const a = world.createBox({ x: 0, y: 0, width: 1, height: 1, vx: 10 });
      const b = world.createBox({ x: 1.1, y: 0, width: 1, height: 1 });
      world.step(DT);
      if (sleep) world.setAwake(b, false);
      const out: number[] = [];
      for (let s = 0; s < 6; s++) {
        if (s === 4) world.createBox({ x: world.getBody(b).x + 1, y: 0, width: 1, height: 1 });
        world.step(DT);
        for (const h of [a, b]) out.push(world.getBody(h).x, world.getBody(h).vx, world.getBody(h).angle);
      }
      return out;
    };
    expect(run(true)).toEqual(run(false));
  });

  it('a body resting on a moving kinematic platform stays awake', () => {
    const world = new World({ gravity: { x: 0, y: 10 }, friction: 0.8, restitution: 0, sleeping: true });
    world.createBox({ x: 0, y: 0, width: 10, height: 1, type: 'kinematic', vx: 0.5 });
    const box = world.createBox({ x: 0, y: -1, width: 1, height: 1 });
    for (let s = 0; s < 300; s++) world.step(DT);
    expect(world.isAwake(box)).toBe(true);
  });

  it('a body resting on a kinematic platform at rest falls asleep once and stays asleep, as on a static one', () => {
    for (const type of ['kinematic', 'static'] as const) {
      const world = new World({ gravity: { x: 0, y: 10 }, friction: 0.6, restitution: 0, sleeping: true });
      world.createBox({ x: 0, y: 0, width: 6, height: 0.5, type });
      const box = world.createBox({ x: 0, y: -0.75, width: 1, height: 1 });
      let naps = 0;
      let awake = true;
      for (let s = 0; s < 600; s++) {
        world.step(DT);
        if (awake && !world.isAwake(box)) naps++;
        awake = world.isAwake(box);
      }
      expect({ type, naps, awake }).toEqual({ type, naps: 1, awake: false });
    }
  });
});
