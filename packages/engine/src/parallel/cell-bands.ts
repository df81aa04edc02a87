import type { BodyStore } from '../store/body-store.js';
import type { CellGrid } from '../broadphase/cell-grid.js';
import { BANDS_PER_THREAD, Slot, shareStart } from './control.js';

// The two middle passes of a parallel step's counting sort (the first, each body's cell, runs in
// motion or the bin stage; see ThreadKernels.binRange). The cells are cut into BANDS_PER_THREAD
// bands per thread, and threads claim bands from a shared counter until none is left, in each
// pass, as they claim the scan's row blocks. A band's count and scatter read all of binOf (or, with
// chunk cell ranges, the chunks that reach the band) but write only the band's own cells and their
// bodies' places, so nothing is merged, whoever runs a band, and the layout is CellGrid.bin's, bit
// for bit.

/** Counts the bodies of every band this thread claims (see countBand). */
export function countClaimedBands(grid: CellGrid, control: Int32Array): void {
  const bands = control[Slot.threads] * BANDS_PER_THREAD;
  for (let band = Atomics.add(control, Slot.countBand, 1); band < bands; band = Atomics.add(control, Slot.countBand, 1)) {
    countBand(grid, control, band, bands);
  }
}

/** Scatters the bodies of every band this thread claims (see scatterBand), once every band is counted. */
export function scatterClaimedBands(grid: CellGrid, bodies: BodyStore, control: Int32Array): void {
  const bands = control[Slot.threads] * BANDS_PER_THREAD;
  for (let band = Atomics.add(control, Slot.scatterBand, 1); band < bands; band = Atomics.add(control, Slot.scatterBand, 1)) {
    scatterBand(grid, bodies, control, band, bands);
  }
}

/**
 * Counts the bodies of the band's cells into cellStart, and writes how many that is in all to
 * Slot.bandTotal + band, where the scatter finds the bodies of the bands before its own.
 */
function countBand(grid: CellGrid, control: Int32Array, band: number, bands: number): void {
  // Two numbers, not a tuple: this runs for every band of every step, which must not allocate.
  const cells = control[Slot.columns] * control[Slot.rows];
  const from = shareStart(cells, band, bands);
  const to = shareStart(cells, band + 1, bands);
  const n = control[Slot.bodyCount];
  const kernel = grid.sharedKernel;
  if (kernel) {
    control[Slot.bandTotal + band] = kernel.countCells(n, from, to);
    return;
  }
  const { binOf, cellStart } = grid;
  cellStart.fill(0, from, to);
  let mine = 0;
  for (let k = 0; k < n; k++) {
    const cell = binOf[k];
    if (cell >= from && cell < to) {
      cellStart[cell]++;
      mine++;
    }
  }
  control[Slot.bandTotal + band] = mine;
}

/**
 * Prefix sums over the band's cells, offset by the bodies of the bands before it, then the
 * scatter of their bodies from the back, as CellGrid.bin does for all cells: slots ascend inside
 * each cell. The last band also writes the two end sentinels.
 */
function scatterBand(grid: CellGrid, bodies: BodyStore, control: Int32Array, band: number, bands: number): void {
  const cells = control[Slot.columns] * control[Slot.rows];
  const from = shareStart(cells, band, bands);
  const to = shareStart(cells, band + 1, bands);
  const n = control[Slot.bodyCount];
  const { binOf, cellStart, sortedSlot, sortedX, sortedY, sortedR } = grid;
  let end = 0;
  for (let b = 0; b < band; b++) end += control[Slot.bandTotal + b];
  const { x, y, radius } = bodies;
  const kernel = grid.sharedKernel;
  if (kernel) {
    // A grid in the body memory reads the columns in place; one in its own memory, the copies
    // that GridInputs made there.
    if (kernel.inBodyMemory) kernel.scatterCells(n, from, to, end, x.byteOffset, y.byteOffset, radius.byteOffset);
    else kernel.scatterCells(n, from, to, end);
  } else {
    for (let cell = from; cell < to; cell++) {
      end += cellStart[cell];
      cellStart[cell] = end;
    }
    for (let k = n - 1; k >= 0; k--) {
      const cell = binOf[k];
      if (cell < from || cell >= to) continue;
      const at = --cellStart[cell];
      sortedSlot[at] = k;
      sortedX[at] = x[k];
      sortedY[at] = y[k];
      sortedR[at] = radius[k];
    }
  }
  if (band === bands - 1) {
    cellStart[cells] = n;
    cellStart[cells + 1] = n;
  }
}
