import type { BroadPhase } from './broadphase.js';
import type { BodyStore } from '../store/body-store.js';
import type { PairSink } from '../store/pair-sink.js';
import { CellGrid } from './cell-grid.js';
import { RADIUS_PAD } from './fat-bounds.js';
import { LiveExtent } from './live-extent.js';
import { grownCapacity } from '../util/grow.js';

/** Radius classes are powers of two; more than this many collapse into the top one. */
const MAX_LEVELS = 24;

/**
 * A hierarchical grid (Mirtich's hierarchical hash grid, without the hash): one Max Grid per
 * power-of-two radius class, so a few large circles no longer make every cell large. This is the
 * answer to the report's own caveat (3.2) that Max Grid tends to O(n^2) when sizes differ by an
 * order of magnitude.
 *
 * Level L holds radii in (rmin 2^(L-1), rmin 2^L] and has cells of at least 2 rmin 2^L, its
 * largest diameter. Pairs within a level come from that level's scan, as in Max Grid. A pair across
 * levels is found once: from the finer body, by looking at the 3x3 cells around its centre in each
 * coarser level (the contact distance r_fine + r_coarse is at most that level's cell size), or
 * from the coarser body, through the window of finer cells it reaches, whichever costs less.
 *
 * Level assignment doubles rmin exactly instead of calling Math.log2, whose rounding is not
 * specified; either way the contact set, and so the result, is the same as every other
 * broad-phase's.
 */
export class HierarchicalGridBroadPhase implements BroadPhase {
  readonly name = 'hgrid';
  private readonly live = new LiveExtent();
  private readonly grids: CellGrid[] = [];
  private levelOf = new Int8Array(0);
  private levelSlots = new Int32Array(0);
  private readonly levelStart = new Int32Array(MAX_LEVELS + 1);
  // What the buckets were made for (see assignLevels).
  private levelsFor: BodyStore | null = null;
  private levelsVersion = -1;
  private levelCount = 0;

  findPairs(bodies: BodyStore, out: PairSink): number {
    const live = this.live;
    live.measure(bodies);
    const n = live.count;
    if (n < 2) return 0;
    const levels = this.assignLevels(bodies, n);
    const base = live.cellSizeFor(live.minRadius);
    const budget = 4 * n + 64;
    for (let level = 0; level < levels; level++) {
      const from = this.levelStart[level];
      const count = this.levelStart[level + 1] - from;
      // A level's cells must cover its largest diameter; the top level takes everything larger.
      const cellSize = level === levels - 1 ? live.cellSizeFor(live.maxRadius) : base * 2 ** level;
      this.grid(level).build(
        bodies,
        this.levelSlots,
        from,
        count,
        live.minX,
        live.minY,
        live.maxX,
        live.maxY,
        cellSize,
        Math.min(budget, 4 * count + 64),
      );
    }
    let examined = 0;
    for (let level = 0; level < levels; level++) {
      const grid = this.grids[level];
      if (grid.count === 0) continue;
      examined += grid.scanSelf(out, live.coordPad);
      for (let coarser = level + 1; coarser < levels; coarser++) {
        const target = this.grids[coarser];
        if (target.count === 0) continue;
        examined += lookAcross(grid, target, live.coordPad, out);
      }
    }
    return examined;
  }

  memoryBytes(): number {
    let bytes = this.live.memoryBytes() + this.levelOf.byteLength + this.levelSlots.byteLength;
    for (const grid of this.grids) bytes += grid.memoryBytes();
    return bytes;
  }

  /**
   * Buckets live slots by level (counting sort, slots stay ascending); returns the level count.
   * Levels depend only on which bodies live and their radii, which never change while a body
   * lives, so the buckets are kept until the set of live bodies changes.
   */
  private assignLevels(bodies: BodyStore, n: number): number {
    if (bodies === this.levelsFor && bodies.membershipVersion === this.levelsVersion) return this.levelCount;
    this.levelsFor = bodies;
    this.levelsVersion = bodies.membershipVersion;
    this.levelCount = this.bucketLevels(bodies, n);
    return this.levelCount;
  }

  private bucketLevels(bodies: BodyStore, n: number): number {
    if (this.levelOf.length < n) {
      const capacity = grownCapacity(this.levelOf.length, n);
      this.levelOf = new Int8Array(capacity);
      this.levelSlots = new Int32Array(capacity);
    }
    const { radius } = bodies;
    const { slots, minRadius, dense } = this.live;
    const { levelOf, levelStart } = this;
    levelStart.fill(0);
    let levels = 1;
    for (let k = 0; k < n; k++) {
      const r = radius[dense ? k : slots[k]];
      let level = 0;
      let limit = minRadius;
      while (limit < r && level < MAX_LEVELS - 1) {
        limit *= 2;
        level++;
      }
      levelOf[k] = level;
      levelStart[level + 1]++;
      if (level + 1 > levels) levels = level + 1;
    }
    for (let level = 0; level < MAX_LEVELS; level++) levelStart[level + 1] += levelStart[level];
    // Scatter from the back, decrementing each level's end: slots stay ascending within a level.
    for (let k = n - 1; k >= 0; k--) this.levelSlots[--levelStart[levelOf[k] + 1]] = dense ? k : slots[k];
    for (let level = 0; level < MAX_LEVELS; level++) levelStart[level] = levelStart[level + 1];
    levelStart[MAX_LEVELS] = n;
    return levels;
  }

  private grid(level: number): CellGrid {
    while (this.grids.length <= level) this.grids.push(new CellGrid());
    return this.grids[level];
  }
}

/**
 * Finds the pairs between a finer level and a coarser one, from whichever side costs less: from
 * each fine body, the 3x3 cells around it in the coarse grid (three row ranges); or from each
 * coarse body, the window of fine cells its reach spans. The first suits many coarse bodies, the
 * second a few large ones among many small (the report's case: at 64,000 bodies with 64 large,
 * 64 windows instead of 64,000 lookups). Either way every pair within reach is examined once, so
 * the contacts are the same. Returns the pairs examined.
 */
function lookAcross(fine: CellGrid, coarse: CellGrid, pad: number, out: PairSink): number {
  const coarseOccupancy = coarse.count / (coarse.columns * coarse.rows);
  const fromFine = fine.count * 3 * (1 + 3 * coarseOccupancy);
  // A coarse body's padded radius is at most half its cell; fine bodies reach half theirs.
  const halfWidth = coarse.cellSize / 2 + pad + fine.cellSize / 2;
  const span = Math.min(2 * Math.ceil(halfWidth / fine.cellSize) + 1, Math.max(fine.columns, fine.rows));
  const fromCoarse = coarse.count * span * (1 + (span * fine.count) / (fine.columns * fine.rows));
  let examined = 0;
  if (fromCoarse < fromFine) {
    const { sortedX, sortedY, sortedR, sortedSlot } = coarse;
    for (let k = 0; k < coarse.count; k++) {
      const reach = sortedR[k] * (1 + RADIUS_PAD) + pad;
      examined += fine.scanWindow(sortedX[k], sortedY[k], reach, sortedSlot[k], reach + fine.cellSize / 2, out);
    }
  } else {
    const { sortedX, sortedY, sortedR, sortedSlot } = fine;
    for (let k = 0; k < fine.count; k++) {
      examined += coarse.scanAround(sortedX[k], sortedY[k], sortedR[k] * (1 + RADIUS_PAD) + pad, sortedSlot[k], out);
    }
  }
  return examined;
}
