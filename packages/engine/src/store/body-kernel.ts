import { BODY_KERNEL_SHARED_SIMD_WASM, BODY_KERNEL_SHARED_WASM, BODY_KERNEL_SIMD_WASM, BODY_KERNEL_WASM } from '../generated/body-kernel-wasm.js';
import { grownCapacity, type Column } from '../util/grow.js';
import type { ContactSink } from './contact-buffer.js';
import { compileKernel, instantiateKernel, PAGE_BYTES, webAssembly, type KernelMemory } from '../util/wasm.js';

/**
 * The body columns laid out in one WebAssembly memory, and the plain cases of the per-body and
 * per-contact stages compiled from assembly/body-kernel.ts over them: integration, the box walls,
 * the narrow-phase and the contact solve. Same operations, same order, same bits as the
 * TypeScript loops, which remain the general path (forces, damping, sleepers, events) and the one
 * wherever WebAssembly is missing. A parallel step's columns live in a shared memory, over which
 * each worker thread instantiates the kernel too (see `attach`).
 *
 * Why: V8 re-checks each typed array's map, base and length on every access inside a loop, and
 * these loops touch 4 to 7 columns per body, so the kernel runs integration and the walls in a
 * fraction of the TypeScript loops' time and shortens the whole step (uniform scene, kernel on
 * against off: docs/engine.md, Numbers).
 *
 * The store owns the layout: it places each column with `place` when it (re)allocates, always in a
 * fresh memory, so views taken before a growth stay readable, exactly as with plain typed arrays.
 */

interface BodyKernelExports {
  firstTooFast(vxs: number, vys: number, from: number, to: number, maxSq: number): number;
  integrate(xs: number, ys: number, vxs: number, vys: number, types: number, from: number, to: number, dvx: number, dvy: number, dt: number, explicit: boolean): void;
  bounceOffBox(
    xs: number, ys: number, vxs: number, vys: number, rs: number, es: number, types: number, from: number, to: number,
    width: number, height: number, wallRestitution: number, restitutionThreshold: number,
  ): void;
  moveInBox(
    xs: number, ys: number, vxs: number, vys: number, rs: number, es: number, types: number, from: number, to: number,
    dvx: number, dvy: number, dt: number, explicit: boolean,
    width: number, height: number, wallRestitution: number, restitutionThreshold: number, maxRadius: number,
  ): void;
  narrowPhase(
    xs: number, ys: number, rs: number, types: number, asleeps: number, categories: number, masks: number,
    as: number, bs: number, count: number, outLo: number, outHi: number,
  ): number;
  filtered(): number;
  solveContacts(
    xs: number, ys: number, vxs: number, vys: number, rs: number, invMasses: number, es: number,
    los: number, his: number, count: number, restitutionThreshold: number, positionCorrection: number, contactSlop: number,
    width: number, height: number, escapes: number,
  ): number;
}

/** The solver settings the kernel's contact solve reads (SolverSettings has them). */
export interface KernelSolverSettings {
  restitutionThreshold: number;
  positionCorrection: number;
  contactSlop: number;
}

/** The columns the kernel reads: the store's, under the same names. */
export interface KernelColumns {
  x: Float64Array;
  y: Float64Array;
  vx: Float64Array;
  vy: Float64Array;
  radius: Float64Array;
  invMass: Float64Array;
  restitution: Float64Array;
  type: Uint8Array;
  asleep: Uint8Array;
  category: Uint32Array;
  mask: Uint32Array;
}

/**
 * Pairs copied into the memory per solve or narrow-phase call, and room for what comes out: the
 * bodies a solve leaves outside the box (two per contact), or the narrow-phase's contacts. 32 KB
 * of scratch at the start of the memory (per thread in a shared one).
 */
const CONTACT_CHUNK = 2048;
const SCRATCH_BYTES = CONTACT_CHUNK * 16;
/** A shared memory has one scratch area per thread of a parallel step (at most 16, control.ts MAX_THREADS). */
const SHARED_SCRATCH_AREAS = 16;
/** Room to start each column on an 8-byte boundary. */
const ALIGN = 8;

/** The shared module's declared maximum, in pages (see scripts/build-kernel.mjs). */
const SHARED_MAXIMUM_PAGES = 32768;

const compiled: { private?: object | null; shared?: object | null } = {};
/** Which build `compiled` holds, per memory kind: for bodyKernelBuild. */
const compiledSimd: { private?: boolean; shared?: boolean } = {};
let enabled = true;
let simdWanted = true;

/** Whether kernels made from now on run (see setBodyKernelEnabled). */
export function bodyKernelEnabled(): boolean {
  return enabled;
}

/** The compiled body kernel for a private or a shared memory, or null where this runtime lacks one. */
export function kernelModule(shared: boolean): object | null {
  const key = shared ? 'shared' : 'private';
  if (compiled[key] === undefined) {
    // The SIMD build where this runtime compiles it (the same bits, see moveInBox), else the plain one.
    const simd = simdWanted ? compileKernel(shared ? BODY_KERNEL_SHARED_SIMD_WASM : BODY_KERNEL_SIMD_WASM) : null;
    compiled[key] = simd ?? compileKernel(shared ? BODY_KERNEL_SHARED_WASM : BODY_KERNEL_WASM);
    compiledSimd[key] = simd !== null;
  }
  return compiled[key]!;
}

/** Which build of the body kernel a private memory's kernels run, or null without WebAssembly: for tests; not part of the public API. */
export function bodyKernelBuild(): 'simd' | 'plain' | null {
  if (kernelModule(false) === null) return null;
  return compiledSimd.private ? 'simd' : 'plain';
}

/**
 * Whether kernels made from now on use the body kernel's SIMD build, where the runtime has one:
 * for tests that compare the two builds; not part of the public API.
 */
export function setBodyKernelSimd(on: boolean): void {
  if (on === simdWanted) return;
  simdWanted = on;
  delete compiled.private;
  delete compiled.shared;
}

/**
 * Whether body stores laid out, and contact buffers made, from now on use the kernel. For tests
 * and measurements that compare the two paths; not part of the public API.
 */
export function setBodyKernelEnabled(on: boolean): void {
  enabled = on;
}

type ColumnConstructor = { new (buffer: ArrayBuffer, byteOffset: number, length: number): Column; readonly BYTES_PER_ELEMENT: number };

export class BodyKernel {
  private next: number;
  // Byte offsets of the columns the kernel reads, taken in `bind`.
  private xAt = 0;
  private yAt = 0;
  private vxAt = 0;
  private vyAt = 0;
  private radiusAt = 0;
  private invMassAt = 0;
  private restitutionAt = 0;
  private typeAt = 0;
  private asleepAt = 0;
  private categoryAt = 0;
  private maskAt = 0;
  private readonly scratchLo: Int32Array;
  private readonly scratchHi: Int32Array;
  private readonly scratchEscapes: Int32Array;
  /** Bodies the last solveContacts in a box left outside it: escaped[0..escapedCount). */
  escaped = new Int32Array(64);
  escapedCount = 0;

  /**
   * A kernel whose memory holds `columns` columns of `capacity` elements totalling `bytesPerBody`
   * bytes per body, shared between threads or not, or null where this runtime has no WebAssembly
   * (or no shared WebAssembly memory) or the kernel is switched off.
   */
  static create(capacity: number, bytesPerBody: number, columns: number, shared: boolean): BodyKernel | null {
    if (!enabled) return null;
    const module = kernelModule(shared);
    if (module === null) return null;
    const scratch = SCRATCH_BYTES * (shared ? SHARED_SCRATCH_AREAS : 1);
    const pages = Math.ceil((scratch + capacity * bytesPerBody + columns * ALIGN) / PAGE_BYTES);
    if (shared && pages > SHARED_MAXIMUM_PAGES) return null;
    let memory: KernelMemory;
    try {
      memory = new (webAssembly()!).Memory(shared ? { initial: pages, maximum: SHARED_MAXIMUM_PAGES, shared: true } : { initial: pages });
    } catch {
      return null; // out of address space or memory: the plain typed arrays may still fit
    }
    const kernel = new BodyKernel(memory, instantiateKernel<BodyKernelExports>(module, memory), shared, 0);
    kernel.next = scratch;
    kernel.ownBytes = memory.buffer.byteLength;
    return kernel;
  }

  /**
   * Thread `index`'s kernel over the caller's shared memory (see `sharedMemory`), with its own
   * scratch area; bind it to the columns.
   */
  static attach(memory: KernelMemory, index: number): BodyKernel | null {
    const module = kernelModule(true);
    return module === null ? null : new BodyKernel(memory, instantiateKernel<BodyKernelExports>(module, memory), true, index);
  }

  private constructor(
    private readonly memory: KernelMemory,
    private readonly fn: BodyKernelExports,
    private readonly shared: boolean,
    scratchArea: number,
  ) {
    const buffer = memory.buffer as ArrayBuffer;
    const at = scratchArea * SCRATCH_BYTES;
    this.scratchLo = new Int32Array(buffer, at, CONTACT_CHUNK);
    this.scratchHi = new Int32Array(buffer, at + CONTACT_CHUNK * 4, CONTACT_CHUNK);
    this.scratchEscapes = new Int32Array(buffer, at + CONTACT_CHUNK * 8, 2 * CONTACT_CHUNK);
    this.next = SCRATCH_BYTES;
  }

  /** A zeroed column of `old`'s kind with `capacity` elements in this memory, holding as much of `old` as fits. */
  place<T extends Column>(old: T, capacity: number): T {
    const Ctor = old.constructor as ColumnConstructor;
    const at = Math.ceil(this.next / ALIGN) * ALIGN;
    const column = new Ctor(this.memory.buffer as ArrayBuffer, at, capacity) as T;
    column.set(old.subarray(0, Math.min(old.length, capacity)) as never);
    this.next = at + capacity * Ctor.BYTES_PER_ELEMENT;
    return column;
  }

  /** Notes where the columns the kernel reads were placed. */
  bind(c: KernelColumns): void {
    this.xAt = c.x.byteOffset;
    this.yAt = c.y.byteOffset;
    this.vxAt = c.vx.byteOffset;
    this.vyAt = c.vy.byteOffset;
    this.radiusAt = c.radius.byteOffset;
    this.invMassAt = c.invMass.byteOffset;
    this.restitutionAt = c.restitution.byteOffset;
    this.typeAt = c.type.byteOffset;
    this.asleepAt = c.asleep.byteOffset;
    this.categoryAt = c.category.byteOffset;
    this.maskAt = c.mask.byteOffset;
  }

  /** The memory, for worker threads to attach to, when it is shared. */
  get sharedMemory(): KernelMemory | null {
    return this.shared ? this.memory : null;
  }

  /**
   * Bytes of the memory as created, which the columns and scratch areas fill: a parallel step's
   * grid lives past them in a shared memory (GridKernel.inside), grows it, and counts that part.
   */
  ownBytes = 0;

  memoryBytes(): number {
    return this.ownBytes;
  }

  /** The first slot in [from, to) whose speed squared is not at most limits[0] (see limitSpeeds), or `to`. */
  firstTooFast(from: number, to: number, limits: Float64Array): number {
    return this.fn.firstTooFast(this.vxAt, this.vyAt, from, to, limits[0]);
  }

  integrateSemiImplicit(from: number, to: number, dvx: number, dvy: number, dt: number): void {
    this.fn.integrate(this.xAt, this.yAt, this.vxAt, this.vyAt, this.typeAt, from, to, dvx, dvy, dt, false);
  }

  integrateExplicit(from: number, to: number, dvx: number, dvy: number, dt: number): void {
    this.fn.integrate(this.xAt, this.yAt, this.vxAt, this.vyAt, this.typeAt, from, to, dvx, dvy, dt, true);
  }

  bounceOffBox(from: number, to: number, width: number, height: number, wallRestitution: number, restitutionThreshold: number): void {
    this.fn.bounceOffBox(
      this.xAt, this.yAt, this.vxAt, this.vyAt, this.radiusAt, this.restitutionAt, this.typeAt, from, to,
      width, height, wallRestitution, restitutionThreshold,
    );
  }

  /** The integrator's plain loop, then bounceOffBox, in one pass over slots [from, to). */
  /** `maxRadius`: at least every moving body's radius (see assembly `moveInBox`). */
  moveInBox(
    from: number, to: number, dvx: number, dvy: number, dt: number, explicit: boolean,
    width: number, height: number, wallRestitution: number, restitutionThreshold: number, maxRadius: number,
  ): void {
    this.fn.moveInBox(
      this.xAt, this.yAt, this.vxAt, this.vyAt, this.radiusAt, this.restitutionAt, this.typeAt, from, to,
      dvx, dvy, dt, explicit, width, height, wallRestitution, restitutionThreshold, maxRadius,
    );
  }

  /**
   * Contacts lo[k], hi[k] for k in [0, count), in order, copied in chunks into the scratch area.
   * With a box (width > 0), notes the bodies separation left outside it in `escaped` (see
   * clampBodies).
   */
  solveContacts(lo: Int32Array, hi: Int32Array, count: number, settings: KernelSolverSettings, width: number, height: number): void {
    const { scratchLo, scratchHi, scratchEscapes } = this;
    const { restitutionThreshold, positionCorrection, contactSlop } = settings;
    this.escapedCount = 0;
    for (let from = 0; from < count; from += CONTACT_CHUNK) {
      const to = Math.min(count, from + CONTACT_CHUNK);
      this.copyToScratch(lo, hi, from, to);
      const escaped = this.fn.solveContacts(
        this.xAt, this.yAt, this.vxAt, this.vyAt, this.radiusAt, this.invMassAt, this.restitutionAt,
        scratchLo.byteOffset, scratchHi.byteOffset, to - from, restitutionThreshold, positionCorrection, contactSlop,
        width, height, scratchEscapes.byteOffset,
      );
      if (escaped > 0) this.keepEscapes(escaped);
    }
  }

  /**
   * NarrowPhase.consume over candidate pairs a[k], b[k] for k in [0, count), copied into the
   * scratch area in chunks: pushes each touching pair to `contacts` as (lo, hi), in order, and
   * returns how many pairs collision layers filtered.
   */
  narrowPhase(a: Int32Array, b: Int32Array, count: number, contacts: ContactSink): number {
    const { scratchLo, scratchHi, scratchEscapes } = this;
    const outHiAt = scratchEscapes.byteOffset + CONTACT_CHUNK * 4;
    let filtered = 0;
    for (let from = 0; from < count; from += CONTACT_CHUNK) {
      const to = Math.min(count, from + CONTACT_CHUNK);
      this.copyToScratch(a, b, from, to);
      const found = this.fn.narrowPhase(
        this.xAt, this.yAt, this.radiusAt, this.typeAt, this.asleepAt, this.categoryAt, this.maskAt,
        scratchLo.byteOffset, scratchHi.byteOffset, to - from, scratchEscapes.byteOffset, outHiAt,
      );
      filtered += this.fn.filtered();
      // Contacts out: the first half of the escapes area holds lo, the second hi.
      for (let k = 0; k < found; k++) contacts.push(scratchEscapes[k], scratchEscapes[CONTACT_CHUNK + k]);
    }
    return filtered;
  }

  /** Contacts waiting for solveQueue: queueLo/queueHi[0..queued). */
  private queueLo = new Int32Array(64);
  private queueHi = new Int32Array(64);
  private queued = 0;

  /** Queues contact (i, j) for solveQueue: a parallel step's solve block, minus what it defers. */
  queue(i: number, j: number): void {
    if (this.queued === this.queueLo.length) {
      const capacity = grownCapacity(this.queueLo.length, this.queued + 1);
      const lo = new Int32Array(capacity);
      const hi = new Int32Array(capacity);
      lo.set(this.queueLo);
      hi.set(this.queueHi);
      this.queueLo = lo;
      this.queueHi = hi;
    }
    this.queueLo[this.queued] = i;
    this.queueHi[this.queued++] = j;
  }

  /** solveContacts over the queued contacts, in the order queued, then empties the queue. */
  solveQueue(settings: KernelSolverSettings, width: number, height: number): void {
    this.solveContacts(this.queueLo, this.queueHi, this.queued, settings, width, height);
    this.queued = 0;
  }

  /** Pairs lo[k], hi[k] for k in [from, to) into the scratch area; element by element, since subarray() would allocate two views per chunk. */
  private copyToScratch(lo: Int32Array, hi: Int32Array, from: number, to: number): void {
    const { scratchLo, scratchHi } = this;
    for (let k = from; k < to; k++) {
      scratchLo[k - from] = lo[k];
      scratchHi[k - from] = hi[k];
    }
  }

  private keepEscapes(n: number): void {
    const at = this.escapedCount;
    if (at + n > this.escaped.length) {
      const grown = new Int32Array(grownCapacity(this.escaped.length, at + n));
      grown.set(this.escaped);
      this.escaped = grown;
    }
    for (let e = 0; e < n; e++) this.escaped[at + e] = this.scratchEscapes[e];
    this.escapedCount = at + n;
  }
}
