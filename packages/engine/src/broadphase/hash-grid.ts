import type { BroadPhase } from './broadphase.js';
import type { BodyStore } from '../store/body-store.js';
import type { PairSink } from '../store/pair-sink.js';
import { grownCapacity } from '../util/grow.js';
import { LiveExtent } from './live-extent.js';
import { RADIUS_PAD } from './fat-bounds.js';

/** Max Grid's half neighbourhood: the cell itself, the next along its row, and the three of the row below. */
const SIDE_X = [0, 1, -1, 0, 1];
const SIDE_Y = [0, 0, 1, 1, 1];

/** A body's fields in `sorted`: its cell, centre, radius and slot. */
const CELL_X = 0;
const CELL_Y = 1;
const X = 2;
const Y = 3;
const R = 4;
const SLOT = 5;
const BODY = 6;

/** Cells per side of a tile (see bucket), and its log2, and that of the cells in a tile. */
const TILE = 8;
const TILE_BITS = 3;
const TILE_BITS_2 = 6;

/** Buckets per body, at least: a power of two, so that most occupied cells have a bucket of their own. */
const BUCKETS_PER_BODY = 2;

/**
 * Max Grid's cells (the largest diameter, each body in the cell of its centre, half of the 3x3
 * neighbourhood scanned) addressed by a hash of the cell's coordinates rather than by its place
 * in an array laid over the bodies' extent. A dense grid holds a cell for every square of the
 * extent, so two crowds far apart make it choose between memory for the empty space between them
 * and cells wide enough to hold a whole crowd (Max Grid caps its cells at 4 per body and
 * enlarges them: two crowds of 10,000 a million units apart examined 5,000 pairs per body). Here
 * the table has at least twice as many buckets as there are bodies, whatever the extent, and a
 * crowd far away costs what it costs near: O(n) with sizes alike.
 *
 * Cells are floor((p - min) / cellSize) along each axis, with the cell size of Max Grid
 * (LiveExtent.cellSizeFor: padded so that touching circles are never more than one cell apart);
 * within the padding that bounds the coordinates' rounding these are integers below 2^41, exact
 * in a double, so neighbouring cells are always distinct. A bucket can hold bodies of several
 * cells; each body carries its cell, and a scan takes only the bodies of the cell it looks for,
 * so every pair is pushed once. Bodies are binned by counting sort into bucket order, copying
 * their cells, positions and radii beside each other, so that a scan reads each body it looks at
 * from one run of memory.
 *
 * The padded overlap test is CellGrid's, so the pairs pushed are Max Grid's pairs, in another
 * order (the step sorts them canonically).
 */
export class HashGridBroadPhase implements BroadPhase {
  readonly name = 'hashgrid';
  private readonly live = new LiveExtent();
  private bucketStart = new Int32Array(2);
  private bucketOf = new Int32Array(0);
  private cellX = new Float64Array(0);
  private cellY = new Float64Array(0);
  /** The bodies in bucket order, BODY doubles each (CELL_X to SLOT): one run of memory per body a scan looks at. */
  private sorted = new Float64Array(0);
  private shift = 32;
  /** The five cells' body ranges in bucket order, [from, to) each, for the cell being scanned. */
  private readonly range = new Int32Array(10);

  findPairs(bodies: BodyStore, out: PairSink): number {
    const live = this.live;
    live.measure(bodies);
    const n = live.count;
    if (n < 2) return 0;
    // Cells of size 0 only where every body is a point at the origin: then one cell holds them all.
    const size = live.cellSizeFor(live.maxRadius);
    this.bin(bodies, live.dense ? null : live.slots, n, live.minX, live.minY, size > 0 ? 1 / size : 0);
    return this.scan(out, n, live.coordPad);
  }

  memoryBytes(): number {
    return (
      this.live.memoryBytes() +
      this.bucketStart.byteLength +
      this.bucketOf.byteLength +
      this.cellX.byteLength * 2 +
      this.sorted.byteLength
    );
  }

  /**
   * The bucket of cell (cx, cy): cells come in tiles of 8 x 8, whose 64 cells take 64 buckets in a
   * row, row by row, and a tile's place is a multiplicative hash of its coordinates' low 32 bits.
   * Neighbouring cells then mostly share a tile and lie together in memory, as in a dense grid,
   * while tiles far apart spread over the table whatever the extent, a long line of cells included.
   */
  private bucket(cx: number, cy: number): number {
    const tile = Math.imul((Math.floor(cx / TILE) | 0) ^ Math.imul(Math.floor(cy / TILE) | 0, 0x85ebca77), 0x9e3779b1) >>> this.shift;
    return (tile << TILE_BITS_2) | (((cy | 0) & (TILE - 1)) << TILE_BITS) | ((cx | 0) & (TILE - 1));
  }

  private reserve(n: number): void {
    let bits = TILE_BITS_2 + 1;
    while (1 << bits < BUCKETS_PER_BODY * n && bits < 30) bits++;
    this.shift = 32 - (bits - TILE_BITS_2);
    if (this.bucketStart.length < (1 << bits) + 1) this.bucketStart = new Int32Array((1 << bits) + 1);
    if (this.bucketOf.length >= n) return;
    const capacity = grownCapacity(this.bucketOf.length, n);
    this.bucketOf = new Int32Array(capacity);
    this.cellX = new Float64Array(capacity);
    this.cellY = new Float64Array(capacity);
    this.sorted = new Float64Array(capacity * BODY);
  }

  /** Counting sort of the bodies (slots 0..n-1, or `slots`) into bucket order. */
  private bin(bodies: BodyStore, slots: Int32Array | null, n: number, minX: number, minY: number, inverse: number): void {
    this.reserve(n);
    const { x, y, radius } = bodies;
    const { bucketOf, cellX, cellY, sorted } = this;
    const buckets = 2 ** (32 - this.shift + TILE_BITS_2);
    const start = this.bucketStart;
    start.fill(0, 0, buckets + 1);
    for (let k = 0; k < n; k++) {
      const slot = slots === null ? k : slots[k];
      // Bodies left of or above the extent's corner (none: the extent holds every body) would floor below 0, which hashes as well.
      const cx = Math.floor((x[slot] - minX) * inverse);
      const cy = Math.floor((y[slot] - minY) * inverse);
      cellX[k] = cx;
      cellY[k] = cy;
      const b = this.bucket(cx, cy);
      bucketOf[k] = b;
      start[b + 1]++;
    }
    for (let b = 0; b < buckets; b++) start[b + 1] += start[b];
    // The scatter uses each bucket's start as its cursor, then shifts the starts back.
    for (let k = 0; k < n; k++) {
      const slot = slots === null ? k : slots[k];
      const at = start[bucketOf[k]]++ * BODY;
      sorted[at + CELL_X] = cellX[k];
      sorted[at + CELL_Y] = cellY[k];
      sorted[at + X] = x[slot];
      sorted[at + Y] = y[slot];
      sorted[at + R] = radius[slot];
      sorted[at + SLOT] = slot;
    }
    for (let b = buckets; b > 0; b--) start[b] = start[b - 1];
    start[0] = 0;
  }

  /**
   * Each body against the later bodies of its own cell, and all bodies of the next cell along its
   * row and the three cells of the row below (Max Grid's half neighbourhood). Returns the pairs
   * examined: every body of a bucket looked through, a hash collision's included.
   */
  private scan(out: PairSink, n: number, pad: number): number {
    const { bucketStart, sorted, range } = this;
    let examined = 0;
    let cx = NaN;
    let cy = NaN;
    // Cell numbers past 2^53, where cx + 1 === cx (a body far outside the extent, which the
    // elastic pass moves before containment brings it back): the neighbours are then those of
    // keptSides, or a neighbour that is the cell itself paired a body with itself, and one that is
    // another's neighbour the other way round found a pair twice.
    let collapsed = false;
    let kept = 0;
    for (let k = 0; k < n; k++) {
      const at = k * BODY;
      // A cell's bodies lie together in its bucket: its neighbours' buckets are found once for them all.
      if (sorted[at + CELL_X] !== cx || sorted[at + CELL_Y] !== cy) {
        cx = sorted[at + CELL_X];
        cy = sorted[at + CELL_Y];
        collapsed = cx + 1 === cx || cx - 1 === cx || cy + 1 === cy;
        if (collapsed) kept = keptSides(cx, cy);
        for (let side = 0; side < 5; side++) {
          const b = this.bucket(cx + SIDE_X[side], cy + SIDE_Y[side]);
          range[2 * side] = bucketStart[b];
          range[2 * side + 1] = bucketStart[b + 1];
        }
      }
      const ax = sorted[at + X];
      const ay = sorted[at + Y];
      const ar = sorted[at + R] * (1 + RADIUS_PAD) + pad;
      const a = sorted[at + SLOT];
      // Its own cell: the bodies after it in its bucket; then the four cells ahead.
      range[0] = k + 1;
      for (let side = 0; side < 5; side++) {
        const ox = cx + SIDE_X[side];
        const oy = cy + SIDE_Y[side];
        if (collapsed && (kept & (1 << side)) === 0) continue;
        const to = range[2 * side + 1];
        for (let m = range[2 * side]; m < to; m++) {
          const o = m * BODY;
          if (sorted[o + CELL_X] !== ox || sorted[o + CELL_Y] !== oy) continue;
          const reach = ar + sorted[o + R] * (1 + RADIUS_PAD);
          const dx = sorted[o + X] - ax;
          const dy = sorted[o + Y] - ay;
          if (dx * dx + dy * dy <= reach * reach) out.push(a, sorted[o + SLOT]);
        }
        examined += to - range[2 * side];
      }
    }
    return examined;
  }
}

/**
 * The sides of cell (cx, cy), as bits, that make its half neighbourhood once its numbers round:
 * the cell itself, and each neighbour whose offset, as rounded, still lies ahead (a row below, or
 * the same row to the right), once. With rows rounded together, (-1, +1) is the cell to the left,
 * which scans this one as its own (+1, 0).
 */
function keptSides(cx: number, cy: number): number {
  let kept = 1;
  for (let side = 1; side < 5; side++) {
    const ex = cx + SIDE_X[side] - cx;
    const ey = cy + SIDE_Y[side] - cy;
    if (!(ey > 0 || (ey === 0 && ex > 0))) continue;
    let repeated = false;
    for (let earlier = 1; earlier < side; earlier++) {
      if ((kept & (1 << earlier)) !== 0 && cx + SIDE_X[earlier] === cx + SIDE_X[side] && cy + SIDE_Y[earlier] === cy + SIDE_Y[side]) repeated = true;
    }
    if (!repeated) kept |= 1 << side;
  }
  return kept;
}
