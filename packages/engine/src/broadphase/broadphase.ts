import type { BodyStore } from '../store/body-store.js';
import type { PairSink } from '../store/pair-sink.js';

/**
 * The broad-phase contract.
 *
 * - Conservative: every pair of live bodies whose circles touch or overlap (distance <= sum of
 *   radii) is pushed. False positives are allowed; a false negative is a bug.
 * - Each unordered pair at most once, as two slot indices in either order.
 * - Never pushes a FREE slot; pairs of non-dynamic bodies may be pushed (the narrow-phase drops
 *   them). Pairs of two sleeping bodies may be skipped: nothing happens between them.
 * - The order of pushed pairs is free: the step sorts contacts canonically afterwards.
 * - No allocation once warm: scratch grows geometrically and is kept between steps.
 *
 * - Returns how many pairs it examined to produce its output: its own work, which is the report's
 *   measure of false positives (7.4) when a broad-phase filters before the narrow-phase.
 *
 * A new algorithm is one file implementing this interface plus one line in `registry.ts`.
 */
export interface BroadPhase {
  readonly name: string;
  findPairs(bodies: BodyStore, out: PairSink): number;
  /** Bytes of scratch memory held, for the lab's memory-per-body accounting. */
  memoryBytes(): number;
}
