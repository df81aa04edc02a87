import { cellOf, countOne, jumpWindow, scatterOne } from './common';

// The three passes of a parallel bin (src/parallel/kernels.ts), each on one thread's share: the
// cells of a body range, then per band of cells the count, and the prefix sums and scatter. Same
// formulas and order as `bin`, so the layout is the serial one.
//
// Every thread's count and scatter must find the bodies of its band among all n. Reading all n
// per thread would leave those two passes barely faster on two threads than on one (measured at
// 1M bodies: docs/engine.md, Numbers). So the cells pass also notes each chunk's smallest and
// largest cell, and the others skip chunks that miss their band and test nothing in chunks wholly
// inside it. Where bodies lie in space as they lie in memory (created row by row, as scenes and
// spawners do) each thread then reads about n / threads bodies; in a shuffled world every chunk
// spans every band and the passes still read all n: such worlds take the banded passes instead
// (bandCounts, partition and sortBand, run by src/parallel/banded-bin.ts).

/** Bodies per chunk of `chunkCells`: its entries are 2 int32 (smallest, largest cell) per chunk. */
const CHUNK_SHIFT = 10;

/**
 * Each body's cell for bodies [from, to), from positions at xs, ys, and each chunk's smallest and
 * largest cell at chunkCells; returns the range's jumps (see jumpsFound in bin.ts) in a grid of `cells`.
 * `from` is a multiple of the chunk size (so no chunk is shared between threads) and `to` one too,
 * unless it is the last body.
 */
export function cellsOf(
  xs: usize, ys: usize, from: i32, to: i32, minX: f64, minY: f64, inverse: f64, columns: i32, cells: i32, binOf: usize, chunkCells: usize,
): i32 {
  const rows = cells / columns;
  const window = jumpWindow(columns, cells);
  let jumped: i32 = 0;
  let last: i32 = 0;
  for (let start = from; start < to; ) {
    const chunk = start >> CHUNK_SHIFT;
    const end = min(to, (chunk + 1) << CHUNK_SHIFT);
    let lowest: i32 = i32.MAX_VALUE;
    let highest: i32 = i32.MIN_VALUE;
    for (let k = start; k < end; k++) {
      const at = <usize>k << 3;
      const c = cellOf(load<f64>(ys + at), minY, inverse, rows) * columns + cellOf(load<f64>(xs + at), minX, inverse, columns);
      store<i32>(binOf + (<usize>k << 2), c);
      lowest = min(lowest, c);
      highest = max(highest, c);
      jumped += <i32>(abs<i32>(c - last) > window);
      last = c;
    }
    store<i32>(chunkCells + (<usize>chunk << 3), lowest);
    store<i32>(chunkCells + (<usize>chunk << 3), highest, 4);
    start = end;
  }
  return jumped;
}

/** Counts the bodies 0..n-1 of each cell in [from, to) into cellStart; returns how many that is. */
export function countCells(binOf: usize, n: i32, from: i32, to: i32, cellStart: usize, chunkCells: usize): i32 {
  memory.fill(cellStart + (<usize>from << 2), 0, <usize>(to - from) << 2);
  let mine: i32 = 0;
  const chunks = (n + (1 << CHUNK_SHIFT) - 1) >> CHUNK_SHIFT;
  for (let chunk: i32 = 0; chunk < chunks; chunk++) {
    const lowest = load<i32>(chunkCells + (<usize>chunk << 3));
    const highest = load<i32>(chunkCells + (<usize>chunk << 3), 4);
    if (highest < from || lowest >= to) continue;
    const start = chunk << CHUNK_SHIFT;
    const end = min(n, start + (1 << CHUNK_SHIFT));
    if (lowest >= from && highest < to) {
      for (let k = start; k < end; k++) countOne(cellStart, load<i32>(binOf + (<usize>k << 2)));
      mine += end - start;
      continue;
    }
    for (let k = start; k < end; k++) {
      const cell = load<i32>(binOf + (<usize>k << 2));
      if (cell < from || cell >= to) continue;
      countOne(cellStart, cell);
      mine++;
    }
  }
  return mine;
}

/**
 * Prefix sums over the cells [from, to), starting from `before` bodies in earlier cells, then the
 * scatter of their bodies from the back (slots ascending inside each cell, as in `bin`).
 */
export function scatterCells(
  binOf: usize, n: i32, from: i32, to: i32, before: i32, cellStart: usize, chunkCells: usize,
  xs: usize, ys: usize, rs: usize,
  sortedSlot: usize, sortedX: usize, sortedY: usize, sortedR: usize,
): void {
  let end = before;
  for (let cell = from; cell < to; cell++) {
    const counter = cellStart + (<usize>cell << 2);
    end += load<i32>(counter);
    store<i32>(counter, end);
  }
  for (let chunk: i32 = (n - 1) >> CHUNK_SHIFT; chunk >= 0; chunk--) {
    const lowest = load<i32>(chunkCells + (<usize>chunk << 3));
    const highest = load<i32>(chunkCells + (<usize>chunk << 3), 4);
    if (highest < from || lowest >= to) continue;
    const start = chunk << CHUNK_SHIFT;
    const last = min(n, start + (1 << CHUNK_SHIFT)) - 1;
    if (lowest >= from && highest < to) {
      for (let k = last; k >= start; k--) {
        scatterOne(k, load<i32>(binOf + (<usize>k << 2)), cellStart, xs, ys, rs, sortedSlot, sortedX, sortedY, sortedR);
      }
      continue;
    }
    for (let k = last; k >= start; k--) {
      const cell = load<i32>(binOf + (<usize>k << 2));
      if (cell < from || cell >= to) continue;
      scatterOne(k, cell, cellStart, xs, ys, rs, sortedSlot, sortedX, sortedY, sortedR);
    }
  }
}
