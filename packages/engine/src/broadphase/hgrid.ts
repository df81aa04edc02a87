import type { BroadPhase } from './broadphase.js';
import type { BodyStore } from '../store/body-store.js';
import type { PairSink } from '../store/pair-sink.js';
import { CellGrid } from './cell-grid.js';
import { RADIUS_PAD } from './fat-bounds.js';
import { LiveExtent } from './live-extent.js';
import { ExtentFitter, type Extent } from './extent-fit.js';
import { grownCapacity } from '../util/grow.js';

/**
 * A class joins the level below it while its cells would be at most this many times the cells the
 * level's cell budget makes anyway (see groupClasses): about one body per cell. Log-uniform radii
 * over six decades stepped a third faster than with 1 (fewer levels), and no scene measured in
 * auto.ts slower.
 */
const JOIN_FACTOR = 2;

/** classBox holds minX, minY, maxX, maxY and the largest radius per class. */
const BOX_STRIDE = 5;

/**
 * A hierarchical grid (Mirtich's hierarchical hash grid, without the hash): one Max Grid per
 * power-of-two radius class, so a few large circles no longer make every cell large. This is the
 * answer to the report's own caveat (3.2) that Max Grid tends to O(n^2) when sizes differ by an
 * order of magnitude.
 *
 * Class c holds radii in (rmin 2^(c-1), rmin 2^c]; a level holds one class or several neighbouring
 * ones, and its cells are at least its largest diameter, over the box around its own bodies (see
 * extent-fit.ts). Pairs within a level come from that level's scan, as in Max Grid. A pair across
 * levels is found once: from the finer body, by looking at the 3x3 cells around its centre in each
 * coarser level (the contact distance r_fine + r_coarse is at most that level's cell size), or
 * from the coarser body, through the window of finer cells it reaches, whichever costs less.
 *
 * Radius classes are the powers of two, as many as the radii span (no limit that folds large
 * bodies into a top class). Neighbouring classes share a level where a level's own cells would
 * be no finer anyway: a grid holds at most 4n + 64 cells, so over a wide extent a sparse class's
 * cells are enlarged until they fit, and classes below that size gain nothing from a grid of
 * their own but cost a lookup per body in every coarser level (log-uniform radii over six decades
 * made twenty levels, twenty times the time of a single Max Grid).
 *
 * Whatever the levels, the contact set, and so the result, is the same as every other
 * broad-phase's.
 */
export class HierarchicalGridBroadPhase implements BroadPhase {
  readonly name = 'hgrid';
  private readonly live = new LiveExtent();
  private readonly grids: CellGrid[] = [];
  private levelOf = new Int32Array(0);
  private levelSlots = new Int32Array(0);
  private levelStart = new Int32Array(2);
  /** Each level's largest radius, which sizes its cells. */
  private levelRadius = new Float64Array(1);
  private classCount = new Int32Array(0);
  private classLevel = new Int32Array(0);
  /** Each class's box around its bodies' centres and largest radius (BOX_STRIDE apiece), for grouping. */
  private classBox = new Float64Array(0);
  private readonly fitter = new ExtentFitter();
  private readonly levelBox: Extent = { minX: 0, minY: 0, maxX: 0, maxY: 0 };
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
    const { x, y } = bodies;
    const { fitter, levelSlots } = this;
    const box = this.levelBox;
    for (let level = 0; level < levels; level++) {
      const from = this.levelStart[level];
      const count = this.levelStart[level + 1] - from;
      // A level's cells must cover its largest diameter.
      const cellSize = live.cellSizeFor(this.levelRadius[level]);
      const budget = 4 * count + 64;
      // Each level over its own bodies: small ones in one crowd, large ones spread wide, must not
      // share the wide extent, whose cells the budget would make huge for the crowd.
      fitter.measure(x, y, levelSlots, from, count, box);
      fitter.fit(x, y, levelSlots, from, count, cellSize, budget, box);
      this.grid(level).build(bodies, levelSlots, from, count, box.minX, box.minY, box.maxX, box.maxY, cellSize, budget);
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
    let bytes = this.live.memoryBytes() + this.levelOf.byteLength + this.levelSlots.byteLength + this.classCount.byteLength + this.classLevel.byteLength + this.classBox.byteLength;
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
      this.levelOf = new Int32Array(capacity);
      this.levelSlots = new Int32Array(capacity);
    }
    const { radius } = bodies;
    const { slots, minRadius, dense } = this.live;
    const levelOf = this.levelOf;
    // Classes first (levelOf holds each body's class until the levels are known).
    let classes = 1;
    for (let k = 0; k < n; k++) {
      const c = radiusClass(radius[dense ? k : slots[k]], minRadius);
      levelOf[k] = c;
      if (c + 1 > classes) classes = c + 1;
    }
    if (this.classCount.length < classes) {
      this.classCount = new Int32Array(grownCapacity(this.classCount.length, classes));
      this.classLevel = new Int32Array(this.classCount.length);
      this.classBox = new Float64Array(BOX_STRIDE * this.classCount.length);
    }
    const { classCount, classLevel, classBox } = this;
    const { x, y } = bodies;
    classCount.fill(0, 0, classes);
    for (let c = 0; c < classes; c++) {
      const b = BOX_STRIDE * c;
      classBox[b] = Infinity;
      classBox[b + 1] = Infinity;
      classBox[b + 2] = -Infinity;
      classBox[b + 3] = -Infinity;
      classBox[b + 4] = 0;
    }
    for (let k = 0; k < n; k++) {
      const c = levelOf[k];
      const i = dense ? k : slots[k];
      classCount[c]++;
      const b = BOX_STRIDE * c;
      if (x[i] < classBox[b]) classBox[b] = x[i];
      if (y[i] < classBox[b + 1]) classBox[b + 1] = y[i];
      if (x[i] > classBox[b + 2]) classBox[b + 2] = x[i];
      if (y[i] > classBox[b + 3]) classBox[b + 3] = y[i];
      if (radius[i] > classBox[b + 4]) classBox[b + 4] = radius[i];
    }
    const levels = this.groupClasses(classes);
    for (let k = 0; k < n; k++) levelOf[k] = classLevel[levelOf[k]];

    if (this.levelStart.length < levels + 1) this.levelStart = new Int32Array(grownCapacity(this.levelStart.length, levels + 1));
    const levelStart = this.levelStart;
    levelStart.fill(0);
    for (let k = 0; k < n; k++) levelStart[levelOf[k] + 1]++;
    for (let level = 0; level < levels; level++) levelStart[level + 1] += levelStart[level];
    // Scatter from the back, decrementing each level's end: slots stay ascending within a level.
    for (let k = n - 1; k >= 0; k--) this.levelSlots[--levelStart[levelOf[k] + 1]] = dense ? k : slots[k];
    for (let level = 0; level < levels; level++) levelStart[level] = levelStart[level + 1];
    levelStart[levels] = n;
    return levels;
  }

  /**
   * Groups the classes below `classes` into levels (classLevel, levelRadius); returns the level
   * count. Walking up from the finest, a class joins the current level when the cells its largest
   * radius needs would be at most JOIN_FACTOR times the cells that the level's budget (4 n + 64
   * over the box around the level's bodies, that class's included) enforces anyway: then about
   * one body per cell or fewer, and one lookup fewer for every finer body. Empty classes join the
   * current level. Positions only steer the cost: the contacts are the same whatever the levels.
   */
  private groupClasses(classes: number): number {
    const { classCount, classLevel, classBox } = this;
    const live = this.live;
    if (this.levelRadius.length < classes) this.levelRadius = new Float64Array(grownCapacity(this.levelRadius.length, classes));
    const levelRadius = this.levelRadius;
    // Class 0 holds the smallest radius, so the first level is never empty.
    let level = 0;
    let inLevel = 0;
    let minX = Infinity;
    let minY = Infinity;
    let maxX = -Infinity;
    let maxY = -Infinity;
    for (let c = 0; c < classes; c++) {
      const count = classCount[c];
      if (count === 0) {
        classLevel[c] = level;
        continue;
      }
      const b = BOX_STRIDE * c;
      const joinedMinX = Math.min(minX, classBox[b]);
      const joinedMinY = Math.min(minY, classBox[b + 1]);
      const joinedMaxX = Math.max(maxX, classBox[b + 2]);
      const joinedMaxY = Math.max(maxY, classBox[b + 3]);
      const cell = live.cellSizeFor(classBox[b + 4]);
      const area = Math.max((joinedMaxX - joinedMinX) * (joinedMaxY - joinedMinY), cell * cell);
      if (inLevel > 0 && cell > JOIN_FACTOR * Math.sqrt(area / (4 * (inLevel + count) + 64))) {
        level++;
        inLevel = 0;
        minX = classBox[b];
        minY = classBox[b + 1];
        maxX = classBox[b + 2];
        maxY = classBox[b + 3];
      } else {
        minX = joinedMinX;
        minY = joinedMinY;
        maxX = joinedMaxX;
        maxY = joinedMaxY;
      }
      classLevel[c] = level;
      levelRadius[level] = classBox[b + 4];
      inLevel += count;
    }
    return level + 1;
  }

  private grid(level: number): CellGrid {
    while (this.grids.length <= level) this.grids.push(new CellGrid());
    return this.grids[level];
  }
}

const bits = new Float64Array(1);
const bitsWords = new Uint32Array(bits.buffer);
/** The index of the word holding the sign and exponent: the second on little-endian machines. */
const HIGH = new Uint8Array(new Uint16Array([1]).buffer)[0] === 1 ? 1 : 0;

/**
 * The power-of-two class of a radius: the least c with r <= rmin 2^c. The binary exponent of
 * r / rmin guesses it (not Math.log2, whose rounding each JavaScript engine chooses); exact
 * doublings and halvings decide.
 */
export function radiusClass(r: number, rmin: number): number {
  if (r <= rmin) return 0;
  bits[0] = r / rmin;
  // A ratio above 1 has a biased exponent of at least 1023, and at most 2046 (it is finite).
  let c = ((bitsWords[HIGH] >>> 20) & 0x7ff) - 1023;
  bitsWords[HIGH] = (c + 1023) << 20;
  bitsWords[1 - HIGH] = 0;
  let limit = rmin * bits[0];
  while (limit < r) {
    limit *= 2;
    c++;
  }
  while (c > 0 && limit / 2 >= r) {
    limit /= 2;
    c--;
  }
  return c;
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
