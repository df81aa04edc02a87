import type { BodyStore } from '../store/body-store.js';
import { integrateExplicitEuler } from './explicit-euler.js';
import { integrateSemiImplicitEuler } from './semi-implicit-euler.js';

/** Advances positions and velocities of moving bodies by dt under a uniform gravity. */
export type Integrator = (bodies: BodyStore, gravityX: number, gravityY: number, dt: number) => void;

export const INTEGRATORS = {
  'explicit-euler': integrateExplicitEuler,
  'semi-implicit-euler': integrateSemiImplicitEuler,
} satisfies Record<string, Integrator>;

export type IntegratorName = keyof typeof INTEGRATORS;

export const INTEGRATOR_NAMES = Object.keys(INTEGRATORS) as IntegratorName[];
