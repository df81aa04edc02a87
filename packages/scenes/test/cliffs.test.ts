import { describe, expect, it } from 'vitest';
import { CLIFF_SCENES, CLIFF_SCENE_NAMES, buildWorld } from '../src/index.js';

const small = { 'far-bodies': 2000, 'sparse-box': 2000, 'two-crowds': 2000, 'segment-floor': 300, 'static-wall': 2000, 'log-radii': 2000 } as const;

describe('cliff scenes', () => {
  it.each(CLIFF_SCENE_NAMES)('%s is deterministic for a seed, and fits its box unless open', (name) => {
    const a = CLIFF_SCENES[name].build({ n: small[name] });
    const b = CLIFF_SCENES[name].build({ n: small[name] });
    for (const column of ['x', 'y', 'vx', 'vy', 'radius'] as const) expect(a[column]).toEqual(b[column]);
    const world = buildWorld(a);
    expect(world.bodyCount).toBe(a.count);
    expect(world.box === null).toBe(a.open === true);
    if (!a.open) {
      for (let k = 0; k < a.count; k++) {
        expect(a.x[k] - a.radius[k]).toBeGreaterThanOrEqual(0);
        expect(a.x[k] + a.radius[k]).toBeLessThanOrEqual(a.bounds.width);
        expect(a.y[k] + a.radius[k]).toBeLessThanOrEqual(a.bounds.height);
      }
    }
  });

  it('each holds what makes it a cliff', () => {
    const far = CLIFF_SCENES['far-bodies'].build({ n: 1000, distance: 1e7 });
    expect(far.count).toBe(1004);
    expect(far.x[1003]).toBeGreaterThan(1e7);
    const sparse = CLIFF_SCENES['sparse-box'].build({ n: 1000 });
    let right = 0;
    for (let k = 0; k < sparse.count; k++) right = Math.max(right, sparse.x[k] + sparse.radius[k]);
    expect(right).toBeLessThan(sparse.bounds.width / 100);
    const crowds = CLIFF_SCENES['two-crowds'].build({ n: 1000 });
    expect(crowds.x[999] - crowds.x[0]).toBeGreaterThan(0.99e6);
    const wall = CLIFF_SCENES['static-wall'].build({ n: 1000 });
    expect(wall.fixed!.reduce((a, b) => a + b, 0)).toBe(1000);
    expect(wall.count).toBe(1100);
    const radii = CLIFF_SCENES['log-radii'].build({ n: 3000 });
    let min = Infinity;
    let max = 0;
    for (const r of radii.radius) {
      min = Math.min(min, r);
      max = Math.max(max, r);
    }
    expect(max / min).toBeGreaterThan(1e5);
  });

  it('segment-floor builds for every n in its range: balls inside the box, above a floor of n segments that spans it', () => {
    // Every n from the least up to where the box is 2n wide whatever n, and a larger one.
    const { min } = CLIFF_SCENES['segment-floor'].params.n;
    for (const n of [...Array.from({ length: 41 - min }, (_, k) => min + k), 1000]) {
      const scene = CLIFF_SCENES['segment-floor'].build({ n, seed: n });
      expect(() => buildWorld(scene), `n = ${n}`).not.toThrow();
      const floor = scene.segments;
      expect(floor).toHaveLength(n);
      expect(floor[0].x1).toBe(0);
      expect(floor[n - 1].x2).toBe(scene.bounds.width);
      for (let k = 1; k < n; k++) expect(floor[k].x1).toBe(floor[k - 1].x2);
      let lowest = 0;
      for (let k = 0; k < n; k++) lowest = Math.max(lowest, scene.y[k] + scene.radius[k]);
      expect(lowest, `n = ${n}`).toBeLessThan(floor[0].y1);
    }
    // From 20 balls on, the box is 2n wide and the segments 2 long, as the lab has measured them.
    const scene = CLIFF_SCENES['segment-floor'].build({ n: 20 });
    expect(scene.bounds.width).toBe(40);
    expect(scene.segments.map((s) => s.x2 - s.x1)).toEqual(new Array(20).fill(2));
  });

  it('segment-floor: the balls tunnel through the floor without continuous collision, and never with it', () => {
    const ends = (continuous: boolean) => {
      const scene = CLIFF_SCENES['segment-floor'].build({ n: 300 });
      const world = buildWorld(scene, { continuous });
      for (let s = 0; s < 240; s++) world.step(1 / 60);
      const floor = scene.segments[0].y1;
      let below = 0;
      for (const h of world.handles()) if (world.getCircle(h).y > floor) below++;
      return below;
    };
    expect(ends(false)).toBeGreaterThan(10);
    expect(ends(true)).toBe(0);
  });
});
