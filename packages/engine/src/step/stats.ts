/**
 * What the last `step()` did. One object per world, overwritten by every step (copy it to keep
 * it). Times are wall-clock milliseconds per stage, in the order the stages run.
 */
export interface StepStats {
  /** Steps taken since the world was created. */
  steps: number;
  /** Live bodies during the last step. */
  bodies: number;
  /**
   * Pairs the broad-phase examined: its own work (n(n-1)/2 for `naive`, every pair in a 3x3
   * neighbourhood for `maxgrid`, each axis's interval overlaps for the sweeps).
   */
  pairTests: number;
  /** Pairs the broad-phase passed to the narrow-phase (n(n-1)/2 for `naive`). */
  candidatePairs: number;
  /** Pairs the narrow-phase found overlapping with at least one awake dynamic body. */
  contacts: number;
  /** Circle-segment contacts resolved. */
  segmentContacts: number;
  /** Fast bodies swept against static shapes by continuous collision. */
  sweptBodies: number;
  /** Candidate pairs dropped by collision layers. */
  filteredPairs: number;
  /** Dynamic bodies asleep after the step. */
  sleepingBodies: number;
  /**
   * Without continuous sweeps, this also covers the box walls (boundaryMs is then 0) when the
   * world runs on worker threads, or moves its bodies in the body kernel (a single-threaded world
   * with a box and no forces, damping, gravity scales or sleepers); with worker threads in a box
   * it also covers binning bodies into the Max Grid.
   */
  integrateMs: number;
  /** Continuous collision against static shapes, then the box walls. */
  boundaryMs: number;
  broadphaseMs: number;
  /**
   * With worker threads (startWorkers): the calling thread's own narrow-phase time. Near 0 where
   * the Max Grid's WebAssembly scan tests touching itself (worlds where every pair collides): that
   * time is then in broadphaseMs.
   */
  narrowphaseMs: number;
  /** Canonical contact ordering plus impulses and separation. */
  solveMs: number;
  /** Keeping separated circles inside the box. */
  correctMs: number;
  /** Contact events, clearing forces, and sleep timers. */
  reportMs: number;
  totalMs: number;
  /**
   * Threads that ran the last step: 1 without workers, below their minBodies, on the shape route,
   * or where the world's thread governor found one thread faster (see startWorkers).
   */
  threads: number;
}

/**
 * A class rather than an object literal so that snapshots can tell it apart: its timings are
 * measurements of this machine, not state, and are left out (see TIMINGS).
 */
class StepStatsRecord implements StepStats {
  steps = 0;
  bodies = 0;
  pairTests = 0;
  candidatePairs = 0;
  contacts = 0;
  segmentContacts = 0;
  sweptBodies = 0;
  filteredPairs = 0;
  sleepingBodies = 0;
  integrateMs = 0;
  boundaryMs = 0;
  broadphaseMs = 0;
  narrowphaseMs = 0;
  solveMs = 0;
  correctMs = 0;
  reportMs = 0;
  totalMs = 0;
  threads = 1;
}

export { StepStatsRecord };

/** The stage timings of StepStats. */
export const TIMINGS = ['integrateMs', 'boundaryMs', 'broadphaseMs', 'narrowphaseMs', 'solveMs', 'correctMs', 'reportMs', 'totalMs'];

export function emptyStats(): StepStats {
  return new StepStatsRecord();
}
