import { describe, expect, it } from 'vitest';
import { World } from '../src/index.js';
import { setBodyKernelEnabled } from '../src/store/body-kernel.js';
import { setGridKernelEnabled } from '../src/broadphase/grid-kernel.js';
import { setSoftStepKernelEnabled } from '../src/solver/soft-step-kernel.js';

describe('world.backend says what steps the world', () => {
  it('circles on the default broad-phase run the grid and body kernels, and no soft step', () => {
    const world = new World({ bounds: { width: 100, height: 100 } });
    for (let k = 0; k < 50; k++) world.createCircle({ x: 5 + (k % 10) * 9, y: 5 + Math.floor(k / 10) * 9, radius: 2 });
    world.step(1 / 60);
    const b = world.backend;
    expect(b.route).toBe('circles');
    expect(b.threads).toBe(1);
    expect(b.lastStepThreads).toBe(1);
    expect(b.webAssembly).toBe(true);
    expect(b.gridKernel).toEqual({ running: true, why: expect.stringMatching(/auto \(now maxgrid\) broad-phase bins and scans in WebAssembly/) });
    expect(b.bodyKernel.running).toBe(true);
    expect(b.softStepKernel).toEqual({ running: false, why: 'the circle route has no soft step' });
  });

  it('an empty world says its body kernel waits for bodies, and runs it with the first', () => {
    const world = new World();
    expect(world.backend.bodyKernel).toEqual({ running: false, why: expect.stringMatching(/^no bodies yet/) });
    world.createCircle({ x: 0, y: 0, radius: 1 });
    expect(world.backend.bodyKernel.running).toBe(true);
  });

  it('a sweep uses no grid; shapes run the soft step in SIMD', () => {
    const sweep = new World({ broadphase: 'sap' });
    expect(sweep.backend.gridKernel).toEqual({ running: false, why: 'the broad-phase (sap) does not use a grid now' });
    const shapes = new World({ gravity: { x: 0, y: 10 } });
    shapes.createBox({ x: 0, y: 0, width: 1, height: 1 });
    shapes.step(1 / 60);
    expect(shapes.backend.route).toBe('shapes');
    expect(shapes.backend.softStepKernel.running).toBe(true);
  });

  it('names a kernel switched off, and the world still steps to the same bits', () => {
    const build = () => {
      const world = new World({ bounds: { width: 100, height: 100 } });
      for (let k = 0; k < 50; k++) world.createCircle({ x: 5 + (k % 10) * 9, y: 5 + Math.floor(k / 10) * 9, radius: 2, vx: k - 25 });
      return world;
    };
    const on = build();
    setBodyKernelEnabled(false);
    setGridKernelEnabled(false);
    setSoftStepKernelEnabled(false);
    try {
      const off = build();
      const box = new World({ solver: 'soft' });
      box.createBox({ x: 0, y: 0, width: 1, height: 1 });
      expect(off.backend.bodyKernel).toEqual({ running: false, why: 'switched off (setBodyKernelEnabled)' });
      expect(off.backend.gridKernel).toEqual({ running: false, why: 'switched off (setGridKernelEnabled)' });
      expect(box.backend.softStepKernel).toEqual({ running: false, why: 'switched off (setSoftStepKernelEnabled)' });
      for (let s = 0; s < 30; s++) {
        on.step(1 / 60);
        off.step(1 / 60);
      }
      expect(off.stateHash()).toBe(on.stateHash());
    } finally {
      setBodyKernelEnabled(true);
      setGridKernelEnabled(true);
      setSoftStepKernelEnabled(true);
    }
  });
});
