// AssemblyScript source of the per-body WebAssembly kernel (compiled by scripts/build-kernel.mjs
// into src/generated/, loaded by src/store/body-kernel.ts and src/store/contact-sorter.ts). It
// runs the plain cases of the per-body and per-contact stages on the body columns, which BodyStore
// lays out in the imported memory: integration (no forces, damping, gravity scales or sleepers),
// the box walls, the narrow-phase, the contact solve (no events, no sleepers) and the canonical
// contact sort. Each function is its TypeScript counterpart operation for operation, so the
// results are the same bits; the TypeScript stays the general path.
//
// Why: these loops touch 4 to 7 columns per body, and in V8's optimized code each typed-array
// access re-checks its array's map, base and length, so the kernel runs integration and the walls
// in a fraction of the TypeScript loops' time and shortens the whole step (uniform scene, kernel
// on against off: docs/engine.md, Numbers).

// TypeCode in src/store/body-types.ts.
const KINEMATIC: u8 = 2;
const DYNAMIC: u8 = 3;
const MAX_BOUNCES = 16; // box-walls.ts

/**
 * limitSpeeds' scan (src/solver/speed-limit.ts): the first slot in [from, to) whose speed squared
 * is not at most maxSq (NaN included), or `to`. Its type is left to the caller, which caps from
 * there: a step's last stage reads two columns of every body, and here without the bounds checks.
 */
export function firstTooFast(vxs: usize, vys: usize, from: i32, to: i32, maxSq: f64): i32 {
  for (let i = from; i < to; i++) {
    const x = load<f64>(vxs + (<usize>i << 3));
    const y = load<f64>(vys + (<usize>i << 3));
    if (!(x * x + y * y <= maxSq)) return i;
  }
  return to;
}

/**
 * The plain loop of integrateSemiImplicitEuler, or with `explicit` of integrateExplicitEuler, over
 * slots [from, to).
 */
export function integrate(
  xs: usize, ys: usize, vxs: usize, vys: usize, types: usize, from: i32, to: i32, dvx: f64, dvy: f64, dt: f64, explicit: bool,
): void {
  for (let i = from; i < to; i++) advance(<usize>i << 3, load<u8>(types + <usize>i), xs, ys, vxs, vys, dvx, dvy, dt, explicit);
}

/** One body's step of `integrate` (byte offset `at`, type t); false for bodies that do not move. */
// @ts-ignore: decorator
@inline
function advance(at: usize, t: u8, xs: usize, ys: usize, vxs: usize, vys: usize, dvx: f64, dvy: f64, dt: f64, explicit: bool): bool {
  if (t == DYNAMIC) {
    const vx = load<f64>(vxs + at);
    const vy = load<f64>(vys + at);
    if (explicit) {
      // Position with the velocity from before the step, then velocity.
      store<f64>(xs + at, load<f64>(xs + at) + vx * dt);
      store<f64>(ys + at, load<f64>(ys + at) + vy * dt);
      store<f64>(vxs + at, vx + dvx);
      store<f64>(vys + at, vy + dvy);
    } else {
      const ux = vx + dvx;
      const uy = vy + dvy;
      store<f64>(vxs + at, ux);
      store<f64>(vys + at, uy);
      store<f64>(xs + at, load<f64>(xs + at) + ux * dt);
      store<f64>(ys + at, load<f64>(ys + at) + uy * dt);
    }
    return true;
  }
  if (t == KINEMATIC) {
    store<f64>(xs + at, load<f64>(xs + at) + load<f64>(vxs + at) * dt);
    store<f64>(ys + at, load<f64>(ys + at) + load<f64>(vys + at) * dt);
    return true;
  }
  return false;
}

// fold's results: a module global, not a boxed pair (AssemblyScript has no tuples).
let foldedV: f64 = 0;

/** bounceOffBox over slots [from, to). */
export function bounceOffBox(
  xs: usize, ys: usize, vxs: usize, vys: usize, rs: usize, es: usize, types: usize, from: i32, to: i32,
  width: f64, height: f64, wallRestitution: f64, restitutionThreshold: f64,
): void {
  for (let i = from; i < to; i++) {
    const t = load<u8>(types + <usize>i);
    if (t != DYNAMIC && t != KINEMATIC) continue;
    bounce(<usize>i << 3, t, xs, ys, vxs, vys, rs, es, width, height, wallRestitution, restitutionThreshold);
  }
}

/**
 * `integrate` then bounceOffBox, body by body in one pass over
 * the columns, for steps with nothing between the two stages (no continuous sweeps). Each body's
 * update reads only that body, so the result is the two passes' bits.
 * A body whose centre lies at least `maxRadius` (the largest radius of any body) from every wall
 * cannot touch one, so its radius is not read: most bodies are far from the walls, and skipping
 * that column's reads shortens this pass (measured at 1M bodies: docs/engine.md, Numbers).
 */
export function moveInBox(
  xs: usize, ys: usize, vxs: usize, vys: usize, rs: usize, es: usize, types: usize, from: i32, to: i32,
  dvx: f64, dvy: f64, dt: f64, explicit: bool,
  width: f64, height: f64, wallRestitution: f64, restitutionThreshold: f64, maxRadius: f64,
): void {
  // One loop per integrator (see moveRange), two bodies at a time where this build has SIMD.
  if (ASC_FEATURE_SIMD) {
    if (explicit) movePairs(xs, ys, vxs, vys, rs, es, types, from, to, dvx, dvy, dt, true, width, height, wallRestitution, restitutionThreshold, maxRadius);
    else movePairs(xs, ys, vxs, vys, rs, es, types, from, to, dvx, dvy, dt, false, width, height, wallRestitution, restitutionThreshold, maxRadius);
  } else {
    if (explicit) moveRange(xs, ys, vxs, vys, rs, es, types, from, to, dvx, dvy, dt, true, width, height, wallRestitution, restitutionThreshold, maxRadius);
    else moveRange(xs, ys, vxs, vys, rs, es, types, from, to, dvx, dvy, dt, false, width, height, wallRestitution, restitutionThreshold, maxRadius);
  }
}

/**
 * moveRange with 128-bit SIMD: two neighbouring dynamic bodies per instruction (each lane's
 * arithmetic is the scalar code's, so the bits are the same), their wall test in two lanes, and
 * the scalar code for a pair that is not two dynamic bodies or has a body near a wall. The
 * integration is a few instructions per body and the loop around it costs as much again in V8, so
 * halving the turns shortened this pass by two fifths at 64,000 bodies (docs/engine.md, Numbers).
 */
// @ts-ignore: decorator
@inline
function movePairs(
  xs: usize, ys: usize, vxs: usize, vys: usize, rs: usize, es: usize, types: usize, from: i32, to: i32,
  dvx: f64, dvy: f64, dt: f64, explicit: bool,
  width: f64, height: f64, wallRestitution: f64, restitutionThreshold: f64, maxRadius: f64,
): void {
  const right = width - maxRadius;
  const top = height - maxRadius;
  const dvx2 = f64x2.splat(dvx);
  const dvy2 = f64x2.splat(dvy);
  const dt2 = f64x2.splat(dt);
  const low2 = f64x2.splat(maxRadius);
  const right2 = f64x2.splat(right);
  const top2 = f64x2.splat(top);
  let i = from;
  for (; i + 1 < to; i += 2) {
    const at = <usize>i << 3;
    // Both bytes DYNAMIC (little-endian).
    if (load<u16>(types + <usize>i) != ((<u16>DYNAMIC << 8) | <u16>DYNAMIC)) {
      moveOne(i, xs, ys, vxs, vys, rs, es, types, dvx, dvy, dt, explicit, width, height, wallRestitution, restitutionThreshold, maxRadius, right, top);
      moveOne(i + 1, xs, ys, vxs, vys, rs, es, types, dvx, dvy, dt, explicit, width, height, wallRestitution, restitutionThreshold, maxRadius, right, top);
      continue;
    }
    const vx = v128.load(vxs + at);
    const vy = v128.load(vys + at);
    let x = v128.load(xs + at);
    let y = v128.load(ys + at);
    if (explicit) {
      x = f64x2.add(x, f64x2.mul(vx, dt2));
      y = f64x2.add(y, f64x2.mul(vy, dt2));
      v128.store(vxs + at, f64x2.add(vx, dvx2));
      v128.store(vys + at, f64x2.add(vy, dvy2));
    } else {
      const ux = f64x2.add(vx, dvx2);
      const uy = f64x2.add(vy, dvy2);
      v128.store(vxs + at, ux);
      v128.store(vys + at, uy);
      x = f64x2.add(x, f64x2.mul(ux, dt2));
      y = f64x2.add(y, f64x2.mul(uy, dt2));
    }
    v128.store(xs + at, x);
    v128.store(ys + at, y);
    const inside = v128.and(v128.and(f64x2.ge(x, low2), f64x2.le(x, right2)), v128.and(f64x2.ge(y, low2), f64x2.le(y, top2)));
    if (i64x2.all_true(inside)) continue;
    nearWall(at, xs, ys, vxs, vys, rs, es, width, height, wallRestitution, restitutionThreshold, maxRadius, right, top);
    nearWall(at + 8, xs, ys, vxs, vys, rs, es, width, height, wallRestitution, restitutionThreshold, maxRadius, right, top);
  }
  if (i < to) moveOne(i, xs, ys, vxs, vys, rs, es, types, dvx, dvy, dt, explicit, width, height, wallRestitution, restitutionThreshold, maxRadius, right, top);
}

/** moveRange's step for the body in slot i (see advance and bounce). */
// @ts-ignore: decorator
@inline
function moveOne(
  i: i32, xs: usize, ys: usize, vxs: usize, vys: usize, rs: usize, es: usize, types: usize,
  dvx: f64, dvy: f64, dt: f64, explicit: bool,
  width: f64, height: f64, wallRestitution: f64, restitutionThreshold: f64, maxRadius: f64, right: f64, top: f64,
): void {
  const t = load<u8>(types + <usize>i);
  const at = <usize>i << 3;
  if (advance(at, t, xs, ys, vxs, vys, dvx, dvy, dt, explicit)) {
    const x = load<f64>(xs + at);
    const y = load<f64>(ys + at);
    if (x >= maxRadius && x <= right && y >= maxRadius && y <= top) return;
    bounce(at, t, xs, ys, vxs, vys, rs, es, width, height, wallRestitution, restitutionThreshold);
  }
}

/** moveRange's wall test and bounce for a dynamic body just moved (byte offset `at`). */
function nearWall(
  at: usize, xs: usize, ys: usize, vxs: usize, vys: usize, rs: usize, es: usize,
  width: f64, height: f64, wallRestitution: f64, restitutionThreshold: f64, maxRadius: f64, right: f64, top: f64,
): void {
  const x = load<f64>(xs + at);
  const y = load<f64>(ys + at);
  if (x >= maxRadius && x <= right && y >= maxRadius && y <= top) return;
  bounce(at, DYNAMIC, xs, ys, vxs, vys, rs, es, width, height, wallRestitution, restitutionThreshold);
}

/**
 * moveInBox's loop, inlined with a constant `explicit`: V8 does not move a loop-invariant test out
 * of a WebAssembly loop. (Four bodies a turn, as the grid kernel's bin runs, made no difference here.)
 */
// @ts-ignore: decorator
@inline
function moveRange(
  xs: usize, ys: usize, vxs: usize, vys: usize, rs: usize, es: usize, types: usize, from: i32, to: i32,
  dvx: f64, dvy: f64, dt: f64, explicit: bool,
  width: f64, height: f64, wallRestitution: f64, restitutionThreshold: f64, maxRadius: f64,
): void {
  const right = width - maxRadius;
  const top = height - maxRadius;
  for (let i = from; i < to; i++) {
    moveOne(i, xs, ys, vxs, vys, rs, es, types, dvx, dvy, dt, explicit, width, height, wallRestitution, restitutionThreshold, maxRadius, right, top);
  }
}

/** The walls for the moving body at byte offset `at` (type t). */
// @ts-ignore: decorator
@inline
function bounce(
  at: usize, t: u8, xs: usize, ys: usize, vxs: usize, vys: usize, rs: usize, es: usize,
  width: f64, height: f64, wallRestitution: f64, restitutionThreshold: f64,
): void {
  const r = load<f64>(rs + at);
  bounceAxis(xs + at, vxs + at, r, width, t, es + at, wallRestitution, restitutionThreshold);
  bounceAxis(ys + at, vys + at, r, height, t, es + at, wallRestitution, restitutionThreshold);
}

/** One axis of `bounce`: the position at `p` and velocity at `v`, between r and extent - r. */
// @ts-ignore: decorator
@inline
function bounceAxis(p: usize, v: usize, r: f64, extent: f64, t: u8, e: usize, wallRestitution: f64, restitutionThreshold: f64): void {
  const position = load<f64>(p);
  if (position < r || position > extent - r) {
    const velocity = load<f64>(v);
    const restitution = t == DYNAMIC ? mix(load<f64>(e), wallRestitution) : 1.0;
    store<f64>(p, fold(position, velocity, r, extent - r, abs(velocity) < restitutionThreshold ? 0 : restitution));
    store<f64>(v, foldedV);
  }
}

/** restitution.ts `mixRestitution`, as a comparison (f64.max orders -0 and +0 differently). */
// @ts-ignore: decorator
@inline
function mix(a: f64, b: f64): f64 {
  return a > b ? a : b;
}

/** box-walls.ts `fold`: returns the position, leaves the velocity in foldedV. */
function fold(p: f64, v: f64, lo: f64, hi: f64, e: f64): f64 {
  for (let bounce = 0; bounce < MAX_BOUNCES; bounce++) {
    if (p < lo) p = lo + (lo - p) * e;
    else if (p > hi) p = hi - (p - hi) * e;
    else break;
    v = -v * e;
  }
  if (!(p >= lo && p <= hi)) {
    const span = hi - lo;
    if (!isFinite(p) || span <= 0) {
      p = lo + span / 2;
    } else {
      let u = (p - lo) % (2 * span);
      if (u < 0) u += 2 * span;
      if (u > span) {
        u = 2 * span - u;
        v = -v;
      }
      p = min(hi, max(lo, lo + u));
    }
  }
  foldedV = v;
  return p;
}

/**
 * solveContacts for `count` contacts whose lo and hi slots are at `los` and `his` (int32 each),
 * in that order: contact-solver.ts `resolveContact` without events or sleepers. With a box
 * (width > 0), each body that a contact's separation leaves outside it is written to `escapes`
 * (as EscapeLog.note does), so that the correct stage clamps those alone; returns how many.
 */
export function solveContacts(
  xs: usize, ys: usize, vxs: usize, vys: usize, rs: usize, invMasses: usize, es: usize,
  los: usize, his: usize, count: i32, restitutionThreshold: f64, positionCorrection: f64, contactSlop: f64,
  width: f64, height: f64, escapes: usize,
): i32 {
  let escaped: i32 = 0;
  for (let k = 0; k < count; k++) {
    const i = <usize>load<i32>(los + (<usize>k << 2)) << 3;
    const j = <usize>load<i32>(his + (<usize>k << 2)) << 3;
    const dx = load<f64>(xs + j) - load<f64>(xs + i);
    const dy = load<f64>(ys + j) - load<f64>(ys + i);
    const reach = load<f64>(rs + i) + load<f64>(rs + j);
    const distSq = dx * dx + dy * dy;
    if (distSq >= reach * reach) continue;
    const wi = load<f64>(invMasses + i);
    const wj = load<f64>(invMasses + j);
    const w = wi + wj;
    if (w == 0) continue;
    let nx: f64 = 1;
    let ny: f64 = 0;
    const dist = sqrt(distSq);
    if (dist > 0) {
      nx = dx / dist;
      ny = dy / dist;
    }
    const vn = (load<f64>(vxs + j) - load<f64>(vxs + i)) * nx + (load<f64>(vys + j) - load<f64>(vys + i)) * ny;
    if (vn < 0) {
      const e = -vn < restitutionThreshold ? 0 : mix(load<f64>(es + i), load<f64>(es + j));
      const impulse = (-(1 + e) * vn) / w;
      const pi = impulse * wi;
      const pj = impulse * wj;
      store<f64>(vxs + i, load<f64>(vxs + i) - pi * nx);
      store<f64>(vys + i, load<f64>(vys + i) - pi * ny);
      store<f64>(vxs + j, load<f64>(vxs + j) + pj * nx);
      store<f64>(vys + j, load<f64>(vys + j) + pj * ny);
    }
    const excess = reach - dist - contactSlop;
    if (excess > 0) {
      const push = excess * positionCorrection;
      const si = (push * wi) / w;
      const sj = (push * wj) / w;
      store<f64>(xs + i, load<f64>(xs + i) - si * nx);
      store<f64>(ys + i, load<f64>(ys + i) - si * ny);
      store<f64>(xs + j, load<f64>(xs + j) + sj * nx);
      store<f64>(ys + j, load<f64>(ys + j) + sj * ny);
    }
    if (width > 0) {
      if (outside(i, xs, ys, rs, width, height)) {
        store<i32>(escapes + (<usize>escaped << 2), <i32>(i >> 3));
        escaped++;
      }
      if (outside(j, xs, ys, rs, width, height)) {
        store<i32>(escapes + (<usize>escaped << 2), <i32>(j >> 3));
        escaped++;
      }
    }
  }
  return escaped;
}

/** box-walls.ts `outsideBox` for the body at byte offset `at`. */
// @ts-ignore: decorator
@inline
function outside(at: usize, xs: usize, ys: usize, rs: usize, width: f64, height: f64): bool {
  const r = load<f64>(rs + at);
  const px = load<f64>(xs + at);
  const py = load<f64>(ys + at);
  return px < r || px > width - r || py < r || py > height - r;
}

/**
 * ContactBuffer.sortCanonical on `count` (lo, hi) int32 pairs at lo and hi, with scratch of the
 * same size at tlo and thi: ascending (lo, hi) order, ending back in lo and hi. Few contacts per
 * slot: byte-wise LSD radix passes over the contacts (buckets: 256 int32). Many: two stable
 * counting passes keyed by slot (counts: slotCount + 1 int32). Pairs are unique, so the order is
 * the same whichever sort runs.
 */
export function sortContacts(lo: usize, hi: usize, tlo: usize, thi: usize, count: i32, slotCount: i32, counts: usize, buckets: usize): void {
  if (count < 2) return;
  if (<i64>count * 8 < <i64>slotCount) {
    let bytes = 1;
    while (bytes < 4 && slotCount > (1 << (8 * bytes))) bytes++;
    let srcLo = lo;
    let srcHi = hi;
    let dstLo = tlo;
    let dstHi = thi;
    for (let pass = 0; pass < 2 * bytes; pass++) {
      const keyIsHi = pass < bytes;
      const shift = 8 * (keyIsHi ? pass : pass - bytes);
      radixPass(keyIsHi ? srcHi : srcLo, shift, srcLo, srcHi, dstLo, dstHi, count, buckets);
      const tl = srcLo;
      srcLo = dstLo;
      dstLo = tl;
      const th = srcHi;
      srcHi = dstHi;
      dstHi = th;
    }
    return; // an even number of passes ends back in lo and hi
  }
  countingPass(hi, lo, hi, tlo, thi, count, slotCount, counts);
  countingPass(tlo, tlo, thi, lo, hi, count, slotCount, counts);
}

function radixPass(key: usize, shift: i32, srcLo: usize, srcHi: usize, dstLo: usize, dstHi: usize, count: i32, buckets: usize): void {
  memory.fill(buckets, 0, 256 << 2);
  for (let k = 0; k < count; k++) {
    const b = buckets + (<usize>((load<i32>(key + (<usize>k << 2)) >>> shift) & 255) << 2);
    store<i32>(b, load<i32>(b) + 1);
  }
  let sum = 0;
  for (let b = 0; b < 256; b++) {
    const at = buckets + (<usize>b << 2);
    const c = load<i32>(at);
    store<i32>(at, sum);
    sum += c;
  }
  for (let k = 0; k < count; k++) {
    const from = <usize>k << 2;
    const b = buckets + (<usize>((load<i32>(key + from) >>> shift) & 255) << 2);
    const to = <usize>load<i32>(b) << 2;
    store<i32>(b, load<i32>(b) + 1);
    store<i32>(dstLo + to, load<i32>(srcLo + from));
    store<i32>(dstHi + to, load<i32>(srcHi + from));
  }
}

function countingPass(key: usize, srcLo: usize, srcHi: usize, dstLo: usize, dstHi: usize, count: i32, slotCount: i32, counts: usize): void {
  memory.fill(counts, 0, (<usize>slotCount + 1) << 2);
  for (let k = 0; k < count; k++) {
    const c = counts + ((<usize>load<i32>(key + (<usize>k << 2)) + 1) << 2);
    store<i32>(c, load<i32>(c) + 1);
  }
  for (let s = 0; s < slotCount; s++) {
    const c = counts + ((<usize>s + 1) << 2);
    store<i32>(c, load<i32>(c) + load<i32>(c - 4));
  }
  for (let k = 0; k < count; k++) {
    const from = <usize>k << 2;
    const c = counts + (<usize>load<i32>(key + from) << 2);
    const to = <usize>load<i32>(c) << 2;
    store<i32>(c, load<i32>(c) + 1);
    store<i32>(dstLo + to, load<i32>(srcLo + from));
    store<i32>(dstHi + to, load<i32>(srcHi + from));
  }
}

// Pairs the last narrowPhase dropped by collision layers (NarrowPhase.filtered).
let filteredPairs: i32 = 0;

export function filtered(): i32 {
  return filteredPairs;
}

/**
 * NarrowPhase.consume for `count` candidate pairs (as[k], bs[k]): drops pairs with no awake
 * dynamic body, then pairs filtered by collision layers (counted), then writes each overlapping
 * pair as (lo, hi) at outLo/outHi; returns how many.
 */
export function narrowPhase(
  xs: usize, ys: usize, rs: usize, types: usize, asleeps: usize, categories: usize, masks: usize,
  as: usize, bs: usize, count: i32, outLo: usize, outHi: usize,
): i32 {
  let found: i32 = 0;
  let filteredHere: i32 = 0;
  for (let k = 0; k < count; k++) {
    const i = <usize>load<i32>(as + (<usize>k << 2));
    const j = <usize>load<i32>(bs + (<usize>k << 2));
    const ti = load<u8>(types + i);
    const tj = load<u8>(types + j);
    const movingI = ti == KINEMATIC || (ti == DYNAMIC && load<u8>(asleeps + i) == 0);
    const movingJ = tj == KINEMATIC || (tj == DYNAMIC && load<u8>(asleeps + j) == 0);
    if (!(movingI || movingJ)) continue;
    if (ti != DYNAMIC && tj != DYNAMIC) continue;
    if ((load<u32>(categories + (i << 2)) & load<u32>(masks + (j << 2))) == 0 || (load<u32>(categories + (j << 2)) & load<u32>(masks + (i << 2))) == 0) {
      filteredHere++;
      continue;
    }
    // circle-circle.ts circlesOverlap.
    const dx = load<f64>(xs + (j << 3)) - load<f64>(xs + (i << 3));
    const dy = load<f64>(ys + (j << 3)) - load<f64>(ys + (i << 3));
    const reach = load<f64>(rs + (i << 3)) + load<f64>(rs + (j << 3));
    if (dx * dx + dy * dy < reach * reach) {
      const at = <usize>found << 2;
      store<i32>(outLo + at, <i32>(i < j ? i : j));
      store<i32>(outHi + at, <i32>(i < j ? j : i));
      found++;
    }
  }
  filteredPairs = filteredHere;
  return found;
}
