import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { World, type RayHit } from '../src/index.js';
import { CROWD_WIDTH, buildFarWorld, expectQueriesAsBrute, farQueriesAsBrute, farQueryArbitrary, farWorldArbitrary, queriesOf, rng } from './helpers.js';

const worldArbitrary = fc
  .array(
    fc.record({
      x: fc.double({ min: -500, max: 500, noNaN: true }),
      y: fc.double({ min: -500, max: 500, noNaN: true }),
      r: fc.double({ min: 0.5, max: 60, noNaN: true }),
      category: fc.constantFrom(1, 2, 4),
    }),
    { minLength: 1, maxLength: 80 },
  )
  .map((circles) => {
    const world = new World();
    for (const c of circles) world.createCircle({ x: c.x, y: c.y, radius: c.r, category: c.category });
    return world;
  });

const coordinate = fc.double({ min: -700, max: 700, noNaN: true });

function bruteRay(world: World, x1: number, y1: number, x2: number, y2: number) {
  const hits: { handle: number; fraction: number }[] = [];
  for (const h of world.handles()) {
    const c = world.getCircle(h);
    const fx = x1 - c.x;
    const fy = y1 - c.y;
    const dx = x2 - x1;
    const dy = y2 - y1;
    const cc = fx * fx + fy * fy - c.radius * c.radius;
    const a = dx * dx + dy * dy;
    const b = fx * dx + fy * dy;
    // The discriminant b^2 - a cc as a r^2 - (f x d)^2, and the near root as cc / (-b + sqrt):
    // the same values, rounded as the engine rounds them, so near-ties sort alike.
    const cross = fx * dy - fy * dx;
    const discriminant = a * c.radius * c.radius - cross * cross;
    if (cc <= 0 || a === 0 || b >= 0 || discriminant < 0) continue;
    const t = cc / (-b + Math.sqrt(discriminant));
    if (t <= 1) hits.push({ handle: h, fraction: t });
  }
  return hits.sort((p, q) => p.fraction - q.fraction || p.handle - q.handle);
}

describe('queries agree with brute force', () => {
  it('point query', () => {
    fc.assert(
      fc.property(worldArbitrary, coordinate, coordinate, fc.constantFrom(0xffffffff, 1, 6), (world, px, py, mask) => {
        const expected = world.handles().filter((h) => {
          const c = world.getCircle(h);
          return (c.category & mask) !== 0 && (px - c.x) ** 2 + (py - c.y) ** 2 <= c.radius ** 2;
        });
        expect(world.queryPoint(px, py, { mask })).toEqual(expected);
      }),
      { numRuns: 300, seed: 1 },
    );
  });

  it('AABB query', () => {
    fc.assert(
      fc.property(worldArbitrary, coordinate, coordinate, coordinate, coordinate, (world, ax, ay, bx, by) => {
        const [minX, maxX] = [Math.min(ax, bx), Math.max(ax, bx)];
        const [minY, maxY] = [Math.min(ay, by), Math.max(ay, by)];
        const expected = world.handles().filter((h) => {
          const c = world.getCircle(h);
          const dx = c.x - Math.min(Math.max(c.x, minX), maxX);
          const dy = c.y - Math.min(Math.max(c.y, minY), maxY);
          return dx * dx + dy * dy <= c.radius * c.radius;
        });
        expect(world.queryAABB(minX, minY, maxX, maxY)).toEqual(expected);
      }),
      { numRuns: 300, seed: 2 },
    );
  });

  it('ray cast: all hits in order, and the first hit', () => {
    fc.assert(
      fc.property(worldArbitrary, coordinate, coordinate, coordinate, coordinate, (world, x1, y1, x2, y2) => {
        const expected = bruteRay(world, x1, y1, x2, y2);
        const all = world.rayCastAll(x1, y1, x2, y2);
        expect(all.map((h) => h.handle)).toEqual(expected.map((h) => h.handle));
        const first = world.rayCast(x1, y1, x2, y2);
        expect(first?.handle ?? null).toBe(expected[0]?.handle ?? null);
        if (first) {
          const c = world.getCircle(first.handle);
          expect(Math.hypot(first.x - c.x, first.y - c.y)).toBeCloseTo(c.radius, 6);
          expect(Math.hypot(first.normalX, first.normalY)).toBeCloseTo(1, 9);
        }
      }),
      { numRuns: 400, seed: 3 },
    );
  });

  it('a ray that starts far away still hits, on the circle, with a unit normal', () => {
    const world = new World();
    const h = world.createCircle({ x: 50, y: 50, radius: 5 });
    // Past 1.3e154 the squares of the lengths overflow; past 1e15, start + t d rounded the hit off the rim.
    for (const far of [1e3, 1e9, 1e12, 1e16, 1e100, 3e154, 1e300]) {
      const rays: [number[], number, number][] = [
        [[-far, 50, far, 50], 45, 50],
        [[50, far, 50, -far], 50, 55],
        [[-far, 52, 60, 52], 50 - Math.sqrt(21), 52],
        [[50 - far, 50 - far, 50 + far, 50 + far], Number.NaN, Number.NaN],
      ];
      for (const [[x1, y1, x2, y2], ex, ey] of rays) {
        const hit = world.rayCast(x1, y1, x2, y2);
        expect(hit?.handle, `from (${x1}, ${y1})`).toBe(h);
        expect(Math.abs(Math.hypot(hit!.x - 50, hit!.y - 50) - 5), `from (${x1}, ${y1})`).toBeLessThanOrEqual(1e-12);
        expect(Math.abs(Math.hypot(hit!.normalX, hit!.normalY) - 1)).toBeLessThanOrEqual(1e-15);
        // Axis-aligned rays are exact; a diagonal start is itself only known to an ulp of its coordinates.
        if (!Number.isNaN(ex)) expect(Math.hypot(hit!.x - ex, hit!.y - ey), `from (${x1}, ${y1})`).toBeLessThanOrEqual(1e-12);
      }
    }
    // Parallel rays just inside and just outside the rim, from far away.
    expect(world.rayCast(-1e9, 54.99, 1e9, 54.99)?.handle).toBe(h);
    expect(world.rayCast(-1e9, 55.01, 1e9, 55.01)).toBeNull();
    expect(world.rayCast(-1e200, 55.01, 1e200, 55.01)).toBeNull();
    expect(world.rayCastAll(-1e200, 54.99, 1e200, 54.99).map((hit) => hit.handle)).toEqual([h]);
    // A ray whose extent overflows a double is refused by name.
    expect(() => world.rayCast(-1e308, 50, 1e308, 50)).toThrow(/a ray from \(-1e\+308, 50\) to \(1e\+308, 50\) spans more than the largest double/);
  });

  it('queries see the world as it is after steps and edits', () => {
    const world = new World();
    const a = world.createCircle({ x: 0, y: 0, vx: 100, radius: 2 });
    expect(world.queryPoint(0, 0)).toEqual([a]);
    world.step(1);
    expect(world.queryPoint(0, 0)).toEqual([]);
    expect(world.queryPoint(100, 0)).toEqual([a]);
    world.setPosition(a, -50, 0);
    expect(world.rayCast(-100, 0, 0, 0)?.handle).toBe(a);
    world.destroyBody(a);
    expect(world.rayCast(-100, 0, 0, 0)).toBeNull();
  });

  it('point and box queries fill an array the caller reuses, emptied first, with the same handles', () => {
    fc.assert(
      fc.property(worldArbitrary, coordinate, coordinate, fc.double({ min: 0, max: 300, noNaN: true }), (world, x, y, size) => {
        const out = [-1, -2, -3];
        expect(world.queryPoint(x, y, {}, out)).toBe(out);
        expect(out).toEqual(world.queryPoint(x, y));
        expect(world.queryAABB(x, y, x + size, y + size, { mask: 2 }, out)).toBe(out);
        expect(out).toEqual(world.queryAABB(x, y, x + size, y + size, { mask: 2 }));
      }),
      { numRuns: 60 },
    );
    const world = new World();
    world.createCircle({ x: 0, y: 0, radius: 5 });
    const out = [7, 8];
    expect(world.queryPoint(100, 100, undefined, out)).toEqual([]);
    expect(out).toEqual([]);
    expect(() => world.queryAABB(0, 0, 1, 1, {}, 'list' as unknown as number[])).toThrow(/out must be an array to fill, got "list"/);
    expect(() => world.queryPoint(0, 0, {}, { length: 0 } as unknown as number[])).toThrow(/out must be an array/);
    expect(() => world.queryPoint(0, 0, {}, Object.freeze([]) as unknown as number[])).toThrow(/out must be an array to fill, got a frozen or sealed array/);
  });

  it('ray casts fill the hit objects the caller reuses, with the same hits as fresh calls', () => {
    // One array and one object across every case: they shrink, grow and get overwritten.
    const out = [{ handle: -1, fraction: 9, x: 0, y: 0, normalX: 0, normalY: 0 }];
    const single = { handle: -1, fraction: 9, x: 0, y: 0, normalX: 0, normalY: 0 };
    fc.assert(
      fc.property(worldArbitrary, coordinate, coordinate, coordinate, coordinate, (world, x1, y1, x2, y2) => {
        const kept = [...out];
        expect(world.rayCastAll(x1, y1, x2, y2, undefined, out)).toBe(out);
        expect(out).toEqual(world.rayCastAll(x1, y1, x2, y2));
        // The objects that were there hold hits again (sorted, so in another order), as far as there are hits.
        const holding = new Set(out);
        for (let k = 0; k < Math.min(kept.length, out.length); k++) expect(holding.has(kept[k])).toBe(true);
        const fresh = world.rayCast(x1, y1, x2, y2, { mask: 1 });
        const reused = world.rayCast(x1, y1, x2, y2, { mask: 1 }, single);
        expect(reused).toEqual(fresh);
        if (fresh) expect(reused).toBe(single);
      }),
      { numRuns: 200, seed: 4 },
    );
    // A crowd of nested circles in one cell, found far from the walk's order: ordered all the same.
    const crowd = new World();
    for (let k = 0; k < 300; k++) crowd.createCircle({ x: 500 + (k % 7), y: 500, radius: 1 + ((k * 37) % 300) });
    const expected = bruteRay(crowd, 0, 500, 1000, 501).map((h) => h.handle);
    expect(expected.length).toBeGreaterThan(250);
    expect(crowd.rayCastAll(0, 500, 1000, 501, undefined, out).map((h) => h.handle)).toEqual(expected);
    const world = new World();
    world.createCircle({ x: 0, y: 0, radius: 5 });
    expect(() => world.rayCast(-10, 0, 10, 0, {}, [] as unknown as RayHit)).toThrow(/out must be a writable hit object to fill, got an array/);
    expect(() => world.rayCast(-10, 0, 10, 0, {}, Object.freeze({ ...single }))).toThrow(/out must be a writable hit object/);
    expect(() => world.rayCastAll(-10, 0, 10, 0, {}, 'hits' as unknown as RayHit[])).toThrow(/out must be an array to fill, got "hits"/);
    expect(() => world.rayCastAll(-10, 0, 10, 0, {}, Object.freeze([]) as unknown as RayHit[])).toThrow(/out must be an array to fill, got a frozen or sealed array/);
    expect(() => world.rayCastAll(-10, 0, 10, 0, {}, [{ ...single }, Object.freeze({ ...single })])).toThrow(/out\[1\] must be a writable hit object to reuse, got a frozen object/);
    expect(() => world.rayCastAll(-10, 0, 10, 0, {}, [7 as unknown as RayHit])).toThrow(/out\[0\] must be a writable hit object to reuse, got 7/);
  });
});

describe('queries with a few bodies far from the crowd', () => {
  it('find what testing every body finds, for points, boxes and rays in, across and beyond the grid', () => {
    // The grid's extent left bodies out (binned into its edge cells) in a good share of the worlds.
    expect(farQueriesAsBrute(false, 120, 5)).toBeGreaterThan(40);
  });

  it('search about as much of the grid as without them', () => {
    const build = (far: boolean) => {
      const random = rng(11);
      const world = new World();
      // 20,000 circles of radius 4 in a patch filled to a quarter, as the far-bodies scene.
      const side = Math.sqrt((20_000 * Math.PI * 16) / 0.25);
      for (let k = 0; k < 20_000; k++) world.createCircle({ x: (k % 141) * (side / 141) + random(), y: Math.floor(k / 141) * (side / 141) + random(), radius: 4 });
      if (far) for (let k = 0; k < 4; k++) world.createCircle({ x: 1e6 + 10 * k, y: 1e6, radius: 4 });
      return { world, side };
    };
    const work = (world: World, side: number) => {
      const q = queriesOf(world);
      const sample = rng(12);
      const total = { point: 0, box: 0, ray: 0, rayAll: 0 };
      for (let k = 0; k < 200; k++) {
        const [x, y, x2, y2] = [sample() * side, sample() * side, sample() * side, sample() * side];
        world.queryPoint(x, y);
        total.point += q.examined;
        world.queryAABB(x, y, x + 20, y + 20);
        total.box += q.examined;
        world.rayCast(x, y, x2, y2);
        total.ray += q.examined;
        world.rayCastAll(x, y, x + 50, y + 30);
        total.rayAll += q.examined;
      }
      return total;
    };
    const near = build(false);
    const far = build(true);
    const without = work(near.world, near.side);
    const withFar = work(far.world, far.side);
    for (const kind of ['point', 'box', 'ray', 'rayAll'] as const) {
      expect(withFar[kind], `${kind}: ${withFar[kind]} examined with the far bodies, ${without[kind]} without`).toBeLessThanOrEqual(2 * without[kind]);
    }
    // At the far bodies, and on rays among them and from them into the crowd, the search stays as small.
    const q = queriesOf(far.world);
    expect(far.world.queryPoint(1e6, 1e6)).toEqual([20_000]);
    expect(q.examined).toBeLessThanOrEqual(64);
    expect(far.world.rayCastAll(1e6 + 100, 1e6, 1e6 - 100, 1e6).map((hit) => hit.handle)).toEqual([20_003, 20_002, 20_001, 20_000]);
    expect(q.examined).toBeLessThanOrEqual(64);
    const centre = far.side / 2;
    const hit = far.world.rayCast(1e6 - 100, 1e6 - 100, centre, centre);
    const fromFar = q.examined;
    expect(hit).toEqual(near.world.rayCast(1e6 - 100, 1e6 - 100, centre, centre));
    expect(fromFar).toBeLessThanOrEqual(2 * queriesOf(near.world).examined + 64);
  });
});

describe('queries with a body far larger than the rest', () => {
  it('find what testing every body finds, the giant kept out of the grid and tested on its own', () => {
    fc.assert(
      fc.property(farWorldArbitrary, fc.array(farQueryArbitrary, { minLength: 1, maxLength: 12 }), fc.boolean(), fc.boolean(), (spec, queries, box, isStatic) => {
        // No body destroyed: the giant would take its slot, and the oracle lists handles in slot order.
        const { world, far } = buildFarWorld({ ...spec, destroy: false }, true);
        // A ground 300 long under the crowd, or a disc of radius 150 over it.
        const type = isStatic ? ('static' as const) : ('dynamic' as const);
        if (box) world.createBox({ x: CROWD_WIDTH / 2, y: CROWD_WIDTH + 5, width: 300, height: 8, type, category: 2 });
        else world.createCircle({ x: CROWD_WIDTH / 2, y: CROWD_WIDTH / 2, radius: 150, type, category: 4 });
        expectQueriesAsBrute(world, far, queries);
      }),
      { numRuns: 40, seed: 23 },
    );
  });

  it('search no more of the crowd for it (500 sensors over 10,000 bodies stepped 24 times slower through the one large cell)', () => {
    const build = (giant: boolean) => {
      const random = rng(5);
      const world = new World();
      for (let k = 0; k < 10_000; k++) world.createCircle({ x: (k % 100) * 2 + random(), y: Math.floor(k / 100) * 2 + random(), radius: 0.5 });
      if (giant) world.createBox({ x: 100, y: 210, width: 220, height: 4, type: 'static' });
      return world;
    };
    const work = (world: World) => {
      const q = queriesOf(world);
      const sample = rng(6);
      let total = 0;
      for (let k = 0; k < 100; k++) {
        const [x, y] = [sample() * 200, sample() * 200];
        world.queryPoint(x, y);
        total += q.examined;
        world.queryAABB(x, y, x + 3, y + 3);
        total += q.examined;
        world.rayCast(x, y, x + 10, y + 5);
        total += q.examined;
      }
      return total;
    };
    const without = work(build(false));
    const withGiant = work(build(true));
    expect(withGiant, `${withGiant} examined with the giant, ${without} without`).toBeLessThanOrEqual(2 * without);
  });
});
