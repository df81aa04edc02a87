import type { BroadPhase } from './broadphase.js';
import type { BodyStore } from '../store/body-store.js';
import type { PairSink } from '../store/pair-sink.js';
import { CellGrid } from './cell-grid.js';
import { LiveExtent } from './live-extent.js';

/** A Max Grid's cells, as gridGeometry returns them for drawing: columns x rows squares of side cellSize from (originX, originY). */
export interface GridGeometry {
  originX: number;
  originY: number;
  cellSize: number;
  columns: number;
  rows: number;
}

/**
 * The report's Max Grid (3.2, 5.11.2): one grid whose cell size is the largest diameter, each
 * circle stored only in the cell of its centre, the 3x3 neighbourhood searched, each pair once
 * (see CellGrid.scanSelf). Every neighbourhood pair counts as examined, which is the report's
 * false-positive measure; only pairs whose padded circles overlap go on to the narrow-phase.
 *
 * The grid spans the live bodies' extent, so it also works without a box, and its cell count is
 * capped at about 4 per body by enlarging cells, so a sparse world cannot make it explode.
 * O(n) when sizes are similar; the report's own caveat holds when they are not (one large circle
 * makes every cell large), which is what `hgrid` is for.
 */
export class MaxGridBroadPhase implements BroadPhase {
  readonly name = 'maxgrid';
  private readonly live = new LiveExtent();
  private readonly grid = new CellGrid();

  get geometry(): GridGeometry {
    const { originX, originY, cellSize, columns, rows } = this.grid;
    return { originX, originY, cellSize, columns, rows };
  }

  findPairs(bodies: BodyStore, out: PairSink): number {
    const live = this.live;
    live.measure(bodies);
    if (live.count < 2) return 0;
    const cellSize = live.cellSizeFor(live.maxRadius);
    live.fit(bodies, cellSize, 4 * live.count + 64);
    this.grid.build(bodies, live.dense ? null : live.slots, 0, live.count, live.minX, live.minY, live.maxX, live.maxY, cellSize, 4 * live.count + 64);
    return this.grid.scanSelf(out, live.coordPad);
  }

  /**
   * For a parallel step: measures the bodies and sizes the grid, on shared memory, without binning
   * them, which the step's threads then do. Returns null where the serial `findPairs` must run
   * instead: fewer than two bodies, or holes in the slots (the parallel passes bin slots 0..n-1).
   */
  layoutForThreads(bodies: BodyStore, threads: number): CellGrid | null {
    this.grid.setShared(true, threads);
    this.grid.useArena(bodies.kernel);
    const live = this.live;
    live.measure(bodies);
    if (live.count < 2 || !live.dense) return null;
    const cellSize = live.cellSizeFor(live.maxRadius);
    live.fit(bodies, cellSize, 4 * live.count + 64);
    this.grid.layout(live.minX, live.minY, live.maxX, live.maxY, cellSize, 4 * live.count + 64, live.count);
    return this.grid;
  }

  /** Absolute padding of the last measured extent (see fat-bounds.ts). */
  get coordPad(): number {
    return this.live.coordPad;
  }

  memoryBytes(): number {
    return this.live.memoryBytes() + this.grid.memoryBytes();
  }
}
