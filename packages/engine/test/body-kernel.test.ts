import { afterEach, describe, expect, it } from 'vitest';
import { buildScene, buildWorld } from '@maxgrid/scenes';
import { World, type WorldOptions } from '../src/index.js';
import { hashWithPath } from './helpers.js';
import { BodyStore } from '../src/store/body-store.js';
import { bodyKernelBuild, setBodyKernelEnabled, setBodyKernelSimd } from '../src/store/body-kernel.js';

// The body kernel (integration, walls and contact solve in WebAssembly) must be the TypeScript
// loops bit for bit: a world steps to the same state whichever path its store took.

afterEach(() => {
  setBodyKernelEnabled(true);
  setBodyKernelSimd(true);
});

function runHash(build: () => World, steps: number, kernel: boolean, mutate?: (world: World, step: number) => void): string {
  return hashWithPath(setBodyKernelEnabled, kernel, build, steps, mutate);
}

/** Circles in a box with mixed restitutions, types and speeds; some cross the box 100 times a step, past the 16 bounces after which walls fold the path in closed form. */
function busyWorld(options: WorldOptions): World {
  const world = new World({ bounds: { width: 400, height: 300 }, ...options });
  for (let i = 0; i < 600; i++) {
    const fast = i % 97 === 0;
    const type = i % 50 === 7 ? 'kinematic' : i % 50 === 8 ? 'static' : 'dynamic';
    world.createCircle({
      x: 10 + (i % 30) * 12.5,
      y: 10 + Math.floor(i / 30) * 13,
      radius: 3 + (i % 4),
      vx: type === 'static' ? 0 : fast ? 3e6 : ((i * 37) % 23) - 11,
      vy: type === 'static' ? 0 : fast ? -7e4 : ((i * 53) % 19) - 9,
      restitution: (i % 5) / 4,
      type,
    });
  }
  return world;
}

describe('body WebAssembly kernel', () => {
  it('lays the columns of a single-threaded world out in its memory (so the comparisons below compare two paths)', () => {
    const on = new BodyStore(100);
    setBodyKernelEnabled(false);
    const off = new BodyStore(100);
    setBodyKernelEnabled(true);
    expect(on.kernel).not.toBeNull();
    expect(off.kernel).toBeNull();
    expect(on.x.buffer).toBe(on.type.buffer);
    // Memory is counted: 115 bytes per body of columns, plus the kernel's scratch and page rounding.
    expect(on.memoryBytes()).toBeGreaterThanOrEqual(off.memoryBytes());
    expect(on.memoryBytes()).toBeLessThan(off.memoryBytes() + 2 * 65536);
  });

  const scenes: [string, number][] = [
    ['uniform', 3000],
    ['seed-box', 2000],
    ['mixed', 2000],
    ['bouncing-ball', 1],
  ];
  it.each(scenes)('steps scene %s to the same state hash with and without the kernel', (scene, n) => {
    const build = () => buildWorld(buildScene(scene, scene === 'bouncing-ball' ? {} : { n, seed: 3 }), { broadphase: 'maxgrid' });
    expect(runHash(build, 60, true)).toBe(runHash(build, 60, false));
  });

  const variants: [string, WorldOptions][] = [
    ['semi-implicit Euler, gravity, restitution threshold', { gravity: { x: 3, y: -400 }, restitution: 0.9, restitutionThreshold: 4 }],
    ["explicit Euler (the report's)", { integrator: 'explicit-euler', gravity: { x: 0, y: -98 }, restitution: 1 }],
    ['inelastic walls', { restitution: 0, gravity: { x: 0, y: -200 } }],
    // Without continuous sweeps nothing runs between motion and walls: the kernel does both in one pass.
    ['one pass, semi-implicit Euler', { continuous: false, gravity: { x: 3, y: -400 }, restitution: 0.9, restitutionThreshold: 4 }],
    ['one pass, explicit Euler', { continuous: false, integrator: 'explicit-euler', gravity: { x: 0, y: -98 } }],
    ['contact events (the solve falls back to TypeScript)', { contactEvents: true, gravity: { x: 0, y: -98 } }],
    ['sleeping', { sleeping: true, gravity: { x: 0, y: -98 }, restitution: 0.2 }],
    ['partial position correction with slop', { gravity: { x: 0, y: -300 }, restitution: 0.2, positionCorrection: 0.2, contactSlop: 0.05 }],
  ];
  it.each(variants)('agrees with kinematic, static, mixed-restitution and folding bodies (past 16 bounces a step): %s', (_label, options) => {
    const build = () => busyWorld(options);
    expect(runHash(build, 90, true)).toBe(runHash(build, 90, false));
  });

  // The SIMD build moves two dynamic bodies per instruction and falls back to the scalar code for
  // other pairs and near the walls; the plain build is what runtimes without SIMD get.
  it('runs the SIMD build on this runtime, and the plain one when asked (so the comparisons below compare two builds)', () => {
    expect(bodyKernelBuild()).toBe('simd');
    setBodyKernelSimd(false);
    expect(bodyKernelBuild()).toBe('plain');
  });

  const simdCases: [string, () => World][] = [
    ['uniform, 3,001 bodies (an odd count: one body left after the pairs)', () => buildWorld(buildScene('uniform', { n: 3001, seed: 5 }), { broadphase: 'maxgrid', continuous: false })],
    ...variants.filter(([label]) => label.startsWith('one pass')).map(([label, options]): [string, () => World] => [label, () => busyWorld(options)]),
  ];
  it.each(simdCases)('steps to the same state hash with the SIMD build and the plain one: %s', (_label, build) => {
    expect(hashWithPath(setBodyKernelSimd, true, build, 90)).toBe(hashWithPath(setBodyKernelSimd, false, build, 90));
  });

  it('agrees with collision layers (the narrow-phase filter)', () => {
    const build = () => {
      const world = busyWorld({ gravity: { x: 0, y: -98 }, continuous: false });
      world.handles().forEach((h, k) => world.setCollisionFilter(h, 1 << (k % 3), k % 4 === 0 ? 0b011 : 0b111));
      return world;
    };
    const steps = (kernel: boolean) => {
      setBodyKernelEnabled(kernel);
      try {
        const world = build();
        let filtered = 0;
        for (let s = 0; s < 60; s++) {
          world.step(1 / 60);
          filtered += world.stats.filteredPairs;
        }
        return { hash: world.stateHash(), filtered };
      } finally {
        setBodyKernelEnabled(true);
      }
    };
    const on = steps(true);
    expect(on.filtered).toBeGreaterThan(0);
    expect(on).toEqual(steps(false));
  });

  it('agrees through growth, forces and holes, and views taken before a growth stay readable', () => {
    let before: Float64Array | null = null;
    const mutate = (world: World, step: number) => {
      if (step === 5) before = world.views().x;
      // Step 10: twice as many bodies (the store moves to a new memory); 20: forces; 30: holes.
      if (step === 10) for (let i = 0; i < 300; i++) world.createCircle({ x: 20 + (i % 15) * 25, y: 150 + Math.floor(i / 15) * 7, radius: 2 });
      if (step === 20) for (let h = 0; h < 300; h += 3) world.applyForce(h, 1e4, -2e4);
      if (step === 30) for (let h = 1; h < 600; h += 11) world.destroyBody(h);
    };
    const build = () => {
      const world = new World({ bounds: { width: 400, height: 300 }, gravity: { x: 0, y: -98 } });
      for (let i = 0; i < 300; i++) world.createCircle({ x: 10 + (i % 30) * 12.5, y: 10 + Math.floor(i / 30) * 13, radius: 4, vx: (i % 7) - 3 });
      return world;
    };
    expect(runHash(build, 50, true, mutate)).toBe(runHash(build, 50, false, mutate));
    expect(before!.length).toBeGreaterThanOrEqual(300);
    expect(Number.isFinite(before![299])).toBe(true);
  });
});
