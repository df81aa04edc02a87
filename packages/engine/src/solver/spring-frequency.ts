import { cos } from '../math/trig.js';

/**
 * The highest frequency a soft-constraint spring is solved at, as a fraction of the sub-step rate:
 * a quarter, 60 Hz at 60 Hz with 4 sub-steps, the bound Box2D v3 puts on its contacts' stiffness.
 * A lone spring is stable at any stiffness, but springs coupled in a lattice, solved one after
 * another, are not: a 6 x 6 jelly with shear springs settled up to 120 Hz there, gained energy
 * from about 150 Hz and reached the speed limit at 240.
 */
export const SPRING_RATE = 0.25;

/**
 * The frequency to solve a spring of `hertz` at over sub-steps of h, so that it oscillates at
 * `hertz`: the soft step's spring (Box2D v3's soft constraint, warm-started, then solved in the
 * biased pass and again in the relax pass) oscillates slower than the frequency it is given, by
 * about 18 (f h)^2 (-0.5 % at 4 Hz, -11 % at 20 Hz, at 60 Hz with 4 sub-steps). The frequency it
 * is solved at is raised until one sub-step of an undamped spring turns its oscillation by 2 pi
 * hertz h, as the exact motion does, up to SPRING_RATE / h: at 60 Hz with 4 sub-steps a spring
 * keeps its frequency up to about 33 Hz, and a stiffer one oscillates at about that. Damping keeps
 * Box2D's form. A pure function of its two numbers, from the engine's own cosine: the same bits
 * everywhere; the last few answers are kept, since every spring of a jelly asks the same.
 */
export function springHertz(hertz: number, h: number): number {
  if (!(hertz > 0)) return 0;
  const most = SPRING_RATE / h;
  if (!(hertz < most)) return most;
  // Below this the correction, about 18 (f h)^2, is under 2e-7 of the frequency, and the
  // cosines compared below, within 2e-7 of 1, would tell it less well than that.
  if (hertz * h < 1e-4) return hertz;
  for (let k = 0; k < CACHED; k++) {
    if (cachedHertz[k] === hertz && cachedStep[k] === h) return cachedAnswer[k];
  }
  const target = cos(2 * Math.PI * hertz * h);
  let answer = most;
  if (turnCosine(most, h) < target) {
    // The sub-step's turn grows with the frequency solved at: bisect between the two.
    let lo = hertz;
    let hi = most;
    for (let i = 0; i < 60; i++) {
      const mid = 0.5 * (lo + hi);
      if (turnCosine(mid, h) > target) lo = mid;
      else hi = mid;
    }
    answer = 0.5 * (lo + hi);
  }
  cachedHertz[next] = hertz;
  cachedStep[next] = h;
  cachedAnswer[next] = answer;
  next = (next + 1) % CACHED;
  return answer;
}

const CACHED = 8;
const cachedHertz = new Float64Array(CACHED).fill(-1);
const cachedStep = new Float64Array(CACHED).fill(-1);
const cachedAnswer = new Float64Array(CACHED);
let next = 0;

/** The sub-step map's columns, (x, v, u) for each unit start (see turnCosine). */
const columns = new Float64Array(9);

/**
 * The cosine of the angle one sub-step turns an undamped soft spring's oscillation by, solved at
 * `hertz`: the complex eigenvalues' of the sub-step's linear map on (stretch x, speed v, kept
 * impulse u, in speed), which is, with makeSoft's bias rate b, mass scale s and impulse scale k,
 *   warm start  v += u
 *   solve       d = -s (v + b x) - k u;  u += d;  v += d
 *   move        x += h v
 *   relax       d = -s (v + b x) - k u;  u += d;  v += d
 * Its characteristic cubic has one real root, within (-1, 1), and the complex pair, of modulus
 * sqrt(C) and real part -B / 2 once the real root is divided out; 2 where there is no pair.
 */
function turnCosine(hertz: number, h: number): number {
  const hw = 2 * Math.PI * hertz * h;
  const a2 = hw * hw;
  const a3 = 1 / (1 + a2);
  const bias = 1 / h;
  const scale = a2 * a3;
  const keep = a3;
  for (let c = 0; c < 3; c++) {
    let x = c === 0 ? 1 : 0;
    let v = c === 1 ? 1 : 0;
    let u = c === 2 ? 1 : 0;
    v += u;
    let d = -scale * (v + bias * x) - keep * u;
    u += d;
    v += d;
    x += h * v;
    d = -scale * (v + bias * x) - keep * u;
    u += d;
    v += d;
    columns[3 * c] = x;
    columns[3 * c + 1] = v;
    columns[3 * c + 2] = u;
  }
  // M[row][col] = columns[3 * col + row].
  const m00 = columns[0];
  const m10 = columns[1];
  const m20 = columns[2];
  const m01 = columns[3];
  const m11 = columns[4];
  const m21 = columns[5];
  const m02 = columns[6];
  const m12 = columns[7];
  const m22 = columns[8];
  const trace = m00 + m11 + m22;
  const minors = m00 * m11 - m01 * m10 + m00 * m22 - m02 * m20 + m11 * m22 - m12 * m21;
  const det = m00 * (m11 * m22 - m12 * m21) - m01 * (m10 * m22 - m12 * m20) + m02 * (m10 * m21 - m11 * m20);
  // The real root by bisection of lambda^3 - trace lambda^2 + minors lambda - det on [-1, 1].
  let lo = -1;
  let hi = 1;
  const atLo = ((lo - trace) * lo + minors) * lo - det;
  for (let i = 0; i < 80; i++) {
    const mid = 0.5 * (lo + hi);
    const atMid = ((mid - trace) * mid + minors) * mid - det;
    if (atMid === 0) {
      lo = hi = mid;
      break;
    }
    if (atMid < 0 === atLo < 0) lo = mid;
    else hi = mid;
  }
  const root = 0.5 * (lo + hi);
  const B = root - trace;
  const C = minors + root * B;
  if (!(C > 0) || B * B >= 4 * C) return 2;
  return -B / (2 * Math.sqrt(C));
}
