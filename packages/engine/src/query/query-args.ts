import type { QueryOptions } from '../world-types.js';
import type { RayHit } from './queries.js';
import type { BodyContact } from './body-contacts.js';
import { describeValue, finiteNumber, knownKeys, plainObject } from '../util/validate.js';
import { layerBits } from '../options.js';

/** The default of every query's options: recognised without reading its keys, which allocates. */
export const NO_QUERY_OPTIONS: QueryOptions = Object.freeze({});

export function queryMask(options: QueryOptions): number {
  if (options === NO_QUERY_OPTIONS) return 0xffffffff;
  // Checked in place, its one key read once: a copy would allocate at every masked query.
  const o = plainObject('query options', options, false);
  knownKeys('query options', o, ['mask']);
  const mask = o.mask;
  return mask === undefined ? 0xffffffff : layerBits('mask', mask);
}

export function rayArguments(x1: number, y1: number, x2: number, y2: number): void {
  finiteNumber('x1', x1);
  finiteNumber('y1', y1);
  finiteNumber('x2', x2);
  finiteNumber('y2', y2);
  if (!Number.isFinite(x2 - x1) || !Number.isFinite(y2 - y1)) {
    throw new RangeError(`a ray from (${x1}, ${y1}) to (${x2}, ${y2}) spans more than the largest double (x2 - x1 = ${x2 - x1}, y2 - y1 = ${y2 - y1})`);
  }
}

/** The array a query fills: `out`, emptied, when the caller passes one to reuse, else a new one. */
export function queryOutput<T>(out: T[] | undefined): T[] {
  if (out === undefined) return [];
  writableArray(out);
  out.length = 0;
  return out;
}

/** bodyContacts' `out`: an array of contact objects to reuse, each with its `points` array. */
export function contactsOutput(out: BodyContact[] | undefined): BodyContact[] {
  if (out === undefined) return [];
  writableArray(out);
  for (let k = 0; k < out.length; k++) {
    const contact: unknown = out[k];
    if (typeof contact !== 'object' || contact === null || Array.isArray(contact) || Object.isFrozen(contact)) {
      throw new TypeError(`out[${k}] must be a writable contact object to reuse, got ${describeOut(contact)}`);
    }
    const points: unknown = (contact as BodyContact).points;
    if (!Array.isArray(points) || Object.isFrozen(points)) throw new TypeError(`out[${k}].points must be a writable array, got ${describeOut(points)}`);
    for (let p = 0; p < points.length; p++) {
      const point: unknown = points[p];
      if (typeof point !== 'object' || point === null || Array.isArray(point) || Object.isFrozen(point)) {
        throw new TypeError(`out[${k}].points[${p}] must be a writable point object to reuse, got ${describeOut(point)}`);
      }
    }
    // One object twice would hold two contacts: the second written over the first.
    for (let j = 0; j < k; j++) {
      if (out[j] === contact) throw new TypeError(`out[${k}] is the same object as out[${j}]: each contact needs its own`);
      if (out[j].points === points) throw new TypeError(`out[${k}].points is out[${j}].points: each contact needs its own`);
    }
  }
  return out;
}

/** rayCast's `out`: an object to fill, or null for a new one. */
export function rayHitOutput(out: RayHit | undefined): RayHit | null {
  if (out === undefined) return null;
  if (typeof out !== 'object' || out === null || Array.isArray(out) || Object.isFrozen(out)) {
    throw new TypeError(`out must be a writable hit object to fill, got ${describeOut(out)}`);
  }
  return out;
}

/** rayCastAll's `out`: an array whose hit objects are reused, else a new one. Not emptied: its objects are the point. */
export function rayHitsOutput(out: RayHit[] | undefined): RayHit[] {
  if (out === undefined) return [];
  writableArray(out);
  for (let k = 0; k < out.length; k++) {
    const hit: unknown = out[k];
    if (typeof hit !== 'object' || hit === null || Array.isArray(hit) || Object.isFrozen(hit)) {
      throw new TypeError(`out[${k}] must be a writable hit object to reuse, got ${describeOut(hit)}`);
    }
  }
  return out;
}

/** A query's `out` array must take new elements and a new length. */
function writableArray(out: unknown): asserts out is unknown[] {
  if (!Array.isArray(out)) throw new TypeError(`out must be an array to fill, got ${describeOut(out)}`);
  if (!Object.isExtensible(out)) throw new TypeError('out must be an array to fill, got a frozen or sealed array');
}

function describeOut(value: unknown): string {
  if (Array.isArray(value)) return 'an array';
  if (typeof value === 'object' && value !== null && Object.isFrozen(value)) return 'a frozen object';
  return describeValue(value);
}
