import { applyState, captureState, hostResource, lazyPart, StateMismatch, transientFields, type StateValue } from './state-graph.js';
import { decodeSnapshot, encodeSnapshot } from './snapshot-format.js';
import { BodyKernel } from '../store/body-kernel.js';
import { GridKernel } from '../broadphase/grid-kernel.js';
import { SoftStepKernel } from '../solver/soft-step-kernel.js';
import { ContactSorter } from '../store/contact-sorter.js';
import { ParallelStep } from '../parallel/parallel-step.js';
import { SoftStep } from '../solver/soft-step.js';
import { PointDistanceJoints } from '../solver/joints/point-distance-joints.js';
import { JointSolver } from '../solver/joint-solver.js';
import { StaticTree } from '../broadphase/static-tree.js';
import { CellGrid } from '../broadphase/cell-grid.js';
import { PairSink } from '../store/pair-sink.js';
import { StepStatsRecord, TIMINGS } from '../step/stats.js';
import { BodyStore } from '../store/body-store.js';
import { ContactBuffer } from '../store/contact-buffer.js';
import { ThreadKernels } from '../parallel/kernels.js';
import { Queries } from '../query/queries.js';
import { describeValue } from '../util/validate.js';

/** The engine's version, written into every snapshot so that a refusal can say who wrote it. */
export const ENGINE_VERSION = '0.1.0';

// Kernels own WebAssembly instances over memories a step fills afresh; a parallel step owns threads.
for (const ctor of [BodyKernel, GridKernel, SoftStepKernel, ContactSorter, ParallelStep]) hostResource(ctor);
// The soft step gathers these afresh each step, into its kernel's memory where it has one; so a
// restored world's lanes hold no preparation to bring up to date (lanesPrepared stays false).
transientFields(SoftStep, ['states', 'constraints', 'pairs', 'lanesPrepared']);
transientFields(PointDistanceJoints, ['rows', 'pairs']);
transientFields(JointSolver, ['arm']);
// Fields that hold a kernel, or null before one is made or where the runtime lacks WebAssembly:
// left out whichever they hold, so that the bytes are the same with or without kernels, and
// before or after a kernel is first made.
transientFields(BodyStore, ['kernel']);
transientFields(CellGrid, ['kernel', 'arena']);
transientFields(SoftStep, ['kernel']);
transientFields(PointDistanceJoints, ['kernel']);
transientFields(ContactBuffer, ['sorter']);
// Whether kernels were wanted where the world was made, and what only one path fills (the kernel
// scan's pair count, the TypeScript sort's scratch): the restoring runtime's own.
transientFields(CellGrid, ['kernelWanted', 'pairsFound']);
transientFields(ContactBuffer, ['sorterWanted', 'scratchLo', 'scratchHi', 'counts', 'buckets']);
transientFields(ThreadKernels, ['sorter']);
// How often the soft step kept its colouring and its lanes' preparation: measurements of its
// shortcuts, which a restored world starts without.
transientFields(SoftStep, ['laneCounts', 'coloursKept']);
// A broad-phase's chunk of candidates is handed on within the step that found them.
transientFields(PairSink, ['a', 'b', 'consumerMs']);
// Timings measure the machine, not the world: left out, a snapshot is the same bytes wherever it is taken.
transientFields(StepStatsRecord, TIMINGS);
// A grid made over the body columns remakes its views of them where its notes of their layout
// (the store's version it was made at, the kernel views it holds) are a new grid's: so a restored
// grid works over the restored world's memory rather than over copies of the original's. Its own
// count of remakes is the grid's history, not state, and is left out with them; every other
// cache's note of a version is saved with the version, so that a restored world keeps its caches
// and steps on to the same bytes as its original.
transientFields(CellGrid, ['layoutVersion', 'kernelViews', 'sourceStore', 'sourceLayout']);
// The grid's buffers are filled afresh by every build (a step bins every body again), and their
// lengths are the grid's history (the most bodies and cells it has held): left out, a world that
// was restored bins into buffers of its own and snapshots to the bytes of one that was not.
transientFields(CellGrid, ['cellStart', 'sortedSlot', 'sortedX', 'sortedY', 'sortedR', 'binOf', 'sourceX', 'sourceY', 'sourceR', 'listSource', 'listOffset', 'listView', 'bandedBins']);
// What queries build to answer (a grid of the positions, remade after every change, and the
// nearest hit of the last ray) is read by nothing else, so asking a question leaves a snapshot
// as it was.
transientFields(Queries, ['live', 'grid', 'builtVersion', 'stamp', 'epoch', 'reachMinX', 'reachMinY', 'reachMaxX', 'reachMaxY', 'examined', 'bestFraction', 'bestSlot', 'bestHandle', 'bestNormalX', 'bestNormalY', 'bestPointX', 'bestPointY', 'hits', 'hitCount', 'spareHits', 'mask', 'gridSlots', 'oversized', 'oversizedCount', 'queryBox', 'shapePose', 'segmentTree', 'segmentsBuilt', 'bestSegment', 'segmentAt']);
lazyPart('StaticTree', StaticTree);
lazyPart('CellGrid', CellGrid);

/** The snapshot of `world`, whose field `creation` holds the options it was built with. */
export function writeSnapshot(world: object): Uint8Array {
  return encodeSnapshot({ engineVersion: ENGINE_VERSION, state: captureState(world) });
}

export interface ReadSnapshot {
  state: StateValue;
  /** The options the world was built with, to build the world the state is written onto. */
  options: Record<string, unknown>;
  engineVersion: string;
}

/** Checks a snapshot's bytes and reads them; a TypeError or RangeError says what is wrong. */
export function readSnapshot(bytes: unknown): ReadSnapshot {
  if (!(bytes instanceof Uint8Array)) {
    throw new TypeError(`snapshot must be a Uint8Array (from world.snapshot()), got ${bytes === null ? 'null' : typeof bytes === 'object' ? (bytes as object).constructor?.name ?? 'an object' : typeof bytes}`);
  }
  const content = decodeSnapshot(bytes, ENGINE_VERSION);
  const creation = field(content.state, 'creation');
  if (creation === null || creation.t !== 'object' || creation.name !== '') throw mismatch(content.engineVersion, 'the world options are missing');
  const options: Record<string, unknown> = {};
  applyState(options, creation);
  return { state: content.state, options, engineVersion: content.engineVersion };
}

/** A field of an object node of the tree, or null where the node is no object or lacks it. */
export function field(node: StateValue | null, ...path: string[]): StateValue | null {
  for (const key of path) {
    if (node === null || node.t !== 'object') return null;
    const found = node.fields.find(([k]) => k === key);
    node = found ? found[1] : null;
  }
  return node;
}

/** Whether a field of the tree holds an object (a lazily made part the original world had). */
export function holdsObject(node: StateValue | null): boolean {
  return node !== null && (node.t === 'object' || node.t === 'ref');
}

/** A number field of the tree, or NaN. */
export function numberField(node: StateValue | null): number {
  return node !== null && node.t === 'value' && typeof node.v === 'number' ? node.v : NaN;
}

/** Writes the state onto `world` (freshly built, its lazy parts made); a RangeError where it does not fit. */
export function writeOnto(world: object, read: ReadSnapshot): void {
  try {
    applyState(world, read.state);
  } catch (error) {
    if (error instanceof StateMismatch) throw mismatch(read.engineVersion, error.message);
    throw error;
  }
}

function mismatch(writtenBy: string, detail: string): RangeError {
  return new RangeError(`snapshot does not match this engine's state layout (written by @maxgrid/engine ${writtenBy}, this is ${ENGINE_VERSION}): ${detail}`);
}

/** A deep copy of plain options data, kept by a world so that a snapshot can rebuild it. */
export function copyOptions(value: unknown): unknown {
  if (value === null || typeof value !== 'object') return value;
  if (Array.isArray(value)) return value.map(copyOptions);
  const out: Record<string, unknown> = {};
  for (const [key, item] of Object.entries(value)) out[key] = copyOptions(item);
  return out;
}

/** Where `actual` first differs from `expected`, plain data both (numbers by Object.is), as 'path is value', or null; paths in `skip` are not compared. */
export function firstDifference(expected: unknown, actual: unknown, path: string, skip: ReadonlySet<string>): string | null {
  if (skip.has(path)) return null;
  if (expected !== null && typeof expected === 'object') {
    if (actual === null || typeof actual !== 'object') return `${path} is ${describeValue(actual)}`;
    const keys = new Set([...Object.keys(expected), ...Object.keys(actual)]);
    for (const key of keys) {
      const found = firstDifference((expected as Record<string, unknown>)[key], (actual as Record<string, unknown>)[key], `${path}.${key}`, skip);
      if (found !== null) return found;
    }
    return null;
  }
  return Object.is(expected, actual) ? null : `${path} is ${describeValue(actual)}`;
}
