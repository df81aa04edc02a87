// AssemblyScript source of the Max Grid's WebAssembly kernel (compiled by scripts/build-kernel.mjs
// into src/generated/, loaded by src/broadphase/grid-kernel.ts). It is CellGrid.bin and
// CellGrid.scanRows operation for operation, on arrays the caller lays out in the imported memory
// and passes as byte offsets, so its pairs, and every result downstream, are the same bits as the
// TypeScript path's.
//
// Why WebAssembly for these two loops: in V8's optimized code every typed-array access inside a
// loop re-checks the array's map, base pointer and length (nothing is hoisted; seen with
// --print-opt-code), which made them about 2x the same loops in C; here the memory base stays in
// a register and bounds are checked by guard pages.
// Measured at 64,000 bodies: bin 1.6-1.7 ms in TS, 0.9 in WebAssembly; scan 2.6-3.1 ms against
// 1.8-2.1 (C: bin 0.7-0.8, scan 1.6-1.9); the scan then lost its loop-exit mispredictions (see
// pushOverlaps) and takes 1.06-1.16. SIMD is not used: the scan examines about 2.1 pairs per
// body (137,000 per step at 64,000 bodies) in ranges of 0 to 3 bodies, so branches rather than
// arithmetic bound it. Tried: one f64x2 test for each range's two-body head, with the scalar tests
// only when a lane hits. The scan alone took 0.95-0.96x as long (64k and 1M, same pairs), about
// 2 % of a step, not worth a module that fails to compile where SIMD is missing.

// 64-bit: a Max Grid over sizes 1:100 examines 67 million pairs per step at 64,000 bodies (scene
// `mixed`, measured), about 1,000 per body, so a world of 2 million such bodies would pass 2^31.
let examinedPairs: i64 = 0;

/** Pairs examined by the last `scan` (CellGrid.scanRows' return value). */
export function examined(): f64 {
  return <f64>examinedPairs;
}

let candidatesFound: i32 = 0;

// Bodies of the last `bin` or `binBanded` whose cell lies far from the previous body's: more than
// two rows and more than 1/64 of all cells away. It says how scattered the bodies lie in memory
// against space, which decides the next bin's kind. Two rows alone was too strict: a world created
// row by row counts 32 % of its bodies as jumps after 1 s of motion and 79 % after 10 s (1M
// bodies), yet its plain bin stayed the faster (ad-hoc probe alternating both kinds step by step,
// medians: 29.0 ms against 42.6 at 1 s, 35.7 against 40.8 at 10 s). With the 1/64 window those
// figures are 0 % and 0.6 %, and a shuffled world's 97 %.
let jumpsFound: i32 = 0;

/** The last bin's jumps (see jumpsFound). */
export function jumps(): i32 {
  return jumpsFound;
}

/** How far (in cells) a body's cell must lie from the previous body's to count as a jump. */
// @ts-ignore: decorator
@inline
function jumpWindow(columns: i32, cells: i32): i32 {
  return max(columns << 1, cells >> 6);
}

/** Pairs whose padded circles overlapped in the last `scan`: its candidates, written or not. */
export function candidates(): i32 {
  return candidatesFound;
}

/**
 * Counting sort of n bodies into `cells` row-major cells: slots 0..n-1, or the n int32 slots at
 * `slots` when it is not 0; positions and radii are read at xs, ys, rs by slot. cellStart
 * (cells + 2 int32) ends as each cell's first index, sorted* hold the bodies in cell order, binOf
 * is scratch. Radii are copied as they are: scans pad them as they read them.
 */
export function bin(
  xs: usize, ys: usize, rs: usize, slots: usize, n: i32,
  minX: f64, minY: f64, inverse: f64, columns: i32, cells: i32,
  cellStart: usize, binOf: usize, sortedSlot: usize, sortedX: usize, sortedY: usize, sortedR: usize,
): void {
  memory.fill(cellStart, 0, (<usize>cells + 2) << 2);
  const window = jumpWindow(columns, cells);
  let last: i32 = 0;
  let jumped: i32 = 0;
  for (let k: i32 = 0; k < n; k++) {
    const at = <usize>slotAt(slots, k) << 3;
    const c = cellOf(load<f64>(ys + at), minY, inverse) * columns + cellOf(load<f64>(xs + at), minX, inverse);
    store<i32>(binOf + (<usize>k << 2), c);
    const counter = cellStart + (<usize>c << 2);
    store<i32>(counter, load<i32>(counter) + 1);
    jumped += <i32>(abs<i32>(c - last) > window);
    last = c;
  }
  jumpsFound = jumped;
  let sum: i32 = 0;
  for (let c: i32 = 0; c < cells; c++) {
    const counter = cellStart + (<usize>c << 2);
    sum += load<i32>(counter);
    store<i32>(counter, sum);
  }
  // From the back with pre-decrement: slots ascend inside each cell, as in CellGrid.bin.
  for (let k: i32 = n - 1; k >= 0; k--) {
    scatterOne(slotAt(slots, k), load<i32>(binOf + (<usize>k << 2)), cellStart, xs, ys, rs, sortedSlot, sortedX, sortedY, sortedR);
  }
  store<i32>(cellStart + (<usize>cells << 2), n);
  store<i32>(cellStart + ((<usize>cells + 1) << 2), n);
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
 * access misses the caches and the TLB. `uniform` at 1M, this bin alone on prepared inputs: 59 ms
 * shuffled against 16.7 created row by row; banded, 38-42 and 25. Inside a stepping world, which
 * evicts the grid between bins, the gain is smaller: 67.2 ms plain against 53.4 banded, 56.3
 * against 45.9 a second later (ad-hoc probe alternating both kinds step by step, medians of 8).
 * Tried, and not better: the bin in the last step's cell order (a gather as random as the
 * scatter, 56 ms); buffering 8 bodies per band before writing them out (the band pass rose from 18
 * to 47 ms); a second level, 16 bands each partitioned into fine bands of this size, whose scatter
 * has 64 streams instead of 896 (in the stepping world within the noise of this one: 51.4 / 42.5
 * / 54.2 ms against 50.4 / 50.5 / 59.0). GridKernel.wantsBanded says when to use it.
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
  const bands = ((cells - 1) >> bandShift) + 1;
  memory.fill(bandStart, 0, (<usize>bands + 1) << 2);
  const window = jumpWindow(columns, cells);
  let last: i32 = 0;
  let jumped: i32 = 0;
  for (let k: i32 = 0; k < n; k++) {
    const at = <usize>k << 3;
    const c = cellOf(load<f64>(ys + at), minY, inverse) * columns + cellOf(load<f64>(xs + at), minX, inverse);
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
    const c = cellOf(load<f64>(scratchY + at), minY, inverse) * columns + cellOf(load<f64>(scratchX + at), minX, inverse);
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

// The three passes of a parallel bin (src/parallel/kernels.ts), each on one thread's share: the
// cells of a body range, then per band of cells the count, and the prefix sums and scatter. Same
// formulas and order as `bin`, so the layout is the serial one.
//
// Every thread's count and scatter must find the bodies of its band among all n. Reading all n
// per thread made those two passes barely faster on two threads than on one (1M bodies: count
// 2.5 ms against 2.8). So the cells pass also notes each chunk's smallest and largest cell, and
// the others skip chunks that miss their band and test nothing in chunks wholly inside it. Where
// bodies lie in space as they lie in memory (created row by row, as scenes and spawners do) each
// thread then reads about n / threads bodies; in a shuffled world every chunk spans every band
// and the passes read all n, as before: such worlds take the banded passes instead (bandCounts,
// partition and sortBand, run by src/parallel/banded-bin.ts).

/** Bodies per chunk of `chunkCells`: its entries are 2 int32 (smallest, largest cell) per chunk. */
const CHUNK_SHIFT = 10;

/**
 * Each body's cell for bodies [from, to), from positions at xs, ys, and each chunk's smallest and
 * largest cell at chunkCells; returns the range's jumps (see jumpsFound) in a grid of `cells`.
 * `from` is a multiple of the chunk size (so no chunk is shared between threads) and `to` one too,
 * unless it is the last body.
 */
export function cellsOf(
  xs: usize, ys: usize, from: i32, to: i32, minX: f64, minY: f64, inverse: f64, columns: i32, cells: i32, binOf: usize, chunkCells: usize,
): i32 {
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
      const c = cellOf(load<f64>(ys + at), minY, inverse) * columns + cellOf(load<f64>(xs + at), minX, inverse);
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

// @ts-ignore: decorator
@inline
function countOne(cellStart: usize, cell: i32): void {
  const counter = cellStart + (<usize>cell << 2);
  store<i32>(counter, load<i32>(counter) + 1);
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

/** The body in slot i into the last free place of its cell (pre-decrement): the scatter step of `bin` and `scatterCells`. */
// @ts-ignore: decorator
@inline
function scatterOne(
  i: i32, cell: i32, cellStart: usize, xs: usize, ys: usize, rs: usize,
  sortedSlot: usize, sortedX: usize, sortedY: usize, sortedR: usize,
): void {
  const counter = cellStart + (<usize>cell << 2);
  const place = load<i32>(counter) - 1;
  store<i32>(counter, place);
  putBody(i, i, xs, ys, rs, place, sortedSlot, sortedX, sortedY, sortedR);
}

/** Body `from` of the columns at xs, ys, rs into place `to` of the sorted columns, as slot `slot`. */
// @ts-ignore: decorator
@inline
function putBody(
  slot: i32, from: i32, xs: usize, ys: usize, rs: usize,
  to: i32, sortedSlot: usize, sortedX: usize, sortedY: usize, sortedR: usize,
): void {
  const src = <usize>from << 3;
  const dst = <usize>to << 3;
  store<i32>(sortedSlot + (<usize>to << 2), slot);
  store<f64>(sortedX + dst, load<f64>(xs + src));
  store<f64>(sortedY + dst, load<f64>(ys + src));
  store<f64>(sortedR + dst, load<f64>(rs + src));
}

/**
 * The TypeScript path's `(p - origin) * inverse | 0`. Offsets are >= 0, where flooring is
 * truncating, and adding 2^52 to a whole number below 2^52 leaves it in the low bits of the
 * double, which are then exactly `| 0` (ToInt32) of it; infinities and NaN (as arithmetic makes
 * it) give 0, as there.
 * Why not `<i32>`: V8 compiles WebAssembly's f64-to-i32 conversions with range checks, and this
 * way computing cells for 500,000 bodies took 1.3 ms against 3.2 (trunc_sat) and 1.7-2.2 (trapping).
 */
// @ts-ignore: decorator
@inline
function cellOf(p: f64, origin: f64, inverse: f64): i32 {
  return <i32>reinterpret<i64>(floor((p - origin) * inverse) + 4503599627370496.0);
}

/** The k-th body to bin: slot k, or the k-th of a slot list. */
// @ts-ignore: decorator
@inline
function slotAt(slots: usize, k: i32): i32 {
  return slots == 0 ? k : load<i32>(slots + (<usize>k << 2));
}

/**
 * CellGrid.scanRows over rows [rowFrom, rowTo): writes each overlapping pair (a, b) as two int32 at
 * `pairs`, up to `capacity` pairs, and returns how many it found, which may exceed `capacity`: the
 * caller then grows the buffer and scans again. Circles are padded as fat-bounds.ts says: radii
 * times `radiusScale`, plus `pad` once per pair.
 *
 * With `touching`, for worlds where every pair collides (no filters, sleepers, static or kinematic
 * bodies: NarrowPhase would pass each pair to the circle test alone), each overlapping pair also
 * takes that test here, on the copies in cell order the scan has just read, and only touching
 * pairs are written, as (lo, hi): the narrow-phase's contacts, the same bits, without reading
 * seven body columns at two random slots per pair (1M bodies: 86 ns per pair). `candidates()`
 * then says how many pairs overlapped.
 */
export function scan(
  cellStart: usize, sortedSlot: usize, sortedX: usize, sortedY: usize, sortedR: usize,
  columns: i32, rows: i32, rowFrom: i32, rowTo: i32, minX: f64, inverse: f64,
  pad: f64, radiusScale: f64, touching: bool, pairs: usize, capacity: i32,
): i32 {
  candidatesFound = 0;
  let found: i32 = 0;
  let examinedHere: i64 = 0;
  // Body by body, in cell order, each body's column recomputed as the bin computed it: the same
  // ranges, pairs and order as CellGrid.scanRows' cell-by-cell loop, without visiting the empty
  // cells (49 % of them on `uniform`, 0.545 bodies per cell, at 64k and at 1M), whose tests mispredict.
  for (let row = rowFrom; row < rowTo; row++) {
    const rowStart = row * columns;
    const hasBelow = row + 1 < rows;
    const rowEnd = load<i32>(cellStart + (<usize>(rowStart + columns) << 2));
    for (let k = load<i32>(cellStart + (<usize>rowStart << 2)); k < rowEnd; k++) {
      const at = <usize>k << 3;
      const ax = load<f64>(sortedX + at);
      const column = cellOf(ax, minX, inverse);
      const c = rowStart + column;
      const sameRowEnd = load<i32>(cellStart + (<usize>(column + 1 < columns ? c + 2 : c + 1) << 2));
      let from: i32 = 0;
      let to: i32 = 0;
      if (hasBelow) {
        const below = c + columns;
        from = load<i32>(cellStart + (<usize>(column > 0 ? below - 1 : below) << 2));
        to = load<i32>(cellStart + (<usize>(column + 1 < columns ? below + 2 : below + 1) << 2));
      }
      const ay = load<f64>(sortedY + at);
      const radius = load<f64>(sortedR + at);
      const ar = radius * radiusScale + pad;
      const a = load<i32>(sortedSlot + (<usize>k << 2));
      found = pushOverlaps(k + 1, sameRowEnd, ax, ay, ar, radius, a, radiusScale, touching, sortedSlot, sortedX, sortedY, sortedR, pairs, capacity, found);
      found = pushOverlaps(from, to, ax, ay, ar, radius, a, radiusScale, touching, sortedSlot, sortedX, sortedY, sortedR, pairs, capacity, found);
      examinedHere += <i64>(sameRowEnd - k - 1 + (to - from));
    }
  }
  examinedPairs = examinedHere;
  return found;
}

/**
 * CellGrid.scanWindow: the circle (px, py, reach) of body `slot`, from another grid, against the
 * bodies of cells [c0, c1] x [r0, r1] here, one range per row; writes pairs (slot, other) as `scan`
 * does and returns how many it found.
 */
export function scanWindow(
  cellStart: usize, sortedSlot: usize, sortedX: usize, sortedY: usize, sortedR: usize,
  columns: i32, c0: i32, c1: i32, r0: i32, r1: i32, px: f64, py: f64, reach: f64, radiusScale: f64, slot: i32, pairs: usize, capacity: i32,
): i32 {
  let found: i32 = 0;
  let examinedHere: i64 = 0;
  for (let row = r0; row <= r1; row++) {
    const from = load<i32>(cellStart + (<usize>(row * columns + c0) << 2));
    const to = load<i32>(cellStart + (<usize>(row * columns + c1 + 1) << 2));
    found = pushOverlaps(from, to, px, py, reach, 0, slot, radiusScale, false, sortedSlot, sortedX, sortedY, sortedR, pairs, capacity, found);
    examinedHere += <i64>(to - from);
  }
  examinedPairs = examinedHere;
  return found;
}

/**
 * Writes (a, other) for each body in [from, to) whose padded circle overlaps a's (padded reach
 * `ar`); with `touching`, only those that touch a (radius `radius`), as (lo, hi), as
 * circle-circle.ts tests them. Returns the new pair count.
 *
 * The first RANGE_HEAD bodies are tested whether or not the range holds them, the test masked by
 * `m < to`, and a loop takes the rest. Why: on `uniform` a body's ranges hold 0, 1 or 2 bodies
 * (same row: 50, 44, 6 %; row below: 12, 36, 36 %, 13 % hold 3), so a loop's exit was
 * mispredicted about once per range, while only 2.3 % of the pairs examined overlap, so the one
 * branch left per pair is nearly always predicted. Measured (64,000 bodies, scan alone, same
 * pairs): 1.69-1.79 ms with the plain loop, 1.06-1.16 with a head of 2; 1.11 with 1 on the same
 * row and 2 below, 1.10-1.13 with 2 and 3, 1.28 with 2 and 4; fully branch-free tests (select, a
 * scratch slot for the stores) 1.44-1.53, slower than this. At 1M: 27.9 ms to 16.9. Reading up
 * to RANGE_HEAD - 1 entries past an array's end stays inside the memory, whose pair buffer comes
 * last, and what is read there is masked off.
 */
// @ts-ignore: decorator
@inline
function pushOverlaps(
  from: i32, to: i32, ax: f64, ay: f64, ar: f64, radius: f64, a: i32, radiusScale: f64, touching: bool,
  sortedSlot: usize, sortedX: usize, sortedY: usize, sortedR: usize, pairs: usize, capacity: i32, found: i32,
): i32 {
  found = pushIfOverlapping(from, to, ax, ay, ar, radius, a, radiusScale, touching, sortedSlot, sortedX, sortedY, sortedR, pairs, capacity, found);
  found = pushIfOverlapping(from + 1, to, ax, ay, ar, radius, a, radiusScale, touching, sortedSlot, sortedX, sortedY, sortedR, pairs, capacity, found);
  for (let m = from + RANGE_HEAD; m < to; m++) {
    found = pushIfOverlapping(m, to, ax, ay, ar, radius, a, radiusScale, touching, sortedSlot, sortedX, sortedY, sortedR, pairs, capacity, found);
  }
  return found;
}

/** Bodies of a range that pushOverlaps tests without a loop (it spells out that many calls). */
const RANGE_HEAD: i32 = 2;

/** pushOverlaps' test of body m, a no-op unless m < to. */
// @ts-ignore: decorator
@inline
function pushIfOverlapping(
  m: i32, to: i32, ax: f64, ay: f64, ar: f64, radius: f64, a: i32, radiusScale: f64, touching: bool,
  sortedSlot: usize, sortedX: usize, sortedY: usize, sortedR: usize, pairs: usize, capacity: i32, found: i32,
): i32 {
  const other = <usize>m << 3;
  const otherRadius = load<f64>(sortedR + other);
  const reach = ar + otherRadius * radiusScale;
  const dx = load<f64>(sortedX + other) - ax;
  const dy = load<f64>(sortedY + other) - ay;
  const squared = dx * dx + dy * dy;
  // One branch for both conditions (`&`, not `&&`): it is the rarely taken one.
  if (<i32>(m < to) & <i32>(squared <= reach * reach)) {
    candidatesFound++;
    const b = load<i32>(sortedSlot + (<usize>m << 2));
    if (touching) {
      const touch = radius + otherRadius;
      if (!(squared < touch * touch)) return found;
    }
    if (found < capacity) {
      const out = pairs + (<usize>found << 3);
      store<i32>(out, touching && b < a ? b : a);
      store<i32>(out, touching && b < a ? a : b, 4);
    }
    found++;
  }
  return found;
}
