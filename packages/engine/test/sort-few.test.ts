import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { sortFew } from '../src/util/sort-by-key.js';

describe('sortFew: a search\'s results in ascending order, in place', () => {
  it('sorts a prefix of any length, few (insertion) or many (heap sort), leaving the rest of the array as it was', () => {
    fc.assert(
      fc.property(fc.array(fc.integer({ min: -1000, max: 1000 }), { maxLength: 300, size: 'max' }), fc.nat(20), (values, extra) => {
        const array = Int32Array.from([...values, ...Array.from({ length: extra }, (_, k) => 7000 + k)]);
        sortFew(array, values.length);
        expect(Array.from(array.subarray(0, values.length))).toEqual(values.slice().sort((a, b) => a - b));
        expect(Array.from(array.subarray(values.length))).toEqual(Array.from({ length: extra }, (_, k) => 7000 + k));
      }),
      { numRuns: 400, seed: 5 },
    );
  });

  it('sorts the orders a tree hands back: reversed, already sorted, all equal', () => {
    for (const n of [31, 32, 33, 1000, 4096]) {
      const reversed = Int32Array.from({ length: n }, (_, k) => n - k);
      sortFew(reversed, n);
      expect(Array.from(reversed)).toEqual(Array.from({ length: n }, (_, k) => k + 1));
      const same = new Int32Array(n).fill(3);
      sortFew(same, n);
      expect(same.every((v) => v === 3)).toBe(true);
    }
  });
});
