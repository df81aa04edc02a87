import { describe, expect, it } from 'vitest';
import { SCENES, SCENE_NAMES, CLIFF_SCENES, buildScene, buildWorld, Prng } from '../src/index.js';
import { clampInside } from '../src/scene.js';

describe('scenes', () => {
  it.each(SCENE_NAMES)('%s is deterministic for a seed and fits inside its box', (name) => {
    const a = buildScene(name, {});
    const b = buildScene(name, {});
    expect(a.count).toBeGreaterThan(0);
    for (const column of ['x', 'y', 'vx', 'vy', 'radius'] as const) expect(a[column]).toEqual(b[column]);
    for (let k = 0; k < a.count; k++) {
      const r = a.radius[k];
      expect(a.x[k] - r).toBeGreaterThanOrEqual(0);
      expect(a.y[k] - r).toBeGreaterThanOrEqual(0);
      expect(a.x[k] + r).toBeLessThanOrEqual(a.bounds.width);
      expect(a.y[k] + r).toBeLessThanOrEqual(a.bounds.height);
    }
    expect(buildWorld(a).bodyCount).toBe(a.count);
  });

  it('uniform: radii in [4, 8], 25% of the box filled, speeds in [0, 100], no overlaps, elastic, no gravity', () => {
    const s = buildScene('uniform', { n: 5000, seed: 3 });
    let area = 0;
    for (let k = 0; k < s.count; k++) {
      expect(s.radius[k]).toBeGreaterThanOrEqual(4);
      expect(s.radius[k]).toBeLessThanOrEqual(8);
      expect(Math.hypot(s.vx[k], s.vy[k])).toBeLessThanOrEqual(100);
      area += Math.PI * s.radius[k] ** 2;
    }
    expect(area / (s.bounds.width * s.bounds.height)).toBeCloseTo(0.25, 10);
    expect(s.bounds.width).toBe(s.bounds.height);
    expect(s.gravity).toEqual({ x: 0, y: 0 });
    expect(s.restitution).toBe(1);
    const world = buildWorld(s);
    world.step(0);
    expect(world.stats.contacts).toBe(0);
  });

  it('seed-box: the report\'s 1600 x 900 box, with gravity and elasticity as parameters', () => {
    const s = buildScene('seed-box', { n: 100, gravity: 250, elasticity: 0.8, seed: 5 });
    expect(s.bounds).toEqual({ width: 1600, height: 900 });
    expect(s.gravity).toEqual({ x: 0, y: 250 });
    expect(s.restitution).toBe(0.8);
    expect(s.count).toBe(100);
    expect(buildScene('seed-box', { n: 100, seed: 6 }).x).not.toEqual(s.x);
  });

  it('mixed: a few circles `ratio` times larger than the rest, none overlapping at the start', () => {
    const s = buildScene('mixed', { n: 3000, seed: 4, ratio: 50, largeFraction: 0.003 });
    const radii = Array.from(s.radius);
    expect(radii.filter((r) => r === 200).length).toBe(9);
    expect(radii.filter((r) => r !== 200).every((r) => r >= 4 && r <= 8)).toBe(true);
    const world = buildWorld(s, { broadphase: 'hgrid' });
    world.step(0);
    expect(world.stats.contacts).toBe(0);
  });

  it('mixed: many large circles with a wide ratio place without overlaps, and a box too sparse to list is a clear error', () => {
    // 5 % of the circles 200 times larger: the sandbox's slider limits, where testing every fine
    // cell against every large circle took 17.7 s at 10,000 circles. Nothing overlaps.
    const s = buildScene('mixed', { n: 2_000, largeFraction: 0.05, ratio: 200 });
    const world = buildWorld(s, { broadphase: 'hgrid' });
    world.step(0);
    expect(world.stats.contacts).toBe(0);
    expect(() => buildScene('mixed', { n: 200_000, largeFraction: 0.05, ratio: 200 })).toThrow(
      /mixed: a box \d+ wide has \d+ places for small circles, more than 16777216 to list; lower n, ratio or largeFraction, or raise fill/,
    );
  });

  it('uniform starts every circle inside its box at the extremes of its radii, for every seed', () => {
    // side - r rounds up for some radii, and a circle clamped there would poke an ulp (about
    // 4e-12 here) past the wall, which the engine refuses: 27 of these 2,000 log-radii seeds and
    // 97 of the linear ones at fill 0.6 would.
    const inside = (s: ReturnType<typeof buildScene>) => {
      for (let k = 0; k < s.count; k++) {
        const r = s.radius[k];
        if (s.x[k] - r < 0 || s.y[k] - r < 0 || s.x[k] + r > s.bounds.width || s.y[k] + r > s.bounds.height) return false;
      }
      return true;
    };
    const outside: string[] = [];
    for (let seed = 0; seed < 2000; seed++) {
      for (const params of [
        { minRadius: 0.01, maxRadius: 1e4, logRadius: 1 },
        { minRadius: 0.01, maxRadius: 1e4, logRadius: 0, fill: 0.6 },
      ]) {
        if (!inside(buildScene('uniform', { n: 40, seed, ...params }))) outside.push(`uniform ${seed} ${JSON.stringify(params)}`);
      }
      if (!inside(CLIFF_SCENES['log-radii'].build({ n: 40, seed }))) outside.push(`log-radii ${seed}`);
    }
    expect(outside).toEqual([]);
  });

  it('clampInside keeps a circle of any radius inside any box, as the engine tests it, and leaves a centre already inside alone', () => {
    const rng = new Prng(7);
    const wrong: string[] = [];
    for (let k = 0; k < 100_000; k++) {
      const side = 10 ** (14 * rng.next() - 4);
      const r = (side / 2) * rng.next() ** 4;
      if (clampInside(side, r, side) + r > side || clampInside(-side, r, side) - r < 0) wrong.push(`r ${r} in ${side}`);
      const at = rng.range(r, side - r);
      if (at + r <= side && clampInside(at, r, side) !== at) wrong.push(`${at} moved, r ${r} in ${side}`);
    }
    expect(wrong).toEqual([]);
  });

  it('uniform with logRadius: as many circles per size octave', () => {
    const s = buildScene('uniform', { n: 4000, seed: 1, minRadius: 1, maxRadius: 16, logRadius: 1 });
    const perOctave = [0, 0, 0, 0];
    for (const r of s.radius) perOctave[Math.min(3, Math.floor(Math.log2(r)))]++;
    for (const count of perOctave) expect(count).toBeGreaterThan(900);
  });

  it('uniform with shuffle: the same circles in another order, the same for a seed', () => {
    const rows = buildScene('uniform', { n: 3000, seed: 2 });
    const shuffled = buildScene('uniform', { n: 3000, seed: 2, shuffle: 1 });
    expect(buildScene('uniform', { n: 3000, seed: 2, shuffle: 0 }).x).toEqual(rows.x);
    expect(buildScene('uniform', { n: 3000, seed: 2, shuffle: 1 }).x).toEqual(shuffled.x);
    const circles = (s: typeof rows) => Array.from({ length: s.count }, (_, k) => [s.x[k], s.y[k], s.vx[k], s.vy[k], s.radius[k]].join(' ')).sort();
    expect(circles(shuffled)).toEqual(circles(rows));
    expect(shuffled.bounds).toEqual(rows.bounds);
    // Listed out of row order: far fewer consecutive circles are lattice neighbours.
    const steps = (s: typeof rows) => {
      let near = 0;
      for (let k = 1; k < s.count; k++) if (Math.hypot(s.x[k] - s.x[k - 1], s.y[k] - s.y[k - 1]) < 50) near++;
      return near / (s.count - 1);
    };
    expect(steps(rows)).toBeGreaterThan(0.9);
    expect(steps(shuffled)).toBeLessThan(0.05);
  });

  it('bouncing-ball: one ball at rest, restitution 1', () => {
    const s = buildScene('bouncing-ball');
    expect(s.count).toBe(1);
    expect([s.vx[0], s.vy[0], s.restitution]).toEqual([0, 0, 1]);
  });

  it('rejects unknown scenes and bad parameters by name', () => {
    expect(() => buildScene('pinball')).toThrow(/unknown scene 'pinball'/);
    expect(() => buildScene('uniform', { n: -1 })).toThrow(/uniform\.n.*-1/);
    expect(() => buildScene('uniform', { n: 1.5 })).toThrow(/integer/);
    expect(() => buildScene('uniform', { radius: 3 })).toThrow(/no parameter 'radius'/);
    expect(() => buildScene('seed-box', { gravity: NaN })).toThrow(/gravity.*NaN/);
    expect(() => buildScene('uniform', { minRadius: 9, maxRadius: 3 })).toThrow(/minRadius/);
    // Names Object.prototype holds are neither scenes nor parameters.
    expect(() => buildScene('toString')).toThrow(/unknown scene 'toString'/);
    expect(() => buildScene('uniform', { n: 10, constructor: 5 })).toThrow(/no parameter 'constructor'/);
    expect(() => buildScene('uniform', JSON.parse('{"n": 10, "__proto__": 3}'))).toThrow(/no parameter '__proto__'/);
    expect(() => buildScene('uniform', [] as never)).toThrow(/object of numbers, got an array/);
    expect(() => buildScene('uniform', null as never)).toThrow(/object of numbers, got null/);
  });

  it('every parameter default lies within its range', () => {
    for (const def of Object.values(SCENES)) {
      for (const spec of Object.values(def.params)) {
        expect(spec.default).toBeGreaterThanOrEqual(spec.min);
        expect(spec.default).toBeLessThanOrEqual(spec.max);
      }
    }
  });

  it('Prng is seeded: same seed, same sequence; values in [0, 1)', () => {
    const a = new Prng(123);
    const b = new Prng(123);
    const xs = Array.from({ length: 1000 }, () => a.next());
    expect(xs).toEqual(Array.from({ length: 1000 }, () => b.next()));
    expect(Math.min(...xs)).toBeGreaterThanOrEqual(0);
    expect(Math.max(...xs)).toBeLessThan(1);
    expect(new Set(xs).size).toBe(1000);
  });
});

describe('portable randomness', () => {
  it('directions are unit vectors spread over the whole circle', () => {
    const rng = new Prng(9);
    const quadrants = [0, 0, 0, 0];
    for (let k = 0; k < 4000; k++) {
      const [x, y] = rng.direction();
      expect(Math.abs(x * x + y * y - 1)).toBeLessThan(1e-15);
      quadrants[(x >= 0 ? 0 : 1) + (y >= 0 ? 0 : 2)]++;
    }
    for (const q of quadrants) expect(q).toBeGreaterThan(900);
  });

  it('logRange stays in [min, max) and matches min * (max/min)^u', () => {
    const a = new Prng(4);
    const b = new Prng(4);
    for (let k = 0; k < 1000; k++) {
      const r = a.logRange(2, 200);
      expect(r).toBeGreaterThanOrEqual(2);
      expect(r).toBeLessThan(200);
      // u is taken to 30 bits: a relative error up to ln(100) 2^-30, about 4e-9.
      expect(Math.abs(r / (2 * 100 ** b.next()) - 1)).toBeLessThan(1e-8);
    }
  });
});

describe('funnel (static shapes)', () => {
  it('builds pegs as static circles and walls as segments, with nothing overlapping at the start', () => {
    const s = buildScene('funnel', { n: 300 });
    expect(s.segments.length).toBe(3);
    const pegs = Array.from(s.fixed!).filter((f) => f === 1).length;
    expect(pegs).toBeGreaterThan(40);
    const world = buildWorld(s);
    expect(world.segmentCount).toBe(3);
    world.step(0);
    expect(world.stats.contacts).toBe(0);
    expect(world.stats.segmentContacts).toBe(0);
  });

  it('circles fall through it and pile up at the bottom, without tunnelling out of the box', () => {
    const world = buildWorld(buildScene('funnel', { n: 200, seed: 3 }));
    for (let s = 0; s < 600; s++) world.step(1 / 60);
    const v = world.views();
    let low = 0;
    for (let i = 0; i < v.slotCount; i++) if (v.type[i] === 3 && v.y[i] > 450) low++;
    expect(low).toBeGreaterThan(150);
  });

  it('refuses more circles than fit above the funnel, by name', () => {
    expect(() => buildScene('funnel', { n: 2000 })).toThrow(/funnel: only 992 circles of size 4 fit/);
  });

  it("n's range and description say how many fit: n.max at the smallest size builds, and each count the description gives is exact", () => {
    const { n, size } = SCENES.funnel.params;
    expect(buildScene('funnel', { n: n.max, size: size.min }).count).toBeGreaterThan(n.max);
    const said = [...n.description.matchAll(/([\d,]+) of size (\d+)/g)].map((m) => [Number(m[1].replaceAll(',', '')), Number(m[2])]);
    expect(said.length).toBeGreaterThanOrEqual(3);
    expect(said).toContainEqual([n.max, size.min]);
    for (const [fits, at] of said) {
      expect(() => buildScene('funnel', { n: fits, size: at })).not.toThrow();
      if (fits < n.max) expect(() => buildScene('funnel', { n: fits + 1, size: at })).toThrow(new RegExp(`only ${fits} circles`));
    }
  });
});
