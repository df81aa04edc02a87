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

/** The circle route's integrators. */
export type CircleIntegratorName = keyof typeof INTEGRATORS;

/**
 * Every integrator a world can be given. 'rk4' (classical Runge-Kutta) is for force-driven
 * springs (joints of kind 'spring'): it moves the world to the shape route, where the soft step
 * integrates each sub-step's spring forces with it (solver/force-springs.ts).
 *
 * @useDeclaredType
 */
export type IntegratorName = CircleIntegratorName | 'rk4';

/** Every integrator name, for option lists and validation. */
export const INTEGRATOR_NAMES: readonly IntegratorName[] = ['explicit-euler', 'semi-implicit-euler', 'rk4'];
