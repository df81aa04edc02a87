import type { BodyType } from './store/body-types.js';
import { BODY_TYPES, TypeCode } from './store/body-types.js';
import type { BroadPhaseName } from './broadphase/registry.js';
import { BROADPHASE_NAMES } from './broadphase/registry.js';
import type { IntegratorName } from './integrate/integrator.js';
import { INTEGRATOR_NAMES } from './integrate/integrator.js';
import type { NewBody } from './store/body-store.js';
import {
  finiteNumber,
  knownKeys,
  nonNegativeNumber,
  oneOf,
  plainObject,
  positiveNumber,
} from './util/validate.js';

export interface Vector {
  x: number;
  y: number;
}

export interface WorldOptions {
  /** An axis-aligned box from (0, 0) to (width, height) that contains every body. Default: none. */
  bounds?: { width: number; height: number } | null;
  /** Acceleration applied to dynamic bodies, in length units per second squared. Default (0, 0). */
  gravity?: Vector;
  /** Restitution of the box walls and default restitution of new bodies. Default 1 (elastic). */
  restitution?: number;
  /** Default 'maxgrid'. */
  broadphase?: BroadPhaseName;
  /** Default 'semi-implicit-euler'; 'explicit-euler' is the report's exact method. */
  integrator?: IntegratorName;
}

export interface CircleOptions {
  x: number;
  y: number;
  vx?: number;
  vy?: number;
  radius: number;
  /** Default 'dynamic'. */
  type?: BodyType;
  /** Default: the world's `restitution`. */
  restitution?: number;
  /** Default density * pi * radius^2. Give `mass` or `density`, not both. */
  mass?: number;
  /** Mass per unit area when `mass` is not given. Default 1. */
  density?: number;
}

export interface ResolvedWorldOptions {
  bounds: { width: number; height: number } | null;
  gravity: Vector;
  restitution: number;
  broadphase: BroadPhaseName;
  integrator: IntegratorName;
}

const WORLD_KEYS = ['bounds', 'gravity', 'restitution', 'broadphase', 'integrator'];
const CIRCLE_KEYS = ['x', 'y', 'vx', 'vy', 'radius', 'type', 'restitution', 'mass', 'density'];

export function resolveWorldOptions(input: unknown): ResolvedWorldOptions {
  const options = plainObject('World options', input ?? {});
  knownKeys('World options', options, WORLD_KEYS);
  let bounds: ResolvedWorldOptions['bounds'] = null;
  if (options.bounds !== undefined && options.bounds !== null) {
    const b = plainObject('bounds', options.bounds);
    knownKeys('bounds', b, ['width', 'height']);
    bounds = { width: positiveNumber('bounds.width', b.width), height: positiveNumber('bounds.height', b.height) };
  }
  return {
    bounds,
    gravity: options.gravity === undefined ? { x: 0, y: 0 } : vector('gravity', options.gravity),
    restitution: options.restitution === undefined ? 1 : nonNegativeNumber('restitution', options.restitution),
    broadphase: options.broadphase === undefined ? 'maxgrid' : broadphaseName(options.broadphase),
    integrator: options.integrator === undefined ? 'semi-implicit-euler' : integratorName(options.integrator),
  };
}

export function vector(field: string, input: unknown): Vector {
  const v = plainObject(field, input);
  knownKeys(field, v, ['x', 'y']);
  return { x: finiteNumber(`${field}.x`, v.x), y: finiteNumber(`${field}.y`, v.y) };
}

export function broadphaseName(value: unknown): BroadPhaseName {
  return oneOf('broadphase', value, BROADPHASE_NAMES);
}

export function integratorName(value: unknown): IntegratorName {
  return oneOf('integrator', value, INTEGRATOR_NAMES);
}

export function bodyType(value: unknown): BodyType {
  return oneOf('type', value, BODY_TYPES);
}

/** Validates circle options into a store record; the containment check is the world's. */
export function resolveCircle(input: unknown, defaultRestitution: number): NewBody {
  const o = plainObject('circle options', input);
  knownKeys('circle options', o, CIRCLE_KEYS);
  const radius = positiveNumber('radius', o.radius);
  let mass: number;
  if (o.mass !== undefined) {
    if (o.density !== undefined) throw new TypeError(`give mass or density, not both (mass ${String(o.mass)}, density ${String(o.density)})`);
    mass = positiveNumber('mass', o.mass);
  } else {
    const density = o.density === undefined ? 1 : positiveNumber('density', o.density);
    mass = density * Math.PI * radius * radius;
    if (!Number.isFinite(mass)) throw new RangeError(`mass from density ${density} and radius ${radius} is not finite`);
  }
  return {
    x: finiteNumber('x', o.x),
    y: finiteNumber('y', o.y),
    vx: o.vx === undefined ? 0 : finiteNumber('vx', o.vx),
    vy: o.vy === undefined ? 0 : finiteNumber('vy', o.vy),
    radius,
    mass,
    restitution: o.restitution === undefined ? defaultRestitution : nonNegativeNumber('restitution', o.restitution),
    type: TypeCode[o.type === undefined ? 'dynamic' : bodyType(o.type)],
  };
}
