// Inline helpers shared by the grid kernel's bins (bin.ts, parallel-bin.ts) and scan (scan.ts):
// one formula each for a body's cell, the jump window and the write of a body into cell order, so
// that every bin, serial, banded or parallel, gives the same layout.

/** How far (in cells) a body's cell must lie from the previous body's to count as a jump. */
// @ts-ignore: decorator
@inline
export function jumpWindow(columns: i32, cells: i32): i32 {
  return max(columns << 1, cells >> 6);
}

/**
 * The TypeScript path's cell of a coordinate: `(p - origin) * inverse`, floored and clamped into
 * [0, count), so that a body outside the grid's extent lands in an edge cell (see
 * CellGrid.layout: clamping keeps touching bodies in neighbouring cells) and no index leaves the
 * arrays. Adding 2^52 to a whole number t in [0, 2^52) gives the double whose bits are those of
 * 2^52 plus t; any other t (negative, larger, infinite or NaN) gives bits below or far above. So
 * one unsigned comparison of the bits less 2^52's finds every body inside the extent, and the rest
 * (NaN clamps to 0) take clampedCell: cheaper than clamping the double on every call, which is in
 * the broad-phase's innermost loops (docs/engine.md, "Numbers").
 * Why not `<i32>`: V8 compiles WebAssembly's f64-to-i32 conversions with range checks, and cells
 * come faster this way than with either the saturating or the trapping conversion (measured at
 * 500,000 bodies: docs/engine.md, Numbers).
 */
// @ts-ignore: decorator
@inline
export function cellOf(p: f64, origin: f64, inverse: f64, count: i32): i32 {
  const t = floor((p - origin) * inverse);
  const offset = reinterpret<i64>(t + 4503599627370496.0) - 0x4330000000000000;
  return <u64>offset < <u64>count ? <i32>offset : clampedCell(t, count);
}

/** cellOf's edge cell for a floored offset t outside [0, count). */
// @ts-ignore: decorator
@inline
function clampedCell(t: f64, count: i32): i32 {
  return t >= <f64>count ? count - 1 : 0;
}

/** The k-th body to bin: slot k, or the k-th of a slot list. */
// @ts-ignore: decorator
@inline
export function slotAt(slots: usize, k: i32): i32 {
  return slots == 0 ? k : load<i32>(slots + (<usize>k << 2));
}

// @ts-ignore: decorator
@inline
export function countOne(cellStart: usize, cell: i32): void {
  const counter = cellStart + (<usize>cell << 2);
  store<i32>(counter, load<i32>(counter) + 1);
}

/** Body `from` of the columns at xs, ys, rs into place `to` of the sorted columns, as slot `slot`. */
// @ts-ignore: decorator
@inline
export function putBody(
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

/** The body in slot i into the last free place of its cell (pre-decrement): the scatter step of `bin` and `scatterCells`. */
// @ts-ignore: decorator
@inline
export function scatterOne(
  i: i32, cell: i32, cellStart: usize, xs: usize, ys: usize, rs: usize,
  sortedSlot: usize, sortedX: usize, sortedY: usize, sortedR: usize,
): void {
  const counter = cellStart + (<usize>cell << 2);
  const place = load<i32>(counter) - 1;
  store<i32>(counter, place);
  putBody(i, i, xs, ys, rs, place, sortedSlot, sortedX, sortedY, sortedR);
}
