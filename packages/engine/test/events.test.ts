import { describe, expect, it } from 'vitest';
import { BoxWall, World } from '../src/index.js';

function pairsOf(count: number, a: Readonly<Float64Array>, b: Readonly<Float64Array>): string[] {
  return Array.from({ length: count }, (_, k) => `${a[k]}-${b[k]}`);
}

describe('contact events', () => {
  it('begin when a pair starts touching, end when it stops or a body is destroyed', () => {
    const world = new World({ contactEvents: true, restitution: 0 });
    // 3 units per step: slower than its radius, so discrete contacts (not continuous sweeps) see it.
    const a = world.createCircle({ x: 0, y: 0, vx: 30, radius: 5 });
    const b = world.createCircle({ x: 12, y: 0, radius: 5, type: 'static' });
    const c = world.createCircle({ x: 0, y: 30, radius: 5 });
    const d = world.createCircle({ x: 8, y: 30, radius: 5 });
    world.step(0.1);
    const events = world.contactEvents();
    expect(pairsOf(events.beginCount, events.beginA, events.beginB).sort()).toEqual([`${a}-${b}`, `${c}-${d}`].sort());
    expect(events.endCount).toBe(0);
    world.destroyBody(d);
    world.step(0.1);
    expect(pairsOf(events.endCount, events.endA, events.endB)).toContain(`${c}-${d}`);
  });

  it('a pair that keeps touching produces one begin and no repeats', () => {
    const world = new World({ contactEvents: true, gravity: { x: 0, y: 100 }, bounds: { width: 100, height: 100 }, restitution: 0 });
    world.createCircle({ x: 50, y: 90, radius: 10, type: 'static' });
    world.createCircle({ x: 50, y: 60, radius: 10 });
    let begins = 0;
    let ends = 0;
    for (let s = 0; s < 300; s++) {
      world.step(1 / 60);
      begins += world.contactEvents().beginCount;
      ends += world.contactEvents().endCount;
    }
    expect(begins).toBeGreaterThan(0);
    expect(begins - ends).toBeGreaterThanOrEqual(0);
    expect(begins - ends).toBeLessThanOrEqual(1);
  });

  it('hit events carry the approach speed and respect the threshold', () => {
    const world = new World({ hitEventThreshold: 15 });
    const slow = world.createCircle({ x: 0, y: 0, vx: 5, radius: 5 });
    world.createCircle({ x: 9, y: 0, vx: -5, radius: 5 });
    const fast = world.createCircle({ x: 0, y: 50, vx: 10, radius: 5 });
    const target = world.createCircle({ x: 9, y: 50, vx: -10, radius: 5 });
    world.step(0);
    const events = world.contactEvents();
    expect(events.hitCount).toBe(1);
    expect([events.hitA[0], events.hitB[0]]).toEqual([fast, target]);
    expect(events.hitSpeed[0]).toBeCloseTo(20, 12);
    // The slow pair (approach speed 10) collided too, below the threshold: no hit for it.
    expect([events.hitA[0], events.hitB[0]]).not.toContain(slow);
    expect(world.getCircle(slow).vx).toBeLessThan(0);
  });

  it('a fast body that the continuous sweep bounces off a static circle reports its hit, as a slow one does', () => {
    // Each shot approaches a static circle head on; 4 units a step is slower than the radius
    // (a discrete contact), 400 is faster (a sweep, which leaves no overlap for the contacts).
    const shoot = (speed: number, dt: number) => {
      const world = new World({ hitEventThreshold: 5, restitution: 1 });
      const target = world.createCircle({ x: 100, y: 0, radius: 5, type: 'static' });
      const bullet = world.createCircle({ x: 100 - 10 - speed * dt * 0.5, y: 0, vx: speed, radius: 5 });
      world.step(dt);
      const events = world.contactEvents();
      return { events: pairsOf(events.hitCount, events.hitA, events.hitB), speed: events.hitSpeed[0], swept: world.stats.sweptBodies, vx: world.getCircle(bullet).vx, pair: `${target}-${bullet}` };
    };
    const slow = shoot(40, 0.1);
    expect(slow.swept).toBe(0);
    expect(slow.events).toEqual([slow.pair]);
    expect(slow.speed).toBeCloseTo(40, 12);
    const fast = shoot(4000, 0.1);
    expect(fast.swept).toBe(1);
    expect(fast.vx).toBeCloseTo(-4000, 9);
    expect(fast.events).toEqual([fast.pair]);
    expect(fast.speed).toBeCloseTo(4000, 9);
    // Below the threshold, no hit either way.
    const world = new World({ hitEventThreshold: 5000 });
    world.createCircle({ x: 100, y: 0, radius: 5, type: 'static' });
    world.createCircle({ x: 100 - 10 - 200, y: 0, vx: 4000, radius: 5 });
    world.step(0.1);
    expect(world.stats.sweptBodies).toBe(1);
    expect(world.contactEvents().hitCount).toBe(0);
  });

  it('a body hitting a static segment reports a segment hit, swept or not, with both handles and the approach speed', () => {
    // A horizontal wall (the second segment, so its handle is not 0); a ball falls onto it at
    // 40 units/s (4 a step, under its radius: a discrete contact) or 4,000 (400 a step: the sweep).
    const drop = (speed: number, solverIterations = 1) => {
      const world = new World({ hitEventThreshold: 5, solverIterations });
      world.createSegment({ x1: 190, y1: 50, x2: 190, y2: 600 });
      const wall = world.createSegment({ x1: 0, y1: 0, x2: 200, y2: 0 });
      const ball = world.createCircle({ x: 50, y: 5 + 1 + speed * 0.1 * 0.5, vy: -speed, radius: 5 });
      world.step(0.1);
      const e = world.contactEvents();
      return { hits: Array.from({ length: e.segmentHitCount }, (_, k) => [e.segmentHitBody[k], e.segmentHitSegment[k], e.segmentHitSpeed[k]]), bodyHits: e.hitCount, swept: world.stats.sweptBodies, wall, ball, vy: world.getCircle(ball).vy };
    };
    // The iterated solve takes segment contacts in with the circles, and reports them the same.
    expect(drop(40, 4).hits).toEqual(drop(40).hits);
    const slow = drop(40);
    expect(slow.swept).toBe(0);
    expect(slow.bodyHits).toBe(0);
    expect(slow.hits).toHaveLength(1);
    expect(slow.hits[0].slice(0, 2)).toEqual([slow.ball, slow.wall]);
    expect(slow.hits[0][2]).toBeCloseTo(40, 12);
    expect(slow.vy).toBeGreaterThan(0);
    const fast = drop(4000);
    expect(fast.swept).toBe(1);
    expect(fast.hits).toHaveLength(1);
    expect(fast.hits[0].slice(0, 2)).toEqual([fast.ball, fast.wall]);
    expect(fast.hits[0][2]).toBeCloseTo(4000, 9);
    expect(fast.vy).toBeGreaterThan(0);
    // Below the threshold: the bounce happens, the event does not.
    const world = new World({ hitEventThreshold: 50 });
    world.createSegment({ x1: 0, y1: 0, x2: 200, y2: 0 });
    world.createCircle({ x: 50, y: 8, vy: -40, radius: 5 });
    world.step(0.1);
    expect(world.contactEvents().segmentHitCount).toBe(0);
  });

  it.each([1, 4])('a body landing on a segment begins touching it once, and ends when it leaves or the segment goes (solverIterations %i)', (solverIterations) => {
    const world = new World({ contactEvents: true, gravity: { x: 0, y: -100 }, restitution: 0, solverIterations, positionCorrection: solverIterations > 1 ? 0.2 : 1 });
    world.createSegment({ x1: 300, y1: 0, x2: 300, y2: 50 });
    const ground = world.createSegment({ x1: 0, y1: 0, x2: 200, y2: 0 });
    const ball = world.createCircle({ x: 50, y: 20, radius: 5 });
    const begins: string[] = [];
    const ends: string[] = [];
    const collect = () => {
      const e = world.contactEvents();
      begins.push(...pairsOf(e.segmentBeginCount, e.segmentBeginBody, e.segmentBeginSegment));
      ends.push(...pairsOf(e.segmentEndCount, e.segmentEndBody, e.segmentEndSegment));
    };
    for (let s = 0; s < 240; s++) {
      world.step(1 / 60);
      collect();
    }
    // It fell, landed and rests: one begin, no end, no body-pair events.
    expect(begins).toEqual([`${ball}-${ground}`]);
    expect(ends).toEqual([]);
    expect(world.contactEvents().beginCount + world.contactEvents().endCount).toBe(0);
    // Thrown up, it leaves the ground: an end; it lands again: another begin.
    world.setVelocity(ball, 0, 60);
    for (let s = 0; s < 120; s++) {
      world.step(1 / 60);
      collect();
    }
    expect(ends).toEqual([`${ball}-${ground}`]);
    expect(begins).toEqual([`${ball}-${ground}`, `${ball}-${ground}`]);
    // The segment destroyed under it: the touch ends, named by the handles it had.
    world.destroySegment(ground);
    world.step(1 / 60);
    collect();
    expect(ends).toEqual([`${ball}-${ground}`, `${ball}-${ground}`]);
  });

  it('a body hitting a box wall reports a wall hit, swept or not, naming the wall, with the approach speed', () => {
    // A ball runs at the wall x = width, from half a step's travel away, at 40 units/s (4 a step: the walls stage) or 4,000 (400 a
    // step; the static peg makes the continuous sweep run, and the sweep meets the wall first).
    const run = (speed: number, peg: boolean) => {
      const world = new World({ hitEventThreshold: 5, bounds: { width: 1000, height: 100 } });
      if (peg) world.createCircle({ x: 20, y: 80, radius: 5, type: 'static' });
      const ball = world.createCircle({ x: 1000 - 5 - speed * 0.1 * 0.5, y: 50, vx: speed, radius: 5 });
      world.step(0.1);
      const e = world.contactEvents();
      const hits = Array.from({ length: e.wallHitCount }, (_, k) => [e.wallHitBody[k], e.wallHitWall[k], e.wallHitSpeed[k]]);
      return { hits, other: e.hitCount + e.segmentHitCount, swept: world.stats.sweptBodies, ball, vx: world.getCircle(ball).vx };
    };
    for (const [speed, peg, swept] of [[40, false, 0], [4000, false, 0], [4000, true, 1]] as const) {
      const r = run(speed, peg);
      expect(r.swept, `${speed} units/s, peg ${peg}`).toBe(swept);
      expect(r.other).toBe(0);
      expect(r.hits).toHaveLength(1);
      expect(r.hits[0].slice(0, 2)).toEqual([r.ball, BoxWall.maxX]);
      expect(r.hits[0][2]).toBeCloseTo(speed, 9);
      expect(r.vx).toBeLessThan(0);
    }
    // The other three walls, each by its number; below the threshold a bounce gives no hit.
    const world = new World({ hitEventThreshold: 50, bounds: { width: 200, height: 100 } });
    const left = world.createCircle({ x: 8, y: 50, vx: -60, radius: 5 });
    const low = world.createCircle({ x: 100, y: 8, vy: -60, radius: 5 });
    const high = world.createCircle({ x: 150, y: 92, vy: 60, radius: 5 });
    world.createCircle({ x: 50, y: 8, vy: -40, radius: 5 });
    world.step(0.1);
    const e = world.contactEvents();
    const hits = Array.from({ length: e.wallHitCount }, (_, k) => `${e.wallHitBody[k]}@${e.wallHitWall[k]}`);
    expect(hits).toEqual([`${left}@${BoxWall.minX}`, `${low}@${BoxWall.minY}`, `${high}@${BoxWall.maxY}`]);
  });

  it('a body landing on the box floor begins touching it once, and ends when it leaves or is destroyed', () => {
    const world = new World({ contactEvents: true, gravity: { x: 0, y: -100 }, bounds: { width: 100, height: 100 }, restitution: 0 });
    const ball = world.createCircle({ x: 50, y: 40, radius: 5 });
    const begins: string[] = [];
    const ends: string[] = [];
    const collect = () => {
      const e = world.contactEvents();
      begins.push(...pairsOf(e.wallBeginCount, e.wallBeginBody, e.wallBeginWall));
      ends.push(...pairsOf(e.wallEndCount, e.wallEndBody, e.wallEndWall));
    };
    for (let s = 0; s < 240; s++) {
      world.step(1 / 60);
      collect();
    }
    const floor = `${ball}-${BoxWall.minY}`;
    expect(begins).toEqual([floor]);
    expect(ends).toEqual([]);
    world.setVelocity(ball, 0, 60);
    for (let s = 0; s < 120; s++) {
      world.step(1 / 60);
      collect();
    }
    expect(ends).toEqual([floor]);
    expect(begins).toEqual([floor, floor]);
    world.destroyBody(ball);
    world.step(1 / 60);
    collect();
    expect(ends).toEqual([floor, floor]);
  });

  it('events do not change the bits: the walls stage that notes them bounces as the fused one does', async () => {
    const { buildScene, buildWorld } = await import('@maxgrid/scenes');
    const hash = (options: object) => {
      const world = buildWorld(buildScene('seed-box', { n: 1500, seed: 5 }), options);
      for (let s = 0; s < 120; s++) world.step(1 / 60);
      return world.stateHash();
    };
    expect(hash({ contactEvents: true, hitEventThreshold: 10 })).toBe(hash({}));
  });

  it('events are off unless asked for', () => {
    expect(() => new World().contactEvents()).toThrow(/contactEvents: true/);
  });

  it('event buffers stop growing after warm-up', async () => {
    const { buildScene, buildWorld } = await import('@maxgrid/scenes');
    const scene = buildScene('uniform', { n: 2000, seed: 3 });
    const world = buildWorld(scene, { contactEvents: true, hitEventThreshold: 0 });
    for (let s = 0; s < 200; s++) world.step(1 / 60);
    const events = world.contactEvents();
    const arrays = [events.beginA, events.endA, events.hitA];
    const before = world.memoryBytes();
    let begins = 0;
    for (let s = 0; s < 300; s++) {
      world.step(1 / 60);
      begins += events.beginCount;
    }
    expect(begins).toBeGreaterThan(1000);
    expect(world.memoryBytes()).toBe(before);
    expect([events.beginA, events.endA, events.hitA]).toEqual(arrays);
  });
});
