import type { BroadPhase } from './broadphase.js';
import type { BodyStore } from '../store/body-store.js';
import type { PairSink } from '../store/pair-sink.js';
import { MaxGridBroadPhase } from './maxgrid.js';
import { HierarchicalGridBroadPhase } from './hgrid.js';
import { PersistentSapBroadPhase } from './sap-persistent.js';
import { HashGridBroadPhase } from './hash-grid.js';
import { LiveExtent } from './live-extent.js';

/**
 * Above this many bodies per Max Grid cell, the hierarchical grid wins. Max Grid's cells are sized
 * by the largest circle, so what hurts it is not the radius spread as such but how many circles
 * crowd each cell: n (2 rmax)^2 / area. Whole steps of 20,000 circles, median of 21 (docs/engine.md
 * has the times):
 *
 *   scene                          bodies/cell  maxgrid / hgrid time
 *   mixed  5%    large, 1:4            1.7           1.03
 *   mixed  5%    large, 1:8            3.8           0.93
 *   mixed  5%    large, 1:16           5.4           1.15
 *   mixed  5%    large, 1:50           6.3           1.26
 *   mixed  0.1%  large, 1:4            2.2           1.29
 *   mixed  0.1%  large, 1:8            8.5           1.97
 *   mixed  0.1%  large, 1:50           165           25
 *   uniform, log-uniform 1..100        3.0           0.51
 *   uniform, log-uniform 0.01..100     5.9           1.14
 *   uniform, log-uniform 0.01..10^4    9.0           1.58
 *
 * so auto is within 1.3x of the faster grid on each. The radius spread alone would have chosen
 * wrongly in both directions (log-uniform radii over four decades crowd less than 1:8 with a few
 * large circles).
 */
export const CROWDING_FOR_HGRID = 5;

/** The choice is re-made this often (and whenever bodies come or go); it only affects cost. */
const RECHOOSE_EVERY = 30;

/**
 * Pairs a grid may examine per body before auto turns to a broad-phase that does not depend on the
 * extent: the hashed grid in place of Max Grid, the persistent sweep in place of the hierarchical
 * grid. A grid holds at most 4n + 64 cells over its extent, which it fits to all but a few bodies
 * (extent-fit.ts), so a few far-away bodies or a huge empty box cost nothing; but two crowds of
 * 10,000 a million units apart still share cells a million units wide, and examined 5,000 pairs
 * per body (docs/engine.md, Numbers). Sparse scenes examine about 2 pairs per body; crowded
 * `mixed` on hgrid stays under 10.
 */
export const EXAMINED_PER_BODY_FOR_SWEEP = 64;

/**
 * SWEEP_MARGIN for the hashed grid: it examines Max Grid's neighbourhoods, at a few times the
 * cost per pair of the dense grid's kernel (its buckets lie apart in memory), and far crowds
 * then examine some 100 times fewer pairs than on the grid.
 */
const HASH_MARGIN = 4;

/**
 * How many times fewer pairs the sweep must examine than the grid it replaced, or auto goes back to
 * the grid. A sweep pair costs more than a grid pair (3,000 circles bursting from one spot, the
 * second step, about 2.3 million pairs on each: docs/engine.md, Numbers), and the margin covers
 * that and leaves borderline cases on the grid. Two crowds far apart give a factor of about 125.
 */
const SWEEP_MARGIN = 8;

/** The most steps between retrying a grid that examined too much: each failed retry doubles the wait. */
const LONGEST_RETRY = 32 * RECHOOSE_EVERY;

/**
 * Picks a broad-phase from the scene: Max Grid while its cells stay sparse, the hierarchical grid
 * when a few large circles make them crowded, and when the chosen grid examined more than
 * EXAMINED_PER_BODY_FOR_SWEEP pairs per body (cells the extent made huge) the hashed grid in place
 * of Max Grid, and the persistent sweep in place of the hierarchical grid or of a hashed grid that
 * examined too much itself or nearly as much as the grid (HASH_MARGIN), unless the sweep then
 * examines nearly as many as the grid (SWEEP_MARGIN); the grid is retried after
 * RECHOOSE_EVERY steps, then after twice as many each time it fails again. Every broad-phase
 * yields the same contacts in the same canonical order, so switching between them never changes
 * the result, only the cost.
 */
export class AutoBroadPhase implements BroadPhase {
  readonly name = 'auto';
  private readonly uniform = new MaxGridBroadPhase();
  private readonly mixed = new HierarchicalGridBroadPhase();
  private readonly sweep = new PersistentSapBroadPhase();
  private readonly hashed = new HashGridBroadPhase();
  private readonly extent = new LiveExtent();
  private chosenFor = -1;
  private stepsSinceChoice = 0;
  /** Steps until the choice is re-made: RECHOOSE_EVERY, doubled by each grid that examined too much. */
  private rechooseAfter = RECHOOSE_EVERY;
  /** The broad-phase used by the last step. */
  current: BroadPhase = this.uniform;
  /** The grid the sweep last replaced, and the pairs it had examined. */
  private lastGrid: BroadPhase = this.uniform;
  private gridExamined = 0;
  /** The sweep did worse than that grid: keep the grid until the next choice. */
  private gridKept = false;

  findPairs(bodies: BodyStore, out: PairSink): number {
    const used = this.select(bodies);
    const examined = used.findPairs(bodies, out);
    this.noteExamined(used, examined, bodies);
    return examined;
  }

  /**
   * What the broad-phase `select` gave examined this step: a grid past the limit hands over to
   * the sweep. The parallel step, which runs the chosen Max Grid itself, reports here too.
   */
  noteExamined(used: BroadPhase, examined: number, bodies: BodyStore): void {
    if (used === this.sweep || used === this.hashed) {
      // A replacement must examine far fewer pairs than the grid it replaced to be worth
      // keeping: when every body starts in one spot, each examines alike and the grid is the
      // faster (see SWEEP_MARGIN). Else the sweep after the hashed grid, and the grid after the
      // sweep, until the next choice.
      if (used === this.hashed) {
        // Hashed cells are as wide as the largest body: crowds far apart whose sizes differ
        // crowd them as they crowd Max Grid's (the choice by crowding saw the extent's empty
        // space, not the crowds), and the sweep, which does not care, is tried next.
        if (examined * HASH_MARGIN > this.gridExamined || examined > EXAMINED_PER_BODY_FOR_SWEEP * bodies.proxyCount) this.current = this.sweep;
      } else if (examined * SWEEP_MARGIN > this.gridExamined) {
        this.current = this.lastGrid;
        this.gridKept = true;
      }
      return;
    }
    if (this.gridKept) return;
    if (examined > EXAMINED_PER_BODY_FOR_SWEEP * bodies.proxyCount) {
      this.gridExamined = examined;
      this.lastGrid = used;
      // Max Grid's cells without its extent, or for sizes that crowd them, the sweep.
      this.current = used === this.uniform ? this.hashed : this.sweep;
      this.rechooseAfter = Math.min(2 * this.rechooseAfter, LONGEST_RETRY);
    } else {
      this.rechooseAfter = RECHOOSE_EVERY;
    }
  }

  /** The broad-phase this step uses (re-chosen every so often and on membership changes). */
  select(bodies: BodyStore): BroadPhase {
    const due = ++this.stepsSinceChoice >= this.rechooseAfter;
    if (due || this.chosenFor !== bodies.membershipVersion) {
      // Bodies coming or going do not cut short a wait on a replacement: a spawner would otherwise
      // bring back the slow grid for one step each time.
      const waiting = (this.current === this.sweep || this.current === this.hashed || this.gridKept) && !due;
      const kept = this.current;
      this.choose(bodies);
      if (waiting) {
        this.current = kept;
      } else {
        this.stepsSinceChoice = 0;
        this.gridKept = false;
      }
    }
    return this.current;
  }

  memoryBytes(): number {
    return this.uniform.memoryBytes() + this.mixed.memoryBytes() + this.sweep.memoryBytes() + this.hashed.memoryBytes() + this.extent.memoryBytes();
  }

  private choose(bodies: BodyStore): void {
    this.chosenFor = bodies.membershipVersion;
    const e = this.extent;
    e.measure(bodies);
    const cell = 2 * e.maxRadius;
    // Extents may be a line or a point; a cell's own area is the least a body can spread over.
    const area = Math.max((e.maxX - e.minX) * (e.maxY - e.minY), cell * cell);
    const crowding = (e.count * cell * cell) / area;
    this.current = crowding > CROWDING_FOR_HGRID ? this.mixed : this.uniform;
  }
}
