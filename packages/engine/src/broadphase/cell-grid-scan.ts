import type { PairSink } from '../store/pair-sink.js';
import type { CellGrid } from './cell-grid.js';
import { RADIUS_PAD } from './fat-bounds.js';

// The TypeScript scan loops of CellGrid: the path without WebAssembly, and for a serial scan of a
// shared grid whose pair buffer overflowed.

/** CellGrid.scanRows' TypeScript loops (the kernel's `scan` is the same, operation for operation). */
export function scanRowsInScript(grid: CellGrid, out: PairSink, pad: number, rowFrom: number, rowTo: number): number {
  const { cellStart, sortedSlot, sortedX, sortedY, sortedR, columns, rows } = grid;
  let examined = 0;
  // Cell by cell, row-major: each cell's two neighbour ranges are found once for all its bodies,
  // and no per-body cell index is needed. Empty cells cost one comparison.
  for (let row = rowFrom; row < rowTo; row++) {
    const rowStart = row * columns;
    const hasBelow = row + 1 < rows;
    for (let column = 0; column < columns; column++) {
      const c = rowStart + column;
      const first = cellStart[c];
      const last = cellStart[c + 1];
      if (first === last) continue;
      const sameRowEnd = cellStart[column + 1 < columns ? c + 2 : c + 1];
      let from = 0;
      let to = 0;
      if (hasBelow) {
        const below = c + columns;
        from = cellStart[column > 0 ? below - 1 : below];
        to = cellStart[column + 1 < columns ? below + 2 : below + 1];
      }
      for (let k = first; k < last; k++) {
        const ax = sortedX[k];
        const ay = sortedY[k];
        const ar = sortedR[k] * (1 + RADIUS_PAD) + pad;
        const a = sortedSlot[k];
        for (let m = k + 1; m < sameRowEnd; m++) {
          const reach = ar + sortedR[m] * (1 + RADIUS_PAD);
          const dx = sortedX[m] - ax;
          const dy = sortedY[m] - ay;
          if (dx * dx + dy * dy <= reach * reach) out.push(a, sortedSlot[m]);
        }
        for (let m = from; m < to; m++) {
          const reach = ar + sortedR[m] * (1 + RADIUS_PAD);
          const dx = sortedX[m] - ax;
          const dy = sortedY[m] - ay;
          if (dx * dx + dy * dy <= reach * reach) out.push(a, sortedSlot[m]);
        }
        examined += sameRowEnd - k - 1 + (to - from);
      }
    }
  }
  return examined;
}

/** Pushes (slot, other) for each body in [from, to) whose padded circle overlaps the given one. */
export function pushOverlaps(
  grid: CellGrid,
  from: number,
  to: number,
  ax: number,
  ay: number,
  ar: number,
  slot: number,
  out: PairSink,
): number {
  const { sortedX, sortedY, sortedR, sortedSlot } = grid;
  for (let m = from; m < to; m++) {
    const reach = ar + sortedR[m] * (1 + RADIUS_PAD);
    const dx = sortedX[m] - ax;
    const dy = sortedY[m] - ay;
    if (dx * dx + dy * dy <= reach * reach) out.push(slot, sortedSlot[m]);
  }
  return to - from;
}
