import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { BodyStore } from '../src/store/body-store.js';
import { PairSink, type PairConsumer } from '../src/store/pair-sink.js';
import { BROADPHASES, BROADPHASE_NAMES } from '../src/broadphase/registry.js';
import { World } from '../src/index.js';
import { storeOf } from './helpers.js';
import { TypeCode } from '../src/store/body-types.js';
import { setGridKernelEnabled } from '../src/broadphase/grid-kernel.js';
import { radiusClass } from '../src/broadphase/hgrid.js';

/** Collects every candidate pair as "lo,hi" strings: test code, so strings are fine here. */
class Collector implements PairConsumer {
  readonly pairs: string[] = [];
  consume(a: Int32Array, b: Int32Array, count: number): void {
    for (let k = 0; k < count; k++) this.pairs.push(a[k] < b[k] ? `${a[k]},${b[k]}` : `${b[k]},${a[k]}`);
  }
  accept(): void {
    throw new Error('a broad-phase pushed a contact while contactsDirect was off');
  }
}

/** The broad-phase auto used for the world's last step. */
function broadPhaseOf(world: World): string {
  return (world as unknown as { pipeline: { broadPhase: { current: { name: string } } } }).pipeline.broadPhase.current.name;
}

function candidates(store: BodyStore, name: (typeof BROADPHASE_NAMES)[number]): string[] {
  const collector = new Collector();
  const sink = new PairSink(collector, () => 0);
  sink.begin();
  BROADPHASES[name]().findPairs(store, sink);
  sink.flush();
  expect(sink.total).toBe(collector.pairs.length);
  return collector.pairs;
}

/** Every pair of live bodies whose circles touch or overlap is in `found` ("lo,hi" keys). */
function expectEveryTouchingPair(store: BodyStore, found: Set<string>): void {
  for (let i = 0; i < store.slotCount; i++) {
    if (store.type[i] === TypeCode.free) continue;
    for (let j = i + 1; j < store.slotCount; j++) {
      if (store.type[j] === TypeCode.free) continue;
      const dx = store.x[j] - store.x[i];
      const dy = store.y[j] - store.y[i];
      const reach = store.radius[i] + store.radius[j];
      if (dx * dx + dy * dy <= reach * reach) expect(found.has(`${i},${j}`), `${i},${j}`).toBe(true);
    }
  }
}

const circles = fc.array(
  fc.record({
    x: fc.double({ min: -1000, max: 1000, noNaN: true }),
    y: fc.double({ min: -1000, max: 1000, noNaN: true }),
    r: fc.double({ min: 0.01, max: 100, noNaN: true }),
  }),
  { minLength: 0, maxLength: 150 },
);

describe('broad-phase contract', () => {
  it.each(BROADPHASE_NAMES)('%s is conservative, reports each pair once and never a free slot', (name) => {
    fc.assert(
      fc.property(circles, fc.array(fc.nat(150), { maxLength: 20 }), (list, holes) => {
        const store = storeOf(list, holes);
        const found = candidates(store, name);
        const set = new Set(found);
        expect(set.size).toBe(found.length);
        for (const key of found) {
          const [i, j] = key.split(',').map(Number);
          expect(i).not.toBe(j);
          expect(store.type[i]).not.toBe(TypeCode.free);
          expect(store.type[j]).not.toBe(TypeCode.free);
        }
        expectEveryTouchingPair(store, set);
      }),
      { numRuns: 150, seed: 99 },
    );
  });

  it.each(BROADPHASE_NAMES)('%s finds exactly tangent circles on both axes', (name) => {
    const store = storeOf([
      { x: 0, y: 0, r: 1 },
      { x: 2, y: 0, r: 1 },
      { x: 2, y: 2, r: 1 },
      { x: 0.1, y: 10, r: 0.1 },
      { x: 0.1, y: 10.3, r: 0.2 },
    ]);
    const found = new Set(candidates(store, name));
    expect(found.has('0,1')).toBe(true);
    expect(found.has('1,2')).toBe(true);
    expect(found.has('3,4')).toBe(true);
  });

  it.each([
    ['maxgrid', true],
    ['hgrid', true],
    ['auto', true],
    ['maxgrid', false],
    ['hgrid', false],
  ] as const)('%s (grid kernel %s) still finds every touching pair when its extent leaves far bodies out (they bin into the edge cells)', (name, kernel) => {
    // A crowd dense enough that a grid over the far bodies' extent would exceed its cell budget,
    // and far clusters of touching circles: some past each side and corner of the crowd.
    const far = fc.record({
      x: fc.double({ min: -1e7, max: 1e7, noNaN: true }),
      y: fc.double({ min: -1e7, max: 1e7, noNaN: true }),
      r: fc.double({ min: 0.1, max: 3, noNaN: true }),
    });
    fc.assert(
      fc.property(fc.integer({ min: 600, max: 1500 }), fc.array(far, { minLength: 1, maxLength: 8 }), (n, clusters) => {
        const list = Array.from({ length: n }, (_, k) => ({ x: (k % 40) * 2, y: Math.floor(k / 40) * 2, r: 0.5 + (k % 3) * 0.25 }));
        // Each cluster two overlapping circles, of sizes hgrid puts on different levels: fewer than
        // the extent's 1/256 tails (2 to 5 bodies), so left out of it.
        for (const c of clusters) list.push({ x: c.x, y: c.y, r: c.r }, { x: c.x + 2 * c.r, y: c.y + 2 * c.r, r: 4 * c.r });
        const store = storeOf(list);
        setGridKernelEnabled(kernel);
        let found: Set<string>;
        try {
          found = new Set(candidates(store, name));
        } finally {
          setGridKernelEnabled(true);
        }
        let touching = 0;
        for (let i = 0; i < store.slotCount; i++) {
          for (let j = i + 1; j < store.slotCount; j++) {
            const dx = store.x[j] - store.x[i];
            const dy = store.y[j] - store.y[i];
            const reach = store.radius[i] + store.radius[j];
            if (dx * dx + dy * dy <= reach * reach) {
              touching++;
              expect(found.has(`${i},${j}`), `${i},${j}`).toBe(true);
            }
          }
        }
        expect(touching).toBeGreaterThanOrEqual(clusters.length);
      }),
      { numRuns: 25, seed: 7 },
    );
  });

  it('naive reports n(n-1)/2 pairs', () => {
    const store = storeOf(Array.from({ length: 37 }, (_, k) => ({ x: k * 100, y: 0, r: 1 })));
    expect(candidates(store, 'naive').length).toBe((37 * 36) / 2);
  });

  it('sap-xy reports no more than sap, and maxgrid prunes far pairs that sap keeps', () => {
    // A row of circles along x at the same y but far apart on y in pairs: sap (x only) keeps them.
    const list = Array.from({ length: 50 }, (_, k) => ({ x: 10, y: k * 100, r: 5 }));
    const store = storeOf(list);
    expect(candidates(store, 'sap').length).toBe((50 * 49) / 2);
    expect(candidates(store, 'sap-xy').length).toBe(0);
    expect(candidates(store, 'maxgrid').length).toBe(0);
  });

  it('maxgrid copes with a far outlier without a huge grid', () => {
    const list = Array.from({ length: 100 }, (_, k) => ({ x: (k % 10) * 3, y: Math.floor(k / 10) * 3, r: 1 }));
    list.push({ x: 1e9, y: -1e9, r: 1 });
    const store = storeOf(list);
    const grid = BROADPHASES.maxgrid();
    const sink = new PairSink(new Collector(), () => 0);
    sink.begin();
    grid.findPairs(store, sink);
    expect(grid.geometry.columns * grid.geometry.rows).toBeLessThanOrEqual(4 * 101 + 64);
  });
});

describe('hashgrid (Max Grid cells in a hash table)', () => {
  it('finds every touching pair, once, whatever the extent: crowds far apart, coordinates to 1e12, tangent pairs, radius 0 points', () => {
    // Clusters of circles at any place up to 1e12 from the origin and of any size from 1e-3 to
    // 1e3, each with a tangent partner beside it and below it, and points of radius 0 on top of
    // each other: the cells' coordinates reach 2^41, and hash to shared buckets.
    const cluster = fc.record({
      x: fc.double({ min: -1e12, max: 1e12, noNaN: true }),
      y: fc.double({ min: -1e12, max: 1e12, noNaN: true }),
      r: fc.double({ min: 1e-3, max: 1e3, noNaN: true }),
      count: fc.integer({ min: 1, max: 12 }),
    });
    fc.assert(
      fc.property(fc.array(cluster, { minLength: 1, maxLength: 10 }), fc.array(fc.nat(200), { maxLength: 10 }), (clusters, holes) => {
        const list: { x: number; y: number; r: number }[] = [];
        for (const c of clusters) {
          for (let k = 0; k < c.count; k++) {
            const x = c.x + (k % 4) * 1.5 * c.r;
            const y = c.y + Math.floor(k / 4) * 1.5 * c.r;
            list.push({ x, y, r: c.r }, { x: x + 2 * c.r, y, r: c.r }, { x, y: y + 2 * c.r, r: c.r });
          }
          list.push({ x: c.x, y: c.y, r: 0 }, { x: c.x, y: c.y, r: 0 });
        }
        const store = storeOf(list, holes);
        const found = candidates(store, 'hashgrid');
        const set = new Set(found);
        expect(set.size).toBe(found.length);
        expectEveryTouchingPair(store, set);
      }),
      { numRuns: 60, seed: 11 },
    );
  });

  it('pairs no body with itself when it lies past 2^53 cells out (the elastic pass moves bodies before the box contains them)', () => {
    // Past 2^53, cx + 1 === cx: the neighbour cells were the body's own, scanned again.
    const run = (broadphase: 'naive' | 'hashgrid', vx: number, gravity: number): [string, number[][]] => {
      // With the speed limit lifted as far as it goes (the default keeps bodies from moving that far).
      const world = new World({ bounds: { width: 60, height: 40 }, solver: 'elastic', broadphase, contactEvents: true, gravity: { x: gravity, y: -7.49 }, maxLinearSpeed: 1e100 });
      world.createCapsule({ x: 25.74, y: 34.58, vx: -5.95, vy: 7.79, length: 1.18, radius: 0.97 });
      world.createCapsule({ x: 3.47, y: 26.45, length: 2.9, radius: 0.72 });
      world.createCircle({ x: 15.57, y: 4.02, vx, vy: -vx, radius: 0.86 });
      world.createCircle({ x: 57.91, y: 35.02, radius: 1.1 });
      const begins: number[][] = [];
      for (let s = 0; s < 3; s++) {
        world.step(1 / 60);
        const e = world.contactEvents();
        for (let k = 0; k < e.beginCount; k++) begins.push([e.beginA[k], e.beginB[k]]);
      }
      return [world.stateHash(), begins];
    };
    for (const [vx, gravity] of [
      [1e30, 0],
      [0, 1e30],
      [1e20, -1e25],
    ]) {
      const [hash, begins] = run('hashgrid', vx, gravity);
      expect(begins.every(([a, b]) => a !== b), `${vx} ${gravity}`).toBe(true);
      expect([hash, begins], `${vx} ${gravity}`).toEqual(run('naive', vx, gravity));
    }
    // Rows rounded together (cy + 1 === cy): the cell to the left's (+1, 0) and this cell's
    // (-1, +1) are the same two cells, and the pair was found twice.
    const twice = (broadphase: 'naive' | 'hashgrid'): [string, number] => {
      const world = new World({ bounds: { width: 60, height: 40 }, solver: 'elastic', broadphase, maxLinearSpeed: 1e100 });
      world.createCircle({ x: 7.276616344228387, y: 4.488070164807141, radius: 0.2548282613279298 });
      world.setGravity(4.74199419375509, -1e30);
      world.createBox({ x: 5.181496420875192, y: 24.45201675593853, vx: 7.637305185198784, vy: -9.563489649444818, width: 3.4213730142917482, height: 0.5781265089288354 });
      world.step(1 / 30);
      return [world.stateHash(), world.stats.candidatePairs];
    };
    expect(twice('hashgrid')).toEqual(twice('naive'));
  });

  it('examines as few pairs per body with two crowds a million units apart as Max Grid does with the crowds side by side', () => {
    const build = (broadphase: 'hashgrid' | 'maxgrid', apart: number) => {
      const world = new World({ broadphase });
      for (let k = 0; k < 3000; k++) {
        const off = k < 1500 ? 0 : apart;
        const j = k % 1500;
        world.createCircle({ x: off + (j % 50) * 9, y: off + Math.floor(j / 50) * 9, radius: 2, vx: (k % 7) - 3, vy: (k % 5) - 2 });
      }
      world.step(1 / 60);
      return world;
    };
    const near = build('maxgrid', 500);
    const far = build('hashgrid', 1e6);
    const farGrid = build('maxgrid', 1e6);
    expect(far.stats.pairTests).toBeLessThan(2 * near.stats.pairTests);
    expect(farGrid.stats.pairTests).toBeGreaterThan(100 * far.stats.pairTests);
    expect(far.stateHash()).toBe(farGrid.stateHash());
  });
});

describe('mixed sizes (report 3.2: Max Grid degrades when sizes differ by an order of magnitude)', () => {
  it('hgrid examines far fewer pairs than maxgrid at a radius ratio of 1:100, and auto follows it', async () => {
    const { buildScene, buildWorld } = await import('@maxgrid/scenes');
    const scene = buildScene('mixed', { n: 4000, seed: 2, ratio: 100, largeFraction: 0.002 });
    const tests: Record<string, number> = {};
    const contacts: Record<string, number> = {};
    for (const broadphase of ['maxgrid', 'hgrid', 'auto'] as const) {
      const world = buildWorld(scene, { broadphase });
      world.step(1 / 60);
      tests[broadphase] = world.stats.pairTests;
      contacts[broadphase] = world.stats.contacts;
    }
    expect(tests.hgrid * 10).toBeLessThan(tests.maxgrid);
    expect(tests.auto).toBe(tests.hgrid);
    expect(contacts.hgrid).toBe(contacts.maxgrid);
  });

  it.each([
    // A few large circles among many small: pairs across levels are found from each large one, through the window of small cells it reaches.
    ['few large circles (windows from the coarse side)', { n: 3000, seed: 4, ratio: 100, largeFraction: 0.003, maxSpeed: 400 }],
  ])('hgrid steps %s to the same state as maxgrid, with contacts across levels', async (_label, params) => {
    const { buildScene, buildWorld } = await import('@maxgrid/scenes');
    const scene = buildScene('mixed', params);
    const hgrid = buildWorld(scene, { broadphase: 'hgrid' });
    const grid = buildWorld(scene, { broadphase: 'maxgrid' });
    const large = Math.round(params.n * params.largeFraction);
    let across = 0;
    for (let s = 0; s < 120; s++) {
      hgrid.step(1 / 60);
      grid.step(1 / 60);
      // Large circles are created first: slots below `large`. A contact across levels pairs one with a small circle.
      const { lo, hi, count } = (hgrid as unknown as { pipeline: { contacts: { lo: Int32Array; hi: Int32Array; count: number } } }).pipeline.contacts;
      for (let k = 0; k < count; k++) if (lo[k] < large && hi[k] >= large) across++;
      expect(hgrid.stats.contacts).toBe(grid.stats.contacts);
    }
    expect(across).toBeGreaterThan(10);
    // Small and large circles on levels of their own, so those contacts came from lookups across levels.
    expect((hgrid as unknown as { pipeline: { broadPhase: { levelCount: number } } }).pipeline.broadPhase.levelCount).toBeGreaterThan(1);
    expect(hgrid.stateHash()).toBe(grid.stateHash());
  });

  it('hgrid steps many coarse circles over a crowd of small ones (3x3 lookups from the fine side) to the same state as maxgrid', async () => {
    const { World } = await import('../src/index.js');
    // 3,000 circles of radius 1 packed in a patch, 400 of radius 20 on a lattice over it and around:
    // a window of fine cells per large circle would cost more than three coarse rows per small one.
    const build = (broadphase: 'hgrid' | 'maxgrid') => {
      const world = new World({ broadphase, bounds: { width: 900, height: 900 } });
      for (let k = 0; k < 400; k++) world.createCircle({ x: 30 + (k % 20) * 41, y: 30 + Math.floor(k / 20) * 41, radius: 20, vx: (k % 5) * 20 - 40 });
      for (let k = 0; k < 3000; k++) world.createCircle({ x: 300 + (k % 55) * 2.5, y: 300 + Math.floor(k / 55) * 2.5, radius: 1, vy: (k % 3) * 30 - 30 });
      return world;
    };
    const hgrid = build('hgrid');
    const grid = build('maxgrid');
    let across = 0;
    for (let s = 0; s < 60; s++) {
      hgrid.step(1 / 60);
      grid.step(1 / 60);
      const { lo, hi, count } = (hgrid as unknown as { pipeline: { contacts: { lo: Int32Array; hi: Int32Array; count: number } } }).pipeline.contacts;
      for (let k = 0; k < count; k++) if (lo[k] < 400 && hi[k] >= 400) across++;
      expect(hgrid.stats.contacts).toBe(grid.stats.contacts);
    }
    expect(across).toBeGreaterThan(100);
    expect((hgrid as unknown as { pipeline: { broadPhase: { levelCount: number } } }).pipeline.broadPhase.levelCount).toBe(2);
    expect(hgrid.stateHash()).toBe(grid.stateHash());
  });

  it('hgrid groups the twenty radius classes of log-uniform radii over six decades into a few levels, with the contacts of a sweep', async () => {
    const { buildScene, buildWorld } = await import('@maxgrid/scenes');
    const scene = buildScene('uniform', { n: 6000, seed: 3, logRadius: 1, minRadius: 0.01, maxRadius: 1e4 });
    const hgrid = buildWorld(scene, { broadphase: 'hgrid' });
    const sap = buildWorld(scene, { broadphase: 'sap' });
    for (let s = 0; s < 5; s++) {
      hgrid.step(1 / 60);
      sap.step(1 / 60);
      expect(hgrid.stats.contacts).toBe(sap.stats.contacts);
    }
    const broad = (hgrid as unknown as { pipeline: { broadPhase: { levelCount: number } } }).pipeline.broadPhase;
    // One class per power of two would be 21 levels (each a lookup per finer body); the classes
    // whose cells the budget enlarges anyway share the first.
    expect(broad.levelCount).toBeGreaterThan(1);
    expect(broad.levelCount).toBeLessThanOrEqual(6);
    expect(hgrid.stats.contacts).toBeGreaterThan(20);
    expect(hgrid.stats.pairTests).toBeLessThan(10 * 6000);
  });

  it("hgrid's radius class is the least c with r <= rmin 2^c, as exact doubling finds it", () => {
    const doubling = (r: number, rmin: number) => {
      let c = 0;
      for (let limit = rmin; limit < r; limit *= 2) c++;
      return c;
    };
    fc.assert(
      fc.property(fc.double({ min: 1e-100, max: 1e100, noNaN: true }), fc.double({ min: 1, max: 1e30, noNaN: true }), (rmin, spread) => {
        const r = Math.min(rmin * spread, 1e100);
        expect(radiusClass(r, rmin)).toBe(doubling(r, rmin));
        // Exactly at a power of two, and just above it.
        const edge = rmin * 2 ** 7;
        expect(radiusClass(edge, rmin)).toBe(7);
        expect(radiusClass(edge * (1 + 2 ** -52), rmin)).toBe(8);
      }),
      { numRuns: 2000, seed: 11 },
    );
  });

  it('hgrid gives every power of two in a radius spread of 2^40 a class (none folds into a top level), and groups classes only where a grid of their own would be no finer', async () => {
    const { World } = await import('../src/index.js');
    // 1,500 circles of radius 10 on a lattice, one of 2^-30 times that, and 50 of 640 far off: a
    // level limit of 24 classes would put the radius-10 circles in the 640s' cells, 1,280 wide.
    const build = (broadphase: 'hgrid' | 'sap') => {
      const world = new World({ broadphase });
      world.createCircle({ x: -50, y: -50, radius: 10 / 2 ** 30 });
      for (let k = 0; k < 1500; k++) world.createCircle({ x: (k % 40) * 19, y: Math.floor(k / 40) * 19, radius: 10, vx: (k % 7) - 3 });
      for (let k = 0; k < 50; k++) world.createCircle({ x: 5000 + (k % 10) * 1300, y: 5000 + Math.floor(k / 10) * 1300, radius: 640 });
      return world;
    };
    const world = build('hgrid');
    const reference = build('sap');
    for (let s = 0; s < 3; s++) {
      world.step(1 / 60);
      reference.step(1 / 60);
      expect(world.stats.pairTests).toBeLessThan(10 * world.bodyCount);
      expect(world.stats.contacts).toBe(reference.stats.contacts);
    }
    expect(world.stats.contacts).toBeGreaterThan(1000);
    expect(world.stateHash()).toBe(reference.stateHash());
  });

  it('hgrid re-buckets its levels when bodies come and go, and stays with maxgrid', async () => {
    const { World } = await import('../src/index.js');
    const build = (broadphase: 'hgrid' | 'maxgrid') => {
      const world = new World({ broadphase, bounds: { width: 600, height: 600 } });
      for (let k = 0; k < 400; k++) world.createCircle({ x: 15 + (k % 20) * 28, y: 15 + Math.floor(k / 20) * 28, radius: 3 + (k % 3), vx: (k % 7) * 20 - 60, vy: (k % 5) * 20 - 40 });
      return world;
    };
    const worlds = [build('hgrid'), build('maxgrid')];
    for (let s = 0; s < 60; s++) {
      for (const world of worlds) {
        // Step 10: larger circles (a new level, and the smallest radius changes); 30: holes; 45: a smaller circle.
        if (s === 10) for (let k = 0; k < 6; k++) world.createCircle({ x: 80 + k * 90, y: 300, radius: 30, vx: 50, vy: -50 });
        if (s === 30) for (let h = 0; h < 400; h += 3) world.destroyBody(h);
        if (s === 45) world.createCircle({ x: 300, y: 590, radius: 1, vy: -300 });
        world.step(1 / 60);
      }
      expect(worlds[0].stats.contacts, `step ${s}`).toBe(worlds[1].stats.contacts);
    }
    expect(worlds[0].stateHash()).toBe(worlds[1].stateHash());
  });

  it('auto uses maxgrid when sizes are similar', async () => {
    const { buildScene, buildWorld } = await import('@maxgrid/scenes');
    const scene = buildScene('uniform', { n: 2000, seed: 2 });
    const auto = buildWorld(scene, { broadphase: 'auto' });
    const grid = buildWorld(scene, { broadphase: 'maxgrid' });
    // No grid before the first build: null, not a grid of zero cells.
    expect(grid.gridGeometry()).toBeNull();
    expect(auto.gridGeometry()).toBeNull();
    auto.step(1 / 60);
    grid.step(1 / 60);
    expect(grid.gridGeometry()!.columns).toBeGreaterThan(0);
    expect(auto.stats.pairTests).toBe(grid.stats.pairTests);
    expect(auto.gridGeometry()).toEqual(grid.gridGeometry());
  });
});

describe('auto, when the grid examines too much (two crowds far apart make its cells huge)', () => {
  it('turns to the hashed grid, keeps the bits, and goes back to the grid once it pays again', () => {
    // Two crowds of 1500, a million units apart: neither is an outlier the extent can leave out,
    // so a grid of about one cell per body has cells far larger than either crowd.
    const build = (broadphase: 'auto' | 'maxgrid') => {
      const world = new World({ broadphase });
      const far: number[] = [];
      for (let k = 0; k < 3000; k++) {
        const off = k < 1500 ? 0 : 1e6;
        const j = k % 1500;
        const handle = world.createCircle({ x: off + (j % 50) * 9, y: off + Math.floor(j / 50) * 9, radius: 2, vx: (k % 7) - 3, vy: (k % 5) - 2 });
        if (k >= 1500) far.push(handle);
      }
      return { world, far };
    };
    const auto = build('auto');
    const grid = build('maxgrid');
    auto.world.step(1 / 60);
    grid.world.step(1 / 60);
    // The grid examined each crowd's pairs in a cell or two: about 2 * 1500 * 1499 / 2.
    expect(auto.world.stats.pairTests).toBeGreaterThan(64 * 3000);
    for (let s = 0; s < 5; s++) {
      auto.world.step(1 / 60);
      grid.world.step(1 / 60);
      expect(auto.world.gridGeometry()).toBeNull();
      expect(broadPhaseOf(auto.world)).toBe('hashgrid');
      expect(auto.world.stats.pairTests).toBeLessThan(grid.world.stats.pairTests / 100);
      expect(auto.world.stateHash()).toBe(grid.world.stateHash());
    }
    // With one crowd left the grid fits it again: after the wait, auto retries it and keeps it.
    for (const h of auto.far) auto.world.destroyBody(h);
    for (let s = 0; s < 70; s++) auto.world.step(1 / 60);
    expect(auto.world.gridGeometry()).not.toBeNull();
    expect(auto.world.stats.pairTests).toBeLessThan(10 * 1500);
  });

  it('keeps the grid when a few bodies are far away: the extent leaves them out', () => {
    const world = new World({ broadphase: 'auto' });
    for (let k = 0; k < 3000; k++) world.createCircle({ x: (k % 60) * 9, y: Math.floor(k / 60) * 9, radius: 2, vx: (k % 7) - 3, vy: (k % 5) - 2 });
    world.createCircle({ x: 1e6, y: 1e6, radius: 2 });
    world.createCircle({ x: -1e6, y: 5e5, radius: 2 });
    for (let s = 0; s < 5; s++) world.step(1 / 60);
    const geometry = world.gridGeometry()!;
    expect(geometry).not.toBeNull();
    // Cells about the crowd's spacing, not the outliers' million units.
    expect(geometry.cellSize).toBeLessThan(100);
    expect(world.stats.pairTests).toBeLessThan(10 * 3000);
  });

  it('turns to the persistent sweep where sizes crowd the hashed cells too, and keeps the bits', () => {
    // Two crowds a million units apart, each of small circles among a few large ones: cells as
    // wide as the large ones hold dozens of small ones.
    const build = (broadphase: 'auto' | 'maxgrid') => {
      const world = new World({ broadphase });
      for (let k = 0; k < 3000; k++) {
        const off = k < 1500 ? 0 : 1e6;
        const j = k % 1500;
        world.createCircle({ x: off + (j % 50) * 9, y: off + Math.floor(j / 50) * 9, radius: j % 300 === 0 ? 60 : 2, vx: (k % 7) - 3, vy: (k % 5) - 2 });
      }
      return world;
    };
    const auto = build('auto');
    const grid = build('maxgrid');
    const used: string[] = [];
    const examined: number[] = [];
    for (let s = 0; s < 5; s++) {
      auto.step(1 / 60);
      grid.step(1 / 60);
      used.push(broadPhaseOf(auto));
      examined.push(auto.stats.pairTests);
      expect(auto.stateHash()).toBe(grid.stateHash());
    }
    // What auto chose after each step: the grid examined hundreds of pairs per body, the hashed
    // grid half as many, and the sweep a fiftieth.
    expect(used).toEqual(['hashgrid', 'sap-persistent', 'sap-persistent', 'sap-persistent', 'sap-persistent']);
    expect(examined[1]).toBeGreaterThan(examined[0] / 4);
    expect(examined[4]).toBeLessThan(examined[0] / 8);
  });

  it('goes back to the grid when its replacement examines about as much (every body bursting from one spot)', () => {
    const worlds = (['auto', 'maxgrid'] as const).map((broadphase) => {
      const world = new World({ broadphase });
      for (let k = 0; k < 1000; k++) world.createCircle({ x: (k % 31) / 16, y: Math.floor(k / 31) / 16, radius: 1 });
      return world;
    });
    const used: string[] = [];
    for (let s = 0; s < 6; s++) {
      for (const world of worlds) world.step(1 / 60);
      used.push(broadPhaseOf(worlds[0]));
      expect(worlds[0].stateHash()).toBe(worlds[1].stateHash());
    }
    // One step on the sweep, which examined nearly as many pairs as the grid, then the grid again.
    expect(used[0]).toBe('sap-persistent');
    expect(used.slice(2).every((name) => name === 'hgrid')).toBe(true);
  });

  it('goes back to Max Grid when the hashed grid and the sweep examine about as much (a crowd in one spot among bodies spread wide)', () => {
    // Max Grid caps its cells at about 4 per body, so over the spread bodies' extent its cells
    // are some 7 times the diameter and the crowd fills one; the hashed cells are the diameter
    // itself, and the crowd, a point, still fills one.
    const worlds = (['auto', 'maxgrid'] as const).map((broadphase) => {
      const world = new World({ broadphase });
      for (let k = 0; k < 1000; k++) world.createCircle({ x: (k % 32) * 30, y: Math.floor(k / 32) * 30, radius: 1 });
      for (let k = 0; k < 600; k++) world.createCircle({ x: 480 + (k % 25) / 100, y: 480 + Math.floor(k / 25) / 100, radius: 1 });
      return world;
    });
    const used: string[] = [];
    for (let s = 0; s < 4; s++) {
      for (const world of worlds) world.step(1 / 60);
      used.push(broadPhaseOf(worlds[0]));
      expect(worlds[0].stateHash()).toBe(worlds[1].stateHash());
    }
    // What auto chose after each step: the hashed grid, then the sweep, then the grid again.
    expect(used).toEqual(['hashgrid', 'sap-persistent', 'maxgrid', 'maxgrid']);
  });
});

describe('the default broad-phase where a grid used to fall off a cliff', () => {
  const crowd = (world: World, n: number, x0: number, y0: number) => {
    for (let k = 0; k < n; k++) world.createCircle({ x: x0 + (k % 60) * 9, y: y0 + Math.floor(k / 60) * 9, radius: 2, vx: (k % 7) - 3, vy: (k % 5) - 2 });
  };
  it.each([
    ['a few bodies a million units away', 10, () => {
      const world = new World();
      crowd(world, 3000, 0, 0);
      for (let k = 0; k < 4; k++) world.createCircle({ x: 1e6 + 10 * k, y: -1e6, radius: 2 });
      return world;
    }],
    ['a crowd in the corner of a huge box', 10, () => {
      const world = new World({ bounds: { width: 1e5, height: 1e5 } });
      crowd(world, 3000, 10, 10);
      return world;
    }],
    // The grid's cells span both crowds: auto hashes its cells instead.
    ['two crowds a million units apart', 10, () => {
      const world = new World();
      crowd(world, 1500, 0, 0);
      crowd(world, 1500, 1e6, 1e6);
      return world;
    }],
    ['radii log-uniform over six decades', 10, () => {
      const world = new World({ bounds: { width: 2e5, height: 2e5 } });
      let u = 1;
      for (let k = 0; k < 3000; k++) {
        u = (u * 16807) % 2147483647;
        world.createCircle({ x: 1e4 + (k % 55) * 3300, y: 1e4 + Math.floor(k / 55) * 3300, radius: 0.01 * 1e6 ** (u / 2147483647) });
      }
      return world;
    }],
  ] as const)('examines few pairs per body with %s (at most %i)', (_label, perBody, build) => {
    const world = build();
    expect(world.broadphase).toBe('auto');
    for (let s = 0; s < 4; s++) world.step(1 / 60);
    expect(world.stats.pairTests).toBeLessThan(perBody * world.bodyCount);
  });
});

describe('static bodies in the sweeps', () => {
  const SWEEPS = ['sap', 'sap-persistent', 'sap-xy'] as const;
  const typed = fc.array(
    fc.record({
      x: fc.double({ min: -300, max: 300, noNaN: true }),
      y: fc.double({ min: -300, max: 300, noNaN: true }),
      r: fc.double({ min: 0.01, max: 60, noNaN: true }),
      type: fc.constantFrom(TypeCode.dynamic, TypeCode.static, TypeCode.kinematic),
    }),
    { maxLength: 120 },
  );

  it.each(BROADPHASE_NAMES)('%s reports every overlapping pair with a moving body, among statics, kinematics and flips', (name) => {
    fc.assert(
      fc.property(typed, fc.array(fc.nat(120), { maxLength: 10 }), (list, flips) => {
        const store = storeOf(list);
        list.forEach((c, k) => store.setTypeCode(k, c.type));
        const phase = BROADPHASES[name]();
        // Twice, with bodies turned static or moving in between: a persistent order must follow.
        for (let round = 0; round < 2; round++) {
          if (round === 1) for (const k of flips) if (k < list.length) store.setTypeCode(k, store.type[k] === TypeCode.static ? TypeCode.dynamic : TypeCode.static);
          const collector = new Collector();
          const sink = new PairSink(collector, () => 0);
          sink.begin();
          phase.findPairs(store, sink);
          sink.flush();
          const found = new Set(collector.pairs);
          expect(found.size).toBe(collector.pairs.length);
          for (let i = 0; i < list.length; i++) {
            for (let j = i + 1; j < list.length; j++) {
              const bothStatic = store.type[i] === TypeCode.static && store.type[j] === TypeCode.static;
              if (bothStatic && (SWEEPS as readonly string[]).includes(name)) expect(found.has(`${i},${j}`)).toBe(false);
              const dx = store.x[j] - store.x[i];
              const dy = store.y[j] - store.y[i];
              const reach = store.radius[i] + store.radius[j];
              if (!bothStatic && dx * dx + dy * dy <= reach * reach) expect(found.has(`${i},${j}`)).toBe(true);
            }
          }
        }
      }),
      { numRuns: 120, seed: 31 },
    );
  });

  it.each([...SWEEPS, 'maxgrid', 'hgrid', 'auto'] as const)('%s examines no static-static pair in a wall of 5,000 overlapping static circles', (broadphase) => {
    const world = new World({ broadphase, bounds: { width: 2000, height: 2000 } });
    for (let k = 0; k < 5000; k++) world.createCircle({ x: 1000, y: 10 + 0.39 * k, radius: 2, type: 'static' });
    for (let k = 0; k < 200; k++) world.createCircle({ x: 20 + 4.5 * k, y: 10 + 9 * k, radius: 2, vx: 300 });
    for (let s = 0; s < 3; s++) world.step(1 / 60);
    // Each static overlaps about ten others on either axis; only the moving bodies' pairs remain.
    expect(world.stats.pairTests).toBeLessThan(2 * world.bodyCount);
    for (let s = 0; s < 40; s++) world.step(1 / 60);
    const movers = world.handles().filter((h) => world.getCircle(h).type === 'dynamic').map((h) => world.getCircle(h));
    expect(movers.every((c) => c.x < 1000)).toBe(true);
    expect(movers.filter((c) => c.vx < 0).length).toBeGreaterThan(20);
  });

  it('a slow circle meets static circles added, moved or turned static between steps, and passes where one was removed', () => {
    const run = (change: (world: World, post: number) => void) => {
      const world = new World({ restitution: 1 });
      const ball = world.createCircle({ x: 0, y: 0, radius: 1, vx: 30 });
      const post = world.createCircle({ x: 50, y: 50, radius: 1, type: 'static' });
      world.step(1 / 60);
      change(world, post);
      for (let s = 0; s < 60; s++) world.step(1 / 60);
      return world.getCircle(ball).vx;
    };
    expect(run(() => {})).toBe(30);
    expect(run((world, post) => world.setPosition(post, 5, 0))).toBe(-30);
    expect(run((world) => world.createCircle({ x: 5, y: 0, radius: 1, type: 'static' }))).toBe(-30);
    expect(run((world) => world.setType(world.createCircle({ x: 5, y: 0, radius: 1, type: 'kinematic' }), 'static'))).toBe(-30);
    expect(run((world, post) => {
      world.setPosition(post, 5, 0);
      world.step(1 / 60);
      world.destroyBody(post);
    })).toBe(30);
  });

  it('sap-xy needs memory linear in the bodies when they all overlap on x, and sweeps y instead', () => {
    const column = (broadphase: 'sap' | 'sap-xy') => {
      const world = new World({ broadphase });
      for (let k = 0; k < 3000; k++) world.createCircle({ x: (k % 3) * 0.5, y: 3.9 * k, radius: 2 });
      world.step(1 / 60);
      return world;
    };
    const xy = column('sap-xy');
    const sap = column('sap');
    expect(sap.stats.candidatePairs).toBe((3000 * 2999) / 2);
    expect(xy.stats.contacts).toBe(sap.stats.contacts);
    expect(xy.stats.contacts).toBeGreaterThan(1000);
    expect(xy.stateHash()).toBe(sap.stateHash());
    expect(xy.stats.pairTests).toBeLessThan(3 * xy.bodyCount);
    expect(xy.memoryBytes()).toBeLessThan(1.5 * sap.memoryBytes());
  });
});

describe('sap-persistent (Tracy, Buss & Woods 2009)', () => {
  it('restores order with little work when bodies move little, and falls back to a full sort after a teleport', async () => {
    const { buildScene, buildWorld } = await import('@maxgrid/scenes');
    const world = buildWorld(buildScene('uniform', { n: 3000, seed: 5 }), { broadphase: 'sap-persistent' });
    const sap = buildWorld(buildScene('uniform', { n: 3000, seed: 5 }), { broadphase: 'sap' });
    for (let s = 0; s < 30; s++) {
      world.step(1 / 60);
      sap.step(1 / 60);
    }
    const internal = (world as unknown as { pipeline: { broadPhase: { lastShifts: number } } }).pipeline.broadPhase;
    // About one neighbour passed per body per step at this density; a random order would need ~n^2/4.
    expect(internal.lastShifts).toBeLessThan(3 * 3000);
    expect(world.stats.candidatePairs).toBe(sap.stats.candidatePairs);
    for (const h of world.handles().slice(0, 1500)) world.setPosition(h, world.box!.width - 10, world.getCircle(h).y);
    world.step(1 / 60);
    expect(world.stats.contacts).toBeGreaterThan(0);
  });

  it('pairs of sleepers are not passed on', async () => {
    const { World } = await import('../src/index.js');
    const build = (broadphase: 'naive' | 'sap-persistent') => {
      const world = new World({ broadphase, sleeping: true, gravity: { x: 0, y: 100 }, bounds: { width: 400, height: 50 }, restitution: 0, sleepTime: 0.1 });
      for (let k = 0; k < 50; k++) world.createCircle({ x: 4 + k * 7.9, y: 46, radius: 4 });
      for (let s = 0; s < 60; s++) world.step(1 / 60);
      return world;
    };
    const persistent = build('sap-persistent');
    const plain = build('naive');
    expect(persistent.stats.sleepingBodies).toBe(50);
    expect(persistent.stats.candidatePairs).toBe(0);
    expect(plain.stats.candidatePairs).toBeGreaterThan(40);
    expect(persistent.stateHash()).toBe(plain.stateHash());
  });
});
