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
 * O(n + cells), no per-cell allocation, and the bodies of one cell end up contiguous.
 * Each pair is reported once by visiting, from every body, the rest of its own cell and the four
 * "forward" neighbours (E, and SW, S, SE on the next row); the other four are covered from the
 * other side. This replaces the report's insert-then-query trick with the same effect.
 *
 * The grid spans the live bodies' extent, so it also works without a box. Its cell count is capped
 * at about 4 cells per body by enlarging cells: a larger cell is still conservative, and a sparse
 * world with a far-away body cannot make the grid explode.
 */
export class MaxGridBroadPhase implements BroadPhase {
  readonly name = 'maxgrid';
  readonly geometry: GridGeometry = { originX: 0, originY: 0, cellSize: 0, columns: 0, rows: 0 };

  private cellStart = new Int32Array(0);
  private sortedSlot = new Int32Array(0);
  private sortedCell = new Int32Array(0);
  private liveSlot = new Int32Array(0);
  private liveCell = new Int32Array(0);

  findPairs(bodies: BodyStore, out: PairSink): void {
    const n = bodies.liveCount;
    if (n < 2) return;
    this.ensureBodies(n);
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
    const cells = columns * rows;
    this.ensureCells(cells);
    const g = this.geometry;
    g.originX = minX;
    g.originY = minY;
    g.cellSize = cellSize;
    g.columns = columns;
    g.rows = rows;

    // Counting sort of bodies by cell.
    const cellStart = this.cellStart;
    const liveCell = this.liveCell;
    cellStart.fill(0, 0, cells + 1);
    for (let k = 0; k < n; k++) {
      const i = liveSlot[k];
      const c = Math.floor((y[i] - minY) * inv) * columns + Math.floor((x[i] - minX) * inv);
      liveCell[k] = c;
      cellStart[c + 1]++;
    }
    for (let c = 0; c < cells; c++) cellStart[c + 1] += cellStart[c];
    const sortedSlot = this.sortedSlot;
    const sortedCell = this.sortedCell;
    // Scatter from the back so each cell keeps ascending slot order; cellStart[c] ends at the start.
    for (let k = n - 1; k >= 0; k--) {
      const c = liveCell[k];
      const at = --cellStart[c + 1];
      sortedSlot[at] = liveSlot[k];
      sortedCell[at] = c;
    }
    // After the scatter cellStart[c + 1] holds the start of cell c; shift back to [start, end).
    for (let c = 0; c < cells; c++) cellStart[c] = cellStart[c + 1];
    cellStart[cells] = n;

    for (let k = 0; k < n; k++) {
      const a = sortedSlot[k];
      const c = sortedCell[k];
      const row = (c / columns) | 0;
      const column = c - row * columns;
      const ownEnd = cellStart[c + 1];
      for (let m = k + 1; m < ownEnd; m++) out.push(a, sortedSlot[m]);
      if (column + 1 < columns) this.emitCell(a, c + 1, out);
      if (row + 1 < rows) {
        const below = c + columns;
        if (column > 0) this.emitCell(a, below - 1, out);
        this.emitCell(a, below, out);
        if (column + 1 < columns) this.emitCell(a, below + 1, out);
      }
    }
  }

  memoryBytes(): number {
    return (
      this.cellStart.byteLength +
      this.sortedSlot.byteLength +
      this.sortedCell.byteLength +
      this.liveSlot.byteLength +
      this.liveCell.byteLength
    );
  }

  private emitCell(a: number, cell: number, out: PairSink): void {
    const end = this.cellStart[cell + 1];
    const sortedSlot = this.sortedSlot;
    for (let m = this.cellStart[cell]; m < end; m++) out.push(a, sortedSlot[m]);
  }

  private ensureBodies(n: number): void {
    if (this.liveSlot.length >= n) return;
    const capacity = grownCapacity(this.liveSlot.length, n);
    this.liveSlot = new Int32Array(capacity);
    this.liveCell = new Int32Array(capacity);
    this.sortedSlot = new Int32Array(capacity);
    this.sortedCell = new Int32Array(capacity);
  }

  private ensureCells(cells: number): void {
    if (this.cellStart.length >= cells + 1) return;
    this.cellStart = new Int32Array(grownCapacity(this.cellStart.length, cells + 1));
  }
}
