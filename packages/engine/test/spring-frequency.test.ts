import { describe, expect, it } from 'vitest';
import { SPRING_RATE, springHertz } from '../src/solver/spring-frequency.js';

describe('the frequency a soft spring is solved at (springHertz)', () => {
  it('rises with the frequency asked, by 11 pi^2 / 6 (f h)^2 (about 18) where f h is small, never past a quarter of the sub-step rate', () => {
    for (const h of [1 / 240, 1 / 480, 1e-6, 2.5e5]) {
      const most = SPRING_RATE / h;
      let previous = 0;
      for (let f = most * 1e-9; f < most * 100; f *= 1.7) {
        const solved = springHertz(f, h);
        expect(Number.isFinite(solved)).toBe(true);
        expect(solved).toBeGreaterThanOrEqual(previous);
        expect(solved).toBeGreaterThanOrEqual(Math.min(f, most));
        expect(solved).toBeLessThanOrEqual(most);
        const fh = f * h;
        const shift = ((11 * Math.PI * Math.PI) / 6) * fh * fh;
        if (fh < 1e-4) expect(solved).toBe(f);
        else if (fh < 0.01) expect(Math.abs(solved / f - 1 - shift), `f h ${fh}`).toBeLessThan(0.02 * shift + 1e-9);
        previous = solved;
      }
    }
    expect(springHertz(0, 1 / 240)).toBe(0);
    expect(springHertz(1e300, 1 / 240)).toBe(60);
  });
});
