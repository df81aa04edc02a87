import { SEGMENT_HANDLES, SEGMENT_MAX_GENERATION, SHAPE_HANDLES, SLOT_SPACE } from './handles.js';
import { grownCapacity, grow } from '../util/grow.js';
import { sortFew } from '../util/sort-by-key.js';

export interface NewSegment {
  ax: number;
  ay: number;
  bx: number;
  by: number;
  thickness: number;
  restitution: number;
  friction: number;
  category: number;
  mask: number;
  /**
   * A chain's link (World.createChain): the point before its start and the point after its end
   * along the chain, where it has them (Box2D's ghost vertices), for the smooth joins of
   * smooth-segment.ts.
   */
  prev?: { x: number; y: number } | null;
  next?: { x: number; y: number } | null;
}

/** Bits of SegmentStore.smooth: the link has a neighbour before its start, after its end. */
export const SmoothJoin = { start: 1, end: 2 } as const;

/**
 * Static line segments (walls at any angle, thick or not), stored apart from bodies: they never
 * move, so they get a grid of their own that is rebuilt only when segments are added or removed.
 * Handles work as body handles do, in a space of their own (see handles.ts).
 */
export class SegmentStore {
  count = 0;
  slotCount = 0;
  ax = new Float64Array(0);
  ay = new Float64Array(0);
  bx = new Float64Array(0);
  by = new Float64Array(0);
  /** Half the wall's width: the segment is a capsule of this radius. */
  thickness = new Float64Array(0);
  restitution = new Float64Array(0);
  friction = new Float64Array(0);
  category = new Uint32Array(0);
  mask = new Uint32Array(0);
  live = new Uint8Array(0);
  generation = new Uint32Array(0);
  /** Per segment, its SmoothJoin bits (0 for a loose segment), and its neighbours' far points there. */
  smooth = new Uint8Array(0);
  prevX = new Float64Array(0);
  prevY = new Float64Array(0);
  nextX = new Float64Array(0);
  nextY = new Float64Array(0);
  /** Bumped on every add and remove, so the segment grid knows to rebuild. */
  version = 0;
  /** Live segments with friction or restitution below 1 (see World's solver 'auto'). */
  inelastic = 0;
  private freeSlots: number[] = [];

  add(segment: NewSegment): number {
    let slot = this.freeSlots.pop();
    if (slot === undefined) {
      if (this.slotCount === this.ax.length) this.grow(this.slotCount + 1);
      slot = this.slotCount++;
    }
    this.ax[slot] = segment.ax;
    this.ay[slot] = segment.ay;
    this.bx[slot] = segment.bx;
    this.by[slot] = segment.by;
    this.thickness[slot] = segment.thickness;
    this.restitution[slot] = segment.restitution;
    this.friction[slot] = segment.friction;
    if (segment.friction > 0 || segment.restitution < 1) this.inelastic++;
    this.category[slot] = segment.category;
    this.mask[slot] = segment.mask;
    const prev = segment.prev ?? null;
    const next = segment.next ?? null;
    this.smooth[slot] = (prev !== null ? SmoothJoin.start : 0) | (next !== null ? SmoothJoin.end : 0);
    this.prevX[slot] = prev !== null ? prev.x : 0;
    this.prevY[slot] = prev !== null ? prev.y : 0;
    this.nextX[slot] = next !== null ? next.x : 0;
    this.nextY[slot] = next !== null ? next.y : 0;
    this.live[slot] = 1;
    this.count++;
    this.version++;
    return this.handleOf(slot);
  }

  /** Writes slot's handle into out[at] (see SlotOwner: a handle passed through memory is never boxed). */
  writeHandle(slot: number, out: Float64Array, at: number): void {
    out[at] = this.handleOf(slot);
  }

  /** Whether slot's handle is handles[at] (see SlotOwner). */
  holdsHandle(slot: number, handles: Float64Array, at: number): boolean {
    return this.handleOf(slot) === handles[at];
  }

  /** The handle of the live segment in `slot`. */
  handleOf(slot: number): number {
    return SEGMENT_HANDLES + this.generation[slot] * SLOT_SPACE + slot;
  }

  /** Whether `add` has slots to give `n` times: free ones, or ones below SLOT_SPACE. */
  hasRoom(n = 1): boolean {
    return this.freeSlots.length + (SLOT_SPACE - this.slotCount) >= n;
  }

  remove(slot: number): void {
    if (this.friction[slot] > 0 || this.restitution[slot] < 1) this.inelastic--;
    this.live[slot] = 0;
    this.count--;
    this.version++;
    // As for bodies: a slot whose generation would overflow the handle encoding is retired.
    if (this.generation[slot] + 1 >= SEGMENT_MAX_GENERATION) return;
    this.generation[slot]++;
    this.freeSlots.push(slot);
  }

  /** The slot of a live segment's handle, or -1 for an unknown or stale one. */
  slotOf(handle: number): number {
    if (!Number.isSafeInteger(handle) || handle < SEGMENT_HANDLES || handle >= SHAPE_HANDLES) return -1;
    const slot = (handle - SEGMENT_HANDLES) % SLOT_SPACE;
    const gen = (handle - SEGMENT_HANDLES - slot) / SLOT_SPACE;
    return slot < this.slotCount && this.live[slot] === 1 && this.generation[slot] === gen ? slot : -1;
  }

  /** Explains why `slotOf` refused a handle, for error messages. */
  describeMissing(handle: number): string {
    if (!Number.isSafeInteger(handle) || handle < 0) return 'is not a segment handle';
    if (handle < SEGMENT_HANDLES) return 'is a body handle, not a segment handle';
    if (handle >= SHAPE_HANDLES) return 'is a shape handle, not a segment handle';
    const slot = (handle - SEGMENT_HANDLES) % SLOT_SPACE;
    const gen = (handle - SEGMENT_HANDLES - slot) / SLOT_SPACE;
    if (slot >= this.slotCount || gen > this.generation[slot]) return 'is unknown to this world';
    return 'is stale: its segment was destroyed';
  }

  memoryBytes(): number {
    return this.ax.byteLength * 11 + this.category.byteLength * 3 + this.live.byteLength * 2;
  }

  private grow(needed: number): void {
    const capacity = grownCapacity(this.ax.length, needed);
    this.ax = grow(this.ax, capacity);
    this.ay = grow(this.ay, capacity);
    this.bx = grow(this.bx, capacity);
    this.by = grow(this.by, capacity);
    this.thickness = grow(this.thickness, capacity);
    this.restitution = grow(this.restitution, capacity);
    this.friction = grow(this.friction, capacity);
    this.category = grow(this.category, capacity);
    this.mask = grow(this.mask, capacity);
    this.live = grow(this.live, capacity);
    this.generation = grow(this.generation, capacity);
    this.smooth = grow(this.smooth, capacity);
    this.prevX = grow(this.prevX, capacity);
    this.prevY = grow(this.prevY, capacity);
    this.nextX = grow(this.nextX, capacity);
    this.nextY = grow(this.nextY, capacity);
  }
}

/**
 * A uniform grid over the segments' bounding boxes, each segment listed in every cell its box
 * touches; about 64 cells across the segments' extent. Queries by a box return each segment
 * once (a stamp per segment), in ascending slot order for determinism.
 */
export class SegmentGrid {
  private builtFor = -1;
  private originX = 0;
  private originY = 0;
  private inverse = 0;
  private columns = 0;
  private rows = 0;
  private cellStart = new Int32Array(1);
  private entries = new Int32Array(0);
  private stamp = new Uint32Array(0);
  private epoch = 0;
  /** Segment slots found by the last query, ascending. */
  found = new Int32Array(16);
  foundCount = 0;

  /** The box `queryBox` reads: min x, min y, max x, max y. */
  readonly box = new Float64Array(4);

  query(segments: SegmentStore, minX: number, minY: number, maxX: number, maxY: number): number {
    const b = this.box;
    b[0] = minX;
    b[1] = minY;
    b[2] = maxX;
    b[3] = maxY;
    return this.queryBox(segments);
  }

  /**
   * `query` over `box`, for hot loops: the box travels in a typed array because V8 boxes each
   * number passed to a call it does not inline (this one is too big to inline), an allocation per
   * argument per call: 128 KB a step for 2,000 bodies.
   */
  queryBox(segments: SegmentStore): number {
    const b = this.box;
    const minX = b[0];
    const minY = b[1];
    const maxX = b[2];
    const maxY = b[3];
    if (this.builtFor !== segments.version) this.build(segments);
    this.foundCount = 0;
    if (segments.count === 0) return 0;
    const c0 = Math.max(0, Math.floor((minX - this.originX) * this.inverse));
    const c1 = Math.min(this.columns - 1, Math.floor((maxX - this.originX) * this.inverse));
    const r0 = Math.max(0, Math.floor((minY - this.originY) * this.inverse));
    const r1 = Math.min(this.rows - 1, Math.floor((maxY - this.originY) * this.inverse));
    if (c0 > c1 || r0 > r1) return 0;
    if (++this.epoch === 0xffffffff) {
      this.stamp.fill(0);
      this.epoch = 1;
    }
    for (let r = r0; r <= r1; r++) {
      for (let c = c0; c <= c1; c++) {
        const cell = r * this.columns + c;
        for (let k = this.cellStart[cell]; k < this.cellStart[cell + 1]; k++) {
          const s = this.entries[k];
          if (this.stamp[s] === this.epoch) continue;
          this.stamp[s] = this.epoch;
          this.push(s);
        }
      }
    }
    // Cells list segments in slot order, but a query spans several cells: restore slot order.
    sortFew(this.found, this.foundCount);
    return this.foundCount;
  }

  private push(s: number): void {
    if (this.foundCount === this.found.length) this.found = grow(this.found, this.found.length * 2);
    this.found[this.foundCount++] = s;
  }

  private build(segments: SegmentStore): void {
    this.builtFor = segments.version;
    let minX = Infinity;
    let minY = Infinity;
    let maxX = -Infinity;
    let maxY = -Infinity;
    const { ax, ay, bx, by, thickness, live, slotCount } = segments;
    for (let s = 0; s < slotCount; s++) {
      if (!live[s]) continue;
      const t = thickness[s];
      minX = Math.min(minX, ax[s] - t, bx[s] - t);
      minY = Math.min(minY, ay[s] - t, by[s] - t);
      maxX = Math.max(maxX, ax[s] + t, bx[s] + t);
      maxY = Math.max(maxY, ay[s] + t, by[s] + t);
    }
    if (segments.count === 0) return;
    const cell = Math.max(maxX - minX, maxY - minY, 1e-9) / 64;
    this.originX = minX;
    this.originY = minY;
    this.inverse = 1 / cell;
    this.columns = Math.floor((maxX - minX) * this.inverse) + 1;
    this.rows = Math.floor((maxY - minY) * this.inverse) + 1;
    const cells = this.columns * this.rows;
    this.cellStart = new Int32Array(cells + 1);
    // Two passes over each segment's cells: count, then fill (a counting sort by cell).
    for (let pass = 0; pass < 2; pass++) {
      const cursor = pass === 0 ? this.cellStart : Int32Array.from(this.cellStart);
      for (let s = 0; s < slotCount; s++) {
        if (!live[s]) continue;
        const t = thickness[s];
        const c0 = Math.floor((Math.min(ax[s], bx[s]) - t - minX) * this.inverse);
        const c1 = Math.floor((Math.max(ax[s], bx[s]) + t - minX) * this.inverse);
        const r0 = Math.floor((Math.min(ay[s], by[s]) - t - minY) * this.inverse);
        const r1 = Math.floor((Math.max(ay[s], by[s]) + t - minY) * this.inverse);
        for (let r = r0; r <= r1; r++) {
          for (let c = c0; c <= c1; c++) {
            if (pass === 0) this.cellStart[r * this.columns + c + 1]++;
            else this.entries[cursor[r * this.columns + c]++] = s;
          }
        }
      }
      if (pass === 0) {
        for (let c = 0; c < cells; c++) this.cellStart[c + 1] += this.cellStart[c];
        this.entries = new Int32Array(this.cellStart[cells]);
      }
    }
    if (this.stamp.length < slotCount) this.stamp = new Uint32Array(grownCapacity(this.stamp.length, slotCount));
  }
}
