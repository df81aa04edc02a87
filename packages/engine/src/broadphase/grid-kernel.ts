import { GRID_KERNEL_WASM } from '../generated/grid-kernel-wasm.js';
import { grownCapacity } from '../util/grow.js';

/**
 * The WebAssembly side of CellGrid: its arrays laid out in one WebAssembly memory, and the two hot
 * loops, binning and scanning, compiled from assembly/grid-kernel.ts. Same operations, same order,
 * same bits as the TypeScript loops in cell-grid.ts, which remain the path wherever WebAssembly is
 * missing, and for the shared grids of a parallel step.
 *
 * Why: V8 re-checks every typed array's map, length and base pointer on each access inside a loop,
 * which left these loops about 2x the same loops in C (issue 5, target 2). See the kernel's header
 * for the measured difference.
 */

// The slice of the WebAssembly API used here, typed locally: the engine compiles against plain
// ES2022, whose lib has no WebAssembly declarations.
interface KernelMemory {
  readonly buffer: ArrayBuffer;
  grow(pages: number): number;
}
interface KernelExports {
  bin(
    xs: number, ys: number, rs: number, n: number,
    minX: number, minY: number, inverse: number, columns: number, cells: number, radiusScale: number,
    cellStart: number, binOf: number, sortedSlot: number, sortedX: number, sortedY: number, sortedR: number,
  ): void;
  scan(
    cellStart: number, sortedSlot: number, sortedX: number, sortedY: number, sortedR: number,
    columns: number, rows: number, rowFrom: number, rowTo: number, pad: number, pairs: number, capacity: number,
  ): number;
  examined(): number;
}
interface WebAssemblyApi {
  Memory: new (descriptor: { initial: number }) => KernelMemory;
  Module: new (bytes: Uint8Array) => object;
  Instance: new (module: object, imports: object) => { exports: unknown };
}

const PAGE_BYTES = 65536;
const FIRST_PAIR_CAPACITY = 1024;

let compiled: object | null | undefined;
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

/** The compiled kernel module, or null where this runtime has no WebAssembly. */
function kernelModule(): object | null {
  if (compiled !== undefined) return compiled;
  const api = (globalThis as { WebAssembly?: WebAssemblyApi }).WebAssembly;
  // Synchronous compile: the module is about 1 KB, under the 4 KB that browsers allow on the main thread.
  compiled = api ? new api.Module(GRID_KERNEL_WASM) : null;
  return compiled;
}

/**
 * One grid's WebAssembly memory. Layout, by byte offset: the float64 arrays (sorted x, y, r, then
 * the input copies of x, y, r), the int32 ones (binOf, sortedSlot, cellStart), and the pair buffer
 * last, so that the pair buffer can grow without moving anything else.
 */
export class GridKernel {
  private readonly memory: KernelMemory;
  private readonly fn: KernelExports;
  bodyCapacity = 0;
  cellCapacity = 0;
  pairCapacity = FIRST_PAIR_CAPACITY;

  // Byte offsets of each array.
  private inputXAt = 0;
  private inputYAt = 0;
  private inputRAt = 0;
  private cellStartAt = 0;
  private binOfAt = 0;
  private sortedSlotAt = 0;
  private sortedXAt = 0;
  private sortedYAt = 0;
  private sortedRAt = 0;
  private pairsAt = 0;

  // Views of the arrays, remade whenever the memory grows (growing detaches the old buffer).
  inputX = new Float64Array(0);
  inputY = new Float64Array(0);
  inputR = new Float64Array(0);
  cellStart = new Int32Array(0);
  binOf = new Int32Array(0);
  sortedSlot = new Int32Array(0);
  sortedX = new Float64Array(0);
  sortedY = new Float64Array(0);
  sortedR = new Float64Array(0);
  pairs = new Int32Array(0);
  /** Bumped whenever the views are remade: holders of the old ones must take the new. */
  viewVersion = 0;

  /** A kernel, or null where this runtime has no WebAssembly. */
  static create(): GridKernel | null {
    const module = kernelModule();
    if (module === null) return null;
    const api = (globalThis as unknown as { WebAssembly: WebAssemblyApi }).WebAssembly;
    const memory = new api.Memory({ initial: 1 });
    const instance = new api.Instance(module, { env: { memory } });
    return new GridKernel(memory, instance.exports as KernelExports);
  }

  private constructor(memory: KernelMemory, fn: KernelExports) {
    this.memory = memory;
    this.fn = fn;
  }

  /**
   * Lays the arrays out for at least `bodies` bodies and `cells` cells (cellStart needs cells + 2).
   * Moving them loses their contents, which is fine before a bin, the only caller.
   */
  ensure(bodies: number, cells: number): void {
    if (this.bodyCapacity >= bodies && this.cellCapacity >= cells + 2) return;
    if (this.bodyCapacity < bodies) this.bodyCapacity = grownCapacity(this.bodyCapacity, bodies);
    if (this.cellCapacity < cells + 2) this.cellCapacity = grownCapacity(this.cellCapacity, cells + 2);
    const floats = this.bodyCapacity * 8;
    const ints = this.bodyCapacity * 4;
    this.sortedXAt = 0;
    this.sortedYAt = floats;
    this.sortedRAt = 2 * floats;
    this.inputXAt = 3 * floats;
    this.inputYAt = 4 * floats;
    this.inputRAt = 5 * floats;
    this.binOfAt = 6 * floats;
    this.sortedSlotAt = this.binOfAt + ints;
    this.cellStartAt = this.sortedSlotAt + ints;
    this.pairsAt = this.cellStartAt + this.cellCapacity * 4;
    this.reserve();
  }

  /** Grows the pair buffer to hold at least `pairs` pairs; the other arrays keep their place and contents. */
  growPairs(pairs: number): void {
    this.pairCapacity = grownCapacity(this.pairCapacity, pairs);
    this.reserve();
  }

  private reserve(): void {
    const bytes = this.pairsAt + this.pairCapacity * 8;
    const have = this.memory.buffer.byteLength;
    if (bytes > have) this.memory.grow(Math.ceil((bytes - have) / PAGE_BYTES));
    const buffer = this.memory.buffer;
    const bodies = this.bodyCapacity;
    this.inputX = new Float64Array(buffer, this.inputXAt, bodies);
    this.inputY = new Float64Array(buffer, this.inputYAt, bodies);
    this.inputR = new Float64Array(buffer, this.inputRAt, bodies);
    this.cellStart = new Int32Array(buffer, this.cellStartAt, this.cellCapacity);
    this.binOf = new Int32Array(buffer, this.binOfAt, bodies);
    this.sortedSlot = new Int32Array(buffer, this.sortedSlotAt, bodies);
    this.sortedX = new Float64Array(buffer, this.sortedXAt, bodies);
    this.sortedY = new Float64Array(buffer, this.sortedYAt, bodies);
    this.sortedR = new Float64Array(buffer, this.sortedRAt, bodies);
    this.pairs = new Int32Array(buffer, this.pairsAt, 2 * this.pairCapacity);
    this.viewVersion++;
  }

  /** CellGrid.bin over inputX/Y/R[0..n), which the caller has filled. */
  bin(n: number, minX: number, minY: number, inverse: number, columns: number, cells: number, radiusScale: number): void {
    this.fn.bin(
      this.inputXAt, this.inputYAt, this.inputRAt, n,
      minX, minY, inverse, columns, cells, radiusScale,
      this.cellStartAt, this.binOfAt, this.sortedSlotAt, this.sortedXAt, this.sortedYAt, this.sortedRAt,
    );
  }

  /**
   * CellGrid.scanRows into `pairs`: returns the pair count, after growing the buffer and scanning
   * again if it overflowed. `examined` then holds the pairs examined.
   */
  scan(columns: number, rows: number, rowFrom: number, rowTo: number, pad: number): number {
    let found = this.scanOnce(columns, rows, rowFrom, rowTo, pad);
    if (found > this.pairCapacity) {
      this.growPairs(found);
      found = this.scanOnce(columns, rows, rowFrom, rowTo, pad);
    }
    return found;
  }

  get examined(): number {
    return this.fn.examined();
  }

  memoryBytes(): number {
    return this.memory.buffer.byteLength;
  }

  private scanOnce(columns: number, rows: number, rowFrom: number, rowTo: number, pad: number): number {
    return this.fn.scan(
      this.cellStartAt, this.sortedSlotAt, this.sortedXAt, this.sortedYAt, this.sortedRAt,
      columns, rows, rowFrom, rowTo, pad, this.pairsAt, this.pairCapacity,
    );
  }
}
