import type { BodyStore } from '../store/body-store.js';
import type { ContactBuffer } from '../store/contact-buffer.js';
import { CellGrid } from '../broadphase/cell-grid.js';
import type { GridKernel } from '../broadphase/grid-kernel.js';
import { grownCapacity, type Column } from '../util/grow.js';
import { EscapeLog, resolveContact, type SolverSettings } from '../solver/contact-solver.js';
import { clampBodies } from '../solver/box-walls.js';
import type { CircleIntegratorName as IntegratorName } from '../integrate/integrator.js';
import {
  BODY_COLUMNS,
  Command,
  INTEGRATOR_IDS,
  MAX_THREADS,
  Param,
  RESULT_STRIDE,
  Result,
  Slot,
  shareStart,
  type BodyColumnName,
  type BufferMessage,
} from './control.js';
import { ThreadKernels } from './kernels.js';
import { ThreadGovernor } from './governor.js';
import { hardwareThreads, spinBudget, startWorker, threadsUnavailable, type WorkerHandle, type WorkerScript } from './host.js';
import { awaitWorkers, publishCommand } from './handoff.js';
import { finiteNumber } from '../util/validate.js';

/**
 * Worlds with fewer live bodies step on one thread by default: each parallel stage costs a
 * handoff, and below this the handoffs cost more than the shared work saves (measured on the
 * uniform scene, one thread against two: docs/engine.md, Numbers).
 */
export const DEFAULT_MIN_BODIES = 32_768;

export function checkWorkerCount(threads: number): void {
  finiteNumber('workerCount', threads);
  if (!Number.isSafeInteger(threads) || threads < 1 || threads > MAX_THREADS) {
    throw new RangeError(`workerCount must be an integer in [1, ${MAX_THREADS}], got ${threads}`);
  }
}

/** Everything a step's motion stage needs, as the pipeline holds it. */
export interface MotionSettings {
  integrator: IntegratorName;
  gravityX: number;
  gravityY: number;
  dt: number;
  box: { width: number; height: number } | null;
  wallRestitution: number;
  restitutionThreshold: number;
}

/**
 * The caller's side of a parallel step: it owns the shared control block and every shared buffer,
 * publishes commands, runs thread 0's share itself and waits for the others.
 *
 * Which stages run in parallel, and why the bits do not change:
 * - motion (integrate, then the box walls, then in a box each body's cell), in chunks claimed as
 *   threads come free: every body's update reads only that body;
 * - the Max Grid build (each body's cell per body range, then count and scatter per band of
 *   cells, bands claimed as threads come free, giving exactly the serial layout) and the scan of row blocks, claimed as threads come
 *   free, with the narrow-phase: each thread finds a disjoint share of the same contact set, and
 *   the step sorts contacts canonically before solving, as it always does;
 * - solve: the canonical order is cut into one block per thread; each thread resolves the
 *   contacts of its block whose bodies no earlier block touches, and the caller then resolves
 *   the deferred rest in order, so every body sees the serial sequence of updates
 *   (solveContactBlock explains why that is exact). With events or sleepers it runs serially;
 * - correct (clamping contact bodies into the box): each thread owns a slot range.
 * Continuous collision, segments, events, sleeping and the other broad-phases run serially,
 * between the parallel stages.
 */
export class ParallelStep {
  readonly threads: number;
  /** Steps of worlds with fewer live bodies than this run on the calling thread alone. */
  minBodies = DEFAULT_MIN_BODIES;
  /** Chooses between the threads and the calling thread alone step by step; null: always the threads. */
  governor: ThreadGovernor | null = new ThreadGovernor();
  private readonly control: Int32Array;
  private readonly params: Float64Array;
  private readonly results: Float64Array;
  private readonly caller: ThreadKernels;
  private epoch = 0;
  private sentBodies = -1;
  private sentGrid: CellGrid | null = null;
  private sentGridVersion = -1;
  private listsVersion = 0;
  private sentLists = -1;
  private sentContacts = -1;
  /** Summed over threads by the last findContacts. */
  candidates = 0;
  filtered = 0;
  narrowMs = 0;

  private constructor(
    private readonly bodies: BodyStore,
    private readonly canonical: ContactBuffer,
    private readonly workers: WorkerHandle[],
    control: Int32Array,
    params: Float64Array,
    results: Float64Array,
  ) {
    this.threads = workers.length + 1;
    this.control = control;
    this.params = params;
    this.results = results;
    this.caller = new ThreadKernels(0, control, params, results, bodies, new CellGrid());
    control[Slot.threads] = this.threads;
    for (let t = 0; t < this.threads; t++) {
      this.caller.contactLo.push(new Int32Array(new SharedArrayBuffer(4 * 1024)));
      this.caller.contactHi.push(new Int32Array(new SharedArrayBuffer(4 * 1024)));
    }
    this.caller.bindContactList();
    this.caller.deferred = new Int32Array(new SharedArrayBuffer(4 * 1024));
    this.caller.escaped = new Int32Array(new SharedArrayBuffer(8 * 1024));
    this.lateEscapes.list = new Int32Array(2 * 1024);
  }

  /**
   * Starts `threads - 1` workers, on `script` or by default the engine's worker script; the caller
   * is thread 0. Moves the body columns and the contact buffer to shared memory. Each step then
   * passes the grid it bins into.
   */
  static async start(threads: number, bodies: BodyStore, contacts: ContactBuffer, script?: WorkerScript): Promise<ParallelStep> {
    checkWorkerCount(threads);
    const why = threadsUnavailable();
    if (why) throw new Error(`cannot start worker threads: ${why}`);
    const control = new Int32Array(new SharedArrayBuffer(Slot.length * 4));
    const params = new Float64Array(new SharedArrayBuffer(Param.length * 8));
    const results = new Float64Array(new SharedArrayBuffer(RESULT_STRIDE * MAX_THREADS * 8));
    control[Slot.spinMicroseconds] = spinBudget(threads, await hardwareThreads());
    const workers: WorkerHandle[] = [];
    try {
      for (let index = 1; index < threads; index++) {
        workers.push(await startWorker({ kind: 'init', index, control: control.buffer, params: params.buffer, results: results.buffer }, script));
      }
    } catch (error) {
      for (const worker of workers) worker.terminate();
      throw error;
    }
    bodies.setShared(true);
    contacts.setShared(true);
    return new ParallelStep(bodies, contacts, workers, control, params, results);
  }

  stop(): void {
    if (this.workers.length > 0) this.publish(Command.stop);
    for (const worker of this.workers) worker.terminate();
    this.workers.length = 0;
  }

  /**
   * Integrates every body, then (with `bounce`) bounces them off the box walls, then (with `grid`,
   * already laid out) computes each body's cell in it.
   */
  motion(settings: MotionSettings, bounce: boolean, grid: CellGrid | null, coordPad: number): void {
    if (grid) this.useGrid(grid, coordPad);
    this.control[Slot.binInMotion] = grid ? 1 : 0;
    this.control[Slot.membership] = this.bodies.membershipVersion | 0;
    const c = this.control;
    const p = this.params;
    const b = this.bodies;
    c[Slot.slotCount] = b.slotCount;
    c[Slot.customMotion] = b.customMotionCount;
    c[Slot.forcesPending] = b.forcesPending ? 1 : 0;
    c[Slot.sleeping] = b.sleepingCount;
    c[Slot.integrator] = INTEGRATOR_IDS.indexOf(settings.integrator);
    c[Slot.bounce] = bounce && settings.box ? 1 : 0;
    p[Param.gravityX] = settings.gravityX;
    p[Param.gravityY] = settings.gravityY;
    p[Param.dt] = settings.dt;
    p[Param.boxWidth] = settings.box?.width ?? 0;
    p[Param.boxHeight] = settings.box?.height ?? 0;
    p[Param.wallRestitution] = settings.wallRestitution;
    p[Param.restitutionThreshold] = settings.restitutionThreshold;
    p[Param.maxRadius] = b.maxRadius();
    p[Param.speedCap] = b.speedCap;
    c[Slot.motionChunk] = 0;
    this.run(Command.motion);
  }

  /**
   * Bins every body into `grid` (already laid out over dense slots 0..n-1; `binned` when motion
   * already computed each body's cell), scans it and
   * narrow-phases the candidates on all threads, then appends each thread's contacts to
   * `contacts`, unsorted. Returns the pairs examined.
   */
  findContacts(grid: CellGrid, coordPad: number, contacts: ContactBuffer, binned: boolean): number {
    const c = this.control;
    c[Slot.everyPairCollides] = this.bodies.everyPairCollides ? 1 : 0;
    if (!binned) {
      this.useGrid(grid, coordPad);
      this.run(Command.bin);
    }
    const kernel = grid.sharedKernel;
    if (kernel) {
      let jumps = 0;
      for (let t = 0; t < this.threads; t++) jumps += c[Slot.jumps + t];
      kernel.noteJumps(jumps);
    }
    if (!(grid.bandedThreads && kernel && this.binBanded(grid, kernel))) {
      c[Slot.countBand] = 0;
      c[Slot.scatterBand] = 0;
      this.run(Command.count);
      this.run(Command.scatter);
    }
    this.growAhead(grid);
    this.scan();
    // Contact lists and pair buffers that overflowed grow, and the scan runs again (both may grow
    // in one round: no short-circuit).
    while (+this.growOverflowingLists() | +this.growOverflowingPairBuffers(grid)) this.scan();

    let examined = 0;
    this.candidates = 0;
    this.filtered = 0;
    this.narrowMs = this.results[Result.narrowMs];
    for (let t = 0; t < this.threads; t++) {
      const at = t * RESULT_STRIDE;
      examined += this.results[at + Result.examined];
      this.candidates += this.results[at + Result.candidates];
      this.filtered += this.results[at + Result.filtered];
      const lo = this.caller.contactLo[t];
      const hi = this.caller.contactHi[t];
      // Lists their threads sorted merge in order; then the step's sort has nothing left to do.
      if (c[Slot.listSorted + t] === 1) contacts.mergeSorted(lo, hi, c[Slot.contactCount + t]);
      else contacts.append(lo, hi, c[Slot.contactCount + t]);
    }
    return examined;
  }

  /**
   * The banded bin on all threads (see banded-bin.ts), once the cells pass has run; false, having
   * binned nothing, when a band is too full for the scratch (the plain passes then bin).
   */
  private binBanded(grid: CellGrid, kernel: GridKernel): boolean {
    // Each thread's share has a counter row and a scratch of its own: one per pair region.
    if (kernel.pairRegions !== this.threads) return false;
    const c = this.control;
    c[Slot.bandShift] = kernel.bandShift;
    c[Slot.bands] = kernel.bands;
    this.run(Command.bandCount);
    if (!kernel.planPartition(grid.count, this.threads, kernel.bands)) return false;
    this.run(Command.partition);
    c[Slot.sortBand] = 0;
    this.run(Command.sortBands);
    const cells = grid.columns * grid.rows;
    grid.cellStart[cells] = grid.count;
    grid.cellStart[cells + 1] = grid.count;
    grid.bandedBins++;
    return true;
  }

  /** Runs the scan with every block unclaimed (threads claim them as they go, see ThreadKernels.scan). */
  private scan(): void {
    this.control[Slot.scanBlock] = 0;
    this.run(Command.scan);
  }

  /**
   * Grows the grid kernel's pair buffers when a thread's scan needed more than its buffer (it then
   * reported the pairs needed as its candidates and pushed none); true when the scan must rerun.
   */
  private growOverflowingPairBuffers(grid: CellGrid): boolean {
    let most = 0;
    for (let t = 0; t < this.threads; t++) most = Math.max(most, this.results[t * RESULT_STRIDE + Result.candidates]);
    return grid.growPairBuffers(most);
  }

  /**
   * Resolves the step's contacts, already in canonical order: blocks of that order on every
   * thread, then the contacts they deferred, here, in order (see solveContactBlock). Only for
   * steps without events or sleepers, whose bookkeeping the solver would otherwise update.
   */
  solve(settings: SolverSettings, box: { width: number; height: number } | null): void {
    const c = this.control;
    const count = this.canonical.count;
    c[Slot.contactTotal] = count;
    c[Slot.slotCount] = this.bodies.slotCount;
    this.params[Param.restitutionThreshold] = settings.restitutionThreshold;
    this.params[Param.positionCorrection] = settings.positionCorrection;
    this.params[Param.contactSlop] = settings.contactSlop;
    this.params[Param.boxWidth] = box?.width ?? 0;
    this.params[Param.boxHeight] = box?.height ?? 0;
    const k = this.caller;
    if (k.deferred.length < count) {
      const capacity = grownCapacity(k.deferred.length, count);
      k.deferred = new Int32Array(new SharedArrayBuffer(capacity * 4));
      k.escaped = new Int32Array(new SharedArrayBuffer(capacity * 8));
      this.lateEscapes.list = new Int32Array(2 * capacity);
      this.listsVersion++;
    }
    k.canonicalLo = this.canonical.lo;
    k.canonicalHi = this.canonical.hi;
    this.run(Command.solve);
    const { lo, hi } = this.canonical;
    const deferred = k.deferred;
    const late = this.lateEscapes;
    late.reset(late.list, 0, box?.width ?? 0, box?.height ?? 0);
    for (let t = 0; t < this.threads; t++) {
      const from = shareStart(count, t, this.threads);
      const waiting = c[Slot.deferredCount + t];
      for (let q = 0; q < waiting; q++) {
        const at = deferred[from + q];
        resolveContact(this.bodies, lo[at], hi[at], settings, null);
        late.note(this.bodies, lo[at], hi[at]);
      }
    }
  }

  /** Bodies the deferred pass of `solve` left outside the box. */
  private readonly lateEscapes = new EscapeLog();

  /**
   * After `solve`: clamps into the box just the bodies that the solve noted outside it, on this
   * thread (a handful per step, against every contact body for `clamp`).
   */
  clampEscaped(box: { width: number; height: number }): void {
    const c = this.control;
    const count = this.canonical.count;
    const escaped = this.caller.escaped;
    for (let t = 0; t < this.threads; t++) {
      const from = 2 * shareStart(count, t, this.threads);
      clampBodies(this.bodies, escaped, from, from + c[Slot.escapedCount + t], box.width, box.height);
    }
    clampBodies(this.bodies, this.lateEscapes.list, 0, this.lateEscapes.count, box.width, box.height);
  }

  private useGrid(grid: CellGrid, coordPad: number): void {
    const c = this.control;
    const p = this.params;
    this.caller.grid = grid;
    c[Slot.bodyCount] = grid.count;
    c[Slot.columns] = grid.columns;
    c[Slot.rows] = grid.rows;
    p[Param.originX] = grid.originX;
    p[Param.originY] = grid.originY;
    p[Param.inverseCell] = grid.inverse;
    p[Param.coordPad] = coordPad;
  }

  /** Clamps the bodies of the step's contacts into the box (when the solve ran serially). */
  clamp(box: { width: number; height: number }): void {
    this.params[Param.boxWidth] = box.width;
    this.params[Param.boxHeight] = box.height;
    this.control[Slot.slotCount] = this.bodies.slotCount;
    this.control[Slot.contactTotal] = this.canonical.count;
    this.caller.canonicalLo = this.canonical.lo;
    this.caller.canonicalHi = this.canonical.hi;
    this.run(Command.clamp);
  }

  memoryBytes(): number {
    let bytes = 0;
    for (let t = 0; t < this.threads; t++) {
      bytes += this.caller.contactLo[t].byteLength * 2;
    }
    return bytes + this.caller.deferred.byteLength + this.caller.escaped.byteLength + this.lateEscapes.list.byteLength;
  }

  /** Publishes a command, runs the caller's share, waits for every worker. */
  private run(command: number): void {
    this.syncBuffers();
    this.publish(command);
    this.caller.run(command);
    this.awaitWorkers();
  }

  private publish(command: number): void {
    publishCommand(this.control, command);
  }

  private awaitWorkers(): void {
    awaitWorkers(this.control, this.workers.length);
  }

  /**
   * Sends workers the shared buffers whenever one was reallocated (bodies added, a larger grid, a
   * longer contact list) and waits until each holds them: a step never runs on stale memory.
   */
  private syncBuffers(): void {
    const grid = this.caller.grid;
    if (
      this.sentBodies === this.bodies.layoutVersion &&
      this.sentGrid === grid &&
      this.sentGridVersion === grid.layoutVersion &&
      this.sentLists === this.listsVersion &&
      this.sentContacts === this.canonical.layoutVersion
    ) {
      return;
    }
    this.sentBodies = this.bodies.layoutVersion;
    this.sentGrid = grid;
    this.sentGridVersion = grid.layoutVersion;
    this.sentLists = this.listsVersion;
    this.sentContacts = this.canonical.layoutVersion;
    if (this.workers.length === 0) return;
    const epoch = ++this.epoch;
    const columns = this.bodies as unknown as Record<BodyColumnName, Column>;
    const bodies = {} as Record<BodyColumnName, Column>;
    for (const name of BODY_COLUMNS) bodies[name] = columns[name];
    const k = this.caller;
    const message: BufferMessage = {
      kind: 'buffers',
      epoch,
      bodies,
      bodyKernel: this.bodies.kernel?.sharedMemory ?? null,
      cellStart: grid.cellStart.buffer as SharedArrayBuffer,
      binOf: grid.binOf.buffer as SharedArrayBuffer,
      sortedSlot: grid.sortedSlot.buffer as SharedArrayBuffer,
      sortedX: grid.sortedX.buffer as SharedArrayBuffer,
      sortedY: grid.sortedY.buffer as SharedArrayBuffer,
      sortedR: grid.sortedR.buffer as SharedArrayBuffer,
      gridKernel: grid.kernelShare,
      contactLo: k.contactLo.map((a) => a.buffer as SharedArrayBuffer),
      contactHi: k.contactHi.map((a) => a.buffer as SharedArrayBuffer),
      canonicalLo: this.canonical.lo.buffer as SharedArrayBuffer,
      canonicalHi: this.canonical.hi.buffer as SharedArrayBuffer,
      deferred: k.deferred.buffer as SharedArrayBuffer,
      escaped: k.escaped.buffer as SharedArrayBuffer,
    };
    for (const worker of this.workers) worker.postMessage(message);
    this.control[Slot.epoch] = epoch;
    this.publish(Command.sync);
    this.awaitWorkers();
  }

  /**
   * Before a step's scan: grows each contact list, and the pair buffers, that the last step filled
   * past three quarters. Counts change little from one step to the next, and a list that overflows
   * costs a second scan of the whole grid: at 1,000,000 bodies, whose contacts climb from 3,000 to
   * 48,000 over the first ten steps, three of the first fifteen steps scanned twice or three times.
   */
  private growAhead(grid: CellGrid): void {
    this.growLists(4 / 3);
    let most = 0;
    for (let t = 0; t < this.threads; t++) most = Math.max(most, this.results[t * RESULT_STRIDE + Result.candidates]);
    grid.growPairBuffers(Math.ceil((most * 4) / 3));
  }

  /** Enlarges every contact list that overflowed in the last scan; true when the scan must rerun. */
  private growOverflowingLists(): boolean {
    return this.growLists(1);
  }

  /** Enlarges every contact list whose last count times `headroom` exceeds it; true when any grew. */
  private growLists(headroom: number): boolean {
    const k = this.caller;
    let grew = false;
    for (let t = 0; t < this.threads; t++) {
      const needed = Math.ceil(this.control[Slot.contactCount + t] * headroom);
      if (needed <= k.contactLo[t].length) continue;
      const capacity = grownCapacity(k.contactLo[t].length, needed);
      k.contactLo[t] = new Int32Array(new SharedArrayBuffer(capacity * 4));
      k.contactHi[t] = new Int32Array(new SharedArrayBuffer(capacity * 4));
      grew = true;
    }
    if (grew) {
      k.bindContactList();
      this.listsVersion++;
    }
    return grew;
  }
}
