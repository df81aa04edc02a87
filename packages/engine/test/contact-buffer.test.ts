import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { ContactBuffer } from '../src/store/contact-buffer.js';
import { setBodyKernelEnabled } from '../src/store/body-kernel.js';

describe('canonical contact order', () => {
  it.each([
    ['in WebAssembly', true],
    ['in TypeScript', false],
  ])('sorts unique (lo, hi) pairs ascending, by counting passes (many contacts) or radix (few), %s', (_label, kernel) => {
    fc.assert(
      fc.property(fc.integer({ min: 2, max: 70_000 }), fc.array(fc.tuple(fc.nat(), fc.nat()), { maxLength: 400 }), (slots, raw) => {
        const unique = new Map<string, [number, number]>();
        for (const [a, b] of raw) {
          const i = a % slots;
          const j = b % slots;
          if (i !== j) unique.set(`${Math.min(i, j)},${Math.max(i, j)}`, [Math.min(i, j), Math.max(i, j)]);
        }
        const pairs = [...unique.values()];
        setBodyKernelEnabled(kernel);
        const buffer = new ContactBuffer();
        setBodyKernelEnabled(true);
        for (const [lo, hi] of pairs) buffer.push(lo, hi);
        buffer.sortCanonical(slots);
        // The path under test really ran (the sorter is made at the first sort of two or more pairs).
        if (pairs.length >= 2) expect(Boolean((buffer as unknown as { sorter: unknown }).sorter)).toBe(kernel);
        const sorted = Array.from({ length: buffer.count }, (_, k) => [buffer.lo[k], buffer.hi[k]]);
        expect(sorted).toEqual(pairs.sort((p, q) => p[0] - q[0] || p[1] - q[1]));
      }),
      { numRuns: 300, seed: 5 },
    );
  });
});
