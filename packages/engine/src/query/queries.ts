import type { BodyStore } from '../store/body-store.js';
import { CellGrid } from '../broadphase/cell-grid.js';
import { LiveExtent } from '../broadphase/live-extent.js';
import { rayCircle, rayCircleEntry } from './ray-circle.js';
import type { ShapeStore } from '../store/shape-store.js';
import type { SegmentStore } from '../store/segment-store.js';
import { StaticTree } from '../broadphase/static-tree.js';
import { rayNormal, rayPoint, raySegment, rayShape, segmentContains, segmentOverlapsBox, shapeContains, shapeOverlapsBox } from './shape-queries.js';

/** Where a ray enters a body or a static segment: the point, the outward surface normal there, and the body's or segment's handle. */
export interface RayHit {
  /** The body's handle, or the static segment's (`world.hasBody` tells them apart). */
  handle: number;
  /** Where along the segment from (x1, y1) to (x2, y2) the ray enters the body or static segment, in [0, 1]. */
  fraction: number;
  x: number;
  y: number;
  normalX: number;
  normalY: number;
}

/** Body slots a query found, in a typed array reused from query to query (nothing allocated once grown). */
export class SlotList {
  slots = new Int32Array(16);
  count = 0;

  push(slot: number): void {
    if (this.count === this.slots.length) {
      const grown = new Int32Array(2 * this.slots.length);
      grown.set(this.slots);
      this.slots = grown;
    }
    this.slots[this.count++] = slot;
  }
}

/**
 * A body whose bounding radius passes this many times the mean is kept out of the grid and tested
 * by every query on its own (see Queries.prepare).
 */
const OVERSIZED = 8;

/**
 * Point, box and ray queries over a Max Grid of the current positions. The grid is rebuilt only
 * when the world's geometry changed since the last query (`version`), so many queries between
 * two steps share one build. Cell size is the largest diameter, so a circle that contains a point,
 * or is crossed by a ray at a point, has its centre within one cell of that point.
 *
 * The grid is laid over an extent fitted as the broad-phase's are (see extent-fit.ts): a few
 * bodies far from the crowd would otherwise make every cell hold the whole crowd. Bodies beyond
 * the extent are binned into its edge cells (cellIndex in cell-grid.ts), so every search clamps
 * its cells the same way: clamping is monotonic and moves no two cells further apart, so a body
 * within one cell of a point stays within one clamped cell of that point's clamped cell.
 *
 * The cells are sized for the bodies of ordinary size: one far larger than the mean (a ground box
 * 200 m long under bodies of 0.5 m) would make every cell hold the whole crowd, and every query
 * scan it (500 sensors among 10,000 bodies took 77 ms a step over such a grid). Such bodies are
 * listed apart (`oversized`) and each query tests them one by one, before its grid search.
 *
 * The world's static segments are found too, by the public queries (point, box, rays), through
 * a packed tree of their boxes rebuilt when they change; the engine's own searches inside a step
 * (slotsInBox) look for bodies alone.
 */
export class Queries {
  private readonly live = new LiveExtent();
  private readonly grid = new CellGrid();
  private builtVersion = -1;
  /** The slots the grid holds, where some are kept out of it, and those kept out (see OVERSIZED). */
  private gridSlots = new Int32Array(0);
  /** The box a box query asks about (see overlapsBox). */
  private readonly queryBox = new Float64Array(4);
  /** The pose of the body a box query tests a shape of (see shapeOverlapsBox). */
  private readonly shapePose = new Float64Array(4);
  private oversized = new Int32Array(0);
  private oversizedCount = 0;
  private stamp = new Uint32Array(0);
  private epoch = 0;
  /**
   * The box around every body's centre, widened by a cell, before the extent is fitted: a point,
   * box or ray beyond it touches nothing, and need not search the clamped edge cells.
   */
  private reachMinX = 0;
  private reachMinY = 0;
  private reachMaxX = 0;
  private reachMaxY = 0;
  /** Cell entries the last query read, before any test: how much of the grid it searched, for tests. */
  examined = 0;
  /**
   * The query's mask, tested against each body's category (the union of its shapes') and then
   * each shape's own: a compound body answers for the shapes the mask names, not for the others.
   * Kept as a signed 32-bit integer (the same bits), which V8 stores without boxing.
   */
  private mask = -1;

  /** A world's shapes once it has them: bodies are then tested shape by shape, their bounding circles only narrowing the search. */
  shapes: ShapeStore | null = null;

  /** The segments' boxes (ids are segment slots), built for the segments' version `segmentsBuilt`. */
  private readonly segmentTree = new StaticTree();
  private segmentsBuilt = -1;
  /** The segment slot of the nearest ray hit so far, or -1 where that is a body (bestSlot). */
  private bestSegment = -1;
  /** The segment slot raySegments is testing, for aheadOfBest. */
  private segmentAt = -1;

  constructor(
    private readonly bodies: BodyStore,
    private readonly segments: SegmentStore,
  ) {}

  /** For the engine's own searches (bodyContacts): segmentsNear for the box in `box` (min x, min y, max x, max y); segmentFound(k) reads them. */
  segmentsInBox(box: Float64Array): number {
    return this.segmentsNear(box[0], box[1], box[2], box[3]);
  }

  segmentFound(k: number): number {
    return this.segmentTree.found[k];
  }

  /** The live segments whose boxes meet the box, ascending, into segmentTree.found; returns how many. */
  private segmentsNear(minX: number, minY: number, maxX: number, maxY: number): number {
    const { segments, segmentTree: tree } = this;
    if (segments.count === 0) return 0;
    if (this.segmentsBuilt !== segments.version) {
      tree.clear();
      tree.addSegments(segments, 0, false);
      tree.finish();
      this.segmentsBuilt = segments.version;
    }
    return tree.query(minX, minY, maxX, maxY);
  }

  /** Whether body `slot` contains the point: its circle, or one of its shapes. */
  private contains(slot: number, px: number, py: number): boolean {
    const bodies = this.bodies;
    const dx = px - bodies.x[slot];
    const dy = py - bodies.y[slot];
    const inCircle = dx * dx + dy * dy <= bodies.radius[slot] * bodies.radius[slot];
    const shapes = this.shapes;
    if (shapes === null || !inCircle) return inCircle;
    const rigid = bodies.rigid!;
    const mask = this.mask;
    for (let k = rigid.firstShape[slot]; k >= 0; k = shapes.next[k]) {
      if ((shapes.category[k] & mask) === 0) continue;
      if (shapeContains(shapes, k, bodies.x[slot], bodies.y[slot], rigid.c[slot], rigid.s[slot], px, py)) return true;
    }
    return false;
  }

  /** Whether body `slot` overlaps the box: its circle, or one of its shapes. */
  private overlaps(slot: number, minX: number, minY: number, maxX: number, maxY: number): boolean {
    const box = this.queryBox;
    box[0] = minX;
    box[1] = minY;
    box[2] = maxX;
    box[3] = maxY;
    return this.overlapsBox(slot);
  }

  /**
   * overlaps for the box in `box`: the sensors' stage asks it of many bodies each step, and a call
   * V8 does not inline boxes each number passed to it, where a slot (a small integer) is not.
   */
  private overlapsBox(slot: number): boolean {
    const minX = this.queryBox[0];
    const minY = this.queryBox[1];
    const maxX = this.queryBox[2];
    const maxY = this.queryBox[3];
    const bodies = this.bodies;
    const cx = bodies.x[slot];
    const cy = bodies.y[slot];
    const dx = cx - Math.min(Math.max(cx, minX), maxX);
    const dy = cy - Math.min(Math.max(cy, minY), maxY);
    const nearCircle = dx * dx + dy * dy <= bodies.radius[slot] * bodies.radius[slot];
    const shapes = this.shapes;
    if (shapes === null || !nearCircle) return nearCircle;
    const rigid = bodies.rigid!;
    const mask = this.mask;
    for (let k = rigid.firstShape[slot]; k >= 0; k = shapes.next[k]) {
      if ((shapes.category[k] & mask) === 0) continue;
      const at = this.shapePose;
      at[0] = cx;
      at[1] = cy;
      at[2] = rigid.c[slot];
      at[3] = rigid.s[slot];
      if (shapeOverlapsBox(shapes, k, at, this.queryBox)) return true;
    }
    return false;
  }

  /** The fraction at which the ray enters body `slot` (its circle or first shape hit), or -1; the normal in rayNormal and the point in rayPoint for shapes. */
  private rayBody(slot: number, x1: number, y1: number, dx: number, dy: number): number {
    const bodies = this.bodies;
    const shapes = this.shapes;
    if (shapes === null) return rayCircle(x1, y1, dx, dy, bodies.x[slot], bodies.y[slot], bodies.radius[slot]);
    const rigid = bodies.rigid!;
    let best = -1;
    let nx = 0;
    let ny = 0;
    let hx = 0;
    let hy = 0;
    const mask = this.mask;
    for (let k = rigid.firstShape[slot]; k >= 0; k = shapes.next[k]) {
      if ((shapes.category[k] & mask) === 0) continue;
      const t = rayShape(shapes, k, bodies.x[slot], bodies.y[slot], rigid.c[slot], rigid.s[slot], x1, y1, dx, dy);
      if (t >= 0 && (best < 0 || t < best)) {
        best = t;
        nx = rayNormal.x;
        ny = rayNormal.y;
        hx = rayPoint.x;
        hy = rayPoint.y;
      }
    }
    rayNormal.x = nx;
    rayNormal.y = ny;
    rayPoint.x = hx;
    rayPoint.y = hy;
    return best;
  }

  point(version: number, px: number, py: number, mask: number, out: number[]): number[] {
    this.mask = mask | 0;
    this.examined = 0;
    const { segments, segmentTree } = this;
    const near = this.segmentsNear(px, py, px, py);
    for (let k = 0; k < near; k++) {
      const g = segmentTree.found[k];
      if ((segments.category[g] & mask) !== 0 && segmentContains(segments, g, px, py)) out.push(segments.handleOf(g));
    }
    if (!this.prepare(version)) return sortHandles(out);
    const { grid, bodies } = this;
    this.examined += this.oversizedCount;
    for (let k = 0; k < this.oversizedCount; k++) {
      const slot = this.oversized[k];
      if ((bodies.category[slot] & mask) !== 0 && this.contains(slot, px, py)) out.push(bodies.handleOf(slot));
    }
    if (!this.reaches(px, py, px, py)) return sortHandles(out);
    const column = grid.columnOf(px);
    const row = grid.rowOf(py);
    const c0 = clamp(column - 1, 0, grid.columns - 1);
    const c1 = clamp(column + 1, 0, grid.columns - 1);
    for (let r = clamp(row - 1, 0, grid.rows - 1); r <= clamp(row + 1, 0, grid.rows - 1); r++) {
      this.examined += grid.cellStart[r * grid.columns + c1 + 1] - grid.cellStart[r * grid.columns + c0];
      for (let m = grid.cellStart[r * grid.columns + c0]; m < grid.cellStart[r * grid.columns + c1 + 1]; m++) {
        const slot = grid.sortedSlot[m];
        if ((bodies.category[slot] & mask) === 0) continue;
        if (this.contains(slot, px, py)) out.push(bodies.handleOf(slot));
      }
    }
    return sortHandles(out);
  }

  box(version: number, minX: number, minY: number, maxX: number, maxY: number, mask: number, out: number[]): number[] {
    const box = this.queryBox;
    box[0] = minX;
    box[1] = minY;
    box[2] = maxX;
    box[3] = maxY;
    this.inBox(version, mask, out, null);
    const { segments, segmentTree } = this;
    const near = this.segmentsNear(minX, minY, maxX, maxY);
    for (let k = 0; k < near; k++) {
      const g = segmentTree.found[k];
      if ((segments.category[g] & mask) !== 0 && segmentOverlapsBox(segments, g, box)) out.push(segments.handleOf(g));
    }
    return sortHandles(out);
  }

  /**
   * The slots of the bodies overlapping the box (minX, minY, maxX, maxY in box[0..3]), unsorted,
   * into `out` (emptied first): for the engine's own use inside a step (waking sleepers, bullets'
   * sweeps, sensors), where the order does not matter and a sort or a growing array would
   * allocate, and the box comes in an array: a call V8 does not inline boxes each number passed.
   */
  slotsInBox(version: number, box: Float64Array, out: SlotList): SlotList {
    out.count = 0;
    const into = this.queryBox;
    into[0] = box[0];
    into[1] = box[1];
    into[2] = box[2];
    into[3] = box[3];
    // Every layer as a signed 32-bit integer: stored in a field, 0xffffffff would be a new boxed number each call.
    this.inBox(version, -1, null, out);
    return out;
  }

  /** The bodies overlapping the box in queryBox, as handles into `handles` or as slots into `slots`. */
  private inBox(version: number, mask: number, handles: number[] | null, slots: SlotList | null): void {
    this.mask = mask | 0;
    this.examined = 0;
    if (!this.prepare(version)) return;
    const { grid, bodies, queryBox: box } = this;
    const minX = box[0];
    const minY = box[1];
    const maxX = box[2];
    const maxY = box[3];
    this.examined += this.oversizedCount;
    for (let k = 0; k < this.oversizedCount; k++) {
      const slot = this.oversized[k];
      if ((bodies.category[slot] & mask) === 0 || !this.overlapsBox(slot)) continue;
      if (handles !== null) handles.push(bodies.handleOf(slot));
      else slots!.push(slot);
    }
    if (!(maxX >= this.reachMinX && minX <= this.reachMaxX && maxY >= this.reachMinY && minY <= this.reachMaxY)) return;
    const c0 = clamp(grid.columnOf(minX) - 1, 0, grid.columns - 1);
    const c1 = clamp(grid.columnOf(maxX) + 1, 0, grid.columns - 1);
    const r0 = clamp(grid.rowOf(minY) - 1, 0, grid.rows - 1);
    const r1 = clamp(grid.rowOf(maxY) + 1, 0, grid.rows - 1);
    for (let r = r0; r <= r1; r++) {
      this.examined += grid.cellStart[r * grid.columns + c1 + 1] - grid.cellStart[r * grid.columns + c0];
      for (let m = grid.cellStart[r * grid.columns + c0]; m < grid.cellStart[r * grid.columns + c1 + 1]; m++) {
        const slot = grid.sortedSlot[m];
        if ((bodies.category[slot] & mask) === 0 || !this.overlapsBox(slot)) continue;
        if (handles !== null) handles.push(bodies.handleOf(slot));
        else slots!.push(slot);
      }
    }
  }

  /**
   * rayCast: the nearest hit (at a tie of fractions, the nearer point, then the lower handle), written into `into` when given, else into
   * a new object; null when the segment enters no circle. Candidates are compared as numbers, so
   * only the answer is an object.
   */
  rayFirst(version: number, x1: number, y1: number, x2: number, y2: number, mask: number, into: RayHit | null): RayHit | null {
    this.bestFraction = Infinity;
    this.bestSegment = -1;
    // Segments first: the grid's walk stops at the nearest hit so far, a wall's included.
    this.raySegments(x1, y1, x2, y2, mask, false);
    this.walk(version, x1, y1, x2, y2, mask, false);
    if (this.bestFraction === Infinity) return null;
    const t = this.bestFraction;
    rayNormal.x = this.bestNormalX;
    rayNormal.y = this.bestNormalY;
    rayPoint.x = this.bestPointX;
    rayPoint.y = this.bestPointY;
    if (this.bestSegment >= 0) return writeSurfaceHit(into ?? blankHit(), this.bestHandle, t);
    return this.write(into ?? blankHit(), this.bestSlot, t, x1, y1, x2 - x1, y2 - y1);
  }

  /**
   * rayCastAll: every hit, nearest first (ties of fractions by their points, then by handle), in `out`. The objects already in `out`
   * are overwritten in place; it is then cut to the number of hits, and the objects cut off are
   * kept to fill later casts' arrays, so that a caller reusing one array stops making hit objects
   * once it has held the most a cast found.
   */
  rayAll(version: number, x1: number, y1: number, x2: number, y2: number, mask: number, out: RayHit[]): RayHit[] {
    this.hitCount = 0;
    this.hits = out;
    this.raySegments(x1, y1, x2, y2, mask, true);
    this.walk(version, x1, y1, x2, y2, mask, true);
    this.hits = NO_HITS;
    for (let k = this.hitCount; k < out.length; k++) {
      const spare = out[k];
      if (typeof spare === 'object' && spare !== null) this.spareHits.push(spare);
    }
    out.length = this.hitCount;
    return sortNearestFirst(out, x2 - x1, y2 - y1);
  }

  private hits: RayHit[] = NO_HITS;
  private readonly spareHits: RayHit[] = [];
  private hitCount = 0;
  private bestFraction = Infinity;
  private bestSlot = -1;
  private bestHandle = -1;
  private bestNormalX = 0;
  private bestNormalY = 0;
  private bestPointX = 0;
  private bestPointY = 0;

  /**
   * The ray against the segments whose boxes meet its own box: each hit noted (all), or kept where
   * it is the nearest so far. A long diagonal ray's box holds segments far from it, which the
   * test then rejects: rays across a terrain of many segments test those in their box.
   */
  private raySegments(x1: number, y1: number, x2: number, y2: number, mask: number, all: boolean): void {
    const { segments, segmentTree } = this;
    const near = this.segmentsNear(Math.min(x1, x2), Math.min(y1, y2), Math.max(x1, x2), Math.max(y1, y2));
    const dx = x2 - x1;
    const dy = y2 - y1;
    for (let k = 0; k < near; k++) {
      const g = segmentTree.found[k];
      if ((segments.category[g] & mask) === 0) continue;
      const t = raySegment(segments, g, x1, y1, dx, dy);
      if (t < 0) continue;
      const handle = segments.handleOf(g);
      this.segmentAt = g;
      if (all) writeSurfaceHit(this.nextHit(), handle, t);
      else if (t < this.bestFraction || (t === this.bestFraction && this.aheadOfBest(-1, x1, y1, dx, dy))) {
        this.keepBest(-1, t);
        this.bestSegment = g;
        this.bestHandle = handle;
      }
    }
  }

  /** The next hit object of rayAll's output: one already there, a spare, or a new one. */
  private nextHit(): RayHit {
    const k = this.hitCount++;
    const reused = this.hits[k];
    return typeof reused === 'object' && reused !== null ? reused : (this.hits[k] = this.spareHits.pop() ?? blankHit());
  }

  /** Notes a hit at fraction t as the nearest so far: body `slot`'s (-1 for a segment's), at rayNormal and rayPoint. */
  private keepBest(slot: number, t: number): void {
    this.bestFraction = t;
    this.bestSlot = slot;
    this.bestSegment = -1;
    this.bestNormalX = rayNormal.x;
    this.bestNormalY = rayNormal.y;
    this.bestPointX = rayPoint.x;
    this.bestPointY = rayPoint.y;
  }

  /** A hit on a circle (from its centre), or on a shape (at the entry, with rayShape's normal). */
  private write(hit: RayHit, slot: number, t: number, x1: number, y1: number, dx: number, dy: number): RayHit {
    if (this.shapes === null) return writeHit(hit, this.bodies, slot, t, x1, y1, dx, dy);
    return writeSurfaceHit(hit, this.bodies.handleOf(slot), t);
  }

  /**
   * Walks the cells the segment crosses (Amanatides & Woo), testing the 3x3 cells around each; a
   * stamp per body avoids testing one twice. With `all` false it stops once the next cell starts
   * beyond the best hit found. The cells are clamped into the grid as its bodies' are: outside the
   * extent the walk stays in the edge cell the ray's point clamps to, and moves on only where the
   * ray crosses a boundary between two cells of the grid, so it takes at most columns + rows steps
   * however far the ray reaches, and the window around each step holds every body that the ray
   * can touch while its point clamps there (see the class comment).
   */
  private walk(version: number, x1: number, y1: number, x2: number, y2: number, mask: number, all: boolean): void {
    this.mask = mask | 0;
    this.examined = 0;
    if (!this.prepare(version)) return;
    const { grid } = this;
    const dx = x2 - x1;
    const dy = y2 - y1;
    this.examined += this.oversizedCount;
    for (let k = 0; k < this.oversizedCount; k++) this.testRay(this.oversized[k], x1, y1, dx, dy, mask, all);
    const cs = grid.cellSize;
    clip.enter = 0;
    clip.exit = 1;
    clip.enterAxis = 0;
    if (!clipAxis(x1, dx, this.reachMinX, this.reachMaxX, 1) || !clipAxis(y1, dy, this.reachMinY, this.reachMaxY, 2)) return;
    const tEnter = clip.enter;
    const tExit = clip.exit;
    if (tEnter > tExit) return;
    this.epoch++;
    const lastColumn = dx > 0 ? grid.columns - 1 : 0;
    const lastRow = dy > 0 ? grid.rows - 1 : 0;
    // Where the ray enters the reach box. From far away x1 + dx tEnter rounds at the size of x1
    // (a ray from -1e20 entered 16,384 out, past the bodies it should meet first): the axis whose
    // bound gave tEnter enters at that bound, and the point is held within the box.
    let ex = x1 + dx * tEnter;
    let ey = y1 + dy * tEnter;
    if (clip.enterAxis === 1) ex = dx > 0 ? this.reachMinX : this.reachMaxX;
    else if (clip.enterAxis === 2) ey = dy > 0 ? this.reachMinY : this.reachMaxY;
    ex = Math.min(Math.max(ex, this.reachMinX), this.reachMaxX);
    ey = Math.min(Math.max(ey, this.reachMinY), this.reachMaxY);
    let column = clamp(grid.columnOf(ex), 0, grid.columns - 1);
    let row = clamp(grid.rowOf(ey), 0, grid.rows - 1);
    const stepX = dx > 0 ? 1 : -1;
    const stepY = dy > 0 ? 1 : -1;
    const deltaX = cs / Math.abs(dx);
    const deltaY = cs / Math.abs(dy);
    // The fractions at which the ray crosses into the next column and row, from the entry point;
    // none once in the last one it moves towards, beyond which its point clamps into that one.
    let nextX = dx === 0 || column === lastColumn ? Infinity : tEnter + (grid.originX + (column + (dx > 0 ? 1 : 0)) * cs - ex) / dx;
    let nextY = dy === 0 || row === lastRow ? Infinity : tEnter + (grid.originY + (row + (dy > 0 ? 1 : 0)) * cs - ey) / dy;
    let cellEnter = tEnter;
    // Each step moves a column or a row towards the last, so the walk ends even if rounding stalls the fractions.
    for (;;) {
      this.testWindow(column, row, x1, y1, dx, dy, mask, all);
      if (nextX < nextY) {
        cellEnter = nextX;
        column += stepX;
        nextX = column === lastColumn ? Infinity : nextX + deltaX;
      } else if (nextY !== Infinity) {
        cellEnter = nextY;
        row += stepY;
        nextY = row === lastRow ? Infinity : nextY + deltaY;
      } else {
        break;
      }
      if (cellEnter > tExit || (!all && cellEnter > this.bestFraction)) break;
    }
  }

  private testWindow(column: number, row: number, x1: number, y1: number, dx: number, dy: number, mask: number, all: boolean): void {
    const { grid, stamp, epoch } = this;
    const c0 = Math.max(column - 1, 0);
    const c1 = Math.min(column + 1, grid.columns - 1);
    if (c0 > c1) return;
    for (let r = Math.max(row - 1, 0); r <= Math.min(row + 1, grid.rows - 1); r++) {
      this.examined += grid.cellStart[r * grid.columns + c1 + 1] - grid.cellStart[r * grid.columns + c0];
      for (let m = grid.cellStart[r * grid.columns + c0]; m < grid.cellStart[r * grid.columns + c1 + 1]; m++) {
        if (stamp[m] === epoch) continue;
        stamp[m] = epoch;
        this.testRay(grid.sortedSlot[m], x1, y1, dx, dy, mask, all);
      }
    }
  }

  /** The ray against body `slot`: a hit noted (all), or kept where it is the nearest so far. */
  private testRay(slot: number, x1: number, y1: number, dx: number, dy: number, mask: number, all: boolean): void {
    const bodies = this.bodies;
    if ((bodies.category[slot] & mask) === 0) return;
    const t = this.rayBody(slot, x1, y1, dx, dy);
    if (t < 0) return;
    if (all) this.write(this.nextHit(), slot, t, x1, y1, dx, dy);
    else if (t < this.bestFraction || (t === this.bestFraction && this.aheadOfBest(slot, x1, y1, dx, dy))) {
      this.keepBest(slot, t);
      this.bestHandle = bodies.handleOf(slot);
    }
  }

  /**
   * For a hit at the best fraction so far, on body `slot` or (slot -1) on the segment whose point
   * is in rayPoint: whether its point lies before the best one's along the ray, or at it with a
   * lower handle. Fractions of a long ray tie for hits far apart (one 2e20 long resolves no finer
   * than 2e4), and the lower handle then won wherever it lay; the points, taken from the shapes,
   * keep their order. A circle's point is found from the circle (rayBody finds only its fraction).
   */
  private aheadOfBest(slot: number, x1: number, y1: number, dx: number, dy: number): boolean {
    const bodies = this.bodies;
    let px = rayPoint.x;
    let py = rayPoint.y;
    let bx = this.bestPointX;
    let by = this.bestPointY;
    if (this.shapes === null && slot >= 0) {
      rayCircleEntry(x1, y1, dx, dy, bodies.x[slot], bodies.y[slot], bodies.radius[slot], entry);
      px = bodies.x[slot] + entry.x;
      py = bodies.y[slot] + entry.y;
    }
    const best = this.bestSlot;
    if (this.shapes === null && best >= 0) {
      rayCircleEntry(x1, y1, dx, dy, bodies.x[best], bodies.y[best], bodies.radius[best], entry);
      bx = bodies.x[best] + entry.x;
      by = bodies.y[best] + entry.y;
    }
    const along = alongRay(px, py, bx, by, dx, dy);
    return along < 0 || (along === 0 && (slot >= 0 ? bodies.handleOf(slot) : this.segments.handleOf(this.segmentAt)) < this.bestHandle);
  }

  private prepare(version: number): boolean {
    const { live, bodies } = this;
    if (this.builtVersion !== version) {
      live.measure(bodies, true);
      this.oversizedCount = 0;
      if (live.count > 0) {
        const gridRadius = this.keepOversizedApart();
        const cellSize = live.cellSizeFor(gridRadius);
        const budget = 4 * live.count + 64;
        // A cell is at least a diameter: every body touching a point lies within half a cell of it.
        this.reachMinX = live.minX - cellSize;
        this.reachMinY = live.minY - cellSize;
        this.reachMaxX = live.maxX + cellSize;
        this.reachMaxY = live.maxY + cellSize;
        live.fit(bodies, cellSize, budget);
        if (this.oversizedCount > 0) this.grid.build(bodies, this.gridSlots, 0, live.count - this.oversizedCount, live.minX, live.minY, live.maxX, live.maxY, cellSize, budget);
        else this.grid.build(bodies, live.dense ? null : live.slots, 0, live.count, live.minX, live.minY, live.maxX, live.maxY, cellSize, budget);
        if (this.stamp.length < live.count) this.stamp = new Uint32Array(Math.max(live.count, 2 * this.stamp.length));
      }
      this.builtVersion = version;
    }
    if (this.epoch > 0xfffffff0) {
      this.stamp.fill(0);
      this.epoch = 0;
    }
    return live.count > 0;
  }

  /**
   * Lists the live bodies more than OVERSIZED times the mean bounding radius apart from the rest
   * (gridSlots), and returns the largest radius of the rest, which sizes the cells. The reach box
   * is the rest's too: the oversized are tested whatever it says. None apart: the largest radius.
   */
  private keepOversizedApart(): number {
    const { live, bodies } = this;
    const radius = bodies.radius;
    const n = live.count;
    const slots = live.dense ? null : live.slots;
    let sum = 0;
    for (let k = 0; k < n; k++) sum += radius[slots === null ? k : slots[k]];
    const cap = (OVERSIZED * sum) / n;
    if (!(live.maxRadius > cap)) return live.maxRadius;
    if (this.gridSlots.length < n) {
      this.gridSlots = new Int32Array(n);
      this.oversized = new Int32Array(n);
    }
    let rest = 0;
    let apart = 0;
    let largest = 0;
    for (let k = 0; k < n; k++) {
      const slot = slots === null ? k : slots[k];
      const r = radius[slot];
      if (r > cap) this.oversized[apart++] = slot;
      else {
        this.gridSlots[rest++] = slot;
        if (r > largest) largest = r;
      }
    }
    this.oversizedCount = apart;
    return largest;
  }

  /** Whether the box meets the reach box: else it touches no body. */
  private reaches(minX: number, minY: number, maxX: number, maxY: number): boolean {
    return maxX >= this.reachMinX && minX <= this.reachMaxX && maxY >= this.reachMinY && minY <= this.reachMaxY;
  }
}

function clamp(v: number, lo: number, hi: number): number {
  return v < lo ? lo : v > hi ? hi : v;
}

const NO_HITS: RayHit[] = [];

function blankHit(): RayHit {
  return { handle: 0, fraction: 0, x: 0, y: 0, normalX: 0, normalY: 0 };
}

const entry = { x: 0, y: 0 };

/** Fills `hit` for the shape or static segment of `handle`, entered at fraction t, at rayPoint with rayNormal. */
function writeSurfaceHit(hit: RayHit, handle: number, t: number): RayHit {
  hit.handle = handle;
  hit.fraction = t;
  hit.x = rayPoint.x;
  hit.y = rayPoint.y;
  hit.normalX = rayNormal.x;
  hit.normalY = rayNormal.y;
  return hit;
}

/** Fills `hit` for the circle in `slot`, entered at fraction t by the ray from (x1, y1) along (dx, dy). */
function writeHit(hit: RayHit, bodies: BodyStore, slot: number, t: number, x1: number, y1: number, dx: number, dy: number): RayHit {
  const r = bodies.radius[slot];
  rayCircleEntry(x1, y1, dx, dy, bodies.x[slot], bodies.y[slot], r, entry);
  hit.handle = bodies.handleOf(slot);
  hit.fraction = t;
  hit.x = bodies.x[slot] + entry.x;
  hit.y = bodies.y[slot] + entry.y;
  hit.normalX = entry.x / r;
  hit.normalY = entry.y / r;
  return hit;
}

/** The ray sortNearestFirst orders hits along, for hits whose fractions tie (see aheadOfBest). */
let sortX = 0;
let sortY = 0;

/** Whether hit a comes before hit b: the smaller fraction; at a tie the point earlier along the ray, then the lower handle. */
function before(a: RayHit, b: RayHit): boolean {
  if (a.fraction !== b.fraction) return a.fraction < b.fraction;
  const along = alongRay(a.x, a.y, b.x, b.y, sortX, sortY);
  return along < 0 || (along === 0 && a.handle < b.handle);
}

/**
 * The sign of how far point (px, py) lies past (qx, qy) along the ray (dx, dy): 0 where that is
 * within the rounding of the points themselves (a millionth of a millionth of their size), so
 * that points one rounding apart, which tie in fraction too, keep the handle order.
 */
function alongRay(px: number, py: number, qx: number, qy: number, dx: number, dy: number): number {
  const along = (px - qx) * dx + (py - qy) * dy;
  const size = Math.abs(px) + Math.abs(py) + Math.abs(qx) + Math.abs(qy);
  return Math.abs(along) <= 1e-12 * size * (Math.abs(dx) + Math.abs(dy)) ? 0 : along;
}

function nearestFirst(a: RayHit, b: RayHit): number {
  return before(a, b) ? -1 : before(b, a) ? 1 : 0;
}

/**
 * The walk finds hits nearly in order, out of order only within the 3x3 window of one cell, so
 * insertion sorts them in about linear time without allocating; Array.prototype.sort copies the
 * array and boxes each number its comparator returns. Should a crowd of overlapping circles make
 * insertion slow (more than 8 moves a hit), it hands over to Array.prototype.sort.
 */
function sortNearestFirst(hits: RayHit[], dx: number, dy: number): RayHit[] {
  sortX = dx;
  sortY = dy;
  let budget = 8 * hits.length;
  for (let k = 1; k < hits.length; k++) {
    const hit = hits[k];
    let j = k - 1;
    for (; j >= 0 && before(hit, hits[j]); j--) {
      hits[j + 1] = hits[j];
      budget--;
    }
    hits[j + 1] = hit;
    if (budget < 0) return hits.sort(nearestFirst);
  }
  return hits;
}

/**
 * Query results ascending, in place: by insertion for the few a query usually finds, which
 * Array.prototype.sort would not do without allocating (about 1 KB a call for two handles or
 * more), and by it for many.
 */
function sortHandles(out: number[]): number[] {
  if (out.length >= 32) return out.sort(ascending);
  for (let k = 1; k < out.length; k++) {
    const v = out[k];
    let j = k - 1;
    while (j >= 0 && out[j] > v) {
      out[j + 1] = out[j];
      j--;
    }
    out[j + 1] = v;
  }
  return out;
}

/** The handle order of query results; one function, not a closure per query. */
function ascending(a: number, b: number): number {
  return a - b;
}

/** The ray's parameter range inside the widened grid, narrowed axis by axis by clipAxis, and which axis's bound gave `enter` (0: its start). */
const clip = { enter: 0, exit: 1, enterAxis: 0 };

/** Narrows `clip` to where p + t d lies in [lo, hi]; false when a ray parallel to the axis misses it. */
function clipAxis(p: number, d: number, lo: number, hi: number, axis: number): boolean {
  if (d === 0) return p >= lo && p <= hi;
  const ta = (lo - p) / d;
  const tb = (hi - p) / d;
  const enter = Math.min(ta, tb);
  if (enter > clip.enter) {
    clip.enter = enter;
    clip.enterAxis = axis;
  }
  clip.exit = Math.min(clip.exit, Math.max(ta, tb));
  return true;
}
