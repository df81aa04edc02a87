import { describe, expect, it } from 'vitest';
import { SPRING_RATE, springDamping, springHertz } from '../src/solver/spring-frequency.js';
import { makeSoft } from '../src/solver/solver-body.js';

/**
 * The frequency of an undamped soft spring solved at `solved` hertz over sub-steps of h, from its
 * motion: the soft step's sub-step (warm start, biased solve, move, relax) on one degree of
 * freedom, stretch x, speed v and kept impulse u, run for `periods` of `hertz` with its
 * down-crossings timed. The motion decays, so it is rescaled each sub-step (the map is linear).
 */
function oscillation(solved: number, hertz: number, h: number, periods: number): number {
  const soft = new Float64Array(3);
  makeSoft(solved, 0, h, soft);
  const [bias, scale, keep] = soft;
  let x = 1;
  let v = 0;
  let u = 0;
  const crossings: number[] = [];
  const steps = Math.ceil(periods / (hertz * h));
  for (let n = 1; n <= steps; n++) {
    const before = x;
    v += u;
    let d = -scale * (v + bias * x) - keep * u;
    u += d;
    v += d;
    x += h * v;
    d = -scale * (v + bias * x) - keep * u;
    u += d;
    v += d;
    if (before > 0 && x <= 0) crossings.push((n - x / (x - before)) * h);
    const size = Math.abs(x) + h * Math.abs(v) + h * Math.abs(u);
    x /= size;
    v /= size;
    u /= size;
  }
  return (crossings.length - 1) / (crossings[crossings.length - 1] - crossings[0]);
}

describe('the frequency a soft spring is solved at (springHertz)', () => {
  it('makes the soft sub-step oscillate at the frequency asked, up to an eighth of the sub-step rate', () => {
    for (const h of [1 / 240, 1 / 480, 1e-3]) {
      for (const fh of [1e-3, 0.01, 0.03, 0.06, 0.1, 0.125]) {
        const hertz = fh / h;
        const solved = springHertz(hertz, h);
        // Crossings are timed by a straight line between sub-steps: at 8 sub-steps a period that is
        // good to about 1e-3, and it averages out over many periods.
        expect(Math.abs(oscillation(solved, hertz, h, 200) / hertz - 1), `f h ${fh}`).toBeLessThan(fh < 0.05 ? 1e-6 : 1e-4);
        // Unwarped, it is slow by 11 pi^2 / 6 (f h)^2 at small f h.
        if (fh >= 0.01) expect(oscillation(hertz, hertz, h, 200) / hertz - 1).toBeLessThan(-fh * fh);
      }
    }
  });

  it('rises with the frequency asked, by 11 pi^2 / 6 (f h)^2 where f h is small, never past a quarter of the sub-step rate', () => {
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
        if (fh < 0.01) expect(Math.abs(solved / f - 1 - shift), `f h ${fh}`).toBeLessThan(0.01 * shift + 1e-15);
        previous = solved;
      }
    }
    expect(springHertz(0, 1 / 240)).toBe(0);
    expect(springHertz(1e300, 1 / 240)).toBe(60);
  });

  it('keeps the damping, 2 zeta w, on the stiffer spring, w the frequency it oscillates at', () => {
    const h = 1 / 240;
    for (const [hertz, zeta] of [[10, 0.1], [20, 1], [0.5, 0.7]]) {
      const solved = springHertz(hertz, h);
      expect(springDamping(zeta, hertz, h) * solved).toBeCloseTo(zeta * hertz, 12);
    }
    // Past the bound, the highest frequency kept: the turn of the spring solved at the bound.
    const kept = oscillation(60, 60, h, 400);
    expect(kept).toBeGreaterThan(33);
    expect(kept).toBeLessThan(33.5);
    // (The crossings, 7 sub-steps a period, time it to about 1e-4.)
    for (const hertz of [40, 1e6]) expect(Math.abs((springDamping(0.5, hertz, h) * 60) / (0.5 * kept) - 1)).toBeLessThan(1e-3);
    expect(springDamping(0.5, 0, h)).toBe(0.5);
  });
});
