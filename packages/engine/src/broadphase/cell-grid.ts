import type { BodyStore } from '../store/body-store.js';
import type { BodyKernel } from '../store/body-kernel.js';
import type { PairSink } from '../store/pair-sink.js';
import { allocateLike, grownCapacity } from '../util/grow.js';
import { ARENA_LIMIT_BYTES, GridKernel, gridKernelEnabled, type KernelLayout, type KernelMemory } from './grid-kernel.js';
import { pushOverlaps, scanRowsInScript } from './cell-grid-scan.js';

/**
 * The cell index of coordinate p along an axis of `count` cells from `origin`: floored, and
 * clamped into [0, count), so that a body outside the grid's extent lands in an edge cell and no
 * index leaves the arrays. Clamping keeps touching bodies in neighbouring cells (it never moves
 * two coordinates further apart), so the extent a grid is laid over is a matter of speed alone.
 * NaN clamps to 0. Within the extent, the `| 0` truncates exactly as Math.floor would, faster.
 */
export function cellIndex(p: number, origin: number, inverse: number, count: number): number {
  const t = (p - origin) * inverse;
  return t > 0 ? (t < count - 1 ? t | 0 : count - 1) : 0;
}

/**
 * One uniform grid over a set of bodies, built by counting sort: count per cell, prefix sum,
 * scatter. O(bodies + cells), nothing allocated per cell, and the scatter copies each body's x, y
 * and radius into cell order so that scans read memory sequentially instead of chasing slots
 * (radii as they are: scans pad them as fat-bounds.ts says while reading them, which gives the
 * same bits as padding them here, and leaves the exact radius for a touching test). Cells are
 * row-major, so a run of cells in one row is one contiguous range of bodies.
 *
 * Where WebAssembly is available the arrays live in a GridKernel's memory and binning (of slots
 * 0..n-1, or of a slot list holding at least a quarter of the slots) and scanning run there, with
 * the same results bit for bit (a large world whose bodies lie scattered in memory against space
 * bins in two levels there, see GridKernel.binBanded and parallel/banded-bin.ts); the loops below
 * are the TypeScript path, used without WebAssembly, for bins over sparser slot lists, for grids a
 * parallel step's threads bin, and for a serial scan whose shared pair buffer overflowed.
 *
 * Correctness rests on one rule, kept by the callers: the cell size is at least the largest
 * contact distance between a body in this grid and any body tested against it, so touching
 * bodies are never more than one cell apart.
 */
export class CellGrid {
  originX = 0;
  originY = 0;
  cellSize = 0;
  columns = 0;
  rows = 0;
  count = 0;

  cellStart: Int32Array = new Int32Array(2);
  sortedSlot: Int32Array = new Int32Array(0);
  sortedX: Float64Array = new Float64Array(0);
  sortedY: Float64Array = new Float64Array(0);
  sortedR: Float64Array = new Float64Array(0);
  /** 1 / cellSize, shared by sizing, binning and lookups so all round identically. */
  inverse = 0;
  /** Each body's cell, in input order: scratch of the counting sort. */
  binOf: Int32Array = new Int32Array(0);
  /** Buffers live on SharedArrayBuffers, for the threads of a parallel step. */
  shared = false;
  /** Bumped whenever the buffers are reallocated. */
  layoutVersion = 0;
  /** Banded bins the kernel refused (see GridKernel.binBanded): for tests. */
  get bandedRefusals(): number {
    return this.kernel?.bandedRefusals ?? 0;
  }
  /** Whether binning and scanning run in WebAssembly (known from the first layout on). */
  get usesKernel(): boolean {
    return !!this.kernel;
  }
  /** The WebAssembly arrays and loops: undefined until the first layout, null on the TypeScript path. */
  private kernel: GridKernel | null | undefined = undefined;
  /** Whether kernels were enabled when this grid was made (see setGridKernelEnabled). */
  private readonly kernelWanted = gridKernelEnabled();
  /** The shared body memory a shared grid's kernel lives in (see useArena), or null. */
  private arena: BodyKernel | null = null;
  /** Threads that scan a shared grid, each into its own pair buffer; this grid's scans use `pairRegion`. */
  private threads = 1;
  pairRegion = 0;
  /** Pairs the last kernel scan found (see scanRowsOrOverflow). */
  pairsFound = 0;
  /** Bins that took the kernel's two-level path (see GridKernel.binBanded): for tests and probes. */
  bandedBins = 0;
  /**
   * Whether the parallel step's threads bin this layout in bands (see parallel/banded-bin.ts):
   * decided as the layout is made, since their cells pass runs before anything else.
   */
  bandedThreads = false;
  private kernelViews = -1;
  // Views of the bodies' columns over slots 0..n-1, which the kernel bins from, remade only when
  // the store reallocates its columns (its layoutVersion) or n changes: a warm step makes no views.
  private sourceX = new Float64Array(0);
  private sourceY = new Float64Array(0);
  private sourceR = new Float64Array(0);
  private sourceStore: BodyStore | null = null;
  private sourceLayout = -1;
  // The view of a slot list's [offset, offset + n) copied for the kernel, remade when any changes.
  private listSource: Int32Array | null = null;
  private listOffset = -1;
  private listView: Int32Array = new Int32Array(0);

  /**
   * Sizes the grid over the extent [minX, maxX] x [minY, maxY] with cells of at least
   * `minCellSize`, enlarged until there are at most `cellBudget` cells, and bins
   * `slots[offset..offset+n)`, or slots 0..n-1 when `slots` is null (a world without holes).
   * An offset rather than a subarray: a subarray is a new object, and this runs every step.
   */
  build(
    bodies: BodyStore,
    slots: Int32Array | null,
    offset: number,
    n: number,
    minX: number,
    minY: number,
    maxX: number,
    maxY: number,
    minCellSize: number,
    cellBudget: number,
  ): void {
    this.layout(minX, minY, maxX, maxY, minCellSize, cellBudget, n);
    this.bin(bodies, slots, offset, n);
  }

  /** Sizes the grid and its buffers for `n` bodies, without binning them (see `build`). */
  layout(minX: number, minY: number, maxX: number, maxY: number, minCellSize: number, cellBudget: number, n: number): void {
    // Bodies of radius 0 (shapeless, with no margin to pad them) all at one point ask for cells of
    // size 0, or near 1e-300 only a few ulps wide, whose inverse (infinite) would make the grid
    // NaN columns wide: any size then does.
    let cellSize = minCellSize > 0 && 1 / minCellSize < Infinity ? minCellSize : 1;
    let inv = 1 / cellSize;
    let columns = Math.floor((maxX - minX) * inv) + 1;
    let rows = Math.floor((maxY - minY) * inv) + 1;
    // Grown a quarter at a time: coarser steps overshoot. On `mixed` at 64,000 (1:100), steps of
    // 1.5 took the small circles' hgrid level from 16 to 36-unit cells and 190,000 pairs examined
    // a step; quarters stop at 25 units and 92,000 pairs (auto's step 2.9-3.3% faster, same contacts).
    while (columns * rows > cellBudget) {
      cellSize *= 1.25;
      inv = 1 / cellSize;
      columns = Math.floor((maxX - minX) * inv) + 1;
      rows = Math.floor((maxY - minY) * inv) + 1;
    }
    this.originX = minX;
    this.originY = minY;
    this.cellSize = cellSize;
    this.inverse = inv;
    this.columns = columns;
    this.rows = rows;
    this.count = n;
    this.ensure(n, columns * rows);
  }

  /** Counting sort of the bodies into the cells sized by `layout`. */
  bin(bodies: BodyStore, slots: Int32Array | null, offset: number, n: number): void {
    const { columns, rows, originX: minX, originY: minY, inverse: inv } = this;
    const cells = columns * rows;
    const { x, y, radius } = bodies;
    const kernel = this.kernel;
    // The kernel reads whole columns, copied in one block each: slots 0..n-1, or for a slot list
    // every slot up to slotCount, which pays when the list holds at least a quarter of them (a
    // world with holes, hgrid's fullest levels); sparser lists bin in the loops below.
    const span = slots === null ? n : bodies.slotCount;
    if (kernel && (slots === null || 4 * n >= span)) {
      kernel.ensureInputs(span);
      if (slots !== null) kernel.ensureSlotList(n);
      // A shared grid binned here (between parallel steps) bins plainly: its threads' choice is made in `ensure`.
      const banded = slots === null && !kernel.shared && kernel.wantsBanded(n);
      if (banded) kernel.ensureBanded(n, cells);
      if (kernel.viewVersion !== this.kernelViews) this.adoptKernelViews(kernel);
      if (this.sourceStore !== bodies || this.sourceLayout !== bodies.layoutVersion || this.sourceX.length !== span) {
        this.sourceStore = bodies;
        this.sourceLayout = bodies.layoutVersion;
        this.sourceX = x.subarray(0, span);
        this.sourceY = y.subarray(0, span);
        this.sourceR = radius.subarray(0, span);
      }
      kernel.inputX.set(this.sourceX);
      kernel.inputY.set(this.sourceY);
      kernel.copyRadii(this.sourceR, 0, bodies.membershipVersion);
      if (slots !== null) {
        if (this.listSource !== slots || this.listOffset !== offset || this.listView.length !== n) {
          this.listSource = slots;
          this.listOffset = offset;
          this.listView = slots.subarray(offset, offset + n);
        }
        kernel.slotList.set(this.listView);
      }
      if (banded && kernel.binBanded(n, minX, minY, inv, columns, cells)) {
        this.bandedBins++;
        return;
      }
      kernel.bin(n, slots !== null, minX, minY, inv, columns, cells);
      return;
    }
    const { cellStart, binOf, sortedSlot, sortedX, sortedY, sortedR } = this;
    cellStart.fill(0, 0, cells + 2);
    for (let k = 0; k < n; k++) {
      const i = slots === null ? k : slots[offset + k];
      const c = cellIndex(y[i], minY, inv, rows) * columns + cellIndex(x[i], minX, inv, columns);
      binOf[k] = c;
      cellStart[c]++;
    }
    // Inclusive prefix sums make cellStart[c] the end of cell c; scattering from the back with
    // pre-decrement then leaves it at the start of cell c, with slots ascending inside each cell.
    for (let c = 1; c < cells; c++) cellStart[c] += cellStart[c - 1];
    for (let k = n - 1; k >= 0; k--) {
      const c = binOf[k];
      const at = --cellStart[c];
      const i = slots === null ? k : slots[offset + k];
      sortedSlot[at] = i;
      sortedX[at] = x[i];
      sortedY[at] = y[i];
      sortedR[at] = radius[i];
    }
    cellStart[cells] = n;
    cellStart[cells + 1] = n;
  }

  /**
   * Examines every pair inside this grid once: from each body, the rest of its cell and the east
   * cell (one range), then the three cells of the next row (another range); the other four
   * neighbours are covered from their side. Pushes pairs whose padded circles overlap (a squared
   * distance test: one branch, and the narrow-phase then sees about as many pairs as contacts); returns the
   * number of pairs examined.
   */
  scanSelf(out: PairSink, pad: number): number {
    return this.scanRows(out, pad, 0, this.rows);
  }

  /**
   * scanSelf for the pairs found from cells in rows [rowFrom, rowTo): disjoint row bands find
   * disjoint sets of pairs, whose union is scanSelf's, so threads can scan bands side by side.
   */
  scanRows(out: PairSink, pad: number, rowFrom: number, rowTo: number): number {
    const examined = this.scanRowsOrOverflow(out, pad, rowFrom, rowTo);
    // Only a shared grid overflows (a private one grows and rescans): scanned serially, say in a
    // world with holes between parallel steps, its band takes the TypeScript loops instead.
    return examined >= 0 ? examined : scanRowsInScript(this, out, pad, rowFrom, rowTo);
  }

  /**
   * scanRows for the threads of a parallel step: returns -1, having pushed nothing, when this
   * thread's shared pair buffer is too small; `pairsFound` then says how many pairs it needs, and
   * the step grows the buffers (growPairBuffers) and scans again, as it does for contact lists.
   */
  scanRowsOrOverflow(out: PairSink, pad: number, rowFrom: number, rowTo: number): number {
    const kernel = this.kernel;
    if (!kernel) return scanRowsInScript(this, out, pad, rowFrom, rowTo);
    const touching = out.contactsDirect;
    const found = kernel.scan(this.columns, this.rows, rowFrom, rowTo, this.originX, this.inverse, pad, touching, this.pairRegion);
    if (kernel.viewVersion !== this.kernelViews) this.adoptKernelViews(kernel);
    this.pairsFound = found;
    if (found > kernel.pairCapacity) return -1;
    const pairs = kernel.pairs;
    const base = 2 * this.pairRegion * kernel.pairCapacity;
    // Read before the loop, so that nothing follows it (see ShapeNarrowPhase.collidePairs).
    const examined = kernel.examined;
    if (touching) {
      // The kernel tested the pairs for touching already (see assembly `scan`): these are contacts.
      out.pushContacts(pairs, base, base + 2 * found, kernel.candidates);
    } else {
      for (let p = base; p < base + 2 * found; p += 2) out.push(pairs[p], pairs[p + 1]);
    }
    return examined;
  }

  /** Grows a shared grid's pair buffers to hold `pairs` pairs each, between stages; true when they grew. */
  growPairBuffers(pairs: number): boolean {
    const kernel = this.kernel;
    if (!kernel || pairs <= kernel.pairCapacity) return false;
    kernel.growPairs(pairs);
    this.adoptKernelViews(kernel);
    return true;
  }

  /**
   * Examines a body of another grid against the full 3x3 neighbourhood of the cell holding its
   * centre here: three row ranges. Used across hierarchy levels, where each pair is found from
   * the finer side only. Returns the number of pairs examined.
   */
  scanAround(px: number, py: number, reach: number, slot: number, out: PairSink): number {
    const { columns, rows, cellStart } = this;
    // A foreign body outside this grid's extent is clamped into an edge cell, as the bin clamps
    // this grid's own (cellIndex): then touching bodies are still at most one cell apart.
    const column = Math.min(Math.max(this.columnOf(px), 0), columns - 1);
    const row = Math.min(Math.max(this.rowOf(py), 0), rows - 1);
    const c0 = Math.max(column - 1, 0);
    const c1 = Math.min(column + 1, columns - 1);
    const r0 = Math.max(row - 1, 0);
    const r1 = Math.min(row + 1, rows - 1);
    let examined = 0;
    for (let r = r0; r <= r1; r++) {
      examined += pushOverlaps(this, cellStart[r * columns + c0], cellStart[r * columns + c1 + 1], px, py, reach, slot, out);
    }
    return examined;
  }

  /**
   * Examines a body of another grid, the circle (px, py, reach), against every body here whose
   * centre lies within `halfWidth` of (px, py) on both axes: the cells of that window, one range
   * per row. Used across hierarchy levels from the coarser side when that side has far fewer
   * bodies; `halfWidth` must cover reach plus this grid's largest padded radius. Returns the
   * number of pairs examined.
   */
  scanWindow(px: number, py: number, reach: number, slot: number, halfWidth: number, out: PairSink): number {
    const { columns, rows, cellStart } = this;
    // Both ends clamped into the grid, as its bodies' cells are (cellIndex): a window past the
    // extent still covers the edge cells that hold the bodies beyond it.
    const c0 = Math.min(Math.max(this.columnOf(px - halfWidth), 0), columns - 1);
    const c1 = Math.min(Math.max(this.columnOf(px + halfWidth), 0), columns - 1);
    const r0 = Math.min(Math.max(this.rowOf(py - halfWidth), 0), rows - 1);
    const r1 = Math.min(Math.max(this.rowOf(py + halfWidth), 0), rows - 1);
    if (c0 > c1 || r0 > r1) return 0;
    const kernel = this.kernel;
    // A shared kernel's pair buffer cannot grow mid-step; such grids take the loop below.
    if (kernel && !kernel.shared) {
      const found = kernel.scanWindow(columns, c0, c1, r0, r1, px, py, reach, slot);
      if (kernel.viewVersion !== this.kernelViews) this.adoptKernelViews(kernel);
      const pairs = kernel.pairs;
      for (let p = 0; p < 2 * found; p += 2) out.push(pairs[p], pairs[p + 1]);
      return kernel.examined;
    }
    let examined = 0;
    for (let r = r0; r <= r1; r++) {
      examined += pushOverlaps(this, cellStart[r * columns + c0], cellStart[r * columns + c1 + 1], px, py, reach, slot, out);
    }
    return examined;
  }

  /** Column of an x coordinate; may lie outside [0, columns) for points outside the extent (unlike a body's cell, see cellIndex). */
  columnOf(px: number): number {
    return Math.floor((px - this.originX) * this.inverse);
  }

  rowOf(py: number): number {
    return Math.floor((py - this.originY) * this.inverse);
  }

  memoryBytes(): number {
    if (this.kernel) return this.kernel.memoryBytes();
    return (
      this.cellStart.byteLength +
      this.sortedSlot.byteLength * 2 +
      this.sortedX.byteLength * 3
    );
  }

  /**
   * Moves the buffers onto shared memory for `threads` threads (or back); the next `layout`
   * reallocates them.
   */
  setShared(shared: boolean, threads = 1): void {
    if (shared === this.shared && threads === this.threads) return;
    this.shared = shared;
    this.threads = shared ? threads : 1;
    this.cellStart = new Int32Array(2);
    this.sortedSlot = new Int32Array(0);
    // A private kernel's memory cannot be shared, nor a shared one's pair buffers re-counted: a
    // fresh kernel of the right kind comes with the next layout.
    this.kernel = undefined;
    this.kernelViews = -1;
  }

  /**
   * For a shared grid: puts its kernel in `bodies`' shared memory, past the columns, from the next
   * layout on, so that the threads' bin passes read positions and radii in place rather than
   * copying them in first (1M bodies, 2 threads: the copies took 1.2-1.5 ms of each thread's
   * motion). Null, a kernel without shared memory, or one whose columns already fill half its
   * maximum (ARENA_LIMIT_BYTES), keeps a memory of the grid's own.
   */
  useArena(bodies: BodyKernel | null): void {
    this.arena = bodies?.sharedMemory && bodies.memoryBytes() <= ARENA_LIMIT_BYTES ? bodies : null;
  }

  private ensure(n: number, cells: number): void {
    const shared = this.shared;
    const arena = shared ? this.arena : null;
    // A kernel in a body memory the bodies have left (they grew into a fresh one) would read stale columns.
    const strayed = this.kernel && this.kernel.inBodyMemory && this.kernel.memory !== arena?.sharedMemory;
    if (this.kernel === undefined || strayed) {
      this.kernel = !this.kernelWanted ? null : arena ? GridKernel.inside(arena.sharedMemory!, arena.ownBytes, this.threads) : GridKernel.create(shared, this.threads);
      this.kernelViews = -1;
    }
    const kernel = this.kernel;
    if (kernel) {
      kernel.ensure(n, cells);
      // Outside the body memory, a parallel step's threads copy positions and radii in before their bin passes.
      if (shared && !kernel.inBodyMemory) kernel.ensureInputs(n);
      // A parallel step's threads bin after this, and must find the banded bin's room in place.
      this.bandedThreads = shared && kernel.wantsBanded(n);
      if (this.bandedThreads) kernel.ensureBanded(n, cells);
      if (kernel.viewVersion !== this.kernelViews) this.adoptKernelViews(kernel);
      return;
    }
    if (this.cellStart.length < cells + 2) {
      this.cellStart = allocateLike(this.cellStart, grownCapacity(this.cellStart.length, cells + 2), shared);
      this.layoutVersion++;
    }
    if (this.sortedSlot.length >= n) return;
    const capacity = grownCapacity(this.sortedSlot.length, n);
    this.binOf = allocateLike(this.binOf, capacity, shared);
    this.sortedSlot = allocateLike(this.sortedSlot, capacity, shared);
    this.sortedX = allocateLike(this.sortedX, capacity, shared);
    this.sortedY = allocateLike(this.sortedY, capacity, shared);
    this.sortedR = allocateLike(this.sortedR, capacity, shared);
    this.layoutVersion++;
  }

  /** The kernel of a shared grid, whose bin passes a parallel step's threads run; null otherwise. */
  get sharedKernel(): GridKernel | null {
    const kernel = this.kernel;
    return kernel && kernel.shared ? kernel : null;
  }

  /** The shared memory and layout that worker threads attach to, or null on the TypeScript path. */
  get kernelShare(): { memory: KernelMemory; layout: KernelLayout } | null {
    const kernel = this.kernel;
    return kernel && kernel.shared ? { memory: kernel.memory, layout: kernel.layout } : null;
  }

  /** A worker's view of the caller's shared kernel grid (see kernelShare). */
  attachKernel(memory: KernelMemory, layout: KernelLayout): boolean {
    const kernel = GridKernel.attach(memory, layout);
    if (!kernel) return false;
    this.kernel = kernel;
    this.adoptKernelViews(kernel);
    return true;
  }

  private adoptKernelViews(kernel: GridKernel): void {
    this.cellStart = kernel.cellStart;
    this.binOf = kernel.binOf;
    this.sortedSlot = kernel.sortedSlot;
    this.sortedX = kernel.sortedX;
    this.sortedY = kernel.sortedY;
    this.sortedR = kernel.sortedR;
    this.kernelViews = kernel.viewVersion;
    this.layoutVersion++;
  }
}
