import type { BodyStore } from '../store/body-store.js';
import { integrateExplicitEuler } from './explicit-euler.js';
import { integrateSemiImplicitEuler } from './semi-implicit-euler.js';

/**
 * Advances positions and velocities of moving bodies by dt under a uniform gravity: slots
 * [from, to), all of them by default. Each body's update reads only that body, so disjoint ranges
 * may run on different threads and give the same bits.
 */
export type Integrator = (bodies: BodyStore, gravityX: number, gravityY: number, dt: number, from?: number, to?: number) => void;

export const INTEGRATORS = {
  'explicit-euler': integrateExplicitEuler,
  'semi-implicit-euler': integrateSemiImplicitEuler,
} satisfies Record<string, Integrator>;

export type IntegratorName = keyof typeof INTEGRATORS;

export const INTEGRATOR_NAMES = Object.keys(INTEGRATORS) as IntegratorName[];
