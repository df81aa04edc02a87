// The serial bins: `bin` (one counting sort) and `binBanded` (bands of cells, then each band in a
// scratch), with the band passes a parallel step runs on its threads (src/parallel/banded-bin.ts).
import { cellOf, countOne, jumpWindow, putBody, scatterOne, slotAt } from './common';

// Bodies of the last `bin` or `binBanded` whose cell lies far from the previous body's: more than
// two rows and more than 1/64 of all cells away. It says how scattered the bodies lie in memory
// against space, which decides the next bin's kind. Two rows alone would be too strict: by that
// test a world created row by row counts 32 % of its bodies as jumps after 1 s of motion and 79 %
// after 10 s (1M bodies), yet its plain bin stays the faster (ad-hoc probe alternating both kinds
// step by step: docs/engine.md, Numbers). With the 1/64 window those figures are 0 % and 0.6 %,
// and a shuffled world's 97 %.
let jumpsFound: i32 = 0;

/** The last bin's jumps (see jumpsFound). */
export function jumps(): i32 {
  return jumpsFound;
}

/**
 * Counting sort of n bodies into `cells` row-major cells: slots 0..n-1, or the n int32 slots at
 * `slots` when it is not 0; positions and radii are read at xs, ys, rs by slot. cellStart
 * (cells + 2 int32) ends as each cell's first index, sorted* hold the bodies in cell order, binOf
 * is scratch. Radii are copied as they are: scans pad them as they read them. With `countJumps`
 * (slots 0..n-1 only: the banded bin takes no slot list), counts the jumps for `jumps()`, which
 * is otherwise 0.
 *
 * The loops run four bodies (or cells) a turn and each case has loops of its own, its choices
 * made outside them: V8 checks for interrupts on every turn of a WebAssembly loop and does not move
 * a loop-invariant test out of one, and at 64,000 bodies those costs were a third of this bin
 * (docs/engine.md, Numbers). For the same reason the cells are computed in a pass of their own
 * before they are counted: the fused loop was the slower.
 */
export function bin(
  xs: usize, ys: usize, rs: usize, slots: usize, n: i32,
  minX: f64, minY: f64, inverse: f64, columns: i32, cells: i32,
  cellStart: usize, binOf: usize, sortedSlot: usize, sortedX: usize, sortedY: usize, sortedR: usize,
  countJumps: bool,
): void {
  const rows = cells / columns;
  if (slots != 0) cellsOfBodies(xs, ys, slots, n, minX, minY, inverse, columns, rows, binOf);
  else cellsOfBodies(xs, ys, 0, n, minX, minY, inverse, columns, rows, binOf);
  memory.fill(cellStart, 0, (<usize>cells + 2) << 2);
  if (countJumps) jumpsFound = countBodies(binOf, n, cellStart, jumpWindow(columns, cells), true);
  else jumpsFound = countBodies(binOf, n, cellStart, 0, false);
  let sum: i32 = 0;
  let c: i32 = 0;
  for (; c + 3 < cells; c += 4) {
    const counter = cellStart + (<usize>c << 2);
    sum += load<i32>(counter);
    store<i32>(counter, sum);
    sum += load<i32>(counter, 4);
    store<i32>(counter, sum, 4);
    sum += load<i32>(counter, 8);
    store<i32>(counter, sum, 8);
    sum += load<i32>(counter, 12);
    store<i32>(counter, sum, 12);
  }
  for (; c < cells; c++) {
    const counter = cellStart + (<usize>c << 2);
    sum += load<i32>(counter);
    store<i32>(counter, sum);
  }
  // From the back with pre-decrement: slots ascend inside each cell, as in CellGrid.bin.
  if (slots != 0) scatterBodies(xs, ys, rs, slots, n, cellStart, binOf, sortedSlot, sortedX, sortedY, sortedR);
  else scatterBodies(xs, ys, rs, 0, n, cellStart, binOf, sortedSlot, sortedX, sortedY, sortedR);
  store<i32>(cellStart + (<usize>cells << 2), n);
  store<i32>(cellStart + ((<usize>cells + 1) << 2), n);
}

/** binOf[k] = the cell of the k-th body to bin (see slotAt), for k in [0, n). */
// @ts-ignore: decorator
@inline
function cellsOfBodies(
  xs: usize, ys: usize, slots: usize, n: i32, minX: f64, minY: f64, inverse: f64, columns: i32, rows: i32, binOf: usize,
): void {
  let k: i32 = 0;
  for (; k + 3 < n; k += 4) {
    const out = binOf + (<usize>k << 2);
    store<i32>(out, cellAt(xs, ys, slotAt(slots, k), minX, minY, inverse, columns, rows));
    store<i32>(out, cellAt(xs, ys, slotAt(slots, k + 1), minX, minY, inverse, columns, rows), 4);
    store<i32>(out, cellAt(xs, ys, slotAt(slots, k + 2), minX, minY, inverse, columns, rows), 8);
    store<i32>(out, cellAt(xs, ys, slotAt(slots, k + 3), minX, minY, inverse, columns, rows), 12);
  }
  for (; k < n; k++) store<i32>(binOf + (<usize>k << 2), cellAt(xs, ys, slotAt(slots, k), minX, minY, inverse, columns, rows));
}

/** The cell of the body in slot i. */
// @ts-ignore: decorator
@inline
function cellAt(xs: usize, ys: usize, i: i32, minX: f64, minY: f64, inverse: f64, columns: i32, rows: i32): i32 {
  const at = <usize>i << 3;
  return cellOf(load<f64>(ys + at), minY, inverse, rows) * columns + cellOf(load<f64>(xs + at), minX, inverse, columns);
}

/**
 * One more in the counter of each of the n cells in binOf; with `countJumps`, returns how many of
 * them lie more than `window` cells from the one before (see jumpsFound), otherwise 0.
 */
// @ts-ignore: decorator
@inline
function countBodies(binOf: usize, n: i32, cellStart: usize, window: i32, countJumps: bool): i32 {
  let last: i32 = 0;
  let jumped: i32 = 0;
  let k: i32 = 0;
  for (; k + 3 < n; k += 4) {
    const at = binOf + (<usize>k << 2);
    const c0 = load<i32>(at);
    const c1 = load<i32>(at, 4);
    const c2 = load<i32>(at, 8);
    const c3 = load<i32>(at, 12);
    countOne(cellStart, c0);
    countOne(cellStart, c1);
    countOne(cellStart, c2);
    countOne(cellStart, c3);
    if (countJumps) {
      jumped += <i32>(abs<i32>(c0 - last) > window) + <i32>(abs<i32>(c1 - c0) > window) + <i32>(abs<i32>(c2 - c1) > window) + <i32>(abs<i32>(c3 - c2) > window);
      last = c3;
    }
  }
  for (; k < n; k++) {
    const c = load<i32>(binOf + (<usize>k << 2));
    countOne(cellStart, c);
    if (countJumps) {
      jumped += <i32>(abs<i32>(c - last) > window);
      last = c;
    }
  }
  return jumped;
}

/** bin's scatter, from the back, four bodies a turn. */
// @ts-ignore: decorator
@inline
function scatterBodies(
  xs: usize, ys: usize, rs: usize, slots: usize, n: i32, cellStart: usize, binOf: usize,
  sortedSlot: usize, sortedX: usize, sortedY: usize, sortedR: usize,
): void {
  let k: i32 = n - 1;
  for (; k >= 3; k -= 4) {
    const at = binOf + (<usize>k << 2);
    scatterOne(slotAt(slots, k), load<i32>(at), cellStart, xs, ys, rs, sortedSlot, sortedX, sortedY, sortedR);
    scatterOne(slotAt(slots, k - 1), load<i32>(at - 4), cellStart, xs, ys, rs, sortedSlot, sortedX, sortedY, sortedR);
    scatterOne(slotAt(slots, k - 2), load<i32>(at - 8), cellStart, xs, ys, rs, sortedSlot, sortedX, sortedY, sortedR);
    scatterOne(slotAt(slots, k - 3), load<i32>(at - 12), cellStart, xs, ys, rs, sortedSlot, sortedX, sortedY, sortedR);
  }
  for (; k >= 0; k--) {
    scatterOne(slotAt(slots, k), load<i32>(binOf + (<usize>k << 2)), cellStart, xs, ys, rs, sortedSlot, sortedX, sortedY, sortedR);
  }
}

/**
 * `bin` of slots 0..n-1 in two levels, for worlds whose bodies lie in memory in another order than
 * in space. First into bands of 2^bandShift cells, each band's bodies in ascending slots (a stable
 * scatter with one write stream per band and column), then each band on its own through
 * `scratch`, where its counts, sums and scatter stay in cache. Same layout as `bin`, bit for bit:
 * cellStart, and slots ascending inside each cell.
 *
 * Why: a plain counting sort of a shuffled world counts each body in a random one of millions of
 * cells and writes it to a random place in 28 MB of sorted columns (at 1M bodies): nearly every
 * access misses the caches and the TLB. On `uniform` at 1M, banding speeds up the shuffled bin and
 * slows the one created row by row; inside a stepping world, which evicts the grid between bins,
 * the gain is smaller (this bin alone on prepared inputs, and an ad-hoc probe alternating both
 * kinds step by step: docs/engine.md, Numbers).
 * Tried, and not better: the bin in the last step's cell order (a gather as random as the
 * scatter); buffering 8 bodies per band before writing them out (the band pass grew slower); a
 * second level, 16 bands each partitioned into fine bands of this size, whose scatter has 64
 * streams instead of 896 (in the stepping world within the noise of this one).
 * GridKernel.wantsBanded says when to use it.
 *
 * `bandStart` holds (cells >> bandShift) + 2 int32. `scratch` holds `scratchCapacity` bodies (32
 * bytes each). Returns 0, or, when a band holds more bodies than that, the most any band holds,
 * having binned nothing: the caller then bins with `bin` and grows the scratch for next time.
 */
export function binBanded(
  xs: usize, ys: usize, rs: usize, n: i32,
  minX: f64, minY: f64, inverse: f64, columns: i32, cells: i32,
  cellStart: usize, binOf: usize, sortedSlot: usize, sortedX: usize, sortedY: usize, sortedR: usize,
  bandShift: i32, bandStart: usize, scratch: usize, scratchCapacity: i32,
): i32 {
  const rows = cells / columns;
  const bands = ((cells - 1) >> bandShift) + 1;
  memory.fill(bandStart, 0, (<usize>bands + 1) << 2);
  const window = jumpWindow(columns, cells);
  let last: i32 = 0;
  let jumped: i32 = 0;
  for (let k: i32 = 0; k < n; k++) {
    const at = <usize>k << 3;
    const c = cellOf(load<f64>(ys + at), minY, inverse, rows) * columns + cellOf(load<f64>(xs + at), minX, inverse, columns);
    store<i32>(binOf + (<usize>k << 2), c);
    countOne(bandStart, c >> bandShift);
    jumped += <i32>(abs<i32>(c - last) > window);
    last = c;
  }
  jumpsFound = jumped;
  let most: i32 = 0;
  let sum: i32 = 0;
  for (let b: i32 = 0; b < bands; b++) {
    const counter = bandStart + (<usize>b << 2);
    const count = load<i32>(counter);
    most = max(most, count);
    store<i32>(counter, sum);
    sum += count;
  }
  if (most > scratchCapacity) return most;
  // bandStart[b], band b's start, ends as its end: band b is [b == 0 ? 0 : bandStart[b - 1], bandStart[b]).
  partition(binOf, 0, n, bandShift, bandStart, xs, ys, rs, sortedSlot, sortedX, sortedY, sortedR);
  let from: i32 = 0;
  for (let b: i32 = 0; b < bands; b++) {
    const to = load<i32>(bandStart + (<usize>b << 2));
    sortBand(b, bandShift, from, to, cells, minX, minY, inverse, columns, cellStart, sortedSlot, sortedX, sortedY, sortedR, scratch, scratchCapacity);
    from = to;
  }
  store<i32>(cellStart + (<usize>cells << 2), n);
  store<i32>(cellStart + ((<usize>cells + 1) << 2), n);
  return 0;
}

/** Counts the bodies [from, to) of each band of 2^bandShift cells into counts[0..bands), from their binOf cells. */
export function bandCounts(binOf: usize, from: i32, to: i32, bandShift: i32, counts: usize, bands: i32): void {
  memory.fill(counts, 0, <usize>bands << 2);
  for (let k = from; k < to; k++) countOne(counts, load<i32>(binOf + (<usize>k << 2)) >> bandShift);
}

/**
 * The stable scatter of bodies [from, to) into their bands: body k goes to place cursor[band]++,
 * slots ascending within each band. A parallel step runs it per share of bodies, each with
 * cursors that start past the bands' bodies of the shares before it.
 */
export function partition(
  binOf: usize, from: i32, to: i32, bandShift: i32, cursor: usize,
  xs: usize, ys: usize, rs: usize, sortedSlot: usize, sortedX: usize, sortedY: usize, sortedR: usize,
): void {
  for (let k = from; k < to; k++) {
    const counter = cursor + (<usize>(load<i32>(binOf + (<usize>k << 2)) >> bandShift) << 2);
    const p = load<i32>(counter);
    store<i32>(counter, p + 1);
    putBody(k, k, xs, ys, rs, p, sortedSlot, sortedX, sortedY, sortedR);
  }
}

/**
 * Band b, whose bodies lie at [from, to) of the sorted columns in ascending slots, sorted into its
 * cells through `scratch` (scratchCapacity >= to - from bodies, 32 bytes each): counts, sums and a
 * scatter from the back, as `bin` does for all cells; cellStart of the band's cells ends as each
 * cell's first place.
 */
export function sortBand(
  b: i32, bandShift: i32, from: i32, to: i32, cells: i32, minX: f64, minY: f64, inverse: f64, columns: i32,
  cellStart: usize, sortedSlot: usize, sortedX: usize, sortedY: usize, sortedR: usize, scratch: usize, scratchCapacity: i32,
): void {
  const rows = cells / columns;
  const capacity = <usize>scratchCapacity;
  const scratchX = scratch;
  const scratchY = scratchX + (capacity << 3);
  const scratchR = scratchY + (capacity << 3);
  const scratchSlot = scratchR + (capacity << 3);
  const scratchCell = scratchSlot + (capacity << 2);
  const m = to - from;
  const firstCell = b << bandShift;
  const endCell = min(cells, firstCell + (1 << bandShift));
  memory.fill(cellStart + (<usize>firstCell << 2), 0, <usize>(endCell - firstCell) << 2);
  memory.copy(scratchX, sortedX + (<usize>from << 3), <usize>m << 3);
  memory.copy(scratchY, sortedY + (<usize>from << 3), <usize>m << 3);
  memory.copy(scratchR, sortedR + (<usize>from << 3), <usize>m << 3);
  memory.copy(scratchSlot, sortedSlot + (<usize>from << 2), <usize>m << 2);
  for (let i: i32 = 0; i < m; i++) {
    const at = <usize>i << 3;
    const c = cellOf(load<f64>(scratchY + at), minY, inverse, rows) * columns + cellOf(load<f64>(scratchX + at), minX, inverse, columns);
    store<i32>(scratchCell + (<usize>i << 2), c);
    countOne(cellStart, c);
  }
  let end = from;
  for (let c = firstCell; c < endCell; c++) {
    const counter = cellStart + (<usize>c << 2);
    end += load<i32>(counter);
    store<i32>(counter, end);
  }
  for (let i: i32 = m - 1; i >= 0; i--) {
    const counter = cellStart + (<usize>load<i32>(scratchCell + (<usize>i << 2)) << 2);
    const p = load<i32>(counter) - 1;
    store<i32>(counter, p);
    putBody(load<i32>(scratchSlot + (<usize>i << 2)), i, scratchX, scratchY, scratchR, p, sortedSlot, sortedX, sortedY, sortedR);
  }
}
