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

describe('merging sorted contact lists (a parallel step\'s threads each sort their own)', () => {
  const sortedPairs = (seed: number, n: number, slots: number): [number, number][] => {
    const unique = new Map<string, [number, number]>();
    let s = seed;
    const next = () => ((s = (s * 1103515245 + 12345) % 2 ** 31), s % slots);
    while (unique.size < n) {
      const i = next();
      const j = next();
      if (i !== j) unique.set(`${Math.min(i, j)},${Math.max(i, j)}`, [Math.min(i, j), Math.max(i, j)]);
    }
    return [...unique.values()].sort((p, q) => p[0] - q[0] || p[1] - q[1]);
  };
  const arrays = (pairs: [number, number][]) => [Int32Array.from(pairs, (p) => p[0]), Int32Array.from(pairs, (p) => p[1])] as const;
  const contents = (buffer: ContactBuffer) => Array.from({ length: buffer.count }, (_, k) => [buffer.lo[k], buffer.hi[k]]);

  it('merges disjoint sorted lists into canonical order, leaving the sort nothing to do', () => {
    // Split one sorted set into three interleaved lists, as bands of rows split a step's contacts.
    const all = sortedPairs(7, 900, 5000);
    const lists = [0, 1, 2].map((t) => all.filter((_, k) => (k * 7919) % 3 === t));
    const buffer = new ContactBuffer();
    buffer.clear();
    for (const list of lists) buffer.mergeSorted(...arrays(list), list.length);
    expect(contents(buffer)).toEqual(all);
    // The buffer knows it is ordered, so the step's sort skips it; run anyway, it changes nothing.
    expect((buffer as unknown as { ordered: boolean }).ordered).toBe(true);
    buffer.sortCanonical(5000);
    expect(contents(buffer)).toEqual(all);
  });

  it('appends instead when the buffer is not in order, and the sort still gives canonical order', () => {
    const all = sortedPairs(11, 400, 3000);
    const [first, second] = [all.filter((_, k) => k % 2 === 0), all.filter((_, k) => k % 2 === 1)];
    const buffer = new ContactBuffer();
    buffer.clear();
    for (let k = first.length - 1; k >= 0; k--) buffer.push(first[k][0], first[k][1]);
    buffer.mergeSorted(...arrays(second), second.length);
    expect(buffer.count).toBe(all.length);
    buffer.sortCanonical(3000);
    expect(contents(buffer)).toEqual(all);
  });

  it('takes interleaved pairs (a scan\'s contacts) past its capacity, and no longer counts as ordered', () => {
    const all = sortedPairs(13, 300, 2000);
    const interleaved = Int32Array.from(all.flat());
    const buffer = new ContactBuffer();
    buffer.clear();
    buffer.pushPairs(interleaved, 0, 2 * 100);
    buffer.pushPairs(interleaved, 2 * 100, interleaved.length);
    expect(contents(buffer)).toEqual(all);
    expect((buffer as unknown as { ordered: boolean }).ordered).toBe(false);
  });
});
