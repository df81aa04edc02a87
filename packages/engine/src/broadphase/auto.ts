import type { BroadPhase } from './broadphase.js';
import type { BodyStore } from '../store/body-store.js';
import type { PairSink } from '../store/pair-sink.js';
import { MaxGridBroadPhase } from './maxgrid.js';
import { HierarchicalGridBroadPhase } from './hgrid.js';
import { LiveExtent } from './live-extent.js';

/**
 * Above this many bodies per Max Grid cell, the hierarchical grid wins. Max Grid's cells are sized
 * by the largest circle, so what hurts it is not the radius spread as such but how many circles
 * crowd each cell: n (2 rmax)^2 / area. Measured on `mixed` (20,000 circles, 2026-11-22):
 *
 *   large share  ratio  bodies/cell  maxgrid / hgrid time
 *        5%       1:4       1.7           0.43  (maxgrid wins)
 *        5%       1:8       3.8           0.83
 *        5%       1:16      5.5           1.06
 *        5%       1:50      6.3           1.37  (hgrid wins)
 *      0.1%       1:8       8.8           1.33
 *      0.1%       1:12      19            2.7
 *      0.1%       1:50      (~100)        16.8
 *
 * The radius spread alone would have chosen wrongly in both directions (a 4x spread threshold,
 * tried first, picked hgrid for the 5% rows where it is slower).
 */
export const CROWDING_FOR_HGRID = 5;

/** The choice is re-made this often (and whenever bodies come or go); it only affects cost. */
const RECHOOSE_EVERY = 30;

/**
 * Picks a broad-phase from the scene: Max Grid while its cells stay sparse, the hierarchical grid
 * when a few large circles make them crowded. Every broad-phase yields the same contacts in the
 * same canonical order, so switching between them never changes the result, only the cost.
 */
export class AutoBroadPhase implements BroadPhase {
  readonly name = 'auto';
  private readonly uniform = new MaxGridBroadPhase();
  private readonly mixed = new HierarchicalGridBroadPhase();
  private readonly extent = new LiveExtent();
  private chosenFor = -1;
  private stepsSinceChoice = 0;
  /** The broad-phase used by the last step. */
  current: BroadPhase = this.uniform;

  findPairs(bodies: BodyStore, out: PairSink): number {
    return this.select(bodies).findPairs(bodies, out);
  }

  /** The broad-phase this step uses (re-chosen every RECHOOSE_EVERY steps and on membership changes). */
  select(bodies: BodyStore): BroadPhase {
    if (this.chosenFor !== bodies.membershipVersion || ++this.stepsSinceChoice >= RECHOOSE_EVERY) this.choose(bodies);
    return this.current;
  }

  memoryBytes(): number {
    return this.uniform.memoryBytes() + this.mixed.memoryBytes() + this.extent.memoryBytes();
  }

  private choose(bodies: BodyStore): void {
    this.chosenFor = bodies.membershipVersion;
    this.stepsSinceChoice = 0;
    const e = this.extent;
    e.measure(bodies);
    const cell = 2 * e.maxRadius;
    // Extents may be a line or a point; a cell's own area is the least a body can spread over.
    const area = Math.max((e.maxX - e.minX) * (e.maxY - e.minY), cell * cell);
    const crowding = (e.count * cell * cell) / area;
    this.current = crowding > CROWDING_FOR_HGRID ? this.mixed : this.uniform;
  }
}
