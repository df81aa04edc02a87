import type { BroadPhase } from './broadphase.js';
import type { BodyStore } from '../store/body-store.js';
import type { PairSink } from '../store/pair-sink.js';
import { SweepSets, sweepSets } from './axis-sweep.js';

/**
 * Sweep-and-prune on x (report 3.1.4.1, 5.11.1): sort intervals by their start, then for each
 * interval walk forward while the next start is within its end. Intervals are closed, so
 * tangent circles are reported. Static bodies are sorted apart and swept against moving ones
 * only (see SweepSets).
 */
export class SapBroadPhase implements BroadPhase {
  readonly name = 'sap';
  private readonly sets = new SweepSets();

  findPairs(bodies: BodyStore, out: PairSink): number {
    const sets = this.sets;
    sets.gather(bodies);
    sets.moving.sortFrom(bodies.x, bodies.radius);
    sets.fixed.sortFrom(bodies.x, bodies.radius);
    return sweepSets(sets, out, bodies.sleepingCount > 0 ? bodies.asleep : null, null);
  }

  memoryBytes(): number {
    return this.sets.memoryBytes();
  }
}
