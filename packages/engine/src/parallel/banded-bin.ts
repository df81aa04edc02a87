import type { BodyStore } from '../store/body-store.js';
import type { GridKernel } from '../broadphase/grid-kernel.js';
import { Param, Slot } from './control.js';

// The banded bin (assembly binBanded) split over a parallel step's threads, for worlds whose bodies
// lie scattered in memory against space, where the plain passes (cell-bands.ts) read every body
// in every band. Three stages: each thread counts its share of bodies per band; the caller turns
// the counts into each share's cursors (GridKernel.planPartition); each thread scatters its share
// into the bands (stable: shares in order, slots ascending); then threads claim whole bands and
// sort each into its cells. The layout is the serial bin's, bit for bit, whoever runs what:
// within a band the bodies lie in ascending slots whatever the shares, and a band's sort depends
// on nothing else.

/** Counts the bodies [from, to) of thread `index`'s share per band. */
export function countShareBands(kernel: GridKernel, control: Int32Array, index: number, from: number, to: number): void {
  kernel.bandCounts(from, to, index, control[Slot.bandShift], control[Slot.bands]);
}

/** Scatters the bodies [from, to) of thread `index`'s share into their bands, at the cursors planPartition left. */
export function partitionShare(kernel: GridKernel, bodies: BodyStore, control: Int32Array, index: number, from: number, to: number): void {
  const shift = control[Slot.bandShift];
  const bands = control[Slot.bands];
  // A grid in the body memory reads the columns in place; one in its own memory, its input copies.
  if (kernel.inBodyMemory) kernel.partition(from, to, index, shift, bands, bodies.x.byteOffset, bodies.y.byteOffset, bodies.radius.byteOffset);
  else kernel.partition(from, to, index, shift, bands);
}

/** Sorts bands into their cells, claimed one at a time, through thread `index`'s scratch. */
export function sortClaimedBands(kernel: GridKernel, control: Int32Array, params: Float64Array, index: number): void {
  const shift = control[Slot.bandShift];
  const bands = control[Slot.bands];
  const threads = control[Slot.threads];
  const columns = control[Slot.columns];
  const cells = columns * control[Slot.rows];
  const minX = params[Param.originX];
  const minY = params[Param.originY];
  const inverse = params[Param.inverseCell];
  for (let b = Atomics.add(control, Slot.sortBand, 1); b < bands; b = Atomics.add(control, Slot.sortBand, 1)) {
    kernel.sortBand(b, shift, bands, threads, cells, minX, minY, inverse, columns, index);
  }
}
