import { kernelModule } from './body-kernel.js';
import { grownCapacity } from '../util/grow.js';
import { instantiateKernel, PAGE_BYTES, webAssembly, type KernelMemory } from '../util/wasm.js';

interface SortExports {
  sortContacts(lo: number, hi: number, tlo: number, thi: number, count: number, slotCount: number, counts: number, buckets: number): void;
}

const BUCKETS_BYTES = 256 * 4;

/**
 * ContactBuffer.sortCanonical in WebAssembly (assembly/body-kernel.ts `sortContacts`), over a
 * private memory of its own: the pairs are copied in, sorted and copied back. The same sorts as
 * the TypeScript ones; pairs are unique, so the order, and every result, is the same.
 *
 * Why: every step sorts its contacts, and a parallel step's threads each sort their own list; this
 * sort beats the TypeScript one for a few thousand contacts and for tens of thousands alike
 * (measured: docs/engine.md, Numbers).
 */
export class ContactSorter {
  private pairCapacity = 0;
  private countsCapacity = 0;
  private loAt = 0;
  private hiAt = 0;
  private tloAt = 0;
  private thiAt = 0;
  private countsAt = 0;
  private lo = new Int32Array(0);
  private hi = new Int32Array(0);

  /** A sorter, or null where this runtime has no WebAssembly. */
  static create(): ContactSorter | null {
    const module = kernelModule(false);
    if (module === null) return null;
    let memory: KernelMemory;
    try {
      memory = new (webAssembly()!).Memory({ initial: 1 });
    } catch {
      return null;
    }
    return new ContactSorter(memory, instantiateKernel<SortExports>(module, memory));
  }

  private constructor(
    private readonly memory: KernelMemory,
    private readonly fn: SortExports,
  ) {}

  /** Sorts lo[0..count), hi[0..count) into ascending (lo, hi) order, for slots below slotCount. */
  sort(lo: Int32Array, hi: Int32Array, count: number, slotCount: number): void {
    // Counts per slot only for the counting passes (see sortContacts): few contacts need none.
    this.reserve(count, count * 8 < slotCount ? 0 : slotCount + 1);
    copyPairs(lo, hi, this.lo, this.hi, count);
    this.fn.sortContacts(this.loAt, this.hiAt, this.tloAt, this.thiAt, count, slotCount, this.countsAt, 0);
    copyPairs(this.lo, this.hi, lo, hi, count);
  }

  memoryBytes(): number {
    return this.memory.buffer.byteLength;
  }

  /** Lays out buckets (at 0), four pair arrays and the counts for at least these sizes. */
  private reserve(pairs: number, counts: number): void {
    if (pairs <= this.pairCapacity && counts <= this.countsCapacity) return;
    if (pairs > this.pairCapacity) this.pairCapacity = grownCapacity(this.pairCapacity, pairs);
    if (counts > this.countsCapacity) this.countsCapacity = grownCapacity(this.countsCapacity, counts);
    const bytes = this.pairCapacity * 4;
    this.loAt = BUCKETS_BYTES;
    this.hiAt = this.loAt + bytes;
    this.tloAt = this.hiAt + bytes;
    this.thiAt = this.tloAt + bytes;
    this.countsAt = this.thiAt + bytes;
    const needed = this.countsAt + this.countsCapacity * 4;
    const have = this.memory.buffer.byteLength;
    if (needed > have) this.memory.grow(Math.ceil((needed - have) / PAGE_BYTES));
    const buffer = this.memory.buffer as ArrayBuffer;
    this.lo = new Int32Array(buffer, this.loAt, this.pairCapacity);
    this.hi = new Int32Array(buffer, this.hiAt, this.pairCapacity);
  }
}

/**
 * The first `count` pairs of (fromLo, fromHi) into (toLo, toHi), element by element: set(subarray())
 * would allocate two views per step. A function of its own with nothing after its loop: V8 compiles
 * a loop this long during the first step (on-stack replacement), before the code after it has run,
 * and an operation there without feedback then left that code at every step.
 */
function copyPairs(fromLo: Int32Array, fromHi: Int32Array, toLo: Int32Array, toHi: Int32Array, count: number): void {
  for (let k = 0; k < count; k++) {
    toLo[k] = fromLo[k];
    toHi[k] = fromHi[k];
  }
}
