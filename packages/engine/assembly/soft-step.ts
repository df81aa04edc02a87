// The soft step's hot passes (src/solver/soft-step.ts: warmStart, solveContacts, relaxContacts),
// run on two constraints at once, one pair of 64-bit SIMD lanes; and its two body passes per
// sub-step. The constraints are stored in pairs, field by field, lane 0 beside lane 1; colours are
// padded to whole pairs, so the two constraints of a pair are of one colour and share no moving
// body, and solving them side by side gives each exactly the bits the TypeScript loop gives it
// one after the other. Every expression below keeps the TypeScript's order of operations. A lane
// without a second point (a one-point manifold's) keeps its old values through a select; a lane
// without a first point is an empty lane closing a colour (the contact list holds only manifolds
// with points), on the dummy body, so its first point's velocity updates need no select: a lane
// writes its bodies back only when they are dynamic, and the dummy never is.
//
// Clamps use f64x2.pmin and pmax (b < a ? b : a, a < b ? b : a), one x86 instruction each,
// where V8 spends eight on min and max to give NaN and -0 < +0 their IEEE meaning. They give the bits
// of the TypeScript's Math.min and Math.max here: no operand is NaN in a finite state, and no clamp
// meets a -0 against a +0: accumulated impulses start at +0 and stay at or above it, so a total is
// -0 only from two -0 terms, and a friction limit's ends are +0 and -0 only where the clamped
// value lands on them either way.
//
// One pair per iteration: two pairs interleaved, each line written once per pair so that their
// chains of dependent operations would overlap, measured slower in every pass, and about twice
// as slow in the warm start and solve of many pyramids' 58,000 lanes (docs/engine.md, Numbers).

export { pointDistanceWarmStart, pointDistanceSolve } from './point-distance-joints';

import { DPX, DPY, DQC, DQS, DYNAMIC, VX, VY, W, bodyAt, field, firsts, gather, put, seconds } from './lanes';

// Constraint field offsets in doubles, per lane pair: the TypeScript's offsets, each even, are
// 2 x the field's index, so a field of a pair is one v128.
const PAIR: i32 = 80;
const NX: i32 = 0;
const NY: i32 = 2;
const FRICTION: i32 = 4;
const RESTITUTION: i32 = 6;
const ROLLING: i32 = 8;
const ROLLING_IMPULSE: i32 = 10;
const ROLLING_MASS: i32 = 12;
const MA: i32 = 14;
const IA: i32 = 16;
const MB: i32 = 18;
const IB: i32 = 20;
const BIAS_RATE: i32 = 22;
const MASS_SCALE: i32 = 24;
const IMPULSE_SCALE: i32 = 26;
const POINTS: i32 = 28;
const P: i32 = 32;
const RAX: i32 = 0;
const RAY: i32 = 2;
const RBX: i32 = 4;
const RBY: i32 = 6;
const BASE_SEPARATION: i32 = 8;
const NORMAL_IMPULSE: i32 = 10;
const TANGENT_IMPULSE: i32 = 12;
const MAX_NORMAL_IMPULSE: i32 = 14;
const NORMAL_MASS: i32 = 16;
const TANGENT_MASS: i32 = 18;
const IMPACT_VELOCITY: i32 = 22;
const POINT: i32 = 24;

@inline function scatter(s: usize, lane: i32, vx: v128, vy: v128, w: v128): void {
  if (load<f64>(s + <usize>DYNAMIC) != 1) return;
  if (lane == 0) {
    v128.store(s + <usize>VX, firsts(vx, vy));
    store<f64>(s + <usize>W, f64x2.extract_lane(w, 0));
  } else {
    v128.store(s + <usize>VX, seconds(vx, vy));
    store<f64>(s + <usize>W, f64x2.extract_lane(w, 1));
  }
}

/** Lanes whose constraint has more than `p` points. */
@inline function hasPoint(c: usize, p: i32): v128 {
  return f64x2.gt(field(c, POINTS), f64x2.splat(<f64>p));
}

/** The largest impulse so far, and the approach speed at the first one (the moment of impact), for the lanes in `mask`. */
@inline function noteImpact(q: usize, mask: v128, total: v128, approach: v128, zero: v128): void {
  const most = field(q, MAX_NORMAL_IMPULSE);
  const grows = v128.and(mask, f64x2.gt(total, most));
  const first = v128.and(v128.and(grows, f64x2.eq(most, zero)), f64x2.lt(approach, zero));
  put(q, IMPACT_VELOCITY, v128.bitselect(approach, field(q, IMPACT_VELOCITY), first));
  put(q, MAX_NORMAL_IMPULSE, v128.bitselect(total, most, grows));
}

/**
 * The largest impulse so far alone, where neither lane of the pair bounces: the impact speed is read
 * by the restitution pass only, which skips constraints with restitution 0. (total and the
 * largest are never -0, so max picks what `total > most` would.)
 */
@inline function noteMost(q: usize, mask: v128, total: v128): void {
  const most = field(q, MAX_NORMAL_IMPULSE);
  put(q, MAX_NORMAL_IMPULSE, v128.bitselect(f64x2.pmax(total, most), most, mask));
}

/**
 * The relative velocity along (dx, dy) at a point with arms (rAx, rAy) and (rBx, rBy): B's
 * velocity there less A's.
 */
@inline function speedAlong(rAx: v128, rAy: v128, rBx: v128, rBy: v128, vAx: v128, vAy: v128, wA: v128, vBx: v128, vBy: v128, wB: v128, dx: v128, dy: v128): v128 {
  const dvx = f64x2.sub(f64x2.sub(vBx, f64x2.mul(wB, rBy)), f64x2.sub(vAx, f64x2.mul(wA, rAy)));
  const dvy = f64x2.sub(f64x2.add(vBy, f64x2.mul(wB, rBx)), f64x2.add(vAy, f64x2.mul(wA, rAx)));
  return f64x2.add(f64x2.mul(dvx, dx), f64x2.mul(dvy, dy));
}

/** The second point's normal speed at the given velocities. */
@inline function secondSpeed(c: usize, vAx: v128, vAy: v128, wA: v128, vBx: v128, vBy: v128, wB: v128, nx: v128, ny: v128): v128 {
  const second = c + (<usize>(P + POINT) << 3);
  return speedAlong(field(second, RAX), field(second, RAY), field(second, RBX), field(second, RBY), vAx, vAy, wA, vBx, vBy, wB, nx, ny);
}

/**
 * The separation of the point at q now: its separation at the step's start plus how its anchors
 * moved apart along the normal, the bodies having moved by (dpx, dpy) relative to each other and
 * turned by (qAc, qAs) and (qBc, qBs) since.
 */
@inline function separation(q: usize, rAx: v128, rAy: v128, rBx: v128, rBy: v128, dpx: v128, dpy: v128, qAc: v128, qAs: v128, qBc: v128, qBs: v128, nx: v128, ny: v128): v128 {
  const dsx = f64x2.sub(f64x2.add(dpx, f64x2.sub(f64x2.mul(qBc, rBx), f64x2.mul(qBs, rBy))), f64x2.sub(f64x2.mul(qAc, rAx), f64x2.mul(qAs, rAy)));
  const dsy = f64x2.sub(f64x2.add(dpy, f64x2.add(f64x2.mul(qBs, rBx), f64x2.mul(qBc, rBy))), f64x2.add(f64x2.mul(qAs, rAx), f64x2.mul(qAc, rAy)));
  return f64x2.add(f64x2.add(field(q, BASE_SEPARATION), f64x2.mul(dsx, nx)), f64x2.mul(dsy, ny));
}

export function warmStart(states: usize, constraints: usize, pairs: usize, lanes: i32): void {
  for (let b = 0; b < lanes >> 1; b++) {
    const c = constraints + (<usize>(b * PAIR) << 3);
    const ix = pairs + (<usize>b << 4);
    const sa0 = bodyAt(states, load<i32>(ix));
    const sb0 = bodyAt(states, load<i32>(ix, 4));
    const sa1 = bodyAt(states, load<i32>(ix, 8));
    const sb1 = bodyAt(states, load<i32>(ix, 12));
    const mA = field(c, MA);
    const iA = field(c, IA);
    const mB = field(c, MB);
    const iB = field(c, IB);
    const nx = field(c, NX);
    const ny = field(c, NY);
    const a00 = v128.load(sa0);
    const a01 = v128.load(sa1);
    const b00 = v128.load(sb0);
    const b01 = v128.load(sb1);
    let vAx = firsts(a00, a01);
    let vAy = seconds(a00, a01);
    let wA = gather(sa0, sa1, W);
    let vBx = firsts(b00, b01);
    let vBy = seconds(b00, b01);
    let wB = gather(sb0, sb1, W);
    {
      const mask = hasPoint(c, 0);
      const q = c + (<usize>P << 3);
      const rAx = field(q, RAX);
      const rAy = field(q, RAY);
      const rBx = field(q, RBX);
      const rBy = field(q, RBY);
      const pn = field(q, NORMAL_IMPULSE);
      const pt = field(q, TANGENT_IMPULSE);
      const px = f64x2.add(f64x2.mul(pn, nx), f64x2.mul(pt, ny));
      const py = f64x2.sub(f64x2.mul(pn, ny), f64x2.mul(pt, nx));
      vAx = f64x2.sub(vAx, f64x2.mul(mA, px));
      vAy = f64x2.sub(vAy, f64x2.mul(mA, py));
      wA = f64x2.sub(wA, f64x2.mul(iA, f64x2.sub(f64x2.mul(rAx, py), f64x2.mul(rAy, px))));
      vBx = f64x2.add(vBx, f64x2.mul(mB, px));
      vBy = f64x2.add(vBy, f64x2.mul(mB, py));
      wB = f64x2.add(wB, f64x2.mul(iB, f64x2.sub(f64x2.mul(rBx, py), f64x2.mul(rBy, px))));
    }
    if (v128.any_true(hasPoint(c, 1))) {
      const mask = hasPoint(c, 1);
      const q = c + (<usize>(P + POINT) << 3);
      const rAx = field(q, RAX);
      const rAy = field(q, RAY);
      const rBx = field(q, RBX);
      const rBy = field(q, RBY);
      const pn = field(q, NORMAL_IMPULSE);
      const pt = field(q, TANGENT_IMPULSE);
      const px = f64x2.add(f64x2.mul(pn, nx), f64x2.mul(pt, ny));
      const py = f64x2.sub(f64x2.mul(pn, ny), f64x2.mul(pt, nx));
      vAx = v128.bitselect(f64x2.sub(vAx, f64x2.mul(mA, px)), vAx, mask);
      vAy = v128.bitselect(f64x2.sub(vAy, f64x2.mul(mA, py)), vAy, mask);
      wA = v128.bitselect(f64x2.sub(wA, f64x2.mul(iA, f64x2.sub(f64x2.mul(rAx, py), f64x2.mul(rAy, px)))), wA, mask);
      vBx = v128.bitselect(f64x2.add(vBx, f64x2.mul(mB, px)), vBx, mask);
      vBy = v128.bitselect(f64x2.add(vBy, f64x2.mul(mB, py)), vBy, mask);
      wB = v128.bitselect(f64x2.add(wB, f64x2.mul(iB, f64x2.sub(f64x2.mul(rBx, py), f64x2.mul(rBy, px)))), wB, mask);
    }
    const rolling = field(c, ROLLING_IMPULSE);
    wA = f64x2.sub(wA, f64x2.mul(iA, rolling));
    wB = f64x2.add(wB, f64x2.mul(iB, rolling));
    scatter(sa0, 0, vAx, vAy, wA);
    scatter(sb0, 0, vBx, vBy, wB);
    scatter(sa1, 1, vAx, vAy, wA);
    scatter(sb1, 1, vBx, vBy, wB);
  }
}

export function solve(states: usize, constraints: usize, pairs: usize, lanes: i32, inverseH: f64, pushSpeed: f64, touchingGap: f64): void {
  const zero = f64x2.splat(0);
  const gap = f64x2.splat(touchingGap);
  const one = f64x2.splat(1);
  const invH = f64x2.splat(inverseH);
  const floor = f64x2.splat(-pushSpeed);
  for (let b = 0; b < lanes >> 1; b++) {
    const c = constraints + (<usize>(b * PAIR) << 3);
    const ix = pairs + (<usize>b << 4);
    const sa0 = bodyAt(states, load<i32>(ix));
    const sb0 = bodyAt(states, load<i32>(ix, 4));
    const sa1 = bodyAt(states, load<i32>(ix, 8));
    const sb1 = bodyAt(states, load<i32>(ix, 12));
    const mA = field(c, MA);
    const iA = field(c, IA);
    const mB = field(c, MB);
    const iB = field(c, IB);
    const a00 = v128.load(sa0);
    const a01 = v128.load(sa1);
    const a10 = v128.load(sa0, 16);
    const a11 = v128.load(sa1, 16);
    const a20 = v128.load(sa0, 32);
    const a21 = v128.load(sa1, 32);
    const b00 = v128.load(sb0);
    const b01 = v128.load(sb1);
    const b10 = v128.load(sb0, 16);
    const b11 = v128.load(sb1, 16);
    const b20 = v128.load(sb0, 32);
    const b21 = v128.load(sb1, 32);
    let vAx = firsts(a00, a01);
    let vAy = seconds(a00, a01);
    let wA = firsts(a10, a11);
    const qAc = seconds(a20, a21);
    const qAs = gather(sa0, sa1, DQS);
    let vBx = firsts(b00, b01);
    let vBy = seconds(b00, b01);
    let wB = firsts(b10, b11);
    const qBc = seconds(b20, b21);
    const qBs = gather(sb0, sb1, DQS);
    const dpx = f64x2.sub(seconds(b10, b11), seconds(a10, a11));
    const dpy = f64x2.sub(firsts(b20, b21), firsts(a20, a21));
    const nx = field(c, NX);
    const ny = field(c, NY);
    const biasRate = field(c, BIAS_RATE);
    const softMassScale = field(c, MASS_SCALE);
    const softImpulseScale = field(c, IMPULSE_SCALE);
    const bouncy = v128.any_true(f64x2.gt(field(c, RESTITUTION), zero));
    // The second point's normal speed before this constraint's impulses, for noting its impact
    // (restitution only: see noteImpact).
    let before1 = zero;
    if (bouncy) before1 = secondSpeed(c, vAx, vAy, wA, vBx, vBy, wB, nx, ny);
    {
      const mask = hasPoint(c, 0);
      const q = c + (<usize>P << 3);
      const rAx = field(q, RAX);
      const rAy = field(q, RAY);
      const rBx = field(q, RBX);
      const rBy = field(q, RBY);
      const s = separation(q, rAx, rAy, rBx, rBy, dpx, dpy, qAc, qAs, qBc, qBs, nx, ny);
      const speculative = f64x2.gt(s, gap);
      const bias = v128.bitselect(f64x2.mul(s, invH), f64x2.pmax(f64x2.mul(f64x2.mul(biasRate, softMassScale), s), floor), speculative);
      const massScale = v128.bitselect(one, softMassScale, speculative);
      const impulseScale = v128.bitselect(zero, softImpulseScale, speculative);
      const vn = speedAlong(rAx, rAy, rBx, rBy, vAx, vAy, wA, vBx, vBy, wB, nx, ny);
      const accumulated = field(q, NORMAL_IMPULSE);
      const total = f64x2.pmax(f64x2.add(accumulated, f64x2.sub(f64x2.mul(f64x2.neg(field(q, NORMAL_MASS)), f64x2.add(f64x2.mul(massScale, vn), bias)), f64x2.mul(impulseScale, accumulated))), zero);
      const impulse = f64x2.sub(total, accumulated);
      put(q, NORMAL_IMPULSE, v128.bitselect(total, accumulated, mask));
      if (bouncy) noteImpact(q, mask, total, vn, zero); else noteMost(q, mask, total);
      const px = f64x2.mul(impulse, nx);
      const py = f64x2.mul(impulse, ny);
      vAx = f64x2.sub(vAx, f64x2.mul(mA, px));
      vAy = f64x2.sub(vAy, f64x2.mul(mA, py));
      wA = f64x2.sub(wA, f64x2.mul(iA, f64x2.sub(f64x2.mul(rAx, py), f64x2.mul(rAy, px))));
      vBx = f64x2.add(vBx, f64x2.mul(mB, px));
      vBy = f64x2.add(vBy, f64x2.mul(mB, py));
      wB = f64x2.add(wB, f64x2.mul(iB, f64x2.sub(f64x2.mul(rBx, py), f64x2.mul(rBy, px))));
    }
    if (v128.any_true(hasPoint(c, 1))) {
      const mask = hasPoint(c, 1);
      const q = c + (<usize>(P + POINT) << 3);
      const rAx = field(q, RAX);
      const rAy = field(q, RAY);
      const rBx = field(q, RBX);
      const rBy = field(q, RBY);
      const s = separation(q, rAx, rAy, rBx, rBy, dpx, dpy, qAc, qAs, qBc, qBs, nx, ny);
      const speculative = f64x2.gt(s, gap);
      const bias = v128.bitselect(f64x2.mul(s, invH), f64x2.pmax(f64x2.mul(f64x2.mul(biasRate, softMassScale), s), floor), speculative);
      const massScale = v128.bitselect(one, softMassScale, speculative);
      const impulseScale = v128.bitselect(zero, softImpulseScale, speculative);
      const vn = speedAlong(rAx, rAy, rBx, rBy, vAx, vAy, wA, vBx, vBy, wB, nx, ny);
      const accumulated = field(q, NORMAL_IMPULSE);
      const total = f64x2.pmax(f64x2.add(accumulated, f64x2.sub(f64x2.mul(f64x2.neg(field(q, NORMAL_MASS)), f64x2.add(f64x2.mul(massScale, vn), bias)), f64x2.mul(impulseScale, accumulated))), zero);
      const impulse = f64x2.sub(total, accumulated);
      put(q, NORMAL_IMPULSE, v128.bitselect(total, accumulated, mask));
      if (bouncy) noteImpact(q, mask, total, before1, zero); else noteMost(q, mask, total);
      const px = f64x2.mul(impulse, nx);
      const py = f64x2.mul(impulse, ny);
      vAx = v128.bitselect(f64x2.sub(vAx, f64x2.mul(mA, px)), vAx, mask);
      vAy = v128.bitselect(f64x2.sub(vAy, f64x2.mul(mA, py)), vAy, mask);
      wA = v128.bitselect(f64x2.sub(wA, f64x2.mul(iA, f64x2.sub(f64x2.mul(rAx, py), f64x2.mul(rAy, px)))), wA, mask);
      vBx = v128.bitselect(f64x2.add(vBx, f64x2.mul(mB, px)), vBx, mask);
      vBy = v128.bitselect(f64x2.add(vBy, f64x2.mul(mB, py)), vBy, mask);
      wB = v128.bitselect(f64x2.add(wB, f64x2.mul(iB, f64x2.sub(f64x2.mul(rBx, py), f64x2.mul(rBy, px)))), wB, mask);
    }
    scatter(sa0, 0, vAx, vAy, wA);
    scatter(sb0, 0, vBx, vBy, wB);
    scatter(sa1, 1, vAx, vAy, wA);
    scatter(sb1, 1, vBx, vBy, wB);
  }
}

export function relax(states: usize, constraints: usize, pairs: usize, lanes: i32, inverseH: f64): void {
  const zero = f64x2.splat(0);
  const invH = f64x2.splat(inverseH);
  for (let b = 0; b < lanes >> 1; b++) {
    const c = constraints + (<usize>(b * PAIR) << 3);
    const ix = pairs + (<usize>b << 4);
    const sa0 = bodyAt(states, load<i32>(ix));
    const sb0 = bodyAt(states, load<i32>(ix, 4));
    const sa1 = bodyAt(states, load<i32>(ix, 8));
    const sb1 = bodyAt(states, load<i32>(ix, 12));
    const mA = field(c, MA);
    const iA = field(c, IA);
    const mB = field(c, MB);
    const iB = field(c, IB);
    const a00 = v128.load(sa0);
    const a01 = v128.load(sa1);
    const a10 = v128.load(sa0, 16);
    const a11 = v128.load(sa1, 16);
    const a20 = v128.load(sa0, 32);
    const a21 = v128.load(sa1, 32);
    const b00 = v128.load(sb0);
    const b01 = v128.load(sb1);
    const b10 = v128.load(sb0, 16);
    const b11 = v128.load(sb1, 16);
    const b20 = v128.load(sb0, 32);
    const b21 = v128.load(sb1, 32);
    let vAx = firsts(a00, a01);
    let vAy = seconds(a00, a01);
    let wA = firsts(a10, a11);
    const qAc = seconds(a20, a21);
    const qAs = gather(sa0, sa1, DQS);
    let vBx = firsts(b00, b01);
    let vBy = seconds(b00, b01);
    let wB = firsts(b10, b11);
    const qBc = seconds(b20, b21);
    const qBs = gather(sb0, sb1, DQS);
    const dpx = f64x2.sub(seconds(b10, b11), seconds(a10, a11));
    const dpy = f64x2.sub(firsts(b20, b21), firsts(a20, a21));
    const nx = field(c, NX);
    const ny = field(c, NY);
    let totalNormalImpulse = zero;
    const bouncy = v128.any_true(f64x2.gt(field(c, RESTITUTION), zero));
    // The second point's normal speed before this constraint's impulses, for noting its impact
    // (restitution only: see noteImpact).
    let before1 = zero;
    if (bouncy) before1 = secondSpeed(c, vAx, vAy, wA, vBx, vBy, wB, nx, ny);
    {
      const mask = hasPoint(c, 0);
      const q = c + (<usize>P << 3);
      const rAx = field(q, RAX);
      const rAy = field(q, RAY);
      const rBx = field(q, RBX);
      const rBy = field(q, RBY);
      const s = separation(q, rAx, rAy, rBx, rBy, dpx, dpy, qAc, qAs, qBc, qBs, nx, ny);
      const bias = v128.bitselect(f64x2.mul(s, invH), zero, f64x2.gt(s, zero));
      const vn = speedAlong(rAx, rAy, rBx, rBy, vAx, vAy, wA, vBx, vBy, wB, nx, ny);
      const accumulated = field(q, NORMAL_IMPULSE);
      const total = f64x2.pmax(f64x2.add(accumulated, f64x2.mul(f64x2.neg(field(q, NORMAL_MASS)), f64x2.add(vn, bias))), zero);
      const impulse = f64x2.sub(total, accumulated);
      put(q, NORMAL_IMPULSE, v128.bitselect(total, accumulated, mask));
      if (bouncy) noteImpact(q, mask, total, vn, zero); else noteMost(q, mask, total);
      totalNormalImpulse = v128.bitselect(f64x2.add(totalNormalImpulse, total), totalNormalImpulse, mask);
      const px = f64x2.mul(impulse, nx);
      const py = f64x2.mul(impulse, ny);
      vAx = f64x2.sub(vAx, f64x2.mul(mA, px));
      vAy = f64x2.sub(vAy, f64x2.mul(mA, py));
      wA = f64x2.sub(wA, f64x2.mul(iA, f64x2.sub(f64x2.mul(rAx, py), f64x2.mul(rAy, px))));
      vBx = f64x2.add(vBx, f64x2.mul(mB, px));
      vBy = f64x2.add(vBy, f64x2.mul(mB, py));
      wB = f64x2.add(wB, f64x2.mul(iB, f64x2.sub(f64x2.mul(rBx, py), f64x2.mul(rBy, px))));
    }
    if (v128.any_true(hasPoint(c, 1))) {
      const mask = hasPoint(c, 1);
      const q = c + (<usize>(P + POINT) << 3);
      const rAx = field(q, RAX);
      const rAy = field(q, RAY);
      const rBx = field(q, RBX);
      const rBy = field(q, RBY);
      const s = separation(q, rAx, rAy, rBx, rBy, dpx, dpy, qAc, qAs, qBc, qBs, nx, ny);
      const bias = v128.bitselect(f64x2.mul(s, invH), zero, f64x2.gt(s, zero));
      const vn = speedAlong(rAx, rAy, rBx, rBy, vAx, vAy, wA, vBx, vBy, wB, nx, ny);
      const accumulated = field(q, NORMAL_IMPULSE);
      const total = f64x2.pmax(f64x2.add(accumulated, f64x2.mul(f64x2.neg(field(q, NORMAL_MASS)), f64x2.add(vn, bias))), zero);
      const impulse = f64x2.sub(total, accumulated);
      put(q, NORMAL_IMPULSE, v128.bitselect(total, accumulated, mask));
      if (bouncy) noteImpact(q, mask, total, before1, zero); else noteMost(q, mask, total);
      totalNormalImpulse = v128.bitselect(f64x2.add(totalNormalImpulse, total), totalNormalImpulse, mask);
      const px = f64x2.mul(impulse, nx);
      const py = f64x2.mul(impulse, ny);
      vAx = v128.bitselect(f64x2.sub(vAx, f64x2.mul(mA, px)), vAx, mask);
      vAy = v128.bitselect(f64x2.sub(vAy, f64x2.mul(mA, py)), vAy, mask);
      wA = v128.bitselect(f64x2.sub(wA, f64x2.mul(iA, f64x2.sub(f64x2.mul(rAx, py), f64x2.mul(rAy, px)))), wA, mask);
      vBx = v128.bitselect(f64x2.add(vBx, f64x2.mul(mB, px)), vBx, mask);
      vBy = v128.bitselect(f64x2.add(vBy, f64x2.mul(mB, py)), vBy, mask);
      wB = v128.bitselect(f64x2.add(wB, f64x2.mul(iB, f64x2.sub(f64x2.mul(rBx, py), f64x2.mul(rBy, px)))), wB, mask);
    }
    const friction = field(c, FRICTION);
    const tx = ny;
    const ty = f64x2.neg(nx);
    {
      const mask = hasPoint(c, 0);
      const q = c + (<usize>P << 3);
      const rAx = field(q, RAX);
      const rAy = field(q, RAY);
      const rBx = field(q, RBX);
      const rBy = field(q, RBY);
      const vt = speedAlong(rAx, rAy, rBx, rBy, vAx, vAy, wA, vBx, vBy, wB, tx, ty);
      const accumulated = field(q, TANGENT_IMPULSE);
      const limit = f64x2.mul(friction, field(q, NORMAL_IMPULSE));
      const total = f64x2.pmax(f64x2.pmin(f64x2.sub(accumulated, f64x2.mul(field(q, TANGENT_MASS), vt)), limit), f64x2.neg(limit));
      const impulse = f64x2.sub(total, accumulated);
      put(q, TANGENT_IMPULSE, v128.bitselect(total, accumulated, mask));
      const px = f64x2.mul(impulse, tx);
      const py = f64x2.mul(impulse, ty);
      vAx = f64x2.sub(vAx, f64x2.mul(mA, px));
      vAy = f64x2.sub(vAy, f64x2.mul(mA, py));
      wA = f64x2.sub(wA, f64x2.mul(iA, f64x2.sub(f64x2.mul(rAx, py), f64x2.mul(rAy, px))));
      vBx = f64x2.add(vBx, f64x2.mul(mB, px));
      vBy = f64x2.add(vBy, f64x2.mul(mB, py));
      wB = f64x2.add(wB, f64x2.mul(iB, f64x2.sub(f64x2.mul(rBx, py), f64x2.mul(rBy, px))));
    }
    if (v128.any_true(hasPoint(c, 1))) {
      const mask = hasPoint(c, 1);
      const q = c + (<usize>(P + POINT) << 3);
      const rAx = field(q, RAX);
      const rAy = field(q, RAY);
      const rBx = field(q, RBX);
      const rBy = field(q, RBY);
      const vt = speedAlong(rAx, rAy, rBx, rBy, vAx, vAy, wA, vBx, vBy, wB, tx, ty);
      const accumulated = field(q, TANGENT_IMPULSE);
      const limit = f64x2.mul(friction, field(q, NORMAL_IMPULSE));
      const total = f64x2.pmax(f64x2.pmin(f64x2.sub(accumulated, f64x2.mul(field(q, TANGENT_MASS), vt)), limit), f64x2.neg(limit));
      const impulse = f64x2.sub(total, accumulated);
      put(q, TANGENT_IMPULSE, v128.bitselect(total, accumulated, mask));
      const px = f64x2.mul(impulse, tx);
      const py = f64x2.mul(impulse, ty);
      vAx = v128.bitselect(f64x2.sub(vAx, f64x2.mul(mA, px)), vAx, mask);
      vAy = v128.bitselect(f64x2.sub(vAy, f64x2.mul(mA, py)), vAy, mask);
      wA = v128.bitselect(f64x2.sub(wA, f64x2.mul(iA, f64x2.sub(f64x2.mul(rAx, py), f64x2.mul(rAy, px)))), wA, mask);
      vBx = v128.bitselect(f64x2.add(vBx, f64x2.mul(mB, px)), vBx, mask);
      vBy = v128.bitselect(f64x2.add(vBy, f64x2.mul(mB, py)), vBy, mask);
      wB = v128.bitselect(f64x2.add(wB, f64x2.mul(iB, f64x2.sub(f64x2.mul(rBx, py), f64x2.mul(rBy, px)))), wB, mask);
    }
    const resistance = field(c, ROLLING);
    const rolls = f64x2.gt(resistance, zero);
    if (v128.any_true(rolls)) {
      const limit = f64x2.mul(resistance, totalNormalImpulse);
      const accumulated = field(c, ROLLING_IMPULSE);
      const total = f64x2.pmax(f64x2.pmin(f64x2.sub(accumulated, f64x2.mul(field(c, ROLLING_MASS), f64x2.sub(wB, wA))), limit), f64x2.neg(limit));
      const delta = f64x2.sub(total, accumulated);
      put(c, ROLLING_IMPULSE, v128.bitselect(total, accumulated, rolls));
      wA = v128.bitselect(f64x2.sub(wA, f64x2.mul(iA, delta)), wA, rolls);
      wB = v128.bitselect(f64x2.add(wB, f64x2.mul(iB, delta)), wB, rolls);
    }
    scatter(sa0, 0, vAx, vAy, wA);
    scatter(sb0, 0, vBx, vBy, wB);
    scatter(sa1, 1, vAx, vAy, wA);
    scatter(sb1, 1, vBx, vBy, wB);
  }
}

// The sub-steps' two body passes, over the moving bodies 1..n (body 0 is the world's dummy).

/**
 * Velocities for a sub-step where no body has forces, torques, damping or a gravity scale:
 * SoftStep.integrateVelocities with its factors of 1 and terms of 0, to the same bits: the
 * velocity plus (dvx, dvy) = h (0 + g), the spin plus 0.
 */
export function integrateVelocities(states: usize, n: i32, dvx: f64, dvy: f64): void {
  for (let k = 1; k <= n; k++) {
    const s = bodyAt(states, k);
    if (load<f64>(s + <usize>DYNAMIC) != 1) continue;
    store<f64>(s + <usize>VX, dvx + load<f64>(s + <usize>VX));
    store<f64>(s + <usize>VY, dvy + load<f64>(s + <usize>VY));
    store<f64>(s + <usize>W, 0.0 + load<f64>(s + <usize>W));
  }
}

/** SoftStep.integratePositions: speeds capped, then the motion since the step began advanced by h. */
export function integratePositions(states: usize, n: i32, h: f64, maxLinearSpeed: f64, maxAngular: f64): void {
  const maxSpeedSq = maxLinearSpeed * maxLinearSpeed;
  for (let k = 1; k <= n; k++) {
    const s = bodyAt(states, k);
    let vx = load<f64>(s + <usize>VX);
    let vy = load<f64>(s + <usize>VY);
    let w = load<f64>(s + <usize>W);
    const speedSq = vx * vx + vy * vy;
    if (speedSq > maxSpeedSq) {
      const ratio = maxLinearSpeed / Math.sqrt(speedSq);
      vx *= ratio;
      vy *= ratio;
    }
    if (w * w > maxAngular * maxAngular) w = w > 0 ? maxAngular : -maxAngular;
    store<f64>(s + <usize>VX, vx);
    store<f64>(s + <usize>VY, vy);
    store<f64>(s + <usize>W, w);
    store<f64>(s + <usize>DPX, load<f64>(s + <usize>DPX) + h * vx);
    store<f64>(s + <usize>DPY, load<f64>(s + <usize>DPY) + h * vy);
    const qc = load<f64>(s + <usize>DQC);
    const qs = load<f64>(s + <usize>DQS);
    const hw = h * w;
    const c2 = qc - hw * qs;
    const s2 = qs + hw * qc;
    const length = Math.sqrt(c2 * c2 + s2 * s2);
    const inverse = length > 0 ? 1 / length : 0;
    store<f64>(s + <usize>DQC, c2 * inverse);
    store<f64>(s + <usize>DQS, s2 * inverse);
  }
}
