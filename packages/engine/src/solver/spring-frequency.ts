import { atan2 } from '../math/trig.js';

/**
 * The highest frequency a soft-constraint spring is solved at, as a fraction of the sub-step rate:
 * a quarter, 60 Hz at 60 Hz with 4 sub-steps, the bound Box2D v3 puts on its joints' stiffness.
 * A lone spring is stable at any stiffness, but springs coupled in a lattice, solved one after
 * another, are not: a 6 x 6 jelly with shear springs settled up to 120 Hz there, gained energy
 * from about 150 Hz and reached the speed limit at 240.
 */
export const SPRING_RATE = 0.25;

/**
 * The frequency to solve a spring of `hertz` at over sub-steps of h, so that it oscillates at
 * `hertz`, at most SPRING_RATE / h.
 *
 * The soft step's spring (Box2D v3's soft constraint: warm-started, solved in the biased pass and
 * again in the relax pass) oscillates slower than the frequency it is solved at. Undamped, its
 * mass scale s and impulse scale k add to 1, so a solve leaves the kept impulse at -s (v + x / h)
 * whatever it was, and a sub-step's map on (stretch, speed, kept impulse) has one eigenvalue 0 and
 * a pair of modulus 1 / (1 + a) and cosine 1 - a / (2 (1 + a)), with a = (h w)^2 for w = 2 pi f:
 * at 60 Hz with 4 sub-steps, -0.5 % at 4 Hz and -11 % at 20 Hz (11 pi^2 / 6 (f h)^2 where f h
 * is small). Setting that angle to the exact motion's, 2 pi f h, gives
 *   h w' = 2 sin(pi f h) / sqrt(1 - 4 sin^2(pi f h)),
 * defined while f h < 1/6. The cap comes first: at 60 Hz with 4 sub-steps a spring keeps its
 * frequency up to about 33 Hz, and a stiffer one oscillates at about that. Arithmetic only: the
 * same bits everywhere.
 */
export function springHertz(hertz: number, h: number): number {
  io[Spring.hertz] = hertz;
  io[Spring.zeta] = 0;
  io[Spring.h] = h;
  softSpring(io);
  return io[Spring.solvedHertz];
}

/** The damping ratio a spring of `hertz` and `zeta` is solved at over sub-steps of h (see softSpring). */
export function springDamping(zeta: number, hertz: number, h: number): number {
  io[Spring.hertz] = hertz;
  io[Spring.zeta] = zeta;
  io[Spring.h] = h;
  softSpring(io);
  return io[Spring.solvedZeta];
}

const io = new Float64Array(8);

/** Where softSpring reads and writes in its array. */
export const Spring = { hertz: 0, zeta: 1, h: 2, bias: 3, massScale: 4, impulseScale: 5, solvedHertz: 6, solvedZeta: 7 } as const;

/**
 * How far a sub-step turns the oscillation of a spring solved at SPRING_RATE / h, in turns: the
 * most any spring keeps, so the highest frequency one oscillates at is KEPT_TURN / h (33 Hz at 60
 * Hz with 4 sub-steps). From the modulus and cosine in springHertz's comment, a = (pi / 2)^2.
 */
const KEPT_TURN = (() => {
  const a = (2 * Math.PI * SPRING_RATE) ** 2;
  const c = 1 - a / (2 * (1 + a));
  return atan2(Math.sqrt(1 - c * c), c) / (2 * Math.PI);
})();

/**
 * The soft constraint of a spring of io[Spring.hertz] hertz and damping ratio io[Spring.zeta]
 * over sub-steps of io[Spring.h]: the frequency it is solved at (springHertz's comment) and the
 * damping ratio that keeps its damping, 2 zeta w, on the stiffer spring, with w the frequency it
 * oscillates at (past the bound, the highest one kept), into io[Spring.solvedHertz] and
 * io[Spring.solvedZeta]; then makeSoft's bias rate, mass scale and impulse scale for those, into
 * io[Spring.bias], io[Spring.massScale], io[Spring.impulseScale]. Numbers travel in the array:
 * V8 boxes a number passed to a call it does not inline, one allocation per spring per step.
 * A hertz of 0 or less gives 0 and no spring (all three scales 0 but the impulse scale 1).
 */
export function softSpring(io: Float64Array): void {
  const hertz = io[Spring.hertz];
  const zeta = io[Spring.zeta];
  const h = io[Spring.h];
  let solved = 0;
  if (hertz > 0) {
    const most = SPRING_RATE / h;
    solved = most;
    if (hertz < most && hertz * h < 1 / 6) {
      // sin(pi f h) by its series, for angles below pi / 6 exact to rounding, spelled out rather
      // than called: a call V8 does not inline boxes its argument, an allocation per spring.
      const t = Math.PI * hertz * h;
      const t2 = t * t;
      const half = t * (1 - (t2 / 6) * (1 - (t2 / 20) * (1 - (t2 / 42) * (1 - (t2 / 72) * (1 - (t2 / 110) * (1 - (t2 / 156) * (1 - t2 / 210)))))));
      const hw = (2 * half) / Math.sqrt(1 - 4 * half * half);
      const warped = hw / (2 * Math.PI * h);
      if (warped < most) solved = warped;
    }
  }
  const kept = KEPT_TURN / h;
  const solvedZeta = solved > 0 ? (zeta * (hertz < kept ? hertz : kept)) / solved : zeta;
  io[Spring.solvedHertz] = solved;
  io[Spring.solvedZeta] = solvedZeta;
  const omega = 2 * Math.PI * solved;
  const a1 = 2 * solvedZeta + h * omega;
  const a2 = h * omega * a1;
  const a3 = 1 / (1 + a2);
  io[Spring.bias] = a1 > 0 ? omega / a1 : 0;
  io[Spring.massScale] = a2 * a3;
  io[Spring.impulseScale] = a3;
}
