import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { World, BROADPHASE_NAMES } from '../src/index.js';

function distanceToSegment(px: number, py: number, s: { x1: number; y1: number; x2: number; y2: number }): number {
  const ex = s.x2 - s.x1;
  const ey = s.y2 - s.y1;
  const t = Math.max(0, Math.min(1, ((px - s.x1) * ex + (py - s.y1) * ey) / (ex * ex + ey * ey)));
  return Math.hypot(px - (s.x1 + t * ex), py - (s.y1 + t * ey));
}

describe('static segments', () => {
  it('a ball dropped on a ramp bounces off it along its normal and never ends a step inside it', () => {
    const world = new World({ gravity: { x: 0, y: 500 }, bounds: { width: 400, height: 400 }, restitution: 1 });
    const ramp = { x1: 50, y1: 200, x2: 350, y2: 300, thickness: 3 };
    world.createSegment(ramp);
    const ball = world.createCircle({ x: 200, y: 100, radius: 10 });
    let touched = 0;
    for (let s = 0; s < 240; s++) {
      world.step(1 / 60);
      touched += world.stats.segmentContacts;
      const c = world.getCircle(ball);
      expect(distanceToSegment(c.x, c.y, ramp)).toBeGreaterThanOrEqual(10 + 3 - 1e-9);
    }
    expect(touched).toBeGreaterThan(0);
    // The ramp slopes down to the right: bouncing off it sends the ball right.
    expect(world.getCircle(ball).x).toBeGreaterThan(210);
  });

  it('a funnel of two segments lets small balls through and stops big ones', () => {
    const world = new World({ gravity: { x: 0, y: 400 }, bounds: { width: 200, height: 300 }, restitution: 0.2 });
    world.createSegment({ x1: 10, y1: 50, x2: 90, y2: 150 });
    world.createSegment({ x1: 190, y1: 50, x2: 110, y2: 150 });
    const small = world.createCircle({ x: 60, y: 20, radius: 5 });
    const big = world.createCircle({ x: 140, y: 20, radius: 15 });
    for (let s = 0; s < 300; s++) world.step(1 / 60);
    expect(world.getCircle(small).y).toBeGreaterThan(200);
    expect(world.getCircle(big).y).toBeLessThan(150);
  });

  it('layers filter segments too', () => {
    const world = new World({ gravity: { x: 0, y: 400 }, bounds: { width: 100, height: 300 } });
    world.createSegment({ x1: 0, y1: 100, x2: 100, y2: 100, category: 2, mask: 0xffffffff });
    const ghost = world.createCircle({ x: 50, y: 50, radius: 5, mask: 1 });
    for (let s = 0; s < 60; s++) world.step(1 / 60);
    expect(world.getCircle(ghost).y).toBeGreaterThan(150);
  });

  it('a circle rests on a long floor as docs/engine.md says: exact to 1e-5 radii up to 1e12 radii from both ends, lost at 1e16', () => {
    // Worst distance from the line, minus the radius, over seconds 2-5, for the segment (-L, -sL)-(L, sL).
    const restingError = (L: number, slope: number): number => {
      const world = new World({ gravity: { x: 0, y: -10 } });
      world.createSegment({ x1: -L, y1: -L * slope, x2: L, y2: L * slope, restitution: 0 });
      const ball = world.createCircle({ x: 3, y: 3 * slope + 3, radius: 1, restitution: 0 });
      let worst = 0;
      for (let s = 0; s < 300; s++) {
        world.step(1 / 60);
        const c = world.getCircle(ball);
        if (s > 120) worst = Math.max(worst, Math.abs((c.y - slope * c.x) / Math.hypot(1, slope) - 1));
      }
      return worst;
    };
    for (const slope of [0, 0.1, 1]) {
      expect(restingError(1e3, slope)).toBeLessThan(1e-12);
      expect(restingError(1e12, slope)).toBeLessThan(1e-4);
      // Past the documented range the rounding of the distance to an endpoint exceeds the radius.
      expect(restingError(1e16, slope)).toBeGreaterThan(10);
    }
  });

  it('a capsule dropped tilted onto a long thin segment comes to rest lying on it, still', () => {
    // The floor's line is the one to clip against: with one point the capsule rocks on it.
    for (const angle of [0.4, 1.2, -0.9]) {
      const world = new World({ gravity: { x: 0, y: 10 }, friction: 0.3, restitution: 0 });
      world.createSegment({ x1: -200, y1: 0, x2: 200, y2: 0, thickness: 0.001 });
      const capsule = world.createCapsule({ x: 0.37, y: -1, angle, length: 0.6, radius: 0.1 });
      for (let s = 0; s < 180; s++) world.step(1 / 60);
      const rest = world.getBody(capsule);
      expect(rest.centerY, `angle ${angle}`).toBeCloseTo(-0.101, 2);
      expect(Math.abs(Math.sin(rest.angle)), `angle ${angle}`).toBeLessThan(1e-3);
      for (let s = 0; s < 60; s++) {
        world.step(1 / 60);
        const b = world.getBody(capsule);
        expect(Math.abs(b.angularVelocity), `angle ${angle}, step ${s}`).toBeLessThan(1e-3);
        expect(Math.abs(b.vy), `angle ${angle}, step ${s}`).toBeLessThan(1e-3);
      }
    }
  });

  it('a circle, a box and a capsule come to rest on a thick segment\'s face, its thickness from its core', () => {
    const world = new World({ gravity: { x: 0, y: 10 }, friction: 0.6, restitution: 0 });
    const thickness = 0.3;
    // A wide floor (its bounding box holds every body) and a thick diagonal rib far from them all.
    world.createSegment({ x1: -20, y1: 0, x2: 20, y2: 0, thickness });
    world.createSegment({ x1: -20, y1: -10, x2: 20, y2: 30, thickness });
    const circle = world.createCircle({ x: -4, y: -2, radius: 0.5 });
    const box = world.createBox({ x: 0, y: -2, width: 1, height: 0.6 });
    const capsule = world.createCapsule({ x: 4, y: -2, length: 1, radius: 0.2 });
    for (let s = 0; s < 180; s++) world.step(1 / 60);
    // At rest within the solver's slop of touching: each body's lowest point on the face at y = -thickness.
    expect(world.getBody(circle).y).toBeCloseTo(-thickness - 0.5, 2);
    expect(world.getBody(box).y).toBeCloseTo(-thickness - 0.3, 2);
    expect(world.getBody(capsule).y).toBeCloseTo(-thickness - 0.2, 2);
  });

  it('results do not depend on the broad-phase', () => {
    const hashes = BROADPHASE_NAMES.map((broadphase) => {
      const world = new World({ broadphase, gravity: { x: 0, y: 300 }, bounds: { width: 300, height: 300 } });
      world.createSegment({ x1: 0, y1: 150, x2: 200, y2: 250, thickness: 2 });
      world.createSegment({ x1: 300, y1: 120, x2: 120, y2: 200 });
      for (let k = 0; k < 120; k++) world.createCircle({ x: 8 + (k % 24) * 12, y: 8 + Math.floor(k / 24) * 12, vx: (k * 29) % 60 - 30, radius: 5 });
      for (let s = 0; s < 200; s++) world.step(1 / 60);
      return world.stateHash();
    });
    expect(new Set(hashes).size).toBe(1);
  });

  it('segment handles: create, read, destroy, stale', () => {
    const world = new World();
    const h = world.createSegment({ x1: 0, y1: 0, x2: 10, y2: 0, thickness: 1 });
    expect(world.getSegment(h)).toMatchObject({ x1: 0, y1: 0, x2: 10, y2: 0, thickness: 1 });
    expect(world.segmentCount).toBe(1);
    world.destroySegment(h);
    expect(world.segmentCount).toBe(0);
    expect(() => world.getSegment(h)).toThrow(/segment handle/);
    expect(() => world.createSegment({ x1: 1, y1: 1, x2: 1, y2: 1 })).toThrow(/thickness > 0/);
    expect(() => world.createSegment({ x1: NaN, y1: 0, x2: 1, y2: 0 })).toThrow(/x1 must be a finite number, got NaN/);
    expect(() => world.createSegment({ x1: 0, y1: 0, x2: 1, y2: 0, thickness: -1 })).toThrow(/thickness must be >= 0, got -1/);
  });

  it('body and segment handles never stand for each other: a mix-up is refused and changes nothing', () => {
    const world = new World({ bounds: { width: 100, height: 100 } });
    const body = world.createCircle({ x: 50, y: 50, radius: 2 });
    const segment = world.createSegment({ x1: 0, y1: 10, x2: 100, y2: 10, thickness: 1 });
    // Both are the first of their kind, in slot 0 at generation 0.
    expect(world.slotOfHandle(body)).toBe(0);
    const before = world.stateHash();
    expect(() => world.destroyBody(segment)).toThrow(new RangeError(`handle ${segment} is a segment handle, not a body handle`));
    expect(world.hasBody(segment)).toBe(false);
    expect(() => world.getCircle(segment)).toThrow(/is a segment handle, not a body handle/);
    expect(() => world.destroySegment(body)).toThrow(new RangeError(`segment handle ${body} is a body handle, not a segment handle`));
    expect(() => world.getSegment(body)).toThrow(/is a body handle, not a segment handle/);
    expect(world.bodyCount).toBe(1);
    expect(world.segmentCount).toBe(1);
    expect(world.stateHash()).toBe(before);
    world.destroySegment(segment);
    expect(() => world.getSegment(segment)).toThrow(new RangeError(`segment handle ${segment} is stale: its segment was destroyed`));
    expect(() => world.getSegment(segment + 5)).toThrow(/segment handle \d+ is unknown to this world/);
  });
});

describe('continuous collision against static shapes (report 3.1.6)', () => {
  function shoot(continuous: boolean, speed: number, target: 'segment' | 'circle') {
    const world = new World({ continuous, bounds: { width: 1000, height: 200 } });
    if (target === 'segment') world.createSegment({ x1: 500, y1: 0, x2: 500, y2: 200 });
    else world.createCircle({ x: 500, y: 100, radius: 2, type: 'static' });
    const ball = world.createCircle({ x: 100, y: 100, vx: speed, radius: 3 });
    let crossed = false;
    for (let s = 0; s < 30; s++) {
      world.step(1 / 60);
      if (world.getCircle(ball).x > 500) crossed = true;
    }
    return crossed;
  }

  it('negative control: without it a fast ball tunnels through a thin wall and a small static circle', () => {
    expect(shoot(false, 60_000, 'segment')).toBe(true);
    expect(shoot(false, 60_000, 'circle')).toBe(true);
  });

  it('with it, no speed gets through', () => {
    for (const speed of [600, 6_000, 60_000, 6e6, 6e12]) {
      expect(shoot(true, speed, 'segment')).toBe(false);
      expect(shoot(true, speed, 'circle')).toBe(false);
    }
  });

  it('random fast shots never cross a closed ring of segments', () => {
    fc.assert(
      fc.property(
        fc.double({ min: 0, max: 2 * Math.PI, noNaN: true }),
        fc.double({ min: 1e3, max: 1e7, noNaN: true }),
        fc.constantFrom(0, 0.5, 1),
        (angle, speed, restitution) => {
          const world = new World({ restitution, bounds: { width: 400, height: 400 } });
          const sides = 7;
          for (let k = 0; k < sides; k++) {
            const a = (2 * Math.PI * k) / sides;
            const b = (2 * Math.PI * (k + 1)) / sides;
            world.createSegment({ x1: 200 + 100 * Math.cos(a), y1: 200 + 100 * Math.sin(a), x2: 200 + 100 * Math.cos(b), y2: 200 + 100 * Math.sin(b), thickness: 1 });
          }
          const ball = world.createCircle({ x: 200, y: 200, vx: speed * Math.cos(angle), vy: speed * Math.sin(angle), radius: 4 });
          for (let s = 0; s < 10; s++) {
            world.step(1 / 60);
            const c = world.getCircle(ball);
            expect(Math.hypot(c.x - 200, c.y - 200)).toBeLessThan(100);
          }
        },
      ),
      { numRuns: 100, seed: 11 },
    );
  });

  // A lattice of static circles with segments across it: the sweep finds the statics it can meet
  // through a static tree, so a path that grazes one (its box misses the centre's box by less
  // than the radius) or crosses many in one step must still meet each of them. The balls do not
  // collide with each other: pushing two overlapping balls apart can press one into a static,
  // which is the discrete contacts' business, not the sweep's.
  function field(continuous: boolean, seed: number) {
    const world = new World({ continuous, restitution: 1 });
    const statics: { x: number; y: number; r: number }[] = [];
    for (let i = 0; i < 60; i++) {
      for (let j = 0; j < 60; j++) {
        const c = { x: 4 * i, y: 4 * j, r: 0.5 + 0.25 * ((i * 7 + j * 3) % 4) };
        statics.push(c);
        world.createCircle({ x: c.x, y: c.y, radius: c.r, type: 'static' });
      }
    }
    for (let k = 1; k < 6; k++) world.createSegment({ x1: 40 * k + 2, y1: 0, x2: 40 * k + 2, y2: 236, thickness: 0.05 });
    let state = seed;
    const random = () => ((state = (state * 1103515245 + 12345) % 2147483648) / 2147483648);
    const balls: number[] = [];
    for (let b = 0; b < 100; b++) {
      const a = 2 * Math.PI * random();
      const speed = 20 + 3000 * random() ** 2;
      balls.push(world.createCircle({ x: 4 * Math.floor(60 * random()) + 2, y: 4 * Math.floor(60 * random()) + 2, radius: 0.3, vx: speed * Math.cos(a), vy: speed * Math.sin(a), category: 2, mask: 1 }));
    }
    let inside = 0;
    let crossed = 0;
    for (let s = 0; s < 40; s++) {
      const before = balls.map((h) => world.getCircle(h).x);
      world.step(1 / 60);
      balls.forEach((h, n) => {
        const c = world.getCircle(h);
        for (const o of statics) if (Math.hypot(c.x - o.x, c.y - o.y) < o.r + 0.3 - 1e-9) inside++;
        for (let k = 1; k < 6; k++) if (Math.sign(before[n] - (40 * k + 2)) * Math.sign(c.x - (40 * k + 2)) < 0 && c.y > 0 && c.y < 236) crossed++;
      });
    }
    return { inside, crossed, swept: world.stats.sweptBodies };
  }

  it('fast balls in a field of 3,600 static circles and five segments never end a step inside one or across a segment', () => {
    expect(field(false, 1).inside + field(false, 1).crossed).toBeGreaterThan(0);
    for (const seed of [1, 2, 3]) {
      const { inside, crossed, swept } = field(true, seed);
      expect(swept).toBeGreaterThan(50);
      expect({ seed, inside }).toEqual({ seed, inside: 0 });
      expect({ seed, crossed }).toEqual({ seed, crossed: 0 });
    }
  });

  it('a fast ball whose line passes within reach of a static circle or a segment end is deflected, and one just beyond it is not', () => {
    fc.assert(
      fc.property(
        fc.oneof(fc.constantFrom(0, 0.5 * Math.PI, Math.PI, 1.5 * Math.PI), fc.double({ min: 0, max: 2 * Math.PI, noNaN: true })),
        fc.double({ min: 0.2, max: 3, noNaN: true }),
        fc.double({ min: 0.1, max: 2, noNaN: true }),
        fc.double({ min: 0, max: 0.998, noNaN: true }),
        fc.boolean(),
        fc.boolean(),
        (angle, size, r, offset, segment, beyond) => {
          const world = new World({ restitution: 1 });
          const c = Math.cos(angle);
          const s = Math.sin(angle);
          // A static circle of radius `size` at the origin, or a segment of that thickness ending
          // there and lying along the path's line, ahead of the ball.
          if (segment) world.createSegment({ x1: 0, y1: 0, x2: -20 * c, y2: -20 * s, thickness: size });
          else world.createCircle({ x: 0, y: 0, radius: size, type: 'static' });
          const d = (size + r) * (beyond ? 1.002 : offset);
          const ball = world.createCircle({ x: 30 * c - d * s, y: 30 * s + d * c, radius: r, vx: -3600 * c, vy: -3600 * s });
          world.step(1 / 60);
          const v = world.getCircle(ball);
          const turned = Math.abs(v.vx + 3600 * c) + Math.abs(v.vy + 3600 * s) > 1e-6;
          expect(turned).toBe(!beyond);
        },
      ),
      { numRuns: 300, seed: 8 },
    );
  });

  it('static shapes added, moved or removed between steps are swept against from the next step on', () => {
    const world = new World({ restitution: 0 });
    const ball = world.createCircle({ x: 0, y: 0, radius: 0.5, vx: 6000 });
    const far = world.createCircle({ x: -500, y: 0, radius: 1, type: 'static' });
    world.step(1 / 60);
    expect(world.getCircle(ball).x).toBe(100);
    // Moved into the path: the ball stops on it rather than passing.
    world.setPosition(far, 150, 0);
    world.step(1 / 60);
    expect(world.getCircle(ball).x).toBeCloseTo(148.5, 6);
    // Removed: it passes where the circle was.
    world.destroyBody(far);
    world.setVelocity(ball, 6000, 0);
    world.step(1 / 60);
    expect(world.getCircle(ball).x).toBeCloseTo(248.5, 6);
    // A new segment ahead stops it; a static turned dynamic no longer counts as static.
    world.createSegment({ x1: 300, y1: -5, x2: 300, y2: 5 });
    world.setVelocity(ball, 6000, 0);
    world.step(1 / 60);
    expect(world.getCircle(ball).x).toBeLessThan(300);
    expect(world.getCircle(ball).x).toBeGreaterThan(299);
    const post = world.createCircle({ x: 200, y: 0, radius: 1, type: 'static' });
    world.setPosition(ball, 120, 0);
    world.setType(post, 'dynamic');
    world.setPosition(post, 200, 30);
    world.setVelocity(ball, 6000, 0);
    world.step(1 / 60);
    expect(world.getCircle(ball).x).toBe(220);
  });
});
