import type { QueryOptions } from '../world-types.js';
import { finiteNumber, knownKeys, plainObject } from '../util/validate.js';
import { layerBits } from '../options.js';

/** The default of every query's options: recognised without reading its keys, which allocates. */
export const NO_QUERY_OPTIONS: QueryOptions = Object.freeze({});

export function queryMask(options: QueryOptions): number {
  if (options === NO_QUERY_OPTIONS) return 0xffffffff;
  const o = plainObject('query options', options);
  knownKeys('query options', o, ['mask']);
  return o.mask === undefined ? 0xffffffff : layerBits('mask', o.mask);
}

export function rayArguments(x1: number, y1: number, x2: number, y2: number): void {
  finiteNumber('x1', x1);
  finiteNumber('y1', y1);
  finiteNumber('x2', x2);
  finiteNumber('y2', y2);
}

/** The array a query fills: `out`, emptied, when the caller passes one to reuse, else a new one. */
export function queryOutput<T>(out: T[] | undefined): T[] {
  if (out === undefined) return [];
  if (!Array.isArray(out)) throw new TypeError(`out must be an array to fill, got ${typeof out === 'object' ? String(out) : typeof out}`);
  out.length = 0;
  return out;
}
