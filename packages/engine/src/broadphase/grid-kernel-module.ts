// The grid kernel's compiled WebAssembly module, the types of its exports, and the constants
// that its memory layout shares with the parallel step. GridKernel (grid-kernel.ts) wraps it.
import { GRID_KERNEL_SHARED_WASM, GRID_KERNEL_WASM } from '../generated/grid-kernel-wasm.js';
import { compileKernel, PAGE_BYTES } from '../util/wasm.js';

export interface KernelExports {
  bin(
    xs: number, ys: number, rs: number, slots: number, n: number,
    minX: number, minY: number, inverse: number, columns: number, cells: number,
    cellStart: number, binOf: number, sortedSlot: number, sortedX: number, sortedY: number, sortedR: number,
    countJumps: boolean,
  ): void;
  scan(
    cellStart: number, sortedSlot: number, sortedX: number, sortedY: number, sortedR: number,
    columns: number, rows: number, rowFrom: number, rowTo: number, minX: number, inverse: number,
    pad: number, radiusScale: number, touching: boolean, pairs: number, capacity: number,
  ): number;
  scanWindow(
    cellStart: number, sortedSlot: number, sortedX: number, sortedY: number, sortedR: number,
    columns: number, c0: number, c1: number, r0: number, r1: number, px: number, py: number, reach: number, radiusScale: number, slot: number,
    pairs: number, capacity: number,
  ): number;
  cellsOf(
    xs: number, ys: number, from: number, to: number, minX: number, minY: number, inverse: number, columns: number, cells: number,
    binOf: number, chunkCells: number,
  ): number;
  countCells(binOf: number, n: number, from: number, to: number, cellStart: number, chunkCells: number): number;
  scatterCells(
    binOf: number, n: number, from: number, to: number, before: number, cellStart: number, chunkCells: number,
    xs: number, ys: number, rs: number,
    sortedSlot: number, sortedX: number, sortedY: number, sortedR: number,
  ): void;
  binBanded(
    xs: number, ys: number, rs: number, n: number,
    minX: number, minY: number, inverse: number, columns: number, cells: number,
    cellStart: number, binOf: number, sortedSlot: number, sortedX: number, sortedY: number, sortedR: number,
    bandShift: number, bandStart: number, scratch: number, scratchCapacity: number,
  ): number;
  bandCounts(binOf: number, from: number, to: number, bandShift: number, counts: number, bands: number): void;
  partition(
    binOf: number, from: number, to: number, bandShift: number, cursor: number,
    xs: number, ys: number, rs: number, sortedSlot: number, sortedX: number, sortedY: number, sortedR: number,
  ): void;
  sortBand(
    b: number, bandShift: number, from: number, to: number, cells: number, minX: number, minY: number, inverse: number, columns: number,
    cellStart: number, sortedSlot: number, sortedX: number, sortedY: number, sortedR: number, scratch: number, scratchCapacity: number,
  ): void;
  jumps(): number;
  examined(): number;
  candidates(): number;
}

/**
 * Bodies per chunk of a parallel bin's chunk cell ranges (CHUNK_SHIFT in assembly/grid/parallel-bin.ts):
 * each thread's share of the cells pass starts on a multiple of it.
 */
export const CELL_CHUNK = 1024;

/** The shared module's declared maximum, in pages (see scripts/build-kernel.mjs). */
export const SHARED_MAXIMUM_PAGES = 32768;

/**
 * A grid lives in a body memory (GridKernel.inside) only while the columns take at most half of
 * the shared maximum: the grid (40 bytes a body at 1M bodies on `uniform`, pair buffers included) then has
 * room to grow, which it must be able to do mid-step. Past it, the grid keeps a memory of its own.
 */
export const ARENA_LIMIT_BYTES = (SHARED_MAXIMUM_PAGES * PAGE_BYTES) / 2;

const compiled: { private?: object | null; shared?: object | null } = {};
let enabled = true;

/**
 * Whether grids created from now on use the kernel. For tests and measurements that compare the
 * two paths; not part of the public API.
 */
export function setGridKernelEnabled(on: boolean): void {
  enabled = on;
}

export function gridKernelEnabled(): boolean {
  return enabled;
}

/** The compiled kernel module for a private or a shared memory, or null where this runtime lacks one. */
export function kernelModule(shared: boolean): object | null {
  const key = shared ? 'shared' : 'private';
  const known = compiled[key];
  if (known !== undefined) return known;
  const module = shared && typeof SharedArrayBuffer !== 'function' ? null : compileKernel(shared ? GRID_KERNEL_SHARED_WASM : GRID_KERNEL_WASM);
  compiled[key] = module;
  return module;
}
