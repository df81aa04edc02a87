import type { BroadPhase } from './broadphase.js';
import type { BodyStore } from '../store/body-store.js';
import type { PairSink } from '../store/pair-sink.js';
import { SweepSets, sweepSets } from './axis-sweep.js';

/**
 * Persistent sweep-and-prune on x (report 3.1.4.1; Tracy, Buss & Woods 2009). The sorted order of
 * interval starts is kept between steps. Bodies move little per step, so insertion sort restores
 * the order in close to linear time, and a sleeping body's entry does not move at all. Pairs of
 * two sleepers are skipped in the sweep, and static bodies, kept in an order of their own, are
 * swept against moving ones only (see SweepSets).
 *
 * When the body set changes the order is rebuilt from scratch, and when insertion sort has to do
 * too much work (a teleport, a reset) it gives up and a merge sort finishes the job, so the worst
 * step is O(n log n), never O(n^2).
 */
export class PersistentSapBroadPhase implements BroadPhase {
  readonly name = 'sap-persistent';
  private readonly sets = new SweepSets();
  private builtFor = -1;
  private builtForFlips = -1;
  /** Element moves made by the last insertion sorts: how much order they had to restore. */
  lastShifts = 0;

  findPairs(bodies: BodyStore, out: PairSink): number {
    const sets = this.sets;
    if (this.builtFor !== bodies.membershipVersion || this.builtForFlips !== bodies.staticFlips) {
      sets.gather(bodies);
      this.builtFor = bodies.membershipVersion;
      this.builtForFlips = bodies.staticFlips;
    }
    this.lastShifts = sets.moving.resortFrom(bodies.x, bodies.radius) + sets.fixed.resortFrom(bodies.x, bodies.radius);
    return sweepSets(sets, out, bodies.sleepingCount > 0 ? bodies.asleep : null, null);
  }

  memoryBytes(): number {
    return this.sets.memoryBytes();
  }
}
