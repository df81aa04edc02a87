import type { QueryOptions } from '../world-types.js';
import { finiteNumber, knownKeys, plainObject } from '../util/validate.js';
import { layerBits } from '../options.js';

export function queryMask(options: QueryOptions): number {
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
