import { afterEach, describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { buildScene, buildWorld } from '@maxgrid/scenes';
import { World, type WorldOptions } from '../src/index.js';
import type { BodyStore } from '../src/store/body-store.js';
import { CellGrid } from '../src/broadphase/cell-grid.js';
import { ARENA_LIMIT_BYTES, CELL_CHUNK, GridKernel, bandedBin, setGridKernelEnabled } from '../src/broadphase/grid-kernel.js';
import { BodyKernel } from '../src/store/body-kernel.js';
import type { PairSink } from '../src/store/pair-sink.js';
import { storeOf, hashWithPath } from './helpers.js';

// The grid's WebAssembly kernel must be the TypeScript loops bit for bit: same pairs in the same
// order, so every world steps to the same state whichever path its grids took.

const BANDED_DEFAULTS = { ...bandedBin };

afterEach(() => {
  setGridKernelEnabled(true);
  Object.assign(bandedBin, BANDED_DEFAULTS);
});

/** A grid made with the kernel on or off. */
function gridWith(kernel: boolean): CellGrid {
  setGridKernelEnabled(kernel);
  const grid = new CellGrid();
  setGridKernelEnabled(true);
  return grid;
}

function pairsOf(grid: CellGrid, store: BodyStore, cellSize: number): { pairs: number[]; examined: number } {
  const pairs: number[] = [];
  const sink = { push: (a: number, b: number) => pairs.push(a, b) } as unknown as PairSink;
  let minX = Infinity;
  let minY = Infinity;
  let maxX = -Infinity;
  let maxY = -Infinity;
  for (let i = 0; i < store.slotCount; i++) {
    minX = Math.min(minX, store.x[i]);
    maxX = Math.max(maxX, store.x[i]);
    minY = Math.min(minY, store.y[i]);
    maxY = Math.max(maxY, store.y[i]);
  }
  grid.build(store, null, 0, store.slotCount, minX, minY, maxX, maxY, cellSize, 4 * store.slotCount + 64);
  const examined = grid.scanSelf(sink, 0);
  return { pairs, examined };
}

function runHash(build: () => World, steps: number, kernel: boolean, mutate?: (world: World, step: number) => void): string {
  return hashWithPath(setGridKernelEnabled, kernel, build, steps, mutate);
}

/**
 * A serial and a shared kernel (`threads` pair regions) laid out for n bodies over `cells` cells,
 * `prepare` run on the shared one (it may move its arrays), both given the same n random circles
 * over columns x rows unit cells from `seed`, sorted by row if asked; and `random` to go on with.
 */
function kernelPair(n: number, threads: number, columns: number, rows: number, sortedByRow: boolean, seed: number, prepare?: (parallel: GridKernel) => void) {
  let state = seed;
  const random = () => ((state = (Math.imul(state, 1103515245) + 12345) >>> 0) / 2 ** 32);
  const x = Float64Array.from({ length: n }, () => random() * columns);
  const y = Float64Array.from({ length: n }, () => random() * rows);
  const r = Float64Array.from({ length: n }, () => 0.1 + random());
  if (sortedByRow) y.sort();
  const serial = GridKernel.create(false)!;
  const parallel = GridKernel.create(true, threads)!;
  for (const kernel of [serial, parallel]) {
    kernel.ensure(n, columns * rows);
    kernel.ensureInputs(n);
  }
  prepare?.(parallel);
  for (const kernel of [serial, parallel]) {
    kernel.inputX.set(x);
    kernel.inputY.set(y);
    kernel.inputR.set(r);
  }
  return { serial, parallel, random };
}

/** The parallel kernel's layout (its end sentinels set here) is the serial one's, for n bodies over `cells` cells. */
function expectSameLayout(parallel: GridKernel, serial: GridKernel, n: number, cells: number): void {
  parallel.cellStart[cells] = n;
  parallel.cellStart[cells + 1] = n;
  expect(parallel.cellStart.subarray(0, cells + 2)).toEqual(serial.cellStart.subarray(0, cells + 2));
  expect(parallel.sortedSlot.subarray(0, n)).toEqual(serial.sortedSlot.subarray(0, n));
  expect(parallel.sortedX.subarray(0, n)).toEqual(serial.sortedX.subarray(0, n));
  expect(parallel.sortedY.subarray(0, n)).toEqual(serial.sortedY.subarray(0, n));
  expect(parallel.sortedR.subarray(0, n)).toEqual(serial.sortedR.subarray(0, n));
}

describe('grid WebAssembly kernel', () => {
  it('runs in this runtime (so the comparisons below compare two paths)', () => {
    const store = storeOf([
      { x: 0, y: 0, r: 1 },
      { x: 1.5, y: 0, r: 1 },
    ]);
    const on = gridWith(true);
    const off = gridWith(false);
    expect(pairsOf(on, store, 2).pairs).toEqual([0, 1]);
    expect(pairsOf(off, store, 2).pairs).toEqual([0, 1]);
    expect(on.usesKernel).toBe(true);
    expect(off.usesKernel).toBe(false);
  });

  it('finds the same pairs in the same order, and examines as many, as the TypeScript loops', () => {
    const circle = fc.record({
      x: fc.double({ min: -500, max: 500, noNaN: true }),
      y: fc.double({ min: -500, max: 500, noNaN: true }),
      r: fc.double({ min: 0.5, max: 20, noNaN: true }),
    });
    // One pair of grids reused across cases, so that layouts grow and shrink between builds.
    const on = gridWith(true);
    const off = gridWith(false);
    fc.assert(
      fc.property(fc.array(circle, { minLength: 2, maxLength: 300 }), (list) => {
        const store = storeOf(list);
        const cell = 2 * Math.max(...list.map((c) => c.r)) * (1 + 2 ** -20);
        const a = pairsOf(on, store, cell);
        const b = pairsOf(off, store, cell);
        expect(a.pairs).toEqual(b.pairs);
        expect(a.examined).toBe(b.examined);
      }),
      { numRuns: 60 },
    );
  });

  it('grows its pair buffer past the first 1,024 pairs and still returns every pair', () => {
    // 2,500 circles on a 50x50 lattice, each touching its 8 neighbours: 9,702 pairs.
    const list = [];
    for (let i = 0; i < 50; i++) for (let j = 0; j < 50; j++) list.push({ x: i * 1.5, y: j * 1.5, r: 1.1 });
    const store = storeOf(list);
    const a = pairsOf(gridWith(true), store, 2.2 * (1 + 2 ** -20));
    const b = pairsOf(gridWith(false), store, 2.2 * (1 + 2 ** -20));
    expect(a.pairs.length / 2).toBe(2 * 49 * 50 + 2 * 49 * 49);
    expect(a.pairs).toEqual(b.pairs);
  });

  const scenes: [string, string, number, WorldOptions['broadphase']][] = [
    ['uniform', 'maxgrid', 3000, 'maxgrid'],
    ['seed-box', 'maxgrid', 2000, 'maxgrid'],
    ['mixed', 'hgrid', 3000, 'hgrid'],
    ['mixed', 'auto', 3000, 'auto'],
  ];
  it.each(scenes)('steps scene %s with %s to the same state hash with and without the kernel', (scene, _label, n, broadphase) => {
    const build = () => buildWorld(buildScene(scene, { n, seed: 7 }), { broadphase });
    expect(runHash(build, 40, true)).toBe(runHash(build, 40, false));
  });

  it('agrees when a destroyed body\'s slot is reused at once by a larger body (the radii it copies must follow)', () => {
    const build = () => buildWorld(buildScene('uniform', { n: 1500, seed: 9 }), { broadphase: 'maxgrid' });
    const mutate = (world: World, step: number) => {
      if (step % 3 !== 1) return;
      const handle = world.handles()[(step * 53) % 1500];
      const { x, y } = world.getCircle(handle);
      const { width, height } = world.box!;
      world.destroyBody(handle);
      // Up to the largest radius in the scene, so the grid's cells stay the same size.
      world.createCircle({ x: Math.min(Math.max(x, 8), width - 8), y: Math.min(Math.max(y, 8), height - 8), radius: 8, vx: -40, vy: 25 });
    };
    expect(runHash(build, 45, true, mutate)).toBe(runHash(build, 45, false, mutate));
  });

  it('agrees through growth, holes and an unbounded world', () => {
    const build = () => {
      const world = new World({ broadphase: 'maxgrid', gravity: { x: 0, y: -50 } });
      for (let i = 0; i < 400; i++) world.createCircle({ x: (i % 20) * 9, y: Math.floor(i / 20) * 9, radius: 4 + (i % 3), vx: (i % 7) - 3, vy: (i % 5) - 2 });
      return world;
    };
    const mutate = (world: World, step: number) => {
      // Step 10: twice as many bodies (the kernel's arrays move); step 20: holes (the slot-list bin).
      if (step === 10) for (let i = 0; i < 400; i++) world.createCircle({ x: 200 + (i % 20) * 9, y: (i / 20) * 9, radius: 5 });
      if (step === 20) for (let h = 0; h < 800; h += 7) world.destroyBody(h);
    };
    expect(runHash(build, 40, true, mutate)).toBe(runHash(build, 40, false, mutate));
  });
  it('lays out a parallel bin (cells per body share, count and scatter per band) exactly as one serial bin', () => {
    // The threads' passes run here one after another. Small grids put band edges inside many
    // chunks of CELL_CHUNK bodies; bodies sorted by row make most chunks lie inside one band, as a
    // world created row by row does, and shuffled ones make every chunk span bands.
    const columns = 9;
    const rows = 7;
    const cells = columns * rows;
    fc.assert(
      fc.property(
        fc.integer({ min: 1, max: 5 * CELL_CHUNK + 300 }),
        fc.integer({ min: 1, max: 5 }),
        fc.boolean(),
        fc.integer({ min: 0, max: 2 ** 31 - 1 }),
        (n, threads, sortedByRow, seed) => {
          const { serial, parallel, random } = kernelPair(n, threads, columns, rows, sortedByRow, seed);
          serial.bin(n, false, 0, 0, 1, columns, cells);
          // Body shares cut on chunk boundaries, as the threads' motion cuts them.
          const cut = (t: number) => (t === threads ? n : Math.floor(Math.floor((n * t) / threads) / CELL_CHUNK) * CELL_CHUNK);
          for (let t = 0; t < threads; t++) parallel.cellsOf(cut(t), cut(t + 1), 0, 0, 1, columns, rows);
          // Bands of cells cut where threads cut them, and also right at chunks' extremes, where
          // "this chunk lies inside the band" and "this chunk misses it" change.
          const edges = new Set([0, cells]);
          for (let t = 1; t < threads; t++) edges.add(Math.floor((cells * t) / threads));
          const chunkCells = parallel.chunkCells;
          for (let e = 0; e < 2 * Math.ceil(n / CELL_CHUNK); e++) if (random() < 0.4) edges.add(chunkCells[e] + Math.floor(random() * 3) - 1);
          const band = [...edges].filter((cell) => cell >= 0 && cell <= cells).sort((a, b) => a - b);
          const mine: number[] = [];
          for (let t = 0; t + 1 < band.length; t++) mine.push(parallel.countCells(n, band[t], band[t + 1]));
          let before = 0;
          for (let t = 0; t + 1 < band.length; t++) {
            parallel.scatterCells(n, band[t], band[t + 1], before);
            before += mine[t];
          }
          expect(before).toBe(n);
          expectSameLayout(parallel, serial, n, cells);
        },
      ),
      { numRuns: 60 },
    );
  });
  it('lays out a banded parallel bin (band counts and partition per share, bands sorted in any order) exactly as one serial bin', () => {
    let compared = 0;
    fc.assert(
      fc.property(
        fc.integer({ min: 1, max: 4 * CELL_CHUNK + 300 }),
        fc.integer({ min: 1, max: 5 }),
        fc.integer({ min: 1, max: 50 }),
        fc.boolean(),
        fc.integer({ min: 0, max: 2 ** 31 - 1 }),
        (n, threads, perBand, sortedByRow, seed) => {
          bandedBin.bodiesPerBand = perBand;
          const columns = 23;
          const rows = 19;
          const cells = columns * rows;
          const { serial, parallel, random } = kernelPair(n, threads, columns, rows, sortedByRow, seed, (kernel) => kernel.ensureBanded(n, cells));
          serial.bin(n, false, 0, 0, 1, columns, cells);
          const { bandShift, bands } = parallel;
          // Shares cut on chunk boundaries, as the threads' motion cuts them.
          const cut = (t: number) => (t === threads ? n : Math.floor(Math.floor((n * t) / threads) / CELL_CHUNK) * CELL_CHUNK);
          for (let t = 0; t < threads; t++) parallel.cellsOf(cut(t), cut(t + 1), 0, 0, 1, columns, rows);
          for (let t = threads - 1; t >= 0; t--) parallel.bandCounts(cut(t), cut(t + 1), t, bandShift, bands);
          if (!parallel.planPartition(n, threads, bands)) {
            // The scratch sized for uniform density cannot hold this band: the step bins plainly.
            expect(parallel.bandedRefusals).toBe(1);
            return;
          }
          for (let t = threads - 1; t >= 0; t--) parallel.partition(cut(t), cut(t + 1), t, bandShift, bands);
          // Bands in a shuffled order, each through some thread's scratch.
          const order = Array.from({ length: bands }, (_, b) => b).sort(() => random() - 0.5);
          for (const b of order) parallel.sortBand(b, bandShift, bands, threads, cells, 0, 0, 1, columns, b % threads);
          expectSameLayout(parallel, serial, n, cells);
          compared++;
        },
      ),
      { numRuns: 60 },
    );
    expect(compared).toBeGreaterThan(30);
  });

  describe('banded bin (bodies scattered in memory against space)', () => {
    /** The arrays a bin leaves, as plain arrays, for comparison. */
    function layoutOf(grid: CellGrid): number[][] {
      const cells = grid.columns * grid.rows;
      return [grid.cellStart.subarray(0, cells + 2), grid.sortedSlot, grid.sortedX, grid.sortedY, grid.sortedR].map((a, i) =>
        Array.from(i === 0 ? a : a.subarray(0, grid.count)),
      );
    }

    it('lays out every bin exactly as the TypeScript loops, bands, crowded bands and scratch growth included', () => {
      // Bands of 1 to 40 bodies at uniform density make many bands, empty ones and a partial last
      // one; clustered worlds overflow the first scratch (binned plainly, then with a grown one)
      // or crowd an eighth of the bodies into one band (plain for a while). Each world is binned
      // three times, moving a little in between, so the later bins follow a scattered first one.
      const off = gridWith(false);
      let banded = 0;
      let refused = 0;
      fc.assert(
        fc.property(
          fc.integer({ min: 2, max: 3000 }),
          fc.integer({ min: 1, max: 40 }),
          fc.constantFrom('spread', 'clustered', 'crowded', 'rows'),
          fc.integer({ min: 0, max: 2 ** 31 - 1 }),
          (n, perBand, shape, seed) => {
            bandedBin.minBodies = 2;
            bandedBin.bodiesPerBand = perBand;
            let state = seed;
            const random = () => ((state = (Math.imul(state, 1103515245) + 12345) >>> 0) / 2 ** 32);
            // Bands are runs of whole rows: clustering in y fills some bands beyond the first
            // scratch (clustered) or beyond an eighth of the bodies (crowded).
            const near = shape === 'clustered' ? 0.1 : shape === 'crowded' ? 0.7 : 0;
            const list = Array.from({ length: n }, (_, i) =>
              shape === 'rows'
                ? { x: (i % 60) * 3, y: Math.floor(i / 60) * 3, r: 1 }
                : { x: 400 * random(), y: random() < near ? 10 * random() : 400 * random(), r: 0.5 + random() },
            );
            const on = gridWith(true);
            const store = storeOf(list);
            for (let bin = 0; bin < 3; bin++) {
              const before = on.bandedBins;
              const a = pairsOf(on, store, 3);
              const b = pairsOf(off, store, 3);
              expect(layoutOf(on)).toEqual(layoutOf(off));
              expect(a.pairs).toEqual(b.pairs);
              banded += on.bandedBins - before;
              for (let i = 0; i < n; i++) store.x[i] += random() - 0.5;
            }
            refused += on.bandedRefusals;
          },
        ),
        { numRuns: 80 },
      );
      // The comparisons above must have reached the banded path, not only the plain one, and
      // also bands too full for the scratch.
      expect(banded).toBeGreaterThan(40);
      expect(refused).toBeGreaterThan(0);
    });

    it('counts the jumps that decide it: bodies whose cell lies far from the one before', () => {
      // Window: more than two rows and more than 1/64 of the cells (assembly jumpWindow).
      fc.assert(
        fc.property(fc.integer({ min: 1, max: 700 }), fc.integer({ min: 0, max: 2 ** 31 - 1 }), fc.boolean(), (n, seed, counted) => {
          bandedBin.minBodies = counted ? 1 : n + 1;
          const columns = 37;
          const rows = 29;
          const { serial } = kernelPair(n, 1, columns, rows, false, seed);
          const x = Array.from(serial.inputX.subarray(0, n));
          const y = Array.from(serial.inputY.subarray(0, n));
          serial.bin(n, false, 0, 0, 1, columns, columns * rows);
          const window = Math.max(2 * columns, (columns * rows) >> 6);
          let expected = 0;
          let last = 0;
          for (let k = 0; k < n; k++) {
            const c = Math.floor(y[k]) * columns + Math.floor(x[k]);
            if (Math.abs(c - last) > window) expected++;
            last = c;
          }
          expect(serial.jumps).toBe(counted ? expected : 0);
        }),
        { numRuns: 60 },
      );
    });

    it('is not taken for bodies created in the order they lie in space', () => {
      bandedBin.minBodies = 2;
      bandedBin.bodiesPerBand = 16;
      const list = [];
      for (let i = 0; i < 2000; i++) list.push({ x: (i % 50) * 3, y: Math.floor(i / 50) * 3, r: 1 });
      const grid = gridWith(true);
      for (let bin = 0; bin < 3; bin++) pairsOf(grid, storeOf(list), 3);
      expect(grid.bandedBins).toBe(0);
    });

    it('steps a shuffled world to the same state hash as the TypeScript loops', () => {
      bandedBin.minBodies = 1000;
      bandedBin.bodiesPerBand = 64;
      const build = () => buildWorld(buildScene('uniform', { n: 4000, seed: 3, shuffle: 1 }), { broadphase: 'maxgrid' });
      let banded = 0;
      const hash = runHash(build, 30, true, (world, step) => {
        if (step === 29) banded = (world as unknown as { pipeline: { broadPhase: { grid: CellGrid } } }).pipeline.broadPhase.grid.bandedBins;
      });
      expect(banded).toBeGreaterThan(20);
      expect(hash).toBe(runHash(build, 30, false));
    });
  });

  describe('touching test in the scan (worlds where every pair collides)', () => {
    /** Per step: contacts, candidates and, at the end, the state hash, with the grid kernel on or off. */
    function trace(on: boolean, build: () => World, steps: number, mutate?: (world: World, step: number) => void): string[] {
      const out: string[] = [];
      hashWithPath(setGridKernelEnabled, on, build, steps, (world, step) => {
        mutate?.(world, step);
        if (step > 0) out.push(`${world.stats.contacts}/${world.stats.candidatePairs}/${world.stats.filteredPairs}`);
      });
      return out;
    }

    it('gives the narrow-phase\'s contacts and candidate counts, step by step, and the same bits', () => {
      const build = () => buildWorld(buildScene('uniform', { n: 3000, seed: 4, fill: 0.5 }), { broadphase: 'maxgrid' });
      expect(trace(true, build, 40)).toEqual(trace(false, build, 40));
      expect(runHash(build, 40, true)).toBe(runHash(build, 40, false));
    });

    it('hands the pairs to the narrow-phase again while a pair of static, kinematic, sleeping or filtered bodies touches', () => {
      const build = () => {
        const world = new World({ broadphase: 'maxgrid', bounds: { width: 400, height: 400 }, gravity: { x: 0, y: 0 } });
        for (let k = 0; k < 600; k++) {
          world.createCircle({ x: 10 + (k % 30) * 9, y: 10 + Math.floor(k / 30) * 9, radius: 5, vx: ((k * 37) % 11) - 5, vy: ((k * 53) % 13) - 6 });
        }
        return world;
      };
      // In a corner of their own, a touching pair per phase, each of which the narrow-phase drops.
      let pair: number[] = [];
      const mutate = (world: World, step: number) => {
        if (step % 5 !== 0 || step === 0) return;
        for (const handle of pair) world.destroyBody(handle);
        const at = (dx: number, options: object) => world.createCircle({ x: 350 + dx, y: 350, radius: 4, ...options });
        const phase = step / 5;
        if (phase === 1) pair = [at(0, { type: 'static' }), at(5, { type: 'static' })];
        else if (phase === 2) pair = [at(0, { type: 'kinematic' }), at(5, { type: 'static' })];
        else if (phase === 3) {
          pair = [at(0, {}), at(5, {})];
          for (const handle of pair) world.setAwake(handle, false);
        } else if (phase === 4) pair = [at(0, { category: 2, mask: 2 }), at(5, {})];
        else pair = [];
      };
      const on = trace(true, build, 30, mutate);
      expect(on).toEqual(trace(false, build, 30, mutate));
      expect(runHash(build, 30, true, mutate)).toBe(runHash(build, 30, false, mutate));
    });

    it('knows when every pair collides', () => {
      const world = new World({ broadphase: 'maxgrid' });
      const store = (world as unknown as { bodies: BodyStore }).bodies;
      const a = world.createCircle({ x: 0, y: 0, radius: 1 });
      const b = world.createCircle({ x: 1, y: 0, radius: 1, category: 0 });
      expect(store.everyPairCollides).toBe(false);
      world.destroyBody(b);
      expect(store.everyPairCollides).toBe(true);
      const c = world.createCircle({ x: 5, y: 0, radius: 1, type: 'kinematic' });
      expect(store.everyPairCollides).toBe(false);
      world.setType(c, 'dynamic');
      expect(store.everyPairCollides).toBe(true);
      world.setCollisionFilter(a, 1, 3);
      expect(store.everyPairCollides).toBe(false);
      world.destroyBody(a);
      expect(store.everyPairCollides).toBe(true);
      world.setAwake(c, false);
      expect(store.everyPairCollides).toBe(false);
    });
  });
  it('lives in a shared body memory past its columns, unless they fill half its maximum', () => {
    const bodies = BodyKernel.create(1000, 100, 20, true)!;
    const gridIn = (fill: number) => {
      const grid = new CellGrid();
      grid.setShared(true, 2);
      // The same memory, reporting `fill` bytes of columns.
      grid.useArena(Object.assign(Object.create(bodies) as BodyKernel, { memoryBytes: () => fill }));
      grid.layout(0, 0, 100, 100, 4, 1000, 500);
      return grid.sharedKernel!;
    };
    const inside = gridIn(bodies.memoryBytes());
    expect(inside.memory).toBe(bodies.sharedMemory);
    expect(inside.base).toBe(bodies.memoryBytes());
    const apart = gridIn(ARENA_LIMIT_BYTES + 1);
    expect(apart.base).toBe(0);
    expect(apart.memory).not.toBe(bodies.sharedMemory);
  });
});
