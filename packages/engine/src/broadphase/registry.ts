import type { BroadPhase } from './broadphase.js';
import { NaiveBroadPhase } from './naive.js';
import { SapBroadPhase } from './sap.js';
import { SapXyBroadPhase } from './sap-xy.js';
import { PersistentSapBroadPhase } from './sap-persistent.js';
import { MaxGridBroadPhase } from './maxgrid.js';
import { HierarchicalGridBroadPhase } from './hgrid.js';
import { HashGridBroadPhase } from './hash-grid.js';
import { AutoBroadPhase } from './auto.js';

export const BROADPHASES = {
  naive: () => new NaiveBroadPhase(),
  sap: () => new SapBroadPhase(),
  'sap-xy': () => new SapXyBroadPhase(),
  'sap-persistent': () => new PersistentSapBroadPhase(),
  maxgrid: () => new MaxGridBroadPhase(),
  hgrid: () => new HierarchicalGridBroadPhase(),
  hashgrid: () => new HashGridBroadPhase(),
  auto: () => new AutoBroadPhase(),
} satisfies Record<string, () => BroadPhase>;

/**
 * A broad-phase a world can be given (WorldOptions.broadphase, setBroadphase); each gives the same
 * bits, at its own speed.
 *
 * @useDeclaredType
 */
export type BroadPhaseName = keyof typeof BROADPHASES;

/** Every broad-phase name, for option lists and validation. */
export const BROADPHASE_NAMES = Object.keys(BROADPHASES) as BroadPhaseName[];
