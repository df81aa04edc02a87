import type { BroadPhase } from './broadphase.js';
import type { BodyStore } from '../store/body-store.js';
import type { PairSink } from '../store/pair-sink.js';
import { TypeCode } from '../store/body-types.js';
import { grownCapacity } from '../util/grow.js';
import { RADIUS_PAD, COORD_PAD } from './fat-bounds.js';

export interface GridGeometry {
  originX: number;
  originY: number;
  cellSize: number;
  columns: number;
  rows: number;
}

/**
 * The report's Max Grid (3.2, 5.11.2). Cell size is the largest diameter, so two touching circles
 * sit in the same or adjacent cells; each circle is stored only in the cell of its centre.
 *
 * Built each step with a counting sort (count per cell, prefix sum, scatter), not a grid of lists:
 * O(n + cells), nothing allocated per cell. The scatter also copies each body's x, y and radius
 * into cell order, so the scan below reads memory sequentially instead of chasing slots.
 *
 * Each pair is examined once: from every body, the rest of its own cell and the east cell (one
 * contiguous range, as cells are stored row-major), then the three cells of the next row (another
 * contiguous range). The other four neighbours are covered from their side. This replaces the
 * report's insert-then-query trick with the same effect. Examined pairs are the report's
 * candidates (`pairTests`); only those whose padded boxes overlap go on to the narrow-phase,
 * which keeps the narrow-phase's input close to the contact count.
 *
 * The grid spans the live bodies' extent, so it also works without a box. Its cell count is capped
 * at about 4 cells per body by enlarging cells: a larger cell is still conservative, and a sparse
 * world with one far-away body cannot make the grid explode.
 */
export class MaxGridBroadPhase implements BroadPhase {
  readonly name = 'maxgrid';
  readonly geometry: GridGeometry = { originX: 0, originY: 0, cellSize: 0, columns: 0, rows: 0 };

  private cellStart = new Int32Array(0);
  private liveSlot = new Int32Array(0);
  private liveCell = new Int32Array(0);
  private sortedSlot = new Int32Array(0);
  private sortedCell = new Int32Array(0);
  private sortedX = new Float64Array(0);
  private sortedY = new Float64Array(0);
  private sortedR = new Float64Array(0);
  /** 1 / cellSize, shared by sizing and binning so both round identically. */
  private inverseCellSize = 0;
  /** Absolute padding for boxes far from the origin (see fat-bounds.ts). */
  private coordPad = 0;

  findPairs(bodies: BodyStore, out: PairSink): number {
    const n = bodies.liveCount;
    if (n < 2) return 0;
    this.ensureBodies(n);
    const { columns, rows, cells } = this.layout(bodies, n);
    this.sortByCell(bodies, n, cells);
    return this.scan(n, columns, rows, out);
  }

  memoryBytes(): number {
    return (
      this.cellStart.byteLength +
      this.liveSlot.byteLength * 4 +
      (this.sortedX.byteLength + this.sortedY.byteLength + this.sortedR.byteLength)
    );
  }

  /** Gathers live slots, measures their extent and sizes the grid. */
  private layout(bodies: BodyStore, n: number): { columns: number; rows: number; cells: number } {
    const { x, y, type, slotCount } = bodies;
    const liveSlot = this.liveSlot;
    let minX = Infinity;
    let minY = Infinity;
    let maxX = -Infinity;
    let maxY = -Infinity;
    let live = 0;
    for (let i = 0; i < slotCount; i++) {
      if (type[i] === TypeCode.free) continue;
      const px = x[i];
      const py = y[i];
      if (px < minX) minX = px;
      if (px > maxX) maxX = px;
      if (py < minY) minY = py;
      if (py > maxY) maxY = py;
      liveSlot[live++] = i;
    }
    const reach = Math.max(Math.abs(minX), Math.abs(maxX), Math.abs(minY), Math.abs(maxY));
    let cellSize = 2 * bodies.maxRadius() * (1 + RADIUS_PAD) + reach * COORD_PAD;
    const budget = 4 * n + 64;
    let inv = 1 / cellSize;
    let columns = Math.floor((maxX - minX) * inv) + 1;
    let rows = Math.floor((maxY - minY) * inv) + 1;
    while (columns * rows > budget) {
      cellSize *= 1.5;
      inv = 1 / cellSize;
      columns = Math.floor((maxX - minX) * inv) + 1;
      rows = Math.floor((maxY - minY) * inv) + 1;
    }
    this.inverseCellSize = inv;
    this.coordPad = reach * COORD_PAD;
    const g = this.geometry;
    g.originX = minX;
    g.originY = minY;
    g.cellSize = cellSize;
    g.columns = columns;
    g.rows = rows;
    return { columns, rows, cells: columns * rows };
  }

  /** Counting sort of live bodies by cell; each cell keeps ascending slot order. */
  private sortByCell(bodies: BodyStore, n: number, cells: number): void {
    if (this.cellStart.length < cells + 2) this.cellStart = new Int32Array(grownCapacity(this.cellStart.length, cells + 2));
    const { x, y, radius } = bodies;
    const { originX, originY, columns } = this.geometry;
    const inv = this.inverseCellSize;
    const { cellStart, liveSlot, liveCell, sortedSlot, sortedCell, sortedX, sortedY, sortedR } = this;
    cellStart.fill(0, 0, cells + 2);
    for (let k = 0; k < n; k++) {
      const i = liveSlot[k];
      const c = Math.floor((y[i] - originY) * inv) * columns + Math.floor((x[i] - originX) * inv);
      liveCell[k] = c;
      cellStart[c + 1]++;
    }
    for (let c = 0; c <= cells; c++) cellStart[c + 1] += cellStart[c];
    // Scatter from the back so that, counting down from each cell's end, slots stay ascending.
    for (let k = n - 1; k >= 0; k--) {
      const c = liveCell[k];
      const at = --cellStart[c + 1];
      const i = liveSlot[k];
      sortedSlot[at] = i;
      sortedCell[at] = c;
      sortedX[at] = x[i];
      sortedY[at] = y[i];
      sortedR[at] = radius[i] * (1 + RADIUS_PAD);
    }
    // The scatter left cellStart[c + 1] at the start of cell c: shift back to [start, end) form.
    for (let c = 0; c <= cells; c++) cellStart[c] = cellStart[c + 1];
    cellStart[cells] = n;
    cellStart[cells + 1] = n;
  }

  private scan(n: number, columns: number, rows: number, out: PairSink): number {
    const { cellStart, sortedSlot, sortedCell, sortedX, sortedY, sortedR } = this;
    const pad = this.coordPad;
    let examined = 0;
    for (let k = 0; k < n; k++) {
      const c = sortedCell[k];
      const row = (c / columns) | 0;
      const column = c - row * columns;
      const ax = sortedX[k];
      const ay = sortedY[k];
      const ar = sortedR[k] + pad;
      const a = sortedSlot[k];
      // Rest of own cell, then the east cell when there is one: contiguous in cell order.
      const sameRowEnd = column + 1 < columns ? cellStart[c + 2] : cellStart[c + 1];
      examined += sameRowEnd - k - 1;
      for (let m = k + 1; m < sameRowEnd; m++) {
        const reach = ar + sortedR[m];
        const dx = sortedX[m] - ax;
        const dy = sortedY[m] - ay;
        if (dx <= reach && dx >= -reach && dy <= reach && dy >= -reach) out.push(a, sortedSlot[m]);
      }
      if (row + 1 < rows) {
        const below = c + columns;
        const from = cellStart[column > 0 ? below - 1 : below];
        const to = cellStart[column + 1 < columns ? below + 2 : below + 1];
        examined += to - from;
        for (let m = from; m < to; m++) {
          const reach = ar + sortedR[m];
          const dx = sortedX[m] - ax;
          const dy = sortedY[m] - ay;
          if (dx <= reach && dx >= -reach && dy <= reach && dy >= -reach) out.push(a, sortedSlot[m]);
        }
      }
    }
    return examined;
  }

  private ensureBodies(n: number): void {
    if (this.liveSlot.length >= n) return;
    const capacity = grownCapacity(this.liveSlot.length, n);
    this.liveSlot = new Int32Array(capacity);
    this.liveCell = new Int32Array(capacity);
    this.sortedSlot = new Int32Array(capacity);
    this.sortedCell = new Int32Array(capacity);
    this.sortedX = new Float64Array(capacity);
    this.sortedY = new Float64Array(capacity);
    this.sortedR = new Float64Array(capacity);
  }
}
