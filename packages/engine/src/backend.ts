import { webAssembly } from './util/wasm.js';
import { gridKernelEnabled, kernelModule as gridKernelModule } from './broadphase/grid-kernel-module.js';
import { bodyKernelEnabled, kernelModule as bodyKernelModule } from './store/body-kernel.js';
import { softStepKernelEnabled } from './solver/soft-step-kernel.js';

/** Whether one of the engine's WebAssembly kernels runs in this world, and why, or why not. */
export interface KernelUse {
  running: boolean;
  why: string;
}

/** What steps a world (World.backend): its route, its threads and its WebAssembly kernels. */
export interface WorldBackend {
  /** The report's circle engine, or the shape route (see World.route). */
  route: 'circles' | 'shapes';
  /** Threads started for the step (startWorkers), this one included. */
  threads: number;
  /** Threads that ran the last step: fewer where the thread governor or minBodies chose so. */
  lastStepThreads: number;
  /** Whether this runtime has WebAssembly at all. */
  webAssembly: boolean;
  /** The Max Grid's bin and scan (maxgrid, hgrid's levels, auto on a grid, the query grid). */
  gridKernel: KernelUse;
  /** Motion in a box and the contact buffers of the circle route (body columns in kernel memory). */
  bodyKernel: KernelUse;
  /** The shape route's soft step (WebAssembly SIMD). */
  softStepKernel: KernelUse;
}

const NO_WASM = 'this runtime has no WebAssembly: the TypeScript loops run (the same bits, slower)';

export function gridKernelUse(broadphase: string, gridInUse: boolean): KernelUse {
  if (webAssembly() === null) return { running: false, why: NO_WASM };
  if (gridKernelModule(false) === null) return { running: false, why: 'the grid kernel did not compile in this runtime' };
  if (!gridKernelEnabled()) return { running: false, why: 'switched off (setGridKernelEnabled)' };
  if (!gridInUse) return { running: false, why: `the broad-phase (${broadphase}) does not use a grid now` };
  return { running: true, why: `the ${broadphase} broad-phase bins and scans in WebAssembly` };
}

export function bodyKernelUse(inUse: boolean, slotCount: number): KernelUse {
  if (inUse) return { running: true, why: 'the body columns live in kernel memory: motion in a box and the contact buffers run in WebAssembly' };
  if (webAssembly() === null) return { running: false, why: NO_WASM };
  if (!bodyKernelEnabled()) return { running: false, why: 'switched off (setBodyKernelEnabled)' };
  if (bodyKernelModule(false) === null) return { running: false, why: 'the body kernel did not compile in this runtime' };
  if (slotCount === 0) return { running: false, why: 'no bodies yet: the columns move into kernel memory with the first' };
  return { running: false, why: 'the body columns were laid out without it: switched off when they last grew, or its memory could not be had (they fall back to plain typed arrays)' };
}

export function softStepKernelUse(route: 'circles' | 'shapes', solver: string, inUse: boolean): KernelUse {
  if (inUse) return { running: true, why: "the soft step's sub-steps run in WebAssembly SIMD" };
  if (route === 'circles') return { running: false, why: 'the circle route has no soft step' };
  if (solver !== 'soft') return { running: false, why: `the shape route's ${solver} solver has no kernel` };
  if (webAssembly() === null) return { running: false, why: NO_WASM };
  if (!softStepKernelEnabled()) return { running: false, why: 'switched off (setSoftStepKernelEnabled)' };
  return { running: false, why: 'this runtime has no WebAssembly SIMD' };
}
