import { cellIndex } from '../broadphase/cell-grid.js';
import { BodyStore } from '../store/body-store.js';
import { CellGrid } from '../broadphase/cell-grid.js';
import { CELL_CHUNK, type GridKernel } from '../broadphase/grid-kernel.js';
import { NarrowPhase } from '../narrowphase/narrowphase.js';
import { PairSink } from '../store/pair-sink.js';
import { INTEGRATORS } from '../integrate/integrator.js';
import { needsGeneralMotion } from '../integrate/motion.js';
import { bounceOffBox, clampContactBodiesInRange } from '../solver/box-walls.js';
import { EscapeLog, solveContactBlock, type SolverSettings } from '../solver/contact-solver.js';
import { grownCapacity } from '../util/grow.js';
import { nowMs } from '../util/timer.js';
import { BODY_COLUMNS, Command, INTEGRATOR_IDS, Param, RESULT_STRIDE, Result, Slot, shareStart, type BufferMessage } from './control.js';
import type { Column } from '../util/grow.js';
import { BodyKernel } from '../store/body-kernel.js';
import { GridInputs } from './grid-inputs.js';
import { BoundedContactList } from './bounded-contact-list.js';
import { ContactSorter } from '../store/contact-sorter.js';
import { countClaimedBands, scatterClaimedBands } from './cell-bands.js';
import { countShareBands, partitionShare, sortClaimedBands } from './banded-bin.js';

/** Bodies per motion chunk: ten columns of 4096 doubles stay inside a core's L2 (and a multiple of CELL_CHUNK). */
const MOTION_CHUNK = 4 * CELL_CHUNK;
/**
 * Scan blocks per thread. More blocks even out threads that run at different speeds (a core shared
 * with the garbage collector or another process) down to one block's time; each block costs an
 * atomic add and a binary search over the rows.
 */
const SCAN_BLOCKS_PER_THREAD = 8;

/**
 * One thread's side of a parallel step: the caller (thread 0) and every worker run the same
 * kernels on their own share, so what a stage computes does not depend on who runs it. Each
 * kernel writes only memory its share owns (a slot range, a cell range, its contact list), so shares never race, and the result is the same bits for any thread count.
 */
export class ThreadKernels {
  contactLo: Int32Array[] = [];
  contactHi: Int32Array[] = [];
  /** The step's contacts in canonical order (the caller's ContactBuffer arrays). */
  canonicalLo: Int32Array = new Int32Array(0);
  canonicalHi: Int32Array = new Int32Array(0);
  deferred: Int32Array = new Int32Array(0);
  /** Where solve blocks note bodies left outside the box: block [from, to) writes from 2 from. */
  escaped: Int32Array = new Int32Array(0);
  private readonly escapes = new EscapeLog();
  private mark = new Int32Array(0);
  private stamp = 0;
  private readonly solverSettings: SolverSettings = { restitutionThreshold: 0, hitThreshold: Infinity, positionCorrection: 1, contactSlop: 0, iterations: 1, wakeSpeed: 0 };
  readonly contacts = new BoundedContactList(new Int32Array(0), new Int32Array(0));
  private readonly narrowPhase: NarrowPhase;
  private readonly sink: PairSink;

  private readonly inputs = new GridInputs(MOTION_CHUNK);
  /** This thread's contact-list sort: undefined until the first, null without WebAssembly. */
  private sorter: ContactSorter | null | undefined = undefined;

  constructor(
    readonly index: number,
    readonly control: Int32Array,
    readonly params: Float64Array,
    readonly results: Float64Array,
    readonly bodies: BodyStore,
    public grid: CellGrid,
  ) {
    this.narrowPhase = new NarrowPhase(bodies, this.contacts);
    this.sink = new PairSink(this.narrowPhase, nowMs);
  }

  /** Installs the caller's buffers in a worker (the caller's own thread already holds them). */
  install(message: BufferMessage): void {
    const columns = this.bodies as unknown as Record<string, Column>;
    for (const name of BODY_COLUMNS) columns[name] = message.bodies[name];
    let kernel: BodyKernel | null = null;
    if (message.bodyKernel) {
      kernel = BodyKernel.attach(message.bodyKernel, this.index);
      if (!kernel) throw new Error(`worker ${this.index} cannot run the body WebAssembly kernel on shared memory`);
      kernel.bind(this.bodies);
    }
    this.bodies.kernel = kernel;
    const grid = this.grid;
    grid.pairRegion = this.index;
    if (message.gridKernel) {
      if (!grid.attachKernel(message.gridKernel.memory, message.gridKernel.layout)) {
        throw new Error(`worker ${this.index} cannot run the grid's WebAssembly kernel on shared memory`);
      }
    } else {
      grid.cellStart = new Int32Array(message.cellStart);
      grid.binOf = new Int32Array(message.binOf);
      grid.sortedSlot = new Int32Array(message.sortedSlot);
      grid.sortedX = new Float64Array(message.sortedX);
      grid.sortedY = new Float64Array(message.sortedY);
      grid.sortedR = new Float64Array(message.sortedR);
    }
    this.contactLo = message.contactLo.map((b) => new Int32Array(b));
    this.contactHi = message.contactHi.map((b) => new Int32Array(b));
    this.canonicalLo = new Int32Array(message.canonicalLo);
    this.canonicalHi = new Int32Array(message.canonicalHi);
    this.deferred = new Int32Array(message.deferred);
    this.escaped = new Int32Array(message.escaped);
  }

  /** Points this thread's contact list at its shared arrays (after `install` or a regrowth). */
  bindContactList(): void {
    this.contacts.lo = this.contactLo[this.index];
    this.contacts.hi = this.contactHi[this.index];
  }

  /** A worker's copy of the scalars the caller's stages read from the body store. */
  loadScalars(): void {
    const c = this.control;
    const b = this.bodies;
    b.slotCount = c[Slot.slotCount];
    b.customMotionCount = c[Slot.customMotion];
    b.forcesPending = c[Slot.forcesPending] === 1;
    b.sleepingCount = c[Slot.sleeping];
    b.speedCap = this.params[Param.speedCap];
    const g = this.grid;
    const p = this.params;
    g.columns = c[Slot.columns];
    g.rows = c[Slot.rows];
    g.count = c[Slot.bodyCount];
    g.originX = p[Param.originX];
    g.originY = p[Param.originY];
    g.inverse = p[Param.inverseCell];
  }

  run(command: number): void {
    switch (command) {
      case Command.motion:
        return this.motion();
      case Command.bin:
        return this.bin();
      case Command.count:
        return this.count();
      case Command.scatter:
        return this.scatter();
      case Command.bandCount:
      case Command.partition:
      case Command.sortBands:
        return this.binInBands(command);
      case Command.scan:
        return this.scan();
      case Command.clamp:
        return this.clamp();
      case Command.solve:
        return this.solve();
      default:
        throw new Error(`parallel step: unknown command ${command}`);
    }
  }

  /** Start of this thread's share of `total` items; `shareEnd` is its end (two numbers, not an array: kernels run every step). */
  private shareFrom(total: number): number {
    return shareStart(total, this.index, this.control[Slot.threads]);
  }

  private shareEnd(total: number): number {
    return shareStart(total, this.index + 1, this.control[Slot.threads]);
  }

  /**
   * This thread's share of `total` bodies for the passes that compute cells, cut on multiples of
   * CELL_CHUNK so that each chunk's cell range (GridKernel.cellsOf) has one writer.
   */
  private bodyShareFrom(total: number): number {
    return chunkAligned(total, this.index, this.control[Slot.threads]);
  }

  private bodyShareEnd(total: number): number {
    return chunkAligned(total, this.index + 1, this.control[Slot.threads]);
  }

  /**
   * Integrates (and bounces, and bins) the bodies in chunks of MOTION_CHUNK, claimed from a shared
   * counter as threads come free, as the scan claims its blocks: every chunk's update reads and
   * writes only its own bodies and cells, so who moves which chunk changes no bit. Only a grid
   * kernel that bins from copies of the bodies (worlds without a body kernel) keeps fixed shares:
   * its copies are prepared per share (GridInputs).
   */
  private motion(): void {
    const c = this.control;
    const total = c[Slot.slotCount];
    c[Slot.jumps + this.index] = 0;
    // Only for worlds without holes, where slot k is body k and both shares are the same range.
    const bin = c[Slot.binInMotion] === 1;
    if (bin && this.copyingKernel) {
      const from = this.bodyShareFrom(total);
      const to = this.bodyShareEnd(total);
      this.prepareInputs(from, to);
      for (let at = from; at < to; at += MOTION_CHUNK) this.moveChunk(at, Math.min(at + MOTION_CHUNK, to), true);
      this.copyRadii();
      return;
    }
    const chunks = Math.ceil(total / MOTION_CHUNK);
    for (let chunk = Atomics.add(c, Slot.motionChunk, 1); chunk < chunks; chunk = Atomics.add(c, Slot.motionChunk, 1)) {
      const at = chunk * MOTION_CHUNK;
      this.moveChunk(at, Math.min(at + MOTION_CHUNK, total), bin);
    }
  }

  /** Motion of bodies [from, to), then, with `bin`, their cells: in cache-sized chunks, so that the walls and the bin read bodies integration has just brought in. */
  private moveChunk(from: number, to: number, bin: boolean): void {
    const c = this.control;
    const p = this.params;
    const integrator = INTEGRATOR_IDS[c[Slot.integrator]];
    const bounce = c[Slot.bounce] === 1;
    const dt = p[Param.dt];
    // Plain motion in a box: the body kernel integrates and bounces in one pass.
    const kernel = bounce && !needsGeneralMotion(this.bodies) ? this.bodies.kernel : null;
    if (kernel) {
      kernel.moveInBox(
        from, to, p[Param.gravityX] * dt, p[Param.gravityY] * dt, dt, integrator === 'explicit-euler',
        p[Param.boxWidth], p[Param.boxHeight], p[Param.wallRestitution], p[Param.restitutionThreshold], p[Param.maxRadius],
      );
    } else {
      INTEGRATORS[integrator](this.bodies, p[Param.gravityX], p[Param.gravityY], dt, from, to);
      if (bounce) bounceOffBox(this.bodies, p[Param.boxWidth], p[Param.boxHeight], p[Param.wallRestitution], p[Param.restitutionThreshold], from, to);
    }
    if (bin) this.binRange(from, to);
  }

  private bin(): void {
    const total = this.control[Slot.bodyCount];
    this.control[Slot.jumps + this.index] = 0;
    const from = this.bodyShareFrom(total);
    const to = this.bodyShareEnd(total);
    this.prepareInputs(from, to);
    for (let at = from; at < to; at += MOTION_CHUNK) this.binRange(at, Math.min(at + MOTION_CHUNK, to));
    this.copyRadii();
  }

  /** The grid kernel that bins from copies of the bodies (not one in their memory), or null. */
  private get copyingKernel(): GridKernel | null {
    const kernel = this.grid.sharedKernel;
    return kernel && !kernel.inBodyMemory ? kernel : null;
  }

  private prepareInputs(from: number, to: number): void {
    if (this.copyingKernel) this.inputs.prepare(this.bodies, from, to);
  }

  /** For the grid kernel's scatter: this thread's radii (binRange copies positions). */
  private copyRadii(): void {
    const kernel = this.copyingKernel;
    if (kernel) this.inputs.copyRadii(kernel, this.control[Slot.membership]);
  }

  /** Each body's cell, for a body range: the same formula as CellGrid.bin. */
  private binRange(from: number, to: number): void {
    const c = this.control;
    const p = this.params;
    const columns = c[Slot.columns];
    const binOf = this.grid.binOf;
    const { x, y } = this.bodies;
    const minX = p[Param.originX];
    const minY = p[Param.originY];
    const inv = p[Param.inverseCell];
    const kernel = this.grid.sharedKernel;
    const rows = c[Slot.rows];
    if (kernel && kernel.inBodyMemory) {
      // In the body memory: the kernel reads the columns in place.
      c[Slot.jumps + this.index] += kernel.cellsOf(from, to, minX, minY, inv, columns, rows, x.byteOffset, y.byteOffset);
      return;
    }
    if (kernel) {
      // The grid kernel's passes read the bodies from its own memory: copy this range in first.
      this.inputs.copyPositions(kernel, from);
      c[Slot.jumps + this.index] += kernel.cellsOf(from, to, minX, minY, inv, columns, rows);
      return;
    }
    for (let k = from; k < to; k++) binOf[k] = cellIndex(y[k], minY, inv, rows) * columns + cellIndex(x[k], minX, inv, columns);
  }

  private count(): void {
    countClaimedBands(this.grid, this.control);
  }

  /** A stage of the banded bin (see banded-bin.ts), which only grids with a kernel take; shares as the cells pass cuts them. */
  private binInBands(command: number): void {
    const kernel = this.grid.sharedKernel!;
    const total = this.control[Slot.bodyCount];
    const from = this.bodyShareFrom(total);
    const to = this.bodyShareEnd(total);
    if (command === Command.bandCount) countShareBands(kernel, this.control, this.index, from, to);
    else if (command === Command.partition) partitionShare(kernel, this.bodies, this.control, this.index, from, to);
    else sortClaimedBands(kernel, this.control, this.params, this.index);
  }

  private scatter(): void {
    scatterClaimedBands(this.grid, this.bodies, this.control);
  }

  /**
   * Scans blocks of rows, each holding about 1/(SCAN_BLOCKS_PER_THREAD * threads) of the bodies,
   * claimed one at a time from a shared counter: a thread slowed down by anything else on its core
   * takes fewer blocks instead of holding the others up. Which thread scans which block changes
   * nothing in the result: each list is sorted into canonical order and the caller merges them.
   */
  private scan(): void {
    const c = this.control;
    const threads = c[Slot.threads];
    const blocks = threads * SCAN_BLOCKS_PER_THREAD;
    const contacts = this.contacts;
    contacts.count = 0;
    this.sink.begin();
    this.sink.contactsDirect = c[Slot.everyPairCollides] === 1;
    this.narrowPhase.begin();
    const pad = this.params[Param.coordPad];
    let examined = 0;
    let pairsNeeded = 0;
    for (let block = Atomics.add(c, Slot.scanBlock, 1); block < blocks; block = Atomics.add(c, Slot.scanBlock, 1)) {
      const blockExamined = this.grid.scanRowsOrOverflow(this.sink, pad, this.rowBound(block, blocks), this.rowBound(block + 1, blocks));
      if (blockExamined >= 0) examined += blockExamined;
      else pairsNeeded = Math.max(pairsNeeded, this.grid.pairsFound);
    }
    this.sink.flush();
    const r = this.results;
    const at = this.index * RESULT_STRIDE;
    r[at + Result.examined] = examined;
    // A block that overflowed pushed nothing: report the pairs it needs, which exceed the buffer,
    // and the caller grows the buffers and runs the whole scan again.
    r[at + Result.candidates] = pairsNeeded > 0 ? pairsNeeded : this.sink.total;
    r[at + Result.filtered] = this.narrowPhase.filtered;
    r[at + Result.narrowMs] = this.sink.consumerMs;
    c[Slot.contactCount + this.index] = contacts.count;
    // Each thread puts its own list in canonical order, so that the caller merges the lists
    // instead of sorting them all on one thread.
    c[Slot.listSorted + this.index] = contacts.count <= contacts.lo.length && this.sortList(c[Slot.slotCount]) ? 1 : 0;
  }

  /** Sorts this thread's contact list with the WebAssembly sort; false where there is none. */
  private sortList(slotCount: number): boolean {
    if (this.sorter === undefined) this.sorter = ContactSorter.create();
    if (this.sorter === null) return false;
    const { lo, hi, count } = this.contacts;
    this.sorter.sort(lo, hi, count, slotCount);
    return true;
  }

  /** The first row whose first cell starts at or after share w of `shares` of the bodies. */
  private rowBound(w: number, shares: number): number {
    const { rows, columns, cellStart } = this.grid;
    if (w === 0) return 0;
    if (w === shares) return rows;
    const target = shareStart(this.control[Slot.bodyCount], w, shares);
    let lo = 0;
    let hi = rows;
    while (lo < hi) {
      const mid = (lo + hi) >> 1;
      if (cellStart[mid * columns] >= target) hi = mid;
      else lo = mid + 1;
    }
    return lo;
  }

  private clamp(): void {
    const c = this.control;
    const p = this.params;
    const total = c[Slot.slotCount];
    const from = this.shareFrom(total);
    const to = this.shareEnd(total);
    clampContactBodiesInRange(this.bodies, this.canonicalLo, this.canonicalHi, c[Slot.contactTotal], p[Param.boxWidth], p[Param.boxHeight], from, to);
  }

  private solve(): void {
    const c = this.control;
    const slots = c[Slot.slotCount];
    if (this.mark.length < slots) {
      this.mark = new Int32Array(grownCapacity(this.mark.length, slots));
      this.stamp = 0;
    }
    const total = c[Slot.contactTotal];
    const from = this.shareFrom(total);
    const to = this.shareEnd(total);
    const settings = this.solverSettings;
    const p = this.params;
    settings.restitutionThreshold = p[Param.restitutionThreshold];
    settings.positionCorrection = p[Param.positionCorrection];
    settings.contactSlop = p[Param.contactSlop];
    this.escapes.reset(this.escaped, 2 * from, p[Param.boxWidth], p[Param.boxHeight]);
    c[Slot.deferredCount + this.index] = solveContactBlock(this.bodies, this.canonicalLo, this.canonicalHi, from, to, settings, this.mark, ++this.stamp, this.deferred, this.escapes);
    c[Slot.escapedCount + this.index] = this.escapes.count;
  }
}

/** Thread w's first body in a share cut on multiples of CELL_CHUNK. */
function chunkAligned(total: number, w: number, threads: number): number {
  return w >= threads ? total : Math.floor(shareStart(total, w, threads) / CELL_CHUNK) * CELL_CHUNK;
}

/** A worker's private body store and grid, whose buffers `install` replaces with shared ones. */
export function workerKernels(index: number, control: Int32Array, params: Float64Array, results: Float64Array): ThreadKernels {
  return new ThreadKernels(index, control, params, results, new BodyStore(), new CellGrid());
}
