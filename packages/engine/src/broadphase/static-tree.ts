import { grownCapacity, grow } from '../util/grow.js';
import { sortFew } from '../util/sort-by-key.js';
import type { SegmentStore } from '../store/segment-store.js';
import { paddedRadius } from './fat-bounds.js';

/** Children per node of the tree. */
const NODE_SIZE = 8;

/**
 * A packed bounding-box tree over things that do not move (static shapes, segments, the box's
 * walls), in the manner of flatbush: entries sorted into leaves by the x of their centre in
 * vertical strips, then by y within each strip (sort-tile-recursive packing), NODE_SIZE to a
 * node, each level's boxes in one array. Rebuilt from scratch when the static set changes,
 * O(n log n); a query visits O(log n + k) nodes. Queries return entry ids sorted ascending, so
 * what they report does not depend on the tree's shape.
 *
 * The broad-phases cover moving bodies only (see BodyStore.staticsApart): this is how a moving
 * body finds the static things near it, so that static-static pairs are never examined, and a
 * huge static ground does not set the Max Grid's cell size.
 */
export class StaticTree {
  /** Entries added since `clear`, before `finish`. */
  count = 0;
  private boxes = new Float64Array(0);
  private ids = new Int32Array(0);
  // The packed tree: node boxes (4 per node), and for each node its first child (an entry index at level 0).
  private nodeBoxes = new Float64Array(0);
  private nodeFirst = new Int32Array(0);
  private nodeCount = new Int32Array(0);
  private levelEnd: number[] = [];
  private order = new Int32Array(0);
  private keys = new Float64Array(0);
  private stack = new Int32Array(64);
  /** Results of the last query, ascending. */
  found = new Int32Array(16);
  foundCount = 0;

  clear(): void {
    this.count = 0;
    this.levelEnd.length = 0;
  }

  add(id: number, minX: number, minY: number, maxX: number, maxY: number): void {
    if (this.count === this.ids.length) {
      const capacity = grownCapacity(this.ids.length, this.count + 1);
      this.ids = grow(this.ids, capacity);
      this.boxes = grow(this.boxes, 4 * capacity);
    }
    const k = this.count++;
    this.ids[k] = id;
    this.boxes[4 * k] = minX;
    this.boxes[4 * k + 1] = minY;
    this.boxes[4 * k + 2] = maxX;
    this.boxes[4 * k + 3] = maxY;
  }

  /**
   * Adds each live segment's capsule box under `firstId` + its slot; `padded` grows the thickness
   * as the broad-phases pad a circle (fat-bounds.ts paddedRadius), for the circle route, whose
   * contacts must be found by every broad-phase alike.
   */
  addSegments(segments: SegmentStore, firstId: number, padded: boolean): void {
    const { ax, ay, bx, by, thickness, live } = segments;
    for (let g = 0; g < segments.slotCount; g++) {
      if (!live[g]) continue;
      const t = padded ? paddedRadius(thickness[g], Math.abs(ax[g]) + Math.abs(ay[g]) + Math.abs(bx[g]) + Math.abs(by[g])) : thickness[g];
      this.add(firstId + g, Math.min(ax[g], bx[g]) - t, Math.min(ay[g], by[g]) - t, Math.max(ax[g], bx[g]) + t, Math.max(ay[g], by[g]) + t);
    }
  }

  /** Packs the entries added since `clear` into the tree. */
  finish(): void {
    const n = this.count;
    this.levelEnd.length = 0;
    if (n === 0) return;
    if (this.order.length < n) {
      this.order = new Int32Array(grownCapacity(this.order.length, n));
      this.keys = new Float64Array(this.order.length);
    }
    const { order, keys, boxes } = this;
    for (let k = 0; k < n; k++) order[k] = k;
    // Strips of about sqrt(n / NODE_SIZE) leaves each, sorted by x; each strip sorted by y.
    for (let k = 0; k < n; k++) keys[k] = boxes[4 * k] + boxes[4 * k + 2];
    sortOrder(order, keys, 0, n);
    const leaves = Math.ceil(n / NODE_SIZE);
    const stripLeaves = Math.max(1, Math.ceil(Math.sqrt(leaves)));
    const stripSize = stripLeaves * NODE_SIZE;
    for (let start = 0; start < n; start += stripSize) {
      const end = Math.min(n, start + stripSize);
      for (let k = start; k < end; k++) keys[order[k]] = boxes[4 * order[k] + 1] + boxes[4 * order[k] + 3];
      sortOrder(order, keys, start, end);
    }
    // Nodes: level 0 groups entries, each level above groups the one below.
    let total = 0;
    for (let size = n; ; size = Math.ceil(size / NODE_SIZE)) {
      total += Math.ceil(size / NODE_SIZE);
      if (size <= NODE_SIZE) break;
    }
    if (this.nodeFirst.length < total) {
      this.nodeBoxes = new Float64Array(4 * total);
      this.nodeFirst = new Int32Array(total);
      this.nodeCount = new Int32Array(total);
    }
    let node = 0;
    let below = n;
    let belowStart = 0;
    for (let level = 0; ; level++) {
      const levelStart = node;
      for (let first = 0; first < below; first += NODE_SIZE) {
        const count = Math.min(NODE_SIZE, below - first);
        let minX = Infinity;
        let minY = Infinity;
        let maxX = -Infinity;
        let maxY = -Infinity;
        for (let c = first; c < first + count; c++) {
          const b = level === 0 ? 4 * order[c] : 4 * (belowStart + c);
          const source = level === 0 ? boxes : this.nodeBoxes;
          if (source[b] < minX) minX = source[b];
          if (source[b + 1] < minY) minY = source[b + 1];
          if (source[b + 2] > maxX) maxX = source[b + 2];
          if (source[b + 3] > maxY) maxY = source[b + 3];
        }
        this.nodeBoxes[4 * node] = minX;
        this.nodeBoxes[4 * node + 1] = minY;
        this.nodeBoxes[4 * node + 2] = maxX;
        this.nodeBoxes[4 * node + 3] = maxY;
        this.nodeFirst[node] = level === 0 ? first : belowStart + first;
        this.nodeCount[node] = count;
        node++;
      }
      this.levelEnd.push(node);
      const made = node - levelStart;
      if (made === 1) break;
      below = made;
      belowStart = levelStart;
    }
  }

  /** The box `queryBox` reads: min x, min y, max x, max y. */
  readonly box = new Float64Array(4);

  /** Ids of entries whose box overlaps [minX, maxX] x [minY, maxY] (touching counts), ascending, into `found`. */
  query(minX: number, minY: number, maxX: number, maxY: number): number {
    const b = this.box;
    b[0] = minX;
    b[1] = minY;
    b[2] = maxX;
    b[3] = maxY;
    return this.queryBox();
  }

  /**
   * `query` over `box`, for hot loops: the box travels in a typed array because V8 boxes each
   * number passed to a call it does not inline (this one is too big to inline), an allocation per
   * argument per call: 128 KB a step for 2,000 bodies.
   */
  queryBox(): number {
    const b = this.box;
    const minX = b[0];
    const minY = b[1];
    const maxX = b[2];
    const maxY = b[3];
    this.foundCount = 0;
    const levels = this.levelEnd.length;
    if (levels === 0) return 0;
    const { nodeBoxes, nodeFirst, nodeCount, boxes, ids, order } = this;
    let top = 0;
    this.stack[top++] = this.levelEnd[levels - 1] - 1;
    this.stack[top++] = levels - 1;
    while (top > 0) {
      const level = this.stack[--top];
      const node = this.stack[--top];
      const b = 4 * node;
      if (nodeBoxes[b] > maxX || nodeBoxes[b + 2] < minX || nodeBoxes[b + 1] > maxY || nodeBoxes[b + 3] < minY) continue;
      const first = nodeFirst[node];
      const count = nodeCount[node];
      if (level === 0) {
        for (let c = first; c < first + count; c++) {
          const e = order[c];
          const eb = 4 * e;
          if (boxes[eb] > maxX || boxes[eb + 2] < minX || boxes[eb + 1] > maxY || boxes[eb + 3] < minY) continue;
          this.push(ids[e]);
        }
      } else {
        if (top + 2 * count > this.stack.length) this.stack = grow(this.stack, 2 * (this.stack.length + 2 * count));
        for (let c = first; c < first + count; c++) {
          this.stack[top++] = c;
          this.stack[top++] = level - 1;
        }
      }
    }
    sortFew(this.found, this.foundCount);
    return this.foundCount;
  }

  memoryBytes(): number {
    return this.boxes.byteLength + this.ids.byteLength + this.nodeBoxes.byteLength + this.nodeFirst.byteLength * 2 + this.order.byteLength + this.keys.byteLength;
  }

  private push(id: number): void {
    if (this.foundCount === this.found.length) this.found = grow(this.found, 2 * this.found.length);
    this.found[this.foundCount++] = id;
  }
}

/** Sorts order[from, to) by keys[order[k]], ties by index: a merge-free insertion sort for short runs, else heap sort. */
function sortOrder(order: Int32Array, keys: Float64Array, from: number, to: number): void {
  const n = to - from;
  if (n < 2) return;
  const less = (a: number, b: number): boolean => keys[a] < keys[b] || (keys[a] === keys[b] && a < b);
  if (n <= 32) {
    for (let i = from + 1; i < to; i++) {
      const v = order[i];
      let j = i - 1;
      while (j >= from && less(v, order[j])) {
        order[j + 1] = order[j];
        j--;
      }
      order[j + 1] = v;
    }
    return;
  }
  // Heap sort: O(n log n) with no scratch.
  const sift = (start: number, end: number): void => {
    let root = start;
    for (;;) {
      let child = 2 * root + 1;
      if (child >= end) return;
      if (child + 1 < end && less(order[from + child], order[from + child + 1])) child++;
      if (!less(order[from + root], order[from + child])) return;
      const t = order[from + root];
      order[from + root] = order[from + child];
      order[from + child] = t;
      root = child;
    }
  };
  for (let start = (n >> 1) - 1; start >= 0; start--) sift(start, n);
  for (let end = n - 1; end > 0; end--) {
    const t = order[from];
    order[from] = order[from + end];
    order[from + end] = t;
    sift(0, end);
  }
}
