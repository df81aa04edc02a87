/**
 * The elastic two-point problem of one manifold, solved as a block: normal impulses p0, p1 >= 0 at
 * its two points. `k00` and `k11` are the points' inverse effective masses along the normal, `k01`
 * their coupling, `b0` and `b1` (1 + e) times each point's normal speed u (negative when closing).
 * A point that takes an impulse leaves with -e u; one that takes none is left no faster towards
 * the other side than that (complementarity). Both points are tried, then each alone; where no
 * point approaches, none takes an impulse. The answer is written to out[0], out[1].
 *
 * Solved as a block so that a box meeting a face flat bounces flat instead of rocking: impulses
 * taken one point after the other would each see the turn the other gave.
 */
export function twoPointImpulses(k00: number, k11: number, k01: number, b0: number, b1: number, out: Float64Array): void {
  let p0 = 0;
  let p1 = 0;
  let solved = false;
  const det = k00 * k11 - k01 * k01;
  if (det > 1e-9 * k00 * k11) {
    const q0 = (-k11 * b0 + k01 * b1) / det;
    const q1 = (k01 * b0 - k00 * b1) / det;
    if (q0 >= 0 && q1 >= 0) {
      p0 = q0;
      p1 = q1;
      solved = true;
    }
  }
  // A released point's speed is checked with a tolerance for round-off: a flat face (or fixed
  // rotation) makes the two points move alike, and a target met to the last bit must count as met.
  const tolerance = 1e-9 * (Math.abs(b0) + Math.abs(b1));
  if (!solved && k00 > 0) {
    const q0 = -b0 / k00;
    if (q0 >= 0 && k01 * q0 + b1 >= -tolerance) {
      p0 = q0;
      solved = true;
    }
  }
  if (!solved && k11 > 0) {
    const q1 = -b1 / k11;
    if (q1 >= 0 && k01 * q1 + b0 >= -tolerance) p1 = q1;
  }
  out[0] = p0;
  out[1] = p1;
}
