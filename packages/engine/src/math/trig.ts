/**
 * Cosine, sine and atan2 from +, -, *, / and sqrt alone, which JavaScript rounds correctly, so
 * every runtime gives the same bits (the language leaves Math.sin and Math.atan2 to each engine).
 * Rotations are (cos, sin) pairs; these turn a user's angle into a rotation and back, and `turn`
 * advances a rotation by a step's angle.
 *
 * Accuracy: within a few units in the last place while |angle| < 2^20 pi/2 (about 1.6e6 radians),
 * where the reduction by pi/2 is exact; beyond that the error grows as |angle| x 1e-16, and the
 * result stays deterministic.
 */

// pi/2 split into three parts whose products with an integer below 2^20 are exact.
const HALF_PI_1 = 1.5707963267341256;
const HALF_PI_2 = 6.077100506303966e-11;
const HALF_PI_3 = 2.0222662487959506e-21;
const TWO_OVER_PI = 0.6366197723675814;

// Taylor coefficients 1/n!, with the sign of their term.
const S3 = -1 / 6;
const S5 = 1 / 120;
const S7 = -1 / 5040;
const S9 = 1 / 362880;
const S11 = -1 / 39916800;
const S13 = 1 / 6227020800;
const S15 = -1 / 1307674368000;
const S17 = 1 / 355687428096000;
const C2 = -1 / 2;
const C4 = 1 / 24;
const C6 = -1 / 720;
const C8 = 1 / 40320;
const C10 = -1 / 3628800;
const C12 = 1 / 479001600;
const C14 = -1 / 87178291200;
const C16 = 1 / 20922789888000;
const C18 = -1 / 6402373705728000;

/** sin(r) for |r| <= pi/4: the Taylor series to r^17, whose next term is below 1e-19. */
function sinKernel(r: number): number {
  const z = r * r;
  return r + r * z * (S3 + z * (S5 + z * (S7 + z * (S9 + z * (S11 + z * (S13 + z * (S15 + z * S17)))))));
}

/** cos(r) for |r| <= pi/4: the Taylor series to r^18. */
function cosKernel(r: number): number {
  const z = r * r;
  return 1 + z * (C2 + z * (C4 + z * (C6 + z * (C8 + z * (C10 + z * (C12 + z * (C14 + z * (C16 + z * C18))))))));
}

/** Beyond this the reduction by pi/2 below loses its exactness; larger angles are first taken modulo 2 pi. */
const EXACT_REDUCTION = 2 ** 20 * HALF_PI_1;
/** 2 pi as a double: `%` by it is exact (IEEE remainder), so the same bits everywhere. */
export const TWO_PI = 6.283185307179586;

/** Writes cos(angle) and sin(angle) into out[0], out[1]. */
export function cosSin(angle: number, out: Float64Array | number[]): void {
  // Huge angles (a spin of 1e100 over a step) first come into range, so the series below always
  // sees |r| <= pi/4 and gives a rotation of length 1; their sense of direction is lost anyway.
  if (!(Math.abs(angle) <= EXACT_REDUCTION)) angle = angle % TWO_PI;
  const k = Math.round(angle * TWO_OVER_PI);
  const r = angle - k * HALF_PI_1 - k * HALF_PI_2 - k * HALF_PI_3;
  const c = cosKernel(r);
  const s = sinKernel(r);
  // The quadrant, k mod 4 in [0, 4): |k| is at most 2^20 + 1 here, so the low two bits of its
  // 32-bit two's complement are exactly that, also for negative k. (`%` on a double compiles to a
  // call in V8, and a fast-spinning body's turn takes this path at every step.)
  const quadrant = (k | 0) & 3;
  if (quadrant === 0) {
    out[0] = c;
    out[1] = s;
  } else if (quadrant === 1) {
    out[0] = -s;
    out[1] = c;
  } else if (quadrant === 2) {
    out[0] = -c;
    out[1] = -s;
  } else {
    out[0] = s;
    out[1] = -c;
  }
}

const scratch = new Float64Array(2);

export function cos(angle: number): number {
  cosSin(angle, scratch);
  return scratch[0];
}

export function sin(angle: number): number {
  cosSin(angle, scratch);
  return scratch[1];
}

const QUARTER_PI = 0.7853981633974483;
const HALF_PI = 1.5707963267948966;
const PI = 3.141592653589793;
/** tan(pi/8) = sqrt(2) - 1. */
const TAN_EIGHTH_PI = 0.41421356237309503;

/** atan(t) for |t| <= 0.2: the alternating series to t^25, whose next term is below 1e-19. */
function atanKernel(t: number): number {
  const z = t * t;
  let sum = 0;
  for (let n = 25; n >= 3; n -= 2) sum = (n % 4 === 1 ? 1 : -1) / n + z * sum;
  return t + t * z * sum;
}

/** atan(t) for 0 <= t <= 1. */
function atanUnit(t: number): number {
  let base = 0;
  if (t > TAN_EIGHTH_PI) {
    // atan(t) = pi/4 + atan((t - 1) / (t + 1)), which lands in [-0.172, 0].
    base = QUARTER_PI;
    t = (t - 1) / (t + 1);
  }
  // atan(t) = 2 atan(t / (1 + sqrt(1 + t^2))) halves the argument's size: |t| <= 0.2 after it.
  const half = t / (1 + Math.sqrt(1 + t * t));
  return base + 2 * atanKernel(half);
}

/** The angle of (x, y) in [-pi, pi], as Math.atan2 defines it for finite inputs, signed zeros included. */
export function atan2(y: number, x: number): number {
  if (y === 0 && x === 0) return 1 / x < 0 ? (1 / y < 0 ? -PI : PI) : y;
  const ax = Math.abs(x);
  const ay = Math.abs(y);
  // atan of the smaller over the larger, then reflected into the right octant.
  let a = ay <= ax ? atanUnit(ay / ax) : HALF_PI - atanUnit(ax / ay);
  if (x < 0) a = PI - a;
  // The sign of y, -0 included, as Math.atan2 gives it (-pi just below the negative x axis).
  return y < 0 || 1 / y < 0 ? -a : a;
}

/**
 * atan2(io[at], io[at + 1]), that is of y then x, into io[at + 2]: atan2's arithmetic, the same
 * bits, written out in one function, for the step, which calls it without number arguments (V8
 * boxes the numbers a call passes or returns where it does not inline it).
 */
export function atan2Into(io: Float64Array, at: number): void {
  const y = io[at];
  const x = io[at + 1];
  if (y === 0 && x === 0) {
    io[at + 2] = 1 / x < 0 ? (1 / y < 0 ? -PI : PI) : y;
    return;
  }
  const ax = Math.abs(x);
  const ay = Math.abs(y);
  const under = ay <= ax;
  let t = under ? ay / ax : ax / ay;
  let base = 0;
  if (t > TAN_EIGHTH_PI) {
    base = QUARTER_PI;
    t = (t - 1) / (t + 1);
  }
  const half = t / (1 + Math.sqrt(1 + t * t));
  const z = half * half;
  let sum = 0;
  for (let n = 25; n >= 3; n -= 2) sum = (n % 4 === 1 ? 1 : -1) / n + z * sum;
  const unit = base + 2 * (half + half * z * sum);
  let a = under ? unit : HALF_PI - unit;
  if (x < 0) a = PI - a;
  io[at + 2] = y < 0 || 1 / y < 0 ? -a : a;
}

/**
 * The angle that names the same turn within [-pi, pi]: `angle` itself there (the same bits), and
 * otherwise atan2 of its cosine and sine. Constraints that subtract angles (a joint's reference
 * angle) rely on both terms lying within [-pi, pi], as one wrap of their difference does.
 */
export function wrapAngle(angle: number): number {
  if (Math.abs(angle) <= PI) return angle;
  cosSin(angle, scratch);
  return atan2(scratch[1], scratch[0]);
}

/**
 * The angle that names the same turn as `angle` and lies within pi of `near`: an angle followed
 * from one reading to the next across ±pi, which stays continuous while it turns less than pi
 * between readings. Whole steps of TWO_PI, so the same bits everywhere.
 */
export function nearestTurn(angle: number, near: number): number {
  return angle + TWO_PI * Math.round((near - angle) / TWO_PI);
}

/** Below this, `turn` sums the short series; its first omitted terms are below 1e-20 of the result. */
const SMALL_TURN = 0.125;

/**
 * Turns the rotation (c[i], s[i]) by the angle in angleIO[0] (an array, since V8 boxes a number
 * passed to a call it does not inline, one allocation per body and step) exactly: by cos(angle)
 * and sin(angle) from the short Taylor series (to angle^11 and angle^10) where |angle| < 1/8, as a
 * step's turn nearly always is, from cosSin's longer series within a quarter turn, and from cosSin
 * itself beyond. The product is renormalised by one Newton step towards 1/length
 * (1.5 - length^2/2), exact to round-off for a length within 1e-8 of 1, which round-off keeps it:
 * a rotation turned a million times stays a rotation, and costs no square root or division.
 */
export function turn(c: Float64Array, s: Float64Array, i: number, angleIO: Float64Array): void {
  const angle = angleIO[0];
  let ca: number;
  let sa: number;
  if (angle < SMALL_TURN && angle > -SMALL_TURN) {
    const z = angle * angle;
    sa = angle + angle * z * (S3 + z * (S5 + z * (S7 + z * (S9 + z * S11))));
    ca = 1 + z * (C2 + z * (C4 + z * (C6 + z * (C8 + z * C10))));
  } else {
    const quarters = angle * TWO_OVER_PI;
    if (quarters >= -0.5 && quarters < 0.5) {
      // Within a quarter turn cosSin rounds angle * 2 / pi to 0 and reduces by nothing: its series
      // of the angle itself, the same bits without the reduction and the call.
      ca = cosKernel(angle);
      sa = sinKernel(angle);
    } else {
      cosSin(angle, scratch);
      ca = scratch[0];
      sa = scratch[1];
    }
  }
  const c0 = c[i];
  const s0 = s[i];
  const c2 = c0 * ca - s0 * sa;
  const s2 = s0 * ca + c0 * sa;
  const f = 1.5 - 0.5 * (c2 * c2 + s2 * s2);
  c[i] = c2 * f;
  s[i] = s2 * f;
}
