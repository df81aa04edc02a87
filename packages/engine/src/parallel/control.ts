/**
 * The control block shared by the threads of a parallel step: one Int32Array for commands,
 * barriers and integer parameters, one Float64Array for real parameters, one for per-thread
 * results. Thread 0 is the caller of `step()`; it publishes a command by bumping SEQ, does its own
 * share, then waits for DONE to count the others in. Atomics order everything: a thread that sees
 * a new SEQ also sees every plain write made before it, and likewise for DONE.
 */

import type { KernelLayout, KernelMemory } from '../broadphase/grid-kernel.js';
import type { Column } from '../util/grow.js';

export const MAX_THREADS = 16;

/** The code units of a worker's error that the control block holds; the rest is cut. */
export const ERROR_TEXT = 2048;

export const Slot = {
  seq: 0,
  command: 1,
  done: 2,
  epoch: 3,
  threads: 4,
  slotCount: 5,
  bodyCount: 6,
  columns: 7,
  rows: 8,
  integrator: 9,
  customMotion: 10,
  forcesPending: 11,
  sleeping: 12,
  bounce: 13,
  hasBox: 14,
  /** Workers that threw (a kernel in a command, or taking new buffers); the caller then fails the step with the first one's error. */
  failed: 15,
  /** Contacts in the step's canonical buffer. */
  contactTotal: 16,
  /** 1: motion also computes each body's cell (the grid is laid out before motion). */
  binInMotion: 17,
  /** The body store's membershipVersion (mod 2^32): radii change only when it does. */
  membership: 18,
  /**
   * How long a thread that has finished its share keeps polling for the next command before it
   * sleeps, in microseconds: 0 where threads outnumber cores (see spinBudget in host.ts).
   */
  spinMicroseconds: 19,
  /** 1 when every pair of bodies collides, so scans hand over contacts (PairSink.contactsDirect). */
  everyPairCollides: 20,
  /** The next scan block to claim: threads take blocks of rows until none is left (see scan). */
  scanBlock: 21,
  /** The next motion chunk to claim, likewise (see ThreadKernels.motion). */
  motionChunk: 22,
  /** The next band of cells to count, and to scatter, likewise (see cell-bands.ts). */
  countBand: 23,
  scatterBand: 24,
  /** The next band of a banded bin to sort, likewise (see banded-bin.ts). */
  sortBand: 25,
  /** A banded bin's bands: cells per band (log 2), and how many. */
  bandShift: 26,
  bands: 27,
  /** The first failed worker's index, and how many UTF-16 code units of its error errorText holds. */
  failedWorker: 28,
  errorLength: 29,
  /** MAX_THREADS cells: each thread's contacts found, which may exceed its list's capacity. */
  contactCount: 64,
  /** MAX_THREADS cells: contacts each thread's solve block deferred. */
  deferredCount: 80,
  /** MAX_THREADS cells: bodies each thread's solve block left outside the box. */
  escapedCount: 96,
  /** MAX_THREADS cells: 1 when the thread sorted its contact list into canonical order. */
  listSorted: 112,
  /** MAX_THREADS * BANDS_PER_THREAD cells: bodies in each band of cells, for the prefix sums. */
  bandTotal: 128,
  /** MAX_THREADS cells: each thread's jumps in this step's cells pass (see GridKernel.noteJumps). */
  jumps: 192,
  /**
   * ERROR_TEXT cells: the first failed worker's error (its stack, as text), a UTF-16 code unit a
   * cell. A step fails on the calling thread, which cannot take a worker's message while it waits
   * in that step: the error comes back through the shared block, with the barrier that counts
   * the worker done.
   */
  errorText: 208,
  length: 208 + ERROR_TEXT,
} as const;

/**
 * Bands of cells per thread in a parallel bin's count and scatter, claimed as threads come free
 * (see cell-bands.ts): more bands even out threads that run at different speeds.
 */
export const BANDS_PER_THREAD = 4;

export const Param = {
  gravityX: 0,
  gravityY: 1,
  dt: 2,
  boxWidth: 3,
  boxHeight: 4,
  wallRestitution: 5,
  restitutionThreshold: 6,
  originX: 7,
  originY: 8,
  inverseCell: 9,
  coordPad: 10,
  /** The largest radius of a live body (see BodyKernel.moveInBox). */
  maxRadius: 11,
  positionCorrection: 12,
  contactSlop: 13,
  /** The body store's speedCap (the circle route's given speed limit), for the general motion loops. */
  speedCap: 14,
  length: 16,
} as const;

/** Per-thread results, RESULT_STRIDE doubles each. */
export const Result = {
  examined: 0,
  candidates: 1,
  filtered: 2,
  narrowMs: 3,
} as const;
export const RESULT_STRIDE = 4;

export const Command = {
  /** Workers wait until they hold the buffers of the current epoch. */
  sync: 1,
  /** Integrate a slot range, then (with Slot.bounce) bounce it off the box walls. */
  motion: 2,
  /** Each body's cell, for a body range. */
  bin: 3,
  /** Count the bodies in a cell range. */
  count: 4,
  /** Prefix sums over a cell range, then scatter the bodies of that range into cell order. */
  scatter: 6,
  /** A banded bin: count this thread's share of bodies per band (see banded-bin.ts). */
  bandCount: 11,
  /** A banded bin: scatter this thread's share of bodies into their bands. */
  partition: 12,
  /** A banded bin: sort bands into their cells, claimed one at a time. */
  sortBands: 13,
  /** Scan a band of rows for pairs, narrow-phase them into this thread's contact list. */
  scan: 7,
  /** Clamp contact bodies of a slot range into the box. */
  clamp: 8,
  /** Resolve a block of the canonical contacts, deferring what must wait (see solveContactBlock). */
  solve: 9,
  stop: 10,
} as const;

/** The integrators by number, as the control block carries them. */
export const INTEGRATOR_IDS = ['explicit-euler', 'semi-implicit-euler'] as const;

/** Thread w's share [from, to) of `total` items split evenly over `threads`. */
export function shareStart(total: number, w: number, threads: number): number {
  return Math.floor((total * w) / threads);
}

/** Names of the body columns that worker threads see. */
export const BODY_COLUMNS = [
  'x',
  'y',
  'vx',
  'vy',
  'radius',
  'mass',
  'invMass',
  'restitution',
  'type',
  'category',
  'mask',
  'gravityScale',
  'linearDamping',
  'forceX',
  'forceY',
  'asleep',
] as const;

export type BodyColumnName = (typeof BODY_COLUMNS)[number];

/** What the caller sends a worker whenever buffers were reallocated. */
export interface BufferMessage {
  kind: 'buffers';
  epoch: number;
  /** Views of the shared columns (all on one memory when the store has a body kernel). */
  bodies: Record<BodyColumnName, Column>;
  /** The body kernel's shared memory, which the views lie in; null without a kernel. */
  bodyKernel: KernelMemory | null;
  cellStart: SharedArrayBuffer;
  binOf: SharedArrayBuffer;
  sortedSlot: SharedArrayBuffer;
  sortedX: SharedArrayBuffer;
  sortedY: SharedArrayBuffer;
  sortedR: SharedArrayBuffer;
  /** Set when the grid lives in a shared WebAssembly memory: the grid arrays above are then unused. */
  gridKernel: { memory: KernelMemory; layout: KernelLayout } | null;
  contactLo: SharedArrayBuffer[];
  contactHi: SharedArrayBuffer[];
  /** The step's canonical contact buffer, and where solve blocks list deferred contacts. */
  canonicalLo: SharedArrayBuffer;
  canonicalHi: SharedArrayBuffer;
  deferred: SharedArrayBuffer;
  escaped: SharedArrayBuffer;
}

export interface InitMessage {
  kind: 'init';
  index: number;
  control: SharedArrayBuffer;
  params: SharedArrayBuffer;
  results: SharedArrayBuffer;
}
