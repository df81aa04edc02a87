import type { BroadPhase } from './broadphase.js';
import type { BodyStore } from '../store/body-store.js';
import type { PairSink } from '../store/pair-sink.js';
import { MaxGridBroadPhase } from './maxgrid.js';
import { HierarchicalGridBroadPhase } from './hgrid.js';

/**
 * Above this ratio of largest to smallest radius, Max Grid's cells (sized by the largest circle)
 * hold too many small circles and the hierarchical grid wins. Measured with the lab's
 * `false-positives` and `step-time` experiments on the uniform scene; see docs/results.md.
 */
export const SPREAD_FOR_HGRID = 4;

/**
 * Picks a broad-phase from the scene each step: Max Grid when sizes are similar, the hierarchical
 * grid when they are not. Every broad-phase yields the same contacts in the same canonical order,
 * so switching between them never changes the result, only the cost.
 */
export class AutoBroadPhase implements BroadPhase {
  readonly name = 'auto';
  private readonly uniform = new MaxGridBroadPhase();
  private readonly mixed = new HierarchicalGridBroadPhase();
  /** The broad-phase used by the last step. */
  current: BroadPhase = this.uniform;

  findPairs(bodies: BodyStore, out: PairSink): number {
    this.current = bodies.radiusSpread() > SPREAD_FOR_HGRID ? this.mixed : this.uniform;
    return this.current.findPairs(bodies, out);
  }

  memoryBytes(): number {
    return this.uniform.memoryBytes() + this.mixed.memoryBytes();
  }
}
