import type { CellGrid } from '../src/broadphase/cell-grid.js';
import { describe, expect, it } from 'vitest';
import { buildScene, buildWorld } from '@maxgrid/scenes';
import { World, type WorldOptions } from '../src/index.js';
import type { BodyStore } from '../src/store/body-store.js';
import { setBodyKernelEnabled } from '../src/store/body-kernel.js';
import { bandedBin, setGridKernelEnabled } from '../src/broadphase/grid-kernel.js';
import { spinBudget, spinWhileEqual } from '../src/parallel/host.js';
import { ThreadGovernor } from '../src/parallel/governor.js';
import { fileURLToPath } from 'node:url';

// Worker threads load the compiled engine (dist/), which `npm test` builds first.

type Build = () => World;

/** Steps a fresh world from `build` with the given worker count (0: none) and returns its hash. */
async function hashWith(build: Build, workers: number, steps: number, during?: (world: World, step: number) => void): Promise<string> {
  const world = build();
  // minBodies 0: these worlds are small, and the parallel path is what is under test.
  if (workers > 0) await world.startWorkers(workers, { minBodies: 0, adaptive: false });
  try {
    for (let s = 0; s < steps; s++) {
      during?.(world, s);
      world.step(1 / 60);
    }
    return world.stateHash();
  } finally {
    world.stopWorkers();
  }
}

async function expectSameBits(build: Build, steps: number, during?: (world: World, step: number) => void): Promise<void> {
  const serial = await hashWith(build, 0, steps, during);
  for (const workers of [1, 2, 3]) {
    expect(await hashWith(build, workers, steps, during), `${workers} worker(s)`).toBe(serial);
  }
}

const uniform = (n: number, options: WorldOptions = {}, params: Record<string, number> = {}) => () =>
  buildWorld(buildScene('uniform', { n, ...params }), { broadphase: 'maxgrid', ...options });

describe('parallel step', () => {
  it('gives the serial step bit for bit with 1, 2 and 3 threads (elastic uniform scene)', async () => {
    await expectSameBits(uniform(4000), 60);
  });

  it('stats.threads says 1 once a threaded world of circles moves to the shape route, which runs on one thread', async () => {
    const world = buildWorld(buildScene('uniform', { n: 2000 }));
    await world.startWorkers(2, { minBodies: 0, adaptive: false });
    try {
      world.step(1 / 60);
      expect(world.stats.threads).toBe(2);
      world.createBox({ x: 100, y: 100, width: 10, height: 10 });
      world.step(1 / 60);
      expect(world.stats.threads).toBe(1);
      expect(world.backend.lastStepThreads).toBe(1);
    } finally {
      world.stopWorkers();
    }
  });

  it('gives the serial bits whether bodies lie in memory in spatial order or shuffled (chunk cell ranges of the parallel bin)', async () => {
    // The uniform scene creates bodies row by row, so most chunks of 1,024 bodies fall in one
    // thread's band of cells; shuffled, every chunk spans every band. 5,000 is no multiple of 1,024.
    await expectSameBits(uniform(5000, {}, { seed: 3, shuffle: 1 }), 40);
    await expectSameBits(uniform(5000, {}, { seed: 3 }), 40);
  });

  it('bins shuffled worlds in bands on every thread count (counts and partition per share, bands claimed) to the serial bits', async () => {
    const defaults = { ...bandedBin };
    // Bands of about 64 bodies: dozens of bands, which threads claim unevenly, from 1,000 bodies on.
    Object.assign(bandedBin, { minBodies: 1000, bodiesPerBand: 64 });
    const gridOf = (world: World) => (world as unknown as { pipeline: { broadPhase: { grid: CellGrid } } }).pipeline.broadPhase.grid;
    try {
      for (const bodyKernel of [true, false]) {
        // Without the body kernel, the grid keeps its own memory and its threads bin from copies.
        setBodyKernelEnabled(bodyKernel);
        const build = uniform(6000, {}, { seed: 5, shuffle: 1 });
        const serial = await hashWith(build, 0, 40);
        for (const workers of [1, 2, 3]) {
          let banded = 0;
          const hash = await hashWith(build, workers, 40, (world, step) => {
            if (step === 39) banded = gridOf(world).bandedBins;
          });
          expect(hash, `${workers} worker(s), body kernel ${bodyKernel}`).toBe(serial);
          // The first step bins plainly and finds the bodies scattered; the later ones band.
          expect(banded, `${workers} worker(s)`).toBeGreaterThan(30);
        }
      }
      // Bodies crowded into a few rows: 10 % overflow the first scratch (a plain bin, then a grown
      // scratch and bands), 30 % fill one band past an eighth of the bodies (plain for a while).
      setBodyKernelEnabled(true);
      for (const [crowd, bandedAfter] of [[0.1, 27], [0.3, 0]]) {
        const crowded = () => {
          const world = new World({ bounds: { width: 600, height: 600 }, broadphase: 'maxgrid' });
          let state = 99;
          const random = () => ((state = (Math.imul(state, 1103515245) + 12345) >>> 0) / 2 ** 32);
          for (let i = 0; i < 4000; i++) {
            const y = random() < crowd ? 10 + 40 * random() : 10 + 580 * random();
            world.createCircle({ x: 5 + 590 * random(), y, radius: 2 + random(), vx: 60 * random() - 30, vy: 60 * random() - 30 });
          }
          return world;
        };
        await expectSameBits(crowded, 30);
        let counts = [0, 0];
        await hashWith(crowded, 2, 30, (world, step) => {
          if (step === 29) counts = [gridOf(world).bandedBins, gridOf(world).bandedRefusals];
        });
        expect(counts, `crowd ${crowd}`).toEqual([bandedAfter, 1]);
      }
    } finally {
      Object.assign(bandedBin, defaults);
      setBodyKernelEnabled(true);
    }
  });

  it('runs the body kernel on shared columns, in every thread, and matches a serial world without any kernel', async () => {
    const build = uniform(4000, { gravity: { x: 0, y: -60 } });
    const world = build();
    await world.startWorkers(2, { minBodies: 0, adaptive: false });
    try {
      const kernel = (world as unknown as { bodies: BodyStore }).bodies.kernel;
      expect(kernel?.sharedMemory).toBeTruthy();
      for (let s = 0; s < 60; s++) world.step(1 / 60);
      // The threads' grid lives in the same memory, past the columns, and reads them in place.
      const grid = (world as unknown as { pipeline: { broadPhase: { grid: CellGrid } } }).pipeline.broadPhase.grid;
      const gridKernel = grid.sharedKernel!;
      expect(gridKernel.memory).toBe(kernel!.sharedMemory);
      expect(gridKernel.base).toBe(kernel!.memoryBytes());
      expect(gridKernel.memoryBytes()).toBe(gridKernel.memory.buffer.byteLength - kernel!.memoryBytes());
    } finally {
      world.stopWorkers();
    }
    setBodyKernelEnabled(false);
    try {
      expect(await hashWith(build, 0, 60)).toBe(world.stateHash());
      // Without the body kernel the grid kernel keeps a memory of its own, and the threads copy
      // positions and radii into it.
      const copying = build();
      await copying.startWorkers(2, { minBodies: 0, adaptive: false });
      try {
        for (let s = 0; s < 60; s++) copying.step(1 / 60);
        const grid = (copying as unknown as { pipeline: { broadPhase: { grid: CellGrid } } }).pipeline.broadPhase.grid;
        expect(grid.sharedKernel?.base).toBe(0);
      } finally {
        copying.stopWorkers();
      }
      expect(copying.stateHash()).toBe(world.stateHash());
    } finally {
      setBodyKernelEnabled(true);
    }
  });

  it('gives the same bits with the grid\'s TypeScript passes on SharedArrayBuffers (no grid kernel), as with the kernel', async () => {
    const build = uniform(5000, {}, { seed: 4 });
    const withKernel = await hashWith(build, 0, 40);
    setGridKernelEnabled(false);
    try {
      const world = build();
      await world.startWorkers(2, { minBodies: 0, adaptive: false });
      try {
        world.step(1 / 60);
        const grid = (world as unknown as { pipeline: { broadPhase: { grid: CellGrid } } }).pipeline.broadPhase.grid;
        expect(grid.usesKernel).toBe(false);
        expect(grid.sortedX.buffer).toBeInstanceOf(SharedArrayBuffer);
      } finally {
        world.stopWorkers();
      }
      await expectSameBits(build, 40);
      expect(await hashWith(build, 2, 40)).toBe(withKernel);
    } finally {
      setGridKernelEnabled(true);
    }
  });

  it('matches the golden seed-box hash with gravity and walls, on the default broad-phase', async () => {
    const build = () => buildWorld(buildScene('seed-box', { n: 800, seed: 42 }), { integrator: 'explicit-euler' });
    const world = build();
    await world.startWorkers(2, { minBodies: 0, adaptive: false });
    expect(world.workerCount).toBe(2);
    for (let s = 0; s < 600; s++) world.step(1 / 60);
    world.stopWorkers();
    // The same pinned hash as determinism.test.ts: the parallel step changes no bit.
    expect(world.stateHash()).toBe('1981b004408be274');
  });

  it('keeps the same bits while bodies are added (buffers regrow and are re-sent) and destroyed (holes)', async () => {
    const during = (world: World, step: number) => {
      if (step % 7 === 3) {
        for (let k = 0; k < 300; k++) world.createCircle({ x: 20 + (k % 50) * 9, y: 20 + Math.floor(k / 50) * 9 + step, radius: 3, vx: 40, vy: -30 });
      }
      if (step === 20) for (const handle of world.handles().slice(0, 500)) world.destroyBody(handle);
    };
    await expectSameBits(uniform(2000), 40, during);
  });

  it('keeps the same bits when a destroyed body\'s slot is reused at once by a body of another size', async () => {
    // No holes remain, so the threads keep binning in motion: the new radius must reach the grid.
    const during = (world: World, step: number) => {
      if (step % 5 !== 2) return;
      const handle = world.handles()[(step * 37) % 2000];
      const { x, y } = world.getCircle(handle);
      const radius = 2 + (step % 9);
      const { width, height } = world.box!;
      world.destroyBody(handle);
      world.createCircle({ x: Math.min(Math.max(x, radius), width - radius), y: Math.min(Math.max(y, radius), height - radius), radius, vx: 30, vy: -20 });
    };
    await expectSameBits(uniform(2000), 40, during);
  });

  it('keeps the same bits in a crowded scene whose contacts overflow the threads\' first contact lists', async () => {
    let most = 0;
    const build = () => buildWorld(buildScene('uniform', { n: 6000, fill: 0.6, maxSpeed: 400 }), { broadphase: 'maxgrid' });
    const serial = await hashWith(build, 0, 30, (world) => (most = Math.max(most, world.stats.contacts)));
    expect(most).toBeGreaterThan(2 * 1024);
    // White-box: the threads scan in WebAssembly into 1,024-pair buffers; one overflowed, so its
    // band was scanned by the TypeScript loops and the buffers grew.
    let pairCapacity = 0;
    const readCapacity = (world: World) => {
      const grid = (world as unknown as { pipeline: { broadPhase: { grid: CellGrid } } }).pipeline.broadPhase.grid;
      pairCapacity = grid.kernelShare?.layout.pairCapacity ?? 0;
    };
    expect(await hashWith(build, 2, 30, readCapacity)).toBe(serial);
    expect(pairCapacity).toBeGreaterThan(1024);
  });

  it('keeps the same bits when a world with holes scans its shared grid serially and overflows its pair buffer', async () => {
    // Holes send the Max Grid down the serial path on the grid the threads share; more than the
    // first 1,024 pairs make that scan overflow its shared pair buffer, which it cannot grow while
    // threads may read it, so it takes the TypeScript loops.
    const build = () => buildWorld(buildScene('uniform', { n: 6000, fill: 0.6, maxSpeed: 400 }), { broadphase: 'maxgrid' });
    let most = 0;
    const holes = (world: World, step: number) => {
      if (step === 0) for (const handle of world.handles().slice(0, 50)) world.destroyBody(handle);
      most = Math.max(most, world.stats.candidatePairs);
    };
    const serial = await hashWith(build, 0, 20, holes);
    expect(most).toBeGreaterThan(1024);
    expect(await hashWith(build, 2, 20, holes)).toBe(serial);
  });

  it('falls back to serial stages where it must and still matches: hgrid, CCD and segments, sleeping, events, forces', async () => {
    await expectSameBits(() => buildWorld(buildScene('mixed', { n: 3000 }), { broadphase: 'auto' }), 30);
    // Static pegs and segments: continuous sweeps between motion and the walls, segment contacts.
    await expectSameBits(() => buildWorld(buildScene('funnel', { n: 400 })), 90);
    const busy = () => {
      const world = buildWorld(buildScene('seed-box', { n: 600, seed: 3 }), { sleeping: true, sleepSpeed: 40, contactEvents: true, hitEventThreshold: 50 });
      return world;
    };
    await expectSameBits(busy, 90, (world, step) => {
      if (step % 10 === 0) world.applyForce(world.handles()[step % 600], 5000, -8000);
    });
  });

  it('keeps a given speed limit through motion on every thread count, with the serial bits (the limit reaches the workers)', async () => {
    const limited = uniform(3000, { maxLinearSpeed: 40 });
    await expectSameBits(limited, 30, (world, step) => {
      if (step % 5 === 0) world.setVelocity(world.handles()[step * 7], 3e4, -4e4);
    });
    const world = limited();
    await world.startWorkers(2, { minBodies: 0, adaptive: false });
    try {
      const h = world.handles()[100];
      world.step(1 / 60);
      world.setVelocity(h, 3e4, -4e4);
      const before = world.getCircle(h);
      world.step(1 / 60);
      const after = world.getCircle(h);
      expect(Math.hypot(after.x - before.x, after.y - before.y)).toBeLessThanOrEqual((40 / 60) * (1 + 1e-12));
    } finally {
      world.stopWorkers();
    }
  });

  it("auto's turn to the hashed grid when two crowds far apart make the grid's cells huge happens on workers too, with the serial bits", async () => {
    const outliers = () => {
      const world = new World({ broadphase: 'auto' });
      for (let k = 0; k < 3000; k++) {
        const off = k < 1500 ? 0 : 1e6;
        const j = k % 1500;
        world.createCircle({ x: off + (j % 50) * 9, y: off + Math.floor(j / 50) * 9, radius: 2, vx: (k % 7) - 3, vy: (k % 5) - 2 });
      }
      return world;
    };
    await expectSameBits(outliers, 8);
    const world = outliers();
    await world.startWorkers(2, { minBodies: 0, adaptive: false });
    try {
      for (let s = 0; s < 3; s++) world.step(1 / 60);
      expect(world.gridGeometry()).toBeNull();
      expect(world.stats.pairTests).toBeLessThan(10 * 3000);
    } finally {
      world.stopWorkers();
    }
  });

  it('wakes the sleepers a destroyed or moved body held up the same way on every thread count', async () => {
    // A pile 99 % asleep by step 240 (792 of 800); then bodies are destroyed and moved under it,
    // and each time 7 to 12 sleepers wake (counted serially).
    const pile = () => buildWorld(buildScene('seed-box', { n: 800, seed: 5, elasticity: 0 }), { sleeping: true, sleepSpeed: 40, sleepTime: 0.2, solverIterations: 4, positionCorrection: 0.2, contactSlop: 0.05 });
    await expectSameBits(pile, 320, (world, step) => {
      if (step < 240 || step % 20 !== 0) return;
      const handles = world.handles();
      world.destroyBody(handles[(step * 7) % handles.length]);
      const moved = handles[(step * 13) % handles.length];
      if (world.hasBody(moved)) world.setPosition(moved, 100 + step, 100);
    });
  });

  it('solves with partial position correction and a slop on every thread as serially (the settings reach the workers)', async () => {
    await expectSameBits(() => buildWorld(buildScene('seed-box', { n: 2000, elasticity: 0 }), { broadphase: 'maxgrid', positionCorrection: 0.2, contactSlop: 0.05 }), 60);
    // Solver iterations solve on the calling thread, between the parallel stages.
    await expectSameBits(() => buildWorld(buildScene('seed-box', { n: 2000, elasticity: 0 }), { broadphase: 'maxgrid', positionCorrection: 0.2, contactSlop: 0.05, solverIterations: 4 }), 60);
  });

  it('notes the same wall touches and hits on any worker count, and events leave the bits alone', async () => {
    // With events, motion leaves the walls to a stage of their own, which notes them first.
    const build = (events: boolean) => uniform(3000, events ? { contactEvents: true, hitEventThreshold: 20 } : {}, { seed: 2 });
    const plain = await hashWith(build(false), 0, 40);
    let serialLog = '';
    for (const workers of [0, 2]) {
      let log = '';
      const note = (world: World) => {
        if (world.stats.steps === 0) return;
        const e = world.contactEvents();
        for (let k = 0; k < e.wallHitCount; k++) log += `${e.wallHitBody[k]}@${e.wallHitWall[k]}:${e.wallHitSpeed[k]} `;
        log += `| ${e.wallBeginCount}/${e.wallEndCount} `;
      };
      expect(await hashWith(build(true), workers, 40, note), `${workers} worker(s)`).toBe(plain);
      if (workers === 0) serialLog = log;
      else expect(log).toBe(serialLog);
    }
    expect(serialLog).toMatch(/@/);
  });

  it('steps on after stopWorkers, and restarting gives the same bits', async () => {
    const serial = await hashWith(uniform(3000), 0, 40);
    const world = uniform(3000)();
    await world.startWorkers(2, { minBodies: 0, adaptive: false });
    for (let s = 0; s < 15; s++) world.step(1 / 60);
    world.stopWorkers();
    expect(world.workerCount).toBe(1);
    for (let s = 0; s < 10; s++) world.step(1 / 60);
    await world.startWorkers(3, { minBodies: 0, adaptive: false });
    for (let s = 0; s < 15; s++) world.step(1 / 60);
    world.stopWorkers();
    expect(world.stateHash()).toBe(serial);
  });

  it('stopWorkers while workers are starting cancels them, and of two starts the last wins', async () => {
    const world = uniform(500)();
    const starting = world.startWorkers(2);
    world.stopWorkers();
    await starting;
    expect(world.workerCount).toBe(1);
    const first = world.startWorkers(2);
    const second = world.startWorkers(3);
    await Promise.all([first, second]);
    expect(world.workerCount).toBe(3);
    world.stopWorkers();
  });

  it('rejects a bad worker count or minBodies by name and value, leaving the world and its workers as they were', async () => {
    const world = uniform(100)();
    const before = world.stateHash();
    await world.startWorkers(2);
    for (const bad of [0, -1, 1.5, 17]) {
      await expect(world.startWorkers(bad)).rejects.toThrow(new RegExp(`workerCount must be an integer in \\[1, 16\\], got ${bad}`));
      expect(world.workerCount).toBe(2);
    }
    for (const [bad, shown] of [[Number.NaN, 'NaN'], ['2', '"2"']] as const) {
      await expect(world.startWorkers(bad as number)).rejects.toThrow(new TypeError(`workerCount must be a finite number, got ${shown}`));
      expect(world.workerCount).toBe(2);
    }
    for (const bad of [-1, 0.5]) {
      await expect(world.startWorkers(2, { minBodies: bad })).rejects.toThrow(`minBodies must be a non-negative integer, got ${bad}`);
      expect(world.workerCount).toBe(2);
    }
    for (const [options, message] of [
      [{ minBodies: Number.POSITIVE_INFINITY }, 'minBodies must be a finite number, got Infinity'],
      [{ minBodies: '5' }, 'minBodies must be a finite number, got "5"'],
      [{ minBodes: 1 }, "startWorkers options has unknown option 'minBodes'"],
      [{ adaptive: 1 }, 'startWorkers option adaptive must be a boolean, got 1'],
      [{ workerUrl: '' }, 'startWorkers option workerUrl must be a URL or a non-empty string, got ""'],
      [{ workerUrl: 7 }, 'startWorkers option workerUrl must be a URL or a non-empty string, got 7'],
      [{ workerUrl: { path: '/worker.js' } }, 'startWorkers option workerUrl must be a URL or a non-empty string, got [object Object]'],
      [null, 'startWorkers options must be an object, got null'],
    ] as const) {
      await expect(world.startWorkers(2, options as never)).rejects.toBeInstanceOf(TypeError);
      await expect(world.startWorkers(2, options as never)).rejects.toThrow(message);
      expect(world.workerCount).toBe(2);
    }
    world.stopWorkers();
    expect(world.stateHash()).toBe(before);
  });

  it('starts its workers on the script workerUrl names, as a URL or a path, with the same bits; a script that is not there rejects', async () => {
    const build = uniform(400);
    const serial = await hashWith(build, 0, 30);
    const script = new URL('../dist/parallel/worker-entry.js', import.meta.url);
    for (const workerUrl of [script, fileURLToPath(script)]) {
      const world = build();
      await world.startWorkers(2, { minBodies: 0, adaptive: false, workerUrl });
      for (let s = 0; s < 30; s++) world.step(1 / 60);
      expect(world.backend.lastStepThreads).toBe(2);
      expect(world.stateHash()).toBe(serial);
      world.stopWorkers();
    }
    const world = build();
    await expect(world.startWorkers(2, { workerUrl: new URL('../dist/parallel/no-such-worker.js', import.meta.url) })).rejects.toThrow(/no-such-worker\.js/);
    expect(world.workerCount).toBe(1);
  });

  it("fails the step with the failing worker's own error, whether a kernel throws in a command or the worker cannot take the buffers", async () => {
    for (const [script, error, threads] of [
      ['kernel-throws.mjs', 'Error: a kernel failed on purpose', 2],
      ['install-throws.mjs', 'Error: buffers refused on purpose', 1],
    ] as const) {
      const world = uniform(400)();
      await world.startWorkers(threads + 1, { minBodies: 0, adaptive: false, workerUrl: new URL(`./workers/${script}`, import.meta.url) });
      try {
        let thrown: unknown = null;
        try {
          world.step(1 / 60);
        } catch (e) {
          thrown = e;
        }
        const message = thrown instanceof Error ? thrown.message : String(thrown);
        // The worker's stack comes with it, the fixture's frame included.
        expect(message, script).toMatch(/^worker thread [12] failed during the step/);
        expect(message, script).toContain(error);
        expect(message, script).toContain(script);
        if (threads === 2) expect(message).toContain('(and 1 more worker)');
      } finally {
        world.stopWorkers();
      }
    }
  });

  it('polls for the next command only where threads fit the cores, and stops polling when the budget runs out', () => {
    expect(spinBudget(2, 2)).toBeGreaterThan(0);
    expect(spinBudget(3, 2)).toBe(0);
    expect(spinBudget(2, 0)).toBe(0);
    const flag = new Int32Array(new SharedArrayBuffer(4));
    const started = performance.now();
    expect(spinWhileEqual(flag, 0, 0, 2000)).toBe(false);
    expect(performance.now() - started).toBeGreaterThanOrEqual(2);
    flag[0] = 1;
    expect(spinWhileEqual(flag, 0, 0, 2000)).toBe(true);
    expect(spinWhileEqual(flag, 0, 1, 0)).toBe(false);
  });
});

describe('thread governor (a machine whose cores are busy elsewhere)', () => {
  /** Runs `steps` steps where the threads cost `threaded(step)` ms and one thread `serial(step)`; returns the steps on threads per window. */
  function drive(steps: number, threaded: (s: number) => number, serial: (s: number) => number, window = steps) {
    const governor = new ThreadGovernor();
    const onThreads: number[] = [];
    let total = 0;
    for (let s = 0; s < steps; s++) {
      const threads = governor.useThreads();
      const ms = threads ? threaded(s) : serial(s);
      total += ms;
      governor.note(threads, ms);
      if (s % window === 0) onThreads.push(0);
      if (threads) onThreads[onThreads.length - 1]++;
    }
    return { onThreads, total };
  }

  it('leaves threads ten times slower than one within a few steps, and tries them again ever more rarely', () => {
    const { onThreads, total } = drive(4000, () => 20, () => 2, 1000);
    // The first try of one thread comes at step 16; afterwards a try (its first step a clear loss here) after 8, 128, then every 1,024 steps.
    expect(onThreads[0]).toBeLessThan(30);
    expect(onThreads[3]).toBeLessThanOrEqual(2);
    // Within 1.1x of stepping on one thread throughout.
    expect(total).toBeLessThan(1.1 * 4000 * 2);
  });

  it('keeps threads that are faster, trying one thread ever more rarely', () => {
    const { onThreads, total } = drive(4000, () => 1, () => 1.6, 1000);
    expect(onThreads[0]).toBeGreaterThan(985);
    expect(onThreads[3]).toBeGreaterThanOrEqual(997);
    expect(total).toBeLessThan(1.01 * 4000);
  });

  it('goes back to the threads once the load is gone, and leaves them when it returns', () => {
    // Busy for 500 steps, idle for 1,500, busy again.
    const busy = (s: number) => s < 500 || s >= 2000;
    const { onThreads } = drive(3000, (s) => (busy(s) ? 20 : 1), () => 1.6, 100);
    expect(onThreads[4]).toBeLessThanOrEqual(2);
    // Idle from step 500: the next try (at most 1,024 steps later, sooner this early) wins.
    expect(onThreads[15]).toBeGreaterThanOrEqual(98);
    expect(onThreads[19]).toBeGreaterThanOrEqual(98);
    expect(onThreads[25]).toBeLessThanOrEqual(2);
  });

  it('noisy timings do not keep it switching: the mode in use is compared by the lower quartile of its recent steps', () => {
    let state = 7;
    const noise = () => ((state = (Math.imul(state, 1103515245) + 12345) >>> 0) / 2 ** 32);
    // Threads 1 ms with spikes to 10 one step in ten; one thread 1.6 ms.
    const { onThreads } = drive(3000, () => (noise() < 0.1 ? 10 : 1), () => 1.6, 1000);
    expect(onThreads[2]).toBeGreaterThan(950);
  });

  it('switching between the threads and one thread, step by step, keeps the serial bits', async () => {
    const build = uniform(3000, {}, { seed: 9 });
    const serial = await hashWith(build, 0, 30);
    const world = build();
    await world.startWorkers(2, { minBodies: 0 });
    const parallel = (world as unknown as { pipeline: { parallel: { governor: unknown } } }).pipeline.parallel;
    let step = 0;
    const used: number[] = [];
    parallel.governor = { useThreads: () => step++ % 3 !== 1, note: () => {} };
    try {
      for (let s = 0; s < 30; s++) {
        world.step(1 / 60);
        used.push(world.stats.threads);
      }
      expect(world.stateHash()).toBe(serial);
      expect(used.filter((t) => t === 1)).toHaveLength(10);
      expect(used.filter((t) => t === 2)).toHaveLength(20);
    } finally {
      world.stopWorkers();
    }
  });
});
