// The scans: `scan` (the grid's pairs, row by row) and `scanWindow` (one body from another grid).
import { cellOf } from './common';

// 64-bit: a Max Grid over sizes 1:100 examines 67 million pairs per step at 64,000 bodies (scene
// `mixed`, measured), about 1,000 per body, so a world of 2 million such bodies would pass 2^31.
let examinedPairs: i64 = 0;

/** Pairs examined by the last `scan` (CellGrid.scanRows' return value). */
export function examined(): f64 {
  return <f64>examinedPairs;
}

let candidatesFound: i32 = 0;

/** Pairs whose padded circles overlapped in the last `scan`: its candidates, written or not. */
export function candidates(): i32 {
  return candidatesFound;
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
 * seven body columns at two random slots per pair (their cost at 1M bodies: docs/engine.md).
 * `candidates()` then says how many pairs overlapped.
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
      const column = cellOf(ax, minX, inverse, columns);
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
 * branch left per pair is nearly always predicted. Measured (scan alone, same pairs, 64,000 and 1M
 * bodies: docs/engine.md, Numbers): a head of 2 is much faster than the plain loop; 1 on the same
 * row and 2 below, or 2 and 3, are no better, 2 and 4 is slower, and fully branch-free tests
 * (select, a scratch slot for the stores) are slower than this. Reading up
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
