import type { BodyStore } from '../store/body-store.js';
import type { CellGrid } from '../broadphase/cell-grid.js';
import { Slot, shareStart } from './control.js';

// The two middle passes of a parallel step's counting sort (the first, each body's cell, runs in
// motion or the bin stage; see ThreadKernels.binRange). Each thread owns a band of whole cells,
// the same band in both passes, and reads all of binOf but writes only its own cells and their
// bodies' places, so nothing is merged and the layout is CellGrid.bin's, bit for bit.

/** The band of cells thread `index` owns, as [from, to). */
function band(control: Int32Array, index: number): [number, number] {
  const cells = control[Slot.columns] * control[Slot.rows];
  const threads = control[Slot.threads];
  return [shareStart(cells, index, threads), shareStart(cells, index + 1, threads)];
}

/**
 * Counts the bodies of thread `index`'s cells into cellStart, and writes how many that is in all
 * to Slot.blockTotal + index, where the scatter finds the bodies of the bands before its own.
 */
export function countCellBand(grid: CellGrid, control: Int32Array, index: number): void {
  const [from, to] = band(control, index);
  const n = control[Slot.bodyCount];
  const kernel = grid.sharedKernel;
  if (kernel) {
    control[Slot.blockTotal + index] = kernel.countCells(n, from, to);
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
  control[Slot.blockTotal + index] = mine;
}

/**
 * Prefix sums over thread `index`'s cells, offset by the bodies of the bands before it, then the
 * scatter of their bodies from the back, as CellGrid.bin does for all cells: slots ascend inside
 * each cell. The last band also writes the two end sentinels.
 */
export function scatterCellBand(grid: CellGrid, bodies: BodyStore, control: Int32Array, index: number): void {
  const [from, to] = band(control, index);
  const cells = control[Slot.columns] * control[Slot.rows];
  const last = index === control[Slot.threads] - 1;
  const n = control[Slot.bodyCount];
  const { binOf, cellStart, sortedSlot, sortedX, sortedY, sortedR } = grid;
  let end = 0;
  for (let t = 0; t < index; t++) end += control[Slot.blockTotal + t];
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
  if (last) {
    cellStart[cells] = n;
    cellStart[cells + 1] = n;
  }
}
