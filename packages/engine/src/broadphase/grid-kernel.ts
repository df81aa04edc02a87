import { grownCapacity } from '../util/grow.js';
import { RADIUS_PAD } from './fat-bounds.js';
import { BandedPolicy, bandedBin, planBandStarts } from './banded-policy.js';
import { instantiateKernel, PAGE_BYTES, webAssembly, type KernelMemory } from '../util/wasm.js';
import { CELL_CHUNK, kernelModule, SHARED_MAXIMUM_PAGES, type KernelExports } from './grid-kernel-module.js';

export { bandedBin } from './banded-policy.js';
export { ARENA_LIMIT_BYTES, CELL_CHUNK, gridKernelEnabled, setGridKernelEnabled } from './grid-kernel-module.js';
export type { KernelMemory };

const FIRST_PAIR_CAPACITY = 1024;

/**
 * The WebAssembly side of CellGrid: its arrays laid out in one WebAssembly memory, and the two hot
 * loops, binning and scanning, compiled from assembly/grid-kernel.ts (code in assembly/grid/).
 * Same operations, same order, same bits as the TypeScript loops in cell-grid.ts, which remain the
 * path wherever WebAssembly is missing, and for the shared grids of a parallel step.
 *
 * Why: V8 re-checks every typed array's map, length and base pointer on each access inside a loop,
 * which left these loops about 2x the same loops in C (issue 5, target 2). See the kernel's header
 * for the measured difference.
 */

/** Where a shared grid's arrays lie in its memory, for the threads that scan it. */
export interface KernelLayout {
  base: number;
  bodyCapacity: number;
  inputCapacity: number;
  slotListCapacity: number;
  cellCapacity: number;
  bandCapacity: number;
  scratchCapacity: number;
  pairCapacity: number;
  pairRegions: number;
}

/**
 * One grid's WebAssembly memory. Layout, by byte offset: the float64 arrays (sorted x, y, r, then
 * the input copies of x, y, r, if any), the int32 ones (chunk cell ranges and slot list if any,
 * binOf, sortedSlot, cellStart), and the pair buffer last, so that the pair buffer can grow
 * without moving anything else.
 */
export class GridKernel {
  /**
   * Where this grid's arrays start: 0 in a memory of its own; past the body columns when it lives
   * in a parallel world's shared body memory (see `inside`), where its passes read the bodies'
   * positions and radii in place instead of copies.
   */
  readonly base: number;
  bodyCapacity = 0;
  /** Room for input copies, made only by grids that bin here (see ensureInputs). */
  inputCapacity = 0;
  /** Room for a slot list, made only by grids that bin one here (see ensureSlotList). */
  slotListCapacity = 0;
  cellCapacity = 0;
  /**
   * Room for a banded bin's band counters (int32: a row of bands + 1 per pair region, then one of
   * band starts) and its scratch (bodies of 32 bytes, per pair region).
   */
  private bandCapacity = 0;
  private scratchCapacity = 0;
  /** When this grid bins in bands, in which, and with how much scratch. */
  private readonly banding = new BandedPolicy();
  /** A shared grid's jumps in the last step's cell passes, which its threads sum (see noteJumps). */
  private sharedJumps = 0;
  pairCapacity = FIRST_PAIR_CAPACITY;
  // What the last copyRadii copied.
  private radiiOf: Float64Array | null = null;
  private radiiAt = -1;
  private radiiMembership = 0;
  private radiiViews = -1;
  /** Pairs the last full scan found (a private kernel's scans grow the buffer ahead of it). */
  private lastFound = 0;

  // Byte offsets of each array.
  private inputXAt = 0;
  private inputYAt = 0;
  private inputRAt = 0;
  private chunkCellsAt = 0;
  private slotListAt = 0;
  private cellStartAt = 0;
  private bandStartAt = 0;
  private scratchAt = 0;
  private binOfAt = 0;
  private sortedSlotAt = 0;
  private sortedXAt = 0;
  private sortedYAt = 0;
  private sortedRAt = 0;
  private pairsAt = 0;

  // Views of the arrays, remade whenever the memory grows (growing detaches the old buffer).
  inputX: Float64Array = new Float64Array(0);
  inputY: Float64Array = new Float64Array(0);
  inputR: Float64Array = new Float64Array(0);
  /** Per chunk of CELL_CHUNK bodies, its smallest and largest cell (see cellsOf). */
  chunkCells: Int32Array = new Int32Array(0);
  slotList: Int32Array = new Int32Array(0);
  cellStart: Int32Array = new Int32Array(0);
  /** A banded bin's counter rows (see bandRowAt). */
  private bandRows: Int32Array = new Int32Array(0);
  binOf: Int32Array = new Int32Array(0);
  sortedSlot: Int32Array = new Int32Array(0);
  sortedX: Float64Array = new Float64Array(0);
  sortedY: Float64Array = new Float64Array(0);
  sortedR: Float64Array = new Float64Array(0);
  pairs: Int32Array = new Int32Array(0);
  /** Bumped whenever the views are remade: holders of the old ones must take the new. */
  viewVersion = 0;

  /** A kernel, or null where this runtime has no WebAssembly. */
  static create(shared = false, pairRegions = 1): GridKernel | null {
    const module = kernelModule(shared);
    if (module === null) return null;
    const api = webAssembly()!;
    let memory: KernelMemory;
    try {
      memory = new api.Memory(shared ? { initial: 1, maximum: SHARED_MAXIMUM_PAGES, shared: true } : { initial: 1 });
    } catch {
      // A shared memory reserves its maximum in address space, which a constrained runtime may
      // refuse: the grid then keeps the TypeScript path, on SharedArrayBuffers.
      return null;
    }
    return GridKernel.on(memory, module, shared, pairRegions);
  }

  /**
   * A shared kernel whose arrays lie in `memory` from byte `base` on, growing it as they need:
   * the body columns' shared memory, whose columns end before `base`. Growing a shared memory
   * moves and detaches nothing, so the columns' views stay valid. Null where this runtime lacks
   * shared WebAssembly memory.
   */
  static inside(memory: KernelMemory, base: number, pairRegions: number): GridKernel | null {
    const module = kernelModule(true);
    return module === null ? null : GridKernel.on(memory, module, true, pairRegions, base);
  }

  /** A worker's kernel over the caller's shared memory and layout (see `layout`). */
  static attach(memory: KernelMemory, layout: KernelLayout): GridKernel | null {
    const module = kernelModule(true);
    if (module === null) return null;
    const kernel = GridKernel.on(memory, module, true, layout.pairRegions, layout.base);
    kernel.pairCapacity = layout.pairCapacity;
    kernel.bodyCapacity = layout.bodyCapacity;
    kernel.inputCapacity = layout.inputCapacity;
    kernel.slotListCapacity = layout.slotListCapacity;
    kernel.cellCapacity = layout.cellCapacity;
    kernel.bandCapacity = layout.bandCapacity;
    kernel.scratchCapacity = layout.scratchCapacity;
    kernel.place();
    return kernel;
  }

  private static on(memory: KernelMemory, module: object, shared: boolean, pairRegions: number, base = 0): GridKernel {
    return new GridKernel(memory, instantiateKernel<KernelExports>(module, memory), shared, pairRegions, base);
  }

  private constructor(
    readonly memory: KernelMemory,
    private readonly fn: KernelExports,
    readonly shared: boolean,
    /** Pair buffers, one per thread that scans (1 for a private grid). */
    readonly pairRegions: number,
    base: number,
  ) {
    this.base = base;
  }

  /** Whether this grid lives in a body memory (see `inside`), where its passes read the columns in place. */
  get inBodyMemory(): boolean {
    return this.base > 0;
  }

  get layout(): KernelLayout {
    const { base, bodyCapacity, inputCapacity, slotListCapacity, cellCapacity, bandCapacity, scratchCapacity, pairCapacity, pairRegions } = this;
    return { base, bodyCapacity, inputCapacity, slotListCapacity, cellCapacity, bandCapacity, scratchCapacity, pairCapacity, pairRegions };
  }

  /**
   * Lays the arrays out for at least `bodies` bodies and `cells` cells (cellStart needs cells + 2).
   * Moving them loses their contents, which is fine before a bin, the only caller.
   */
  ensure(bodies: number, cells: number): void {
    if (this.bodyCapacity >= bodies && this.cellCapacity >= cells + 2) return;
    if (this.bodyCapacity < bodies) this.bodyCapacity = grownCapacity(this.bodyCapacity, bodies);
    if (this.cellCapacity < cells + 2) this.cellCapacity = grownCapacity(this.cellCapacity, cells + 2);
    this.place();
  }

  /**
   * Makes room for input copies of n bodies (24 bytes per body), which only grids that bin in the
   * kernel need: not the smaller hgrid levels, which bin sparse slot lists in TypeScript. Like
   * `ensure`, it may move the arrays, so call it before binning.
   */
  ensureInputs(n: number): void {
    if (this.inputCapacity >= n) return;
    this.inputCapacity = grownCapacity(this.inputCapacity, n);
    this.place();
  }

  /** Makes room for a slot list of n slots (bins of slot lists, see CellGrid.bin); may move the arrays, as ensureInputs. */
  ensureSlotList(n: number): void {
    if (this.slotListCapacity >= n) return;
    this.slotListCapacity = grownCapacity(this.slotListCapacity, n);
    this.place();
  }

  /** Grows the pair buffers to hold at least `pairs` pairs each; the other arrays keep their place and contents. */
  growPairs(pairs: number): void {
    this.pairCapacity = grownCapacity(this.pairCapacity, pairs);
    this.reserve();
  }

  /** Two int32 per chunk of bodies (cellsOf's chunk cell ranges), for the shared grids that use them. */
  private get chunkCellsLength(): number {
    return this.shared ? 2 * Math.ceil(this.bodyCapacity / CELL_CHUNK) : 0;
  }

  private place(): void {
    const floats = this.bodyCapacity * 8;
    const inputs = this.inputCapacity * 8;
    const ints = this.bodyCapacity * 4;
    this.sortedXAt = this.base;
    this.sortedYAt = this.sortedXAt + floats;
    this.sortedRAt = this.sortedYAt + floats;
    this.inputXAt = this.sortedRAt + floats;
    this.inputYAt = this.inputXAt + inputs;
    this.inputRAt = this.inputYAt + inputs;
    this.chunkCellsAt = this.inputRAt + inputs;
    this.slotListAt = this.chunkCellsAt + this.chunkCellsLength * 4;
    this.binOfAt = this.slotListAt + this.slotListCapacity * 4;
    this.sortedSlotAt = this.binOfAt + ints;
    this.cellStartAt = this.sortedSlotAt + ints;
    this.bandStartAt = this.cellStartAt + this.cellCapacity * 4;
    // Rounded up to 8: the scratch holds float64s.
    this.scratchAt = (this.bandStartAt + this.bandCapacity * 4 + 7) & ~7;
    this.pairsAt = this.scratchAt + this.pairRegions * this.scratchCapacity * 32;
    this.reserve();
  }

  private reserve(): void {
    const bytes = this.pairsAt + this.pairRegions * this.pairCapacity * 8;
    const have = this.memory.buffer.byteLength;
    // A worker attached to a shared memory only reads the size the caller grew it to.
    if (bytes > have) this.memory.grow(Math.ceil((bytes - have) / PAGE_BYTES));
    const buffer = this.memory.buffer;
    const bodies = this.bodyCapacity;
    const inputs = this.inputCapacity;
    this.inputX = new Float64Array(buffer, this.inputXAt, inputs);
    this.inputY = new Float64Array(buffer, this.inputYAt, inputs);
    this.inputR = new Float64Array(buffer, this.inputRAt, inputs);
    this.chunkCells = new Int32Array(buffer, this.chunkCellsAt, this.chunkCellsLength);
    this.slotList = new Int32Array(buffer, this.slotListAt, this.slotListCapacity);
    this.cellStart = new Int32Array(buffer, this.cellStartAt, this.cellCapacity);
    this.bandRows = new Int32Array(buffer, this.bandStartAt, this.bandCapacity);
    this.binOf = new Int32Array(buffer, this.binOfAt, bodies);
    this.sortedSlot = new Int32Array(buffer, this.sortedSlotAt, bodies);
    this.sortedX = new Float64Array(buffer, this.sortedXAt, bodies);
    this.sortedY = new Float64Array(buffer, this.sortedYAt, bodies);
    this.sortedR = new Float64Array(buffer, this.sortedRAt, bodies);
    this.pairs = new Int32Array(buffer, this.pairsAt, 2 * this.pairCapacity * this.pairRegions);
    this.viewVersion++;
  }

  /**
   * CellGrid.bin over inputX/Y/R, which the caller has filled: of slots 0..n-1, or with `slotList`
   * of the n slots in slotList[0..n) (and inputs filled up to the largest of them).
   */
  bin(n: number, slotList: boolean, minX: number, minY: number, inverse: number, columns: number, cells: number): void {
    // Offset 0 means "no list": no slot list starts there, the sorted x column lies ahead of it.
    this.fn.bin(
      this.inputXAt, this.inputYAt, this.inputRAt, slotList ? this.slotListAt : 0, n,
      minX, minY, inverse, columns, cells,
      this.cellStartAt, this.binOfAt, this.sortedSlotAt, this.sortedXAt, this.sortedYAt, this.sortedRAt,
      // Jumps only decide whether the next bin is banded, which smaller grids never are.
      !slotList && n >= bandedBin.minBodies,
    );
  }

  /**
   * Whether the next bin of n bodies (slots 0..n-1) should be banded: at least bandedBin.minBodies
   * of them, and the last bin found more than a quarter of them far from the body before (assembly
   * `jumps`; for a shared grid, what its threads' cells pass counted, see noteJumps).
   */
  wantsBanded(n: number): boolean {
    return this.banding.wants(n, this.jumps);
  }

  /** The last bin's jumps (assembly `jumps`; 0 where it had fewer than bandedBin.minBodies bodies), or a shared grid's (see noteJumps). */
  get jumps(): number {
    return this.shared ? this.sharedJumps : this.fn.jumps();
  }

  /** A shared grid's jumps, summed over the threads' cell passes of a step (cellsOf's returns). */
  noteJumps(jumps: number): void {
    this.sharedJumps = jumps;
  }

  /** The bands the last ensureBanded chose: cells per band (log 2), and how many. */
  get bandShift(): number {
    return this.banding.shift;
  }

  get bands(): number {
    return this.banding.bands;
  }

  /** Banded bins that found a band too full for the scratch and left the bin to `bin`: for tests. */
  get bandedRefusals(): number {
    return this.banding.refusals;
  }

  /**
   * Makes room for a banded bin of n bodies over `cells` cells and chooses its bands (bandShift,
   * bands). Like `ensure`, it may move the arrays: call it before filling the inputs or cells.
   */
  ensureBanded(n: number, cells: number): void {
    const scratch = this.banding.choose(n, cells);
    const counters = (this.pairRegions + 1) * (this.banding.bands + 1);
    if (this.bandCapacity >= counters && this.scratchCapacity >= scratch) return;
    if (this.bandCapacity < counters) this.bandCapacity = grownCapacity(this.bandCapacity, counters);
    if (this.scratchCapacity < scratch) this.scratchCapacity = grownCapacity(this.scratchCapacity, scratch);
    this.place();
  }

  /**
   * `bin` of slots 0..n-1 in two levels (assembly binBanded), after ensureBanded gave `shift`.
   * Returns false, having binned nothing, when a band held more bodies than the scratch: the
   * caller then bins with `bin` (BandedPolicy.refuse says what follows).
   */
  binBanded(n: number, minX: number, minY: number, inverse: number, columns: number, cells: number): boolean {
    const most = this.fn.binBanded(
      this.inputXAt, this.inputYAt, this.inputRAt, n, minX, minY, inverse, columns, cells,
      this.cellStartAt, this.binOfAt, this.sortedSlotAt, this.sortedXAt, this.sortedYAt, this.sortedRAt,
      this.banding.shift, this.bandStartAt, this.scratchAt, this.scratchCapacity,
    );
    return most === 0 || this.banding.refuse(most, n);
  }

  // A parallel banded bin (see parallel/banded-bin.ts): band counts and a partition per share of
  // bodies, whose counter rows are the pair regions' (shares are threads), then bands claimed one
  // at a time. Band b of `bands` lies at [bandStarts[b], bandStarts[b + 1]).

  /** The counters of row `row` (a share's, or the band starts after the last share's). */
  private bandRowAt(row: number, bands: number): number {
    return this.bandStartAt + row * (bands + 1) * 4;
  }

  /** Counts share `share`'s bodies [from, to) per band (after cellsOf). */
  bandCounts(from: number, to: number, share: number, bandShift: number, bands: number): void {
    this.fn.bandCounts(this.binOfAt, from, to, bandShift, this.bandRowAt(share, bands), bands);
  }

  /**
   * Between the counts and the partition, on one thread: the shares' cursors and the band starts
   * (see planBandStarts). False, when a band holds more bodies than the scratch: the step then
   * bins plainly (see binBanded).
   */
  planPartition(n: number, shares: number, bands: number): boolean {
    const most = planBandStarts(this.bandRows, shares, bands, n);
    return most <= this.scratchCapacity || this.banding.refuse(most, n);
  }

  /** The stable scatter of share `share`'s bodies [from, to) into their bands; bodies read as scatterCells reads them. */
  partition(from: number, to: number, share: number, bandShift: number, bands: number, xs = this.inputXAt, ys = this.inputYAt, rs = this.inputRAt): void {
    this.fn.partition(this.binOfAt, from, to, bandShift, this.bandRowAt(share, bands), xs, ys, rs, this.sortedSlotAt, this.sortedXAt, this.sortedYAt, this.sortedRAt);
  }

  /** Sorts band b into its cells, through pair region `region`'s scratch. */
  sortBand(b: number, bandShift: number, bands: number, shares: number, cells: number, minX: number, minY: number, inverse: number, columns: number, region: number): void {
    const start = shares * (bands + 1) + b;
    this.fn.sortBand(
      b, bandShift, this.bandRows[start], this.bandRows[start + 1], cells, minX, minY, inverse, columns,
      this.cellStartAt, this.sortedSlotAt, this.sortedXAt, this.sortedYAt, this.sortedRAt,
      this.scratchAt + region * this.scratchCapacity * 32, this.scratchCapacity,
    );
  }

  /**
   * CellGrid.scanRows into pair buffer `region` (pairs from index 2 * region * pairCapacity):
   * returns the pair count, which exceeds pairCapacity when the buffer overflowed. A private
   * kernel then grows the buffer and scans again; a shared one cannot grow while other threads
   * read it, so the parallel step grows it between stages and runs the scan stage again.
   * `examined` then holds the pairs examined.
   */
  scan(columns: number, rows: number, rowFrom: number, rowTo: number, originX: number, inverse: number, pad: number, touching: boolean, region = 0): number {
    // Pair counts change little between steps: grow ahead of a full buffer rather than scan twice.
    if (!this.shared && 4 * this.lastFound > 3 * this.pairCapacity) this.growPairs(Math.ceil((this.lastFound * 4) / 3));
    let found = this.scanOnce(columns, rows, rowFrom, rowTo, originX, inverse, pad, touching, region);
    if (found > this.pairCapacity && !this.shared) {
      this.growPairs(found);
      found = this.scanOnce(columns, rows, rowFrom, rowTo, originX, inverse, pad, touching, region);
    }
    this.lastFound = found;
    return found;
  }

  /** CellGrid.scanWindow into pair buffer 0, growing it (private kernels only) until the pairs fit. */
  scanWindow(columns: number, c0: number, c1: number, r0: number, r1: number, px: number, py: number, reach: number, slot: number): number {
    for (;;) {
      const found = this.fn.scanWindow(
        this.cellStartAt, this.sortedSlotAt, this.sortedXAt, this.sortedYAt, this.sortedRAt,
        columns, c0, c1, r0, r1, px, py, reach, 1 + RADIUS_PAD, slot, this.pairsAt, this.pairCapacity,
      );
      if (found <= this.pairCapacity || this.shared) return found;
      this.growPairs(found);
    }
  }

  /**
   * Copies `radius` into inputR from index `at`, unless this very copy is still there: radii never
   * change while a body lives, so only a change of membership (`membership`, the store's
   * membershipVersion) or a move of the arrays calls for it again.
   */
  copyRadii(radius: Float64Array, at: number, membership: number): void {
    if (this.radiiOf === radius && this.radiiAt === at && this.radiiMembership === membership && this.radiiViews === this.viewVersion) return;
    this.inputR.set(radius, at);
    this.radiiOf = radius;
    this.radiiAt = at;
    this.radiiMembership = membership;
    this.radiiViews = this.viewVersion;
  }

  // A parallel bin's passes (see assembly/grid/parallel-bin.ts), over the input copies.

  /**
   * Cells of bodies [from, to), and their chunks' cell ranges: `from` must be a multiple of
   * CELL_CHUNK. Positions are read at byte offsets xs, ys: the body columns themselves for a grid
   * `inside` their memory, otherwise the input copies.
   */
  cellsOf(from: number, to: number, minX: number, minY: number, inverse: number, columns: number, rows: number, xs = this.inputXAt, ys = this.inputYAt): number {
    return this.fn.cellsOf(xs, ys, from, to, minX, minY, inverse, columns, columns * rows, this.binOfAt, this.chunkCellsAt);
  }

  countCells(n: number, from: number, to: number): number {
    return this.fn.countCells(this.binOfAt, n, from, to, this.cellStartAt, this.chunkCellsAt);
  }

  /** Prefix sums and scatter of the cells [from, to); bodies are read as cellsOf reads them, radii at rs. */
  scatterCells(n: number, from: number, to: number, before: number, xs = this.inputXAt, ys = this.inputYAt, rs = this.inputRAt): void {
    this.fn.scatterCells(
      this.binOfAt, n, from, to, before, this.cellStartAt, this.chunkCellsAt,
      xs, ys, rs,
      this.sortedSlotAt, this.sortedXAt, this.sortedYAt, this.sortedRAt,
    );
  }

  get examined(): number {
    return this.fn.examined();
  }

  /** Bytes this grid takes: all of its own memory, or what it added to the body memory it lives in. */
  memoryBytes(): number {
    return this.memory.buffer.byteLength - this.base;
  }

  private scanOnce(
    columns: number, rows: number, rowFrom: number, rowTo: number, originX: number, inverse: number, pad: number, touching: boolean, region: number,
  ): number {
    return this.fn.scan(
      this.cellStartAt, this.sortedSlotAt, this.sortedXAt, this.sortedYAt, this.sortedRAt,
      columns, rows, rowFrom, rowTo, originX, inverse, pad, 1 + RADIUS_PAD, touching, this.pairsAt + region * this.pairCapacity * 8, this.pairCapacity,
    );
  }

  /** Pairs whose padded circles overlapped in the last scan, touching or not (see assembly `scan`). */
  get candidates(): number {
    return this.fn.candidates();
  }
}
