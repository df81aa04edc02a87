// The soft step's hot passes (src/solver/soft-step.ts: warmStart, solveContacts, relaxContacts),
// run on four constraints at once: two pairs of 64-bit SIMD lanes; and its two body passes per
// sub-step. The constraints are stored in pairs, field by field, lane 0 beside lane 1; colours are
// padded to whole quads (two pairs), so the four constraints of a quad are of one colour and share
// no moving body, and solving them side by side gives each exactly the bits the TypeScript loop
// gives it one after the other. Every expression below keeps the TypeScript's order of
// operations; a lane without a point (a one-point manifold's second, or an empty lane closing a
// colour) keeps its old values through a select, and a lane writes its bodies back only when they
// are dynamic.
//
// Why two pairs per iteration (X and Y below, each line written once per pair): a constraint's
// points are solved one after the other, each through a chain of some twenty dependent
// operations, and one pair alone left the processor waiting on that chain (about 24 ns a
// constraint for the solve); the two chains interleaved keep it busy.

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
 * The largest impulse so far alone, where no lane of the quad bounces: the impact speed is read
 * by the restitution pass only, which skips constraints with restitution 0. (total and the
 * largest are never -0, so max picks what `total > most` would.)
 */
@inline function noteMost(q: usize, mask: v128, total: v128): void {
  const most = field(q, MAX_NORMAL_IMPULSE);
  put(q, MAX_NORMAL_IMPULSE, v128.bitselect(f64x2.max(total, most), most, mask));
}

/** The second point's normal speed at the given velocities. */
@inline function secondSpeed(c: usize, vAx: v128, vAy: v128, wA: v128, vBx: v128, vBy: v128, wB: v128, nx: v128, ny: v128): v128 {
  const second = c + (<usize>(P + POINT) << 3);
  return f64x2.add(
    f64x2.mul(f64x2.sub(f64x2.sub(vBx, f64x2.mul(wB, field(second, RBY))), f64x2.sub(vAx, f64x2.mul(wA, field(second, RAY)))), nx),
    f64x2.mul(f64x2.sub(f64x2.add(vBy, f64x2.mul(wB, field(second, RBX))), f64x2.add(vAy, f64x2.mul(wA, field(second, RAX)))), ny),
  );
}

export function warmStart(states: usize, constraints: usize, pairs: usize, lanes: i32): void {
  for (let b = 0; b < lanes >> 1; b += 2) {
    const cX = constraints + (<usize>((b + 0) * PAIR) << 3);
    const cY = constraints + (<usize>((b + 1) * PAIR) << 3);
    const ixX = pairs + (<usize>(b + 0) << 4);
    const ixY = pairs + (<usize>(b + 1) << 4);
    const sa0X = bodyAt(states, load<i32>(ixX));
    const sa0Y = bodyAt(states, load<i32>(ixY));
    const sb0X = bodyAt(states, load<i32>(ixX, 4));
    const sb0Y = bodyAt(states, load<i32>(ixY, 4));
    const sa1X = bodyAt(states, load<i32>(ixX, 8));
    const sa1Y = bodyAt(states, load<i32>(ixY, 8));
    const sb1X = bodyAt(states, load<i32>(ixX, 12));
    const sb1Y = bodyAt(states, load<i32>(ixY, 12));
    const mAX = field(cX, MA);
    const mAY = field(cY, MA);
    const iAX = field(cX, IA);
    const iAY = field(cY, IA);
    const mBX = field(cX, MB);
    const mBY = field(cY, MB);
    const iBX = field(cX, IB);
    const iBY = field(cY, IB);
    const nxX = field(cX, NX);
    const nxY = field(cY, NX);
    const nyX = field(cX, NY);
    const nyY = field(cY, NY);
    const a00X = v128.load(sa0X);
    const a00Y = v128.load(sa0Y);
    const a01X = v128.load(sa1X);
    const a01Y = v128.load(sa1Y);
    const b00X = v128.load(sb0X);
    const b00Y = v128.load(sb0Y);
    const b01X = v128.load(sb1X);
    const b01Y = v128.load(sb1Y);
    let vAxX = firsts(a00X, a01X);
    let vAxY = firsts(a00Y, a01Y);
    let vAyX = seconds(a00X, a01X);
    let vAyY = seconds(a00Y, a01Y);
    let wAX = gather(sa0X, sa1X, W);
    let wAY = gather(sa0Y, sa1Y, W);
    let vBxX = firsts(b00X, b01X);
    let vBxY = firsts(b00Y, b01Y);
    let vByX = seconds(b00X, b01X);
    let vByY = seconds(b00Y, b01Y);
    let wBX = gather(sb0X, sb1X, W);
    let wBY = gather(sb0Y, sb1Y, W);
    {
      const maskX = hasPoint(cX, 0);
      const maskY = hasPoint(cY, 0);
      const qX = cX + (<usize>P << 3);
      const qY = cY + (<usize>P << 3);
      const rAxX = field(qX, RAX);
      const rAxY = field(qY, RAX);
      const rAyX = field(qX, RAY);
      const rAyY = field(qY, RAY);
      const rBxX = field(qX, RBX);
      const rBxY = field(qY, RBX);
      const rByX = field(qX, RBY);
      const rByY = field(qY, RBY);
      const pnX = field(qX, NORMAL_IMPULSE);
      const pnY = field(qY, NORMAL_IMPULSE);
      const ptX = field(qX, TANGENT_IMPULSE);
      const ptY = field(qY, TANGENT_IMPULSE);
      const pxX = f64x2.add(f64x2.mul(pnX, nxX), f64x2.mul(ptX, nyX));
      const pxY = f64x2.add(f64x2.mul(pnY, nxY), f64x2.mul(ptY, nyY));
      const pyX = f64x2.sub(f64x2.mul(pnX, nyX), f64x2.mul(ptX, nxX));
      const pyY = f64x2.sub(f64x2.mul(pnY, nyY), f64x2.mul(ptY, nxY));
      vAxX = v128.bitselect(f64x2.sub(vAxX, f64x2.mul(mAX, pxX)), vAxX, maskX);
      vAxY = v128.bitselect(f64x2.sub(vAxY, f64x2.mul(mAY, pxY)), vAxY, maskY);
      vAyX = v128.bitselect(f64x2.sub(vAyX, f64x2.mul(mAX, pyX)), vAyX, maskX);
      vAyY = v128.bitselect(f64x2.sub(vAyY, f64x2.mul(mAY, pyY)), vAyY, maskY);
      wAX = v128.bitselect(f64x2.sub(wAX, f64x2.mul(iAX, f64x2.sub(f64x2.mul(rAxX, pyX), f64x2.mul(rAyX, pxX)))), wAX, maskX);
      wAY = v128.bitselect(f64x2.sub(wAY, f64x2.mul(iAY, f64x2.sub(f64x2.mul(rAxY, pyY), f64x2.mul(rAyY, pxY)))), wAY, maskY);
      vBxX = v128.bitselect(f64x2.add(vBxX, f64x2.mul(mBX, pxX)), vBxX, maskX);
      vBxY = v128.bitselect(f64x2.add(vBxY, f64x2.mul(mBY, pxY)), vBxY, maskY);
      vByX = v128.bitselect(f64x2.add(vByX, f64x2.mul(mBX, pyX)), vByX, maskX);
      vByY = v128.bitselect(f64x2.add(vByY, f64x2.mul(mBY, pyY)), vByY, maskY);
      wBX = v128.bitselect(f64x2.add(wBX, f64x2.mul(iBX, f64x2.sub(f64x2.mul(rBxX, pyX), f64x2.mul(rByX, pxX)))), wBX, maskX);
      wBY = v128.bitselect(f64x2.add(wBY, f64x2.mul(iBY, f64x2.sub(f64x2.mul(rBxY, pyY), f64x2.mul(rByY, pxY)))), wBY, maskY);
    }
    if (v128.any_true(v128.or(hasPoint(cX, 1), hasPoint(cY, 1)))) {
      const maskX = hasPoint(cX, 1);
      const maskY = hasPoint(cY, 1);
      const qX = cX + (<usize>(P + POINT) << 3);
      const qY = cY + (<usize>(P + POINT) << 3);
      const rAxX = field(qX, RAX);
      const rAxY = field(qY, RAX);
      const rAyX = field(qX, RAY);
      const rAyY = field(qY, RAY);
      const rBxX = field(qX, RBX);
      const rBxY = field(qY, RBX);
      const rByX = field(qX, RBY);
      const rByY = field(qY, RBY);
      const pnX = field(qX, NORMAL_IMPULSE);
      const pnY = field(qY, NORMAL_IMPULSE);
      const ptX = field(qX, TANGENT_IMPULSE);
      const ptY = field(qY, TANGENT_IMPULSE);
      const pxX = f64x2.add(f64x2.mul(pnX, nxX), f64x2.mul(ptX, nyX));
      const pxY = f64x2.add(f64x2.mul(pnY, nxY), f64x2.mul(ptY, nyY));
      const pyX = f64x2.sub(f64x2.mul(pnX, nyX), f64x2.mul(ptX, nxX));
      const pyY = f64x2.sub(f64x2.mul(pnY, nyY), f64x2.mul(ptY, nxY));
      vAxX = v128.bitselect(f64x2.sub(vAxX, f64x2.mul(mAX, pxX)), vAxX, maskX);
      vAxY = v128.bitselect(f64x2.sub(vAxY, f64x2.mul(mAY, pxY)), vAxY, maskY);
      vAyX = v128.bitselect(f64x2.sub(vAyX, f64x2.mul(mAX, pyX)), vAyX, maskX);
      vAyY = v128.bitselect(f64x2.sub(vAyY, f64x2.mul(mAY, pyY)), vAyY, maskY);
      wAX = v128.bitselect(f64x2.sub(wAX, f64x2.mul(iAX, f64x2.sub(f64x2.mul(rAxX, pyX), f64x2.mul(rAyX, pxX)))), wAX, maskX);
      wAY = v128.bitselect(f64x2.sub(wAY, f64x2.mul(iAY, f64x2.sub(f64x2.mul(rAxY, pyY), f64x2.mul(rAyY, pxY)))), wAY, maskY);
      vBxX = v128.bitselect(f64x2.add(vBxX, f64x2.mul(mBX, pxX)), vBxX, maskX);
      vBxY = v128.bitselect(f64x2.add(vBxY, f64x2.mul(mBY, pxY)), vBxY, maskY);
      vByX = v128.bitselect(f64x2.add(vByX, f64x2.mul(mBX, pyX)), vByX, maskX);
      vByY = v128.bitselect(f64x2.add(vByY, f64x2.mul(mBY, pyY)), vByY, maskY);
      wBX = v128.bitselect(f64x2.add(wBX, f64x2.mul(iBX, f64x2.sub(f64x2.mul(rBxX, pyX), f64x2.mul(rByX, pxX)))), wBX, maskX);
      wBY = v128.bitselect(f64x2.add(wBY, f64x2.mul(iBY, f64x2.sub(f64x2.mul(rBxY, pyY), f64x2.mul(rByY, pxY)))), wBY, maskY);
    }
    const rollingX = field(cX, ROLLING_IMPULSE);
    const rollingY = field(cY, ROLLING_IMPULSE);
    wAX = f64x2.sub(wAX, f64x2.mul(iAX, rollingX));
    wAY = f64x2.sub(wAY, f64x2.mul(iAY, rollingY));
    wBX = f64x2.add(wBX, f64x2.mul(iBX, rollingX));
    wBY = f64x2.add(wBY, f64x2.mul(iBY, rollingY));
    scatter(sa0X, 0, vAxX, vAyX, wAX);
    scatter(sa0Y, 0, vAxY, vAyY, wAY);
    scatter(sb0X, 0, vBxX, vByX, wBX);
    scatter(sb0Y, 0, vBxY, vByY, wBY);
    scatter(sa1X, 1, vAxX, vAyX, wAX);
    scatter(sa1Y, 1, vAxY, vAyY, wAY);
    scatter(sb1X, 1, vBxX, vByX, wBX);
    scatter(sb1Y, 1, vBxY, vByY, wBY);
  }
}

export function solve(states: usize, constraints: usize, pairs: usize, lanes: i32, inverseH: f64, pushSpeed: f64): void {
  const zero = f64x2.splat(0);
  const one = f64x2.splat(1);
  const invH = f64x2.splat(inverseH);
  const floor = f64x2.splat(-pushSpeed);
  for (let b = 0; b < lanes >> 1; b += 2) {
    const cX = constraints + (<usize>((b + 0) * PAIR) << 3);
    const cY = constraints + (<usize>((b + 1) * PAIR) << 3);
    const ixX = pairs + (<usize>(b + 0) << 4);
    const ixY = pairs + (<usize>(b + 1) << 4);
    const sa0X = bodyAt(states, load<i32>(ixX));
    const sa0Y = bodyAt(states, load<i32>(ixY));
    const sb0X = bodyAt(states, load<i32>(ixX, 4));
    const sb0Y = bodyAt(states, load<i32>(ixY, 4));
    const sa1X = bodyAt(states, load<i32>(ixX, 8));
    const sa1Y = bodyAt(states, load<i32>(ixY, 8));
    const sb1X = bodyAt(states, load<i32>(ixX, 12));
    const sb1Y = bodyAt(states, load<i32>(ixY, 12));
    const mAX = field(cX, MA);
    const mAY = field(cY, MA);
    const iAX = field(cX, IA);
    const iAY = field(cY, IA);
    const mBX = field(cX, MB);
    const mBY = field(cY, MB);
    const iBX = field(cX, IB);
    const iBY = field(cY, IB);
    const a00X = v128.load(sa0X);
    const a00Y = v128.load(sa0Y);
    const a01X = v128.load(sa1X);
    const a01Y = v128.load(sa1Y);
    const a10X = v128.load(sa0X, 16);
    const a10Y = v128.load(sa0Y, 16);
    const a11X = v128.load(sa1X, 16);
    const a11Y = v128.load(sa1Y, 16);
    const a20X = v128.load(sa0X, 32);
    const a20Y = v128.load(sa0Y, 32);
    const a21X = v128.load(sa1X, 32);
    const a21Y = v128.load(sa1Y, 32);
    const b00X = v128.load(sb0X);
    const b00Y = v128.load(sb0Y);
    const b01X = v128.load(sb1X);
    const b01Y = v128.load(sb1Y);
    const b10X = v128.load(sb0X, 16);
    const b10Y = v128.load(sb0Y, 16);
    const b11X = v128.load(sb1X, 16);
    const b11Y = v128.load(sb1Y, 16);
    const b20X = v128.load(sb0X, 32);
    const b20Y = v128.load(sb0Y, 32);
    const b21X = v128.load(sb1X, 32);
    const b21Y = v128.load(sb1Y, 32);
    let vAxX = firsts(a00X, a01X);
    let vAxY = firsts(a00Y, a01Y);
    let vAyX = seconds(a00X, a01X);
    let vAyY = seconds(a00Y, a01Y);
    let wAX = firsts(a10X, a11X);
    let wAY = firsts(a10Y, a11Y);
    const qAcX = seconds(a20X, a21X);
    const qAcY = seconds(a20Y, a21Y);
    const qAsX = gather(sa0X, sa1X, DQS);
    const qAsY = gather(sa0Y, sa1Y, DQS);
    let vBxX = firsts(b00X, b01X);
    let vBxY = firsts(b00Y, b01Y);
    let vByX = seconds(b00X, b01X);
    let vByY = seconds(b00Y, b01Y);
    let wBX = firsts(b10X, b11X);
    let wBY = firsts(b10Y, b11Y);
    const qBcX = seconds(b20X, b21X);
    const qBcY = seconds(b20Y, b21Y);
    const qBsX = gather(sb0X, sb1X, DQS);
    const qBsY = gather(sb0Y, sb1Y, DQS);
    const dpxX = f64x2.sub(seconds(b10X, b11X), seconds(a10X, a11X));
    const dpxY = f64x2.sub(seconds(b10Y, b11Y), seconds(a10Y, a11Y));
    const dpyX = f64x2.sub(firsts(b20X, b21X), firsts(a20X, a21X));
    const dpyY = f64x2.sub(firsts(b20Y, b21Y), firsts(a20Y, a21Y));
    const nxX = field(cX, NX);
    const nxY = field(cY, NX);
    const nyX = field(cX, NY);
    const nyY = field(cY, NY);
    const biasRateX = field(cX, BIAS_RATE);
    const biasRateY = field(cY, BIAS_RATE);
    const softMassScaleX = field(cX, MASS_SCALE);
    const softMassScaleY = field(cY, MASS_SCALE);
    const softImpulseScaleX = field(cX, IMPULSE_SCALE);
    const softImpulseScaleY = field(cY, IMPULSE_SCALE);
    const bouncy = v128.any_true(v128.or(f64x2.gt(field(cX, RESTITUTION), zero), f64x2.gt(field(cY, RESTITUTION), zero)));
    // The second point's normal speed before this constraint's impulses, for noting its impact
    // (restitution only: see noteImpact).
    let before1X = zero;
    let before1Y = zero;
    if (bouncy) before1X = secondSpeed(cX, vAxX, vAyX, wAX, vBxX, vByX, wBX, nxX, nyX);
    if (bouncy) before1Y = secondSpeed(cY, vAxY, vAyY, wAY, vBxY, vByY, wBY, nxY, nyY);
    {
      const maskX = hasPoint(cX, 0);
      const maskY = hasPoint(cY, 0);
      const qX = cX + (<usize>P << 3);
      const qY = cY + (<usize>P << 3);
      const rAxX = field(qX, RAX);
      const rAxY = field(qY, RAX);
      const rAyX = field(qX, RAY);
      const rAyY = field(qY, RAY);
      const rBxX = field(qX, RBX);
      const rBxY = field(qY, RBX);
      const rByX = field(qX, RBY);
      const rByY = field(qY, RBY);
      const dsxX = f64x2.sub(f64x2.add(dpxX, f64x2.sub(f64x2.mul(qBcX, rBxX), f64x2.mul(qBsX, rByX))), f64x2.sub(f64x2.mul(qAcX, rAxX), f64x2.mul(qAsX, rAyX)));
      const dsxY = f64x2.sub(f64x2.add(dpxY, f64x2.sub(f64x2.mul(qBcY, rBxY), f64x2.mul(qBsY, rByY))), f64x2.sub(f64x2.mul(qAcY, rAxY), f64x2.mul(qAsY, rAyY)));
      const dsyX = f64x2.sub(f64x2.add(dpyX, f64x2.add(f64x2.mul(qBsX, rBxX), f64x2.mul(qBcX, rByX))), f64x2.add(f64x2.mul(qAsX, rAxX), f64x2.mul(qAcX, rAyX)));
      const dsyY = f64x2.sub(f64x2.add(dpyY, f64x2.add(f64x2.mul(qBsY, rBxY), f64x2.mul(qBcY, rByY))), f64x2.add(f64x2.mul(qAsY, rAxY), f64x2.mul(qAcY, rAyY)));
      const sX = f64x2.add(f64x2.add(field(qX, BASE_SEPARATION), f64x2.mul(dsxX, nxX)), f64x2.mul(dsyX, nyX));
      const sY = f64x2.add(f64x2.add(field(qY, BASE_SEPARATION), f64x2.mul(dsxY, nxY)), f64x2.mul(dsyY, nyY));
      const speculativeX = f64x2.gt(sX, zero);
      const speculativeY = f64x2.gt(sY, zero);
      const biasX = v128.bitselect(f64x2.mul(sX, invH), f64x2.max(f64x2.mul(f64x2.mul(biasRateX, softMassScaleX), sX), floor), speculativeX);
      const biasY = v128.bitselect(f64x2.mul(sY, invH), f64x2.max(f64x2.mul(f64x2.mul(biasRateY, softMassScaleY), sY), floor), speculativeY);
      const massScaleX = v128.bitselect(one, softMassScaleX, speculativeX);
      const massScaleY = v128.bitselect(one, softMassScaleY, speculativeY);
      const impulseScaleX = v128.bitselect(zero, softImpulseScaleX, speculativeX);
      const impulseScaleY = v128.bitselect(zero, softImpulseScaleY, speculativeY);
      const dvxX = f64x2.sub(f64x2.sub(vBxX, f64x2.mul(wBX, rByX)), f64x2.sub(vAxX, f64x2.mul(wAX, rAyX)));
      const dvxY = f64x2.sub(f64x2.sub(vBxY, f64x2.mul(wBY, rByY)), f64x2.sub(vAxY, f64x2.mul(wAY, rAyY)));
      const dvyX = f64x2.sub(f64x2.add(vByX, f64x2.mul(wBX, rBxX)), f64x2.add(vAyX, f64x2.mul(wAX, rAxX)));
      const dvyY = f64x2.sub(f64x2.add(vByY, f64x2.mul(wBY, rBxY)), f64x2.add(vAyY, f64x2.mul(wAY, rAxY)));
      const vnX = f64x2.add(f64x2.mul(dvxX, nxX), f64x2.mul(dvyX, nyX));
      const vnY = f64x2.add(f64x2.mul(dvxY, nxY), f64x2.mul(dvyY, nyY));
      const accumulatedX = field(qX, NORMAL_IMPULSE);
      const accumulatedY = field(qY, NORMAL_IMPULSE);
      const totalX = f64x2.max(f64x2.add(accumulatedX, f64x2.sub(f64x2.mul(f64x2.neg(field(qX, NORMAL_MASS)), f64x2.add(f64x2.mul(massScaleX, vnX), biasX)), f64x2.mul(impulseScaleX, accumulatedX))), zero);
      const totalY = f64x2.max(f64x2.add(accumulatedY, f64x2.sub(f64x2.mul(f64x2.neg(field(qY, NORMAL_MASS)), f64x2.add(f64x2.mul(massScaleY, vnY), biasY)), f64x2.mul(impulseScaleY, accumulatedY))), zero);
      const impulseX = f64x2.sub(totalX, accumulatedX);
      const impulseY = f64x2.sub(totalY, accumulatedY);
      put(qX, NORMAL_IMPULSE, v128.bitselect(totalX, accumulatedX, maskX));
      put(qY, NORMAL_IMPULSE, v128.bitselect(totalY, accumulatedY, maskY));
      if (bouncy) noteImpact(qX, maskX, totalX, vnX, zero); else noteMost(qX, maskX, totalX);
      if (bouncy) noteImpact(qY, maskY, totalY, vnY, zero); else noteMost(qY, maskY, totalY);
      const pxX = f64x2.mul(impulseX, nxX);
      const pxY = f64x2.mul(impulseY, nxY);
      const pyX = f64x2.mul(impulseX, nyX);
      const pyY = f64x2.mul(impulseY, nyY);
      vAxX = v128.bitselect(f64x2.sub(vAxX, f64x2.mul(mAX, pxX)), vAxX, maskX);
      vAxY = v128.bitselect(f64x2.sub(vAxY, f64x2.mul(mAY, pxY)), vAxY, maskY);
      vAyX = v128.bitselect(f64x2.sub(vAyX, f64x2.mul(mAX, pyX)), vAyX, maskX);
      vAyY = v128.bitselect(f64x2.sub(vAyY, f64x2.mul(mAY, pyY)), vAyY, maskY);
      wAX = v128.bitselect(f64x2.sub(wAX, f64x2.mul(iAX, f64x2.sub(f64x2.mul(rAxX, pyX), f64x2.mul(rAyX, pxX)))), wAX, maskX);
      wAY = v128.bitselect(f64x2.sub(wAY, f64x2.mul(iAY, f64x2.sub(f64x2.mul(rAxY, pyY), f64x2.mul(rAyY, pxY)))), wAY, maskY);
      vBxX = v128.bitselect(f64x2.add(vBxX, f64x2.mul(mBX, pxX)), vBxX, maskX);
      vBxY = v128.bitselect(f64x2.add(vBxY, f64x2.mul(mBY, pxY)), vBxY, maskY);
      vByX = v128.bitselect(f64x2.add(vByX, f64x2.mul(mBX, pyX)), vByX, maskX);
      vByY = v128.bitselect(f64x2.add(vByY, f64x2.mul(mBY, pyY)), vByY, maskY);
      wBX = v128.bitselect(f64x2.add(wBX, f64x2.mul(iBX, f64x2.sub(f64x2.mul(rBxX, pyX), f64x2.mul(rByX, pxX)))), wBX, maskX);
      wBY = v128.bitselect(f64x2.add(wBY, f64x2.mul(iBY, f64x2.sub(f64x2.mul(rBxY, pyY), f64x2.mul(rByY, pxY)))), wBY, maskY);
    }
    if (v128.any_true(v128.or(hasPoint(cX, 1), hasPoint(cY, 1)))) {
      const maskX = hasPoint(cX, 1);
      const maskY = hasPoint(cY, 1);
      const qX = cX + (<usize>(P + POINT) << 3);
      const qY = cY + (<usize>(P + POINT) << 3);
      const rAxX = field(qX, RAX);
      const rAxY = field(qY, RAX);
      const rAyX = field(qX, RAY);
      const rAyY = field(qY, RAY);
      const rBxX = field(qX, RBX);
      const rBxY = field(qY, RBX);
      const rByX = field(qX, RBY);
      const rByY = field(qY, RBY);
      const dsxX = f64x2.sub(f64x2.add(dpxX, f64x2.sub(f64x2.mul(qBcX, rBxX), f64x2.mul(qBsX, rByX))), f64x2.sub(f64x2.mul(qAcX, rAxX), f64x2.mul(qAsX, rAyX)));
      const dsxY = f64x2.sub(f64x2.add(dpxY, f64x2.sub(f64x2.mul(qBcY, rBxY), f64x2.mul(qBsY, rByY))), f64x2.sub(f64x2.mul(qAcY, rAxY), f64x2.mul(qAsY, rAyY)));
      const dsyX = f64x2.sub(f64x2.add(dpyX, f64x2.add(f64x2.mul(qBsX, rBxX), f64x2.mul(qBcX, rByX))), f64x2.add(f64x2.mul(qAsX, rAxX), f64x2.mul(qAcX, rAyX)));
      const dsyY = f64x2.sub(f64x2.add(dpyY, f64x2.add(f64x2.mul(qBsY, rBxY), f64x2.mul(qBcY, rByY))), f64x2.add(f64x2.mul(qAsY, rAxY), f64x2.mul(qAcY, rAyY)));
      const sX = f64x2.add(f64x2.add(field(qX, BASE_SEPARATION), f64x2.mul(dsxX, nxX)), f64x2.mul(dsyX, nyX));
      const sY = f64x2.add(f64x2.add(field(qY, BASE_SEPARATION), f64x2.mul(dsxY, nxY)), f64x2.mul(dsyY, nyY));
      const speculativeX = f64x2.gt(sX, zero);
      const speculativeY = f64x2.gt(sY, zero);
      const biasX = v128.bitselect(f64x2.mul(sX, invH), f64x2.max(f64x2.mul(f64x2.mul(biasRateX, softMassScaleX), sX), floor), speculativeX);
      const biasY = v128.bitselect(f64x2.mul(sY, invH), f64x2.max(f64x2.mul(f64x2.mul(biasRateY, softMassScaleY), sY), floor), speculativeY);
      const massScaleX = v128.bitselect(one, softMassScaleX, speculativeX);
      const massScaleY = v128.bitselect(one, softMassScaleY, speculativeY);
      const impulseScaleX = v128.bitselect(zero, softImpulseScaleX, speculativeX);
      const impulseScaleY = v128.bitselect(zero, softImpulseScaleY, speculativeY);
      const dvxX = f64x2.sub(f64x2.sub(vBxX, f64x2.mul(wBX, rByX)), f64x2.sub(vAxX, f64x2.mul(wAX, rAyX)));
      const dvxY = f64x2.sub(f64x2.sub(vBxY, f64x2.mul(wBY, rByY)), f64x2.sub(vAxY, f64x2.mul(wAY, rAyY)));
      const dvyX = f64x2.sub(f64x2.add(vByX, f64x2.mul(wBX, rBxX)), f64x2.add(vAyX, f64x2.mul(wAX, rAxX)));
      const dvyY = f64x2.sub(f64x2.add(vByY, f64x2.mul(wBY, rBxY)), f64x2.add(vAyY, f64x2.mul(wAY, rAxY)));
      const vnX = f64x2.add(f64x2.mul(dvxX, nxX), f64x2.mul(dvyX, nyX));
      const vnY = f64x2.add(f64x2.mul(dvxY, nxY), f64x2.mul(dvyY, nyY));
      const accumulatedX = field(qX, NORMAL_IMPULSE);
      const accumulatedY = field(qY, NORMAL_IMPULSE);
      const totalX = f64x2.max(f64x2.add(accumulatedX, f64x2.sub(f64x2.mul(f64x2.neg(field(qX, NORMAL_MASS)), f64x2.add(f64x2.mul(massScaleX, vnX), biasX)), f64x2.mul(impulseScaleX, accumulatedX))), zero);
      const totalY = f64x2.max(f64x2.add(accumulatedY, f64x2.sub(f64x2.mul(f64x2.neg(field(qY, NORMAL_MASS)), f64x2.add(f64x2.mul(massScaleY, vnY), biasY)), f64x2.mul(impulseScaleY, accumulatedY))), zero);
      const impulseX = f64x2.sub(totalX, accumulatedX);
      const impulseY = f64x2.sub(totalY, accumulatedY);
      put(qX, NORMAL_IMPULSE, v128.bitselect(totalX, accumulatedX, maskX));
      put(qY, NORMAL_IMPULSE, v128.bitselect(totalY, accumulatedY, maskY));
      if (bouncy) noteImpact(qX, maskX, totalX, before1X, zero); else noteMost(qX, maskX, totalX);
      if (bouncy) noteImpact(qY, maskY, totalY, before1Y, zero); else noteMost(qY, maskY, totalY);
      const pxX = f64x2.mul(impulseX, nxX);
      const pxY = f64x2.mul(impulseY, nxY);
      const pyX = f64x2.mul(impulseX, nyX);
      const pyY = f64x2.mul(impulseY, nyY);
      vAxX = v128.bitselect(f64x2.sub(vAxX, f64x2.mul(mAX, pxX)), vAxX, maskX);
      vAxY = v128.bitselect(f64x2.sub(vAxY, f64x2.mul(mAY, pxY)), vAxY, maskY);
      vAyX = v128.bitselect(f64x2.sub(vAyX, f64x2.mul(mAX, pyX)), vAyX, maskX);
      vAyY = v128.bitselect(f64x2.sub(vAyY, f64x2.mul(mAY, pyY)), vAyY, maskY);
      wAX = v128.bitselect(f64x2.sub(wAX, f64x2.mul(iAX, f64x2.sub(f64x2.mul(rAxX, pyX), f64x2.mul(rAyX, pxX)))), wAX, maskX);
      wAY = v128.bitselect(f64x2.sub(wAY, f64x2.mul(iAY, f64x2.sub(f64x2.mul(rAxY, pyY), f64x2.mul(rAyY, pxY)))), wAY, maskY);
      vBxX = v128.bitselect(f64x2.add(vBxX, f64x2.mul(mBX, pxX)), vBxX, maskX);
      vBxY = v128.bitselect(f64x2.add(vBxY, f64x2.mul(mBY, pxY)), vBxY, maskY);
      vByX = v128.bitselect(f64x2.add(vByX, f64x2.mul(mBX, pyX)), vByX, maskX);
      vByY = v128.bitselect(f64x2.add(vByY, f64x2.mul(mBY, pyY)), vByY, maskY);
      wBX = v128.bitselect(f64x2.add(wBX, f64x2.mul(iBX, f64x2.sub(f64x2.mul(rBxX, pyX), f64x2.mul(rByX, pxX)))), wBX, maskX);
      wBY = v128.bitselect(f64x2.add(wBY, f64x2.mul(iBY, f64x2.sub(f64x2.mul(rBxY, pyY), f64x2.mul(rByY, pxY)))), wBY, maskY);
    }
    scatter(sa0X, 0, vAxX, vAyX, wAX);
    scatter(sa0Y, 0, vAxY, vAyY, wAY);
    scatter(sb0X, 0, vBxX, vByX, wBX);
    scatter(sb0Y, 0, vBxY, vByY, wBY);
    scatter(sa1X, 1, vAxX, vAyX, wAX);
    scatter(sa1Y, 1, vAxY, vAyY, wAY);
    scatter(sb1X, 1, vBxX, vByX, wBX);
    scatter(sb1Y, 1, vBxY, vByY, wBY);
  }
}

export function relax(states: usize, constraints: usize, pairs: usize, lanes: i32, inverseH: f64): void {
  const zero = f64x2.splat(0);
  const invH = f64x2.splat(inverseH);
  for (let b = 0; b < lanes >> 1; b += 2) {
    const cX = constraints + (<usize>((b + 0) * PAIR) << 3);
    const cY = constraints + (<usize>((b + 1) * PAIR) << 3);
    const ixX = pairs + (<usize>(b + 0) << 4);
    const ixY = pairs + (<usize>(b + 1) << 4);
    const sa0X = bodyAt(states, load<i32>(ixX));
    const sa0Y = bodyAt(states, load<i32>(ixY));
    const sb0X = bodyAt(states, load<i32>(ixX, 4));
    const sb0Y = bodyAt(states, load<i32>(ixY, 4));
    const sa1X = bodyAt(states, load<i32>(ixX, 8));
    const sa1Y = bodyAt(states, load<i32>(ixY, 8));
    const sb1X = bodyAt(states, load<i32>(ixX, 12));
    const sb1Y = bodyAt(states, load<i32>(ixY, 12));
    const mAX = field(cX, MA);
    const mAY = field(cY, MA);
    const iAX = field(cX, IA);
    const iAY = field(cY, IA);
    const mBX = field(cX, MB);
    const mBY = field(cY, MB);
    const iBX = field(cX, IB);
    const iBY = field(cY, IB);
    const a00X = v128.load(sa0X);
    const a00Y = v128.load(sa0Y);
    const a01X = v128.load(sa1X);
    const a01Y = v128.load(sa1Y);
    const a10X = v128.load(sa0X, 16);
    const a10Y = v128.load(sa0Y, 16);
    const a11X = v128.load(sa1X, 16);
    const a11Y = v128.load(sa1Y, 16);
    const a20X = v128.load(sa0X, 32);
    const a20Y = v128.load(sa0Y, 32);
    const a21X = v128.load(sa1X, 32);
    const a21Y = v128.load(sa1Y, 32);
    const b00X = v128.load(sb0X);
    const b00Y = v128.load(sb0Y);
    const b01X = v128.load(sb1X);
    const b01Y = v128.load(sb1Y);
    const b10X = v128.load(sb0X, 16);
    const b10Y = v128.load(sb0Y, 16);
    const b11X = v128.load(sb1X, 16);
    const b11Y = v128.load(sb1Y, 16);
    const b20X = v128.load(sb0X, 32);
    const b20Y = v128.load(sb0Y, 32);
    const b21X = v128.load(sb1X, 32);
    const b21Y = v128.load(sb1Y, 32);
    let vAxX = firsts(a00X, a01X);
    let vAxY = firsts(a00Y, a01Y);
    let vAyX = seconds(a00X, a01X);
    let vAyY = seconds(a00Y, a01Y);
    let wAX = firsts(a10X, a11X);
    let wAY = firsts(a10Y, a11Y);
    const qAcX = seconds(a20X, a21X);
    const qAcY = seconds(a20Y, a21Y);
    const qAsX = gather(sa0X, sa1X, DQS);
    const qAsY = gather(sa0Y, sa1Y, DQS);
    let vBxX = firsts(b00X, b01X);
    let vBxY = firsts(b00Y, b01Y);
    let vByX = seconds(b00X, b01X);
    let vByY = seconds(b00Y, b01Y);
    let wBX = firsts(b10X, b11X);
    let wBY = firsts(b10Y, b11Y);
    const qBcX = seconds(b20X, b21X);
    const qBcY = seconds(b20Y, b21Y);
    const qBsX = gather(sb0X, sb1X, DQS);
    const qBsY = gather(sb0Y, sb1Y, DQS);
    const dpxX = f64x2.sub(seconds(b10X, b11X), seconds(a10X, a11X));
    const dpxY = f64x2.sub(seconds(b10Y, b11Y), seconds(a10Y, a11Y));
    const dpyX = f64x2.sub(firsts(b20X, b21X), firsts(a20X, a21X));
    const dpyY = f64x2.sub(firsts(b20Y, b21Y), firsts(a20Y, a21Y));
    const nxX = field(cX, NX);
    const nxY = field(cY, NX);
    const nyX = field(cX, NY);
    const nyY = field(cY, NY);
    let totalNormalImpulseX = zero;
    let totalNormalImpulseY = zero;
    const bouncy = v128.any_true(v128.or(f64x2.gt(field(cX, RESTITUTION), zero), f64x2.gt(field(cY, RESTITUTION), zero)));
    // The second point's normal speed before this constraint's impulses, for noting its impact
    // (restitution only: see noteImpact).
    let before1X = zero;
    let before1Y = zero;
    if (bouncy) before1X = secondSpeed(cX, vAxX, vAyX, wAX, vBxX, vByX, wBX, nxX, nyX);
    if (bouncy) before1Y = secondSpeed(cY, vAxY, vAyY, wAY, vBxY, vByY, wBY, nxY, nyY);
    {
      const maskX = hasPoint(cX, 0);
      const maskY = hasPoint(cY, 0);
      const qX = cX + (<usize>P << 3);
      const qY = cY + (<usize>P << 3);
      const rAxX = field(qX, RAX);
      const rAxY = field(qY, RAX);
      const rAyX = field(qX, RAY);
      const rAyY = field(qY, RAY);
      const rBxX = field(qX, RBX);
      const rBxY = field(qY, RBX);
      const rByX = field(qX, RBY);
      const rByY = field(qY, RBY);
      const dsxX = f64x2.sub(f64x2.add(dpxX, f64x2.sub(f64x2.mul(qBcX, rBxX), f64x2.mul(qBsX, rByX))), f64x2.sub(f64x2.mul(qAcX, rAxX), f64x2.mul(qAsX, rAyX)));
      const dsxY = f64x2.sub(f64x2.add(dpxY, f64x2.sub(f64x2.mul(qBcY, rBxY), f64x2.mul(qBsY, rByY))), f64x2.sub(f64x2.mul(qAcY, rAxY), f64x2.mul(qAsY, rAyY)));
      const dsyX = f64x2.sub(f64x2.add(dpyX, f64x2.add(f64x2.mul(qBsX, rBxX), f64x2.mul(qBcX, rByX))), f64x2.add(f64x2.mul(qAsX, rAxX), f64x2.mul(qAcX, rAyX)));
      const dsyY = f64x2.sub(f64x2.add(dpyY, f64x2.add(f64x2.mul(qBsY, rBxY), f64x2.mul(qBcY, rByY))), f64x2.add(f64x2.mul(qAsY, rAxY), f64x2.mul(qAcY, rAyY)));
      const sX = f64x2.add(f64x2.add(field(qX, BASE_SEPARATION), f64x2.mul(dsxX, nxX)), f64x2.mul(dsyX, nyX));
      const sY = f64x2.add(f64x2.add(field(qY, BASE_SEPARATION), f64x2.mul(dsxY, nxY)), f64x2.mul(dsyY, nyY));
      const biasX = v128.bitselect(f64x2.mul(sX, invH), zero, f64x2.gt(sX, zero));
      const biasY = v128.bitselect(f64x2.mul(sY, invH), zero, f64x2.gt(sY, zero));
      const dvxX = f64x2.sub(f64x2.sub(vBxX, f64x2.mul(wBX, rByX)), f64x2.sub(vAxX, f64x2.mul(wAX, rAyX)));
      const dvxY = f64x2.sub(f64x2.sub(vBxY, f64x2.mul(wBY, rByY)), f64x2.sub(vAxY, f64x2.mul(wAY, rAyY)));
      const dvyX = f64x2.sub(f64x2.add(vByX, f64x2.mul(wBX, rBxX)), f64x2.add(vAyX, f64x2.mul(wAX, rAxX)));
      const dvyY = f64x2.sub(f64x2.add(vByY, f64x2.mul(wBY, rBxY)), f64x2.add(vAyY, f64x2.mul(wAY, rAxY)));
      const vnX = f64x2.add(f64x2.mul(dvxX, nxX), f64x2.mul(dvyX, nyX));
      const vnY = f64x2.add(f64x2.mul(dvxY, nxY), f64x2.mul(dvyY, nyY));
      const accumulatedX = field(qX, NORMAL_IMPULSE);
      const accumulatedY = field(qY, NORMAL_IMPULSE);
      const totalX = f64x2.max(f64x2.add(accumulatedX, f64x2.mul(f64x2.neg(field(qX, NORMAL_MASS)), f64x2.add(vnX, biasX))), zero);
      const totalY = f64x2.max(f64x2.add(accumulatedY, f64x2.mul(f64x2.neg(field(qY, NORMAL_MASS)), f64x2.add(vnY, biasY))), zero);
      const impulseX = f64x2.sub(totalX, accumulatedX);
      const impulseY = f64x2.sub(totalY, accumulatedY);
      put(qX, NORMAL_IMPULSE, v128.bitselect(totalX, accumulatedX, maskX));
      put(qY, NORMAL_IMPULSE, v128.bitselect(totalY, accumulatedY, maskY));
      if (bouncy) noteImpact(qX, maskX, totalX, vnX, zero); else noteMost(qX, maskX, totalX);
      if (bouncy) noteImpact(qY, maskY, totalY, vnY, zero); else noteMost(qY, maskY, totalY);
      totalNormalImpulseX = v128.bitselect(f64x2.add(totalNormalImpulseX, totalX), totalNormalImpulseX, maskX);
      totalNormalImpulseY = v128.bitselect(f64x2.add(totalNormalImpulseY, totalY), totalNormalImpulseY, maskY);
      const pxX = f64x2.mul(impulseX, nxX);
      const pxY = f64x2.mul(impulseY, nxY);
      const pyX = f64x2.mul(impulseX, nyX);
      const pyY = f64x2.mul(impulseY, nyY);
      vAxX = v128.bitselect(f64x2.sub(vAxX, f64x2.mul(mAX, pxX)), vAxX, maskX);
      vAxY = v128.bitselect(f64x2.sub(vAxY, f64x2.mul(mAY, pxY)), vAxY, maskY);
      vAyX = v128.bitselect(f64x2.sub(vAyX, f64x2.mul(mAX, pyX)), vAyX, maskX);
      vAyY = v128.bitselect(f64x2.sub(vAyY, f64x2.mul(mAY, pyY)), vAyY, maskY);
      wAX = v128.bitselect(f64x2.sub(wAX, f64x2.mul(iAX, f64x2.sub(f64x2.mul(rAxX, pyX), f64x2.mul(rAyX, pxX)))), wAX, maskX);
      wAY = v128.bitselect(f64x2.sub(wAY, f64x2.mul(iAY, f64x2.sub(f64x2.mul(rAxY, pyY), f64x2.mul(rAyY, pxY)))), wAY, maskY);
      vBxX = v128.bitselect(f64x2.add(vBxX, f64x2.mul(mBX, pxX)), vBxX, maskX);
      vBxY = v128.bitselect(f64x2.add(vBxY, f64x2.mul(mBY, pxY)), vBxY, maskY);
      vByX = v128.bitselect(f64x2.add(vByX, f64x2.mul(mBX, pyX)), vByX, maskX);
      vByY = v128.bitselect(f64x2.add(vByY, f64x2.mul(mBY, pyY)), vByY, maskY);
      wBX = v128.bitselect(f64x2.add(wBX, f64x2.mul(iBX, f64x2.sub(f64x2.mul(rBxX, pyX), f64x2.mul(rByX, pxX)))), wBX, maskX);
      wBY = v128.bitselect(f64x2.add(wBY, f64x2.mul(iBY, f64x2.sub(f64x2.mul(rBxY, pyY), f64x2.mul(rByY, pxY)))), wBY, maskY);
    }
    if (v128.any_true(v128.or(hasPoint(cX, 1), hasPoint(cY, 1)))) {
      const maskX = hasPoint(cX, 1);
      const maskY = hasPoint(cY, 1);
      const qX = cX + (<usize>(P + POINT) << 3);
      const qY = cY + (<usize>(P + POINT) << 3);
      const rAxX = field(qX, RAX);
      const rAxY = field(qY, RAX);
      const rAyX = field(qX, RAY);
      const rAyY = field(qY, RAY);
      const rBxX = field(qX, RBX);
      const rBxY = field(qY, RBX);
      const rByX = field(qX, RBY);
      const rByY = field(qY, RBY);
      const dsxX = f64x2.sub(f64x2.add(dpxX, f64x2.sub(f64x2.mul(qBcX, rBxX), f64x2.mul(qBsX, rByX))), f64x2.sub(f64x2.mul(qAcX, rAxX), f64x2.mul(qAsX, rAyX)));
      const dsxY = f64x2.sub(f64x2.add(dpxY, f64x2.sub(f64x2.mul(qBcY, rBxY), f64x2.mul(qBsY, rByY))), f64x2.sub(f64x2.mul(qAcY, rAxY), f64x2.mul(qAsY, rAyY)));
      const dsyX = f64x2.sub(f64x2.add(dpyX, f64x2.add(f64x2.mul(qBsX, rBxX), f64x2.mul(qBcX, rByX))), f64x2.add(f64x2.mul(qAsX, rAxX), f64x2.mul(qAcX, rAyX)));
      const dsyY = f64x2.sub(f64x2.add(dpyY, f64x2.add(f64x2.mul(qBsY, rBxY), f64x2.mul(qBcY, rByY))), f64x2.add(f64x2.mul(qAsY, rAxY), f64x2.mul(qAcY, rAyY)));
      const sX = f64x2.add(f64x2.add(field(qX, BASE_SEPARATION), f64x2.mul(dsxX, nxX)), f64x2.mul(dsyX, nyX));
      const sY = f64x2.add(f64x2.add(field(qY, BASE_SEPARATION), f64x2.mul(dsxY, nxY)), f64x2.mul(dsyY, nyY));
      const biasX = v128.bitselect(f64x2.mul(sX, invH), zero, f64x2.gt(sX, zero));
      const biasY = v128.bitselect(f64x2.mul(sY, invH), zero, f64x2.gt(sY, zero));
      const dvxX = f64x2.sub(f64x2.sub(vBxX, f64x2.mul(wBX, rByX)), f64x2.sub(vAxX, f64x2.mul(wAX, rAyX)));
      const dvxY = f64x2.sub(f64x2.sub(vBxY, f64x2.mul(wBY, rByY)), f64x2.sub(vAxY, f64x2.mul(wAY, rAyY)));
      const dvyX = f64x2.sub(f64x2.add(vByX, f64x2.mul(wBX, rBxX)), f64x2.add(vAyX, f64x2.mul(wAX, rAxX)));
      const dvyY = f64x2.sub(f64x2.add(vByY, f64x2.mul(wBY, rBxY)), f64x2.add(vAyY, f64x2.mul(wAY, rAxY)));
      const vnX = f64x2.add(f64x2.mul(dvxX, nxX), f64x2.mul(dvyX, nyX));
      const vnY = f64x2.add(f64x2.mul(dvxY, nxY), f64x2.mul(dvyY, nyY));
      const accumulatedX = field(qX, NORMAL_IMPULSE);
      const accumulatedY = field(qY, NORMAL_IMPULSE);
      const totalX = f64x2.max(f64x2.add(accumulatedX, f64x2.mul(f64x2.neg(field(qX, NORMAL_MASS)), f64x2.add(vnX, biasX))), zero);
      const totalY = f64x2.max(f64x2.add(accumulatedY, f64x2.mul(f64x2.neg(field(qY, NORMAL_MASS)), f64x2.add(vnY, biasY))), zero);
      const impulseX = f64x2.sub(totalX, accumulatedX);
      const impulseY = f64x2.sub(totalY, accumulatedY);
      put(qX, NORMAL_IMPULSE, v128.bitselect(totalX, accumulatedX, maskX));
      put(qY, NORMAL_IMPULSE, v128.bitselect(totalY, accumulatedY, maskY));
      if (bouncy) noteImpact(qX, maskX, totalX, before1X, zero); else noteMost(qX, maskX, totalX);
      if (bouncy) noteImpact(qY, maskY, totalY, before1Y, zero); else noteMost(qY, maskY, totalY);
      totalNormalImpulseX = v128.bitselect(f64x2.add(totalNormalImpulseX, totalX), totalNormalImpulseX, maskX);
      totalNormalImpulseY = v128.bitselect(f64x2.add(totalNormalImpulseY, totalY), totalNormalImpulseY, maskY);
      const pxX = f64x2.mul(impulseX, nxX);
      const pxY = f64x2.mul(impulseY, nxY);
      const pyX = f64x2.mul(impulseX, nyX);
      const pyY = f64x2.mul(impulseY, nyY);
      vAxX = v128.bitselect(f64x2.sub(vAxX, f64x2.mul(mAX, pxX)), vAxX, maskX);
      vAxY = v128.bitselect(f64x2.sub(vAxY, f64x2.mul(mAY, pxY)), vAxY, maskY);
      vAyX = v128.bitselect(f64x2.sub(vAyX, f64x2.mul(mAX, pyX)), vAyX, maskX);
      vAyY = v128.bitselect(f64x2.sub(vAyY, f64x2.mul(mAY, pyY)), vAyY, maskY);
      wAX = v128.bitselect(f64x2.sub(wAX, f64x2.mul(iAX, f64x2.sub(f64x2.mul(rAxX, pyX), f64x2.mul(rAyX, pxX)))), wAX, maskX);
      wAY = v128.bitselect(f64x2.sub(wAY, f64x2.mul(iAY, f64x2.sub(f64x2.mul(rAxY, pyY), f64x2.mul(rAyY, pxY)))), wAY, maskY);
      vBxX = v128.bitselect(f64x2.add(vBxX, f64x2.mul(mBX, pxX)), vBxX, maskX);
      vBxY = v128.bitselect(f64x2.add(vBxY, f64x2.mul(mBY, pxY)), vBxY, maskY);
      vByX = v128.bitselect(f64x2.add(vByX, f64x2.mul(mBX, pyX)), vByX, maskX);
      vByY = v128.bitselect(f64x2.add(vByY, f64x2.mul(mBY, pyY)), vByY, maskY);
      wBX = v128.bitselect(f64x2.add(wBX, f64x2.mul(iBX, f64x2.sub(f64x2.mul(rBxX, pyX), f64x2.mul(rByX, pxX)))), wBX, maskX);
      wBY = v128.bitselect(f64x2.add(wBY, f64x2.mul(iBY, f64x2.sub(f64x2.mul(rBxY, pyY), f64x2.mul(rByY, pxY)))), wBY, maskY);
    }
    const frictionX = field(cX, FRICTION);
    const frictionY = field(cY, FRICTION);
    const txX = nyX;
    const txY = nyY;
    const tyX = f64x2.neg(nxX);
    const tyY = f64x2.neg(nxY);
    {
      const maskX = hasPoint(cX, 0);
      const maskY = hasPoint(cY, 0);
      const qX = cX + (<usize>P << 3);
      const qY = cY + (<usize>P << 3);
      const rAxX = field(qX, RAX);
      const rAxY = field(qY, RAX);
      const rAyX = field(qX, RAY);
      const rAyY = field(qY, RAY);
      const rBxX = field(qX, RBX);
      const rBxY = field(qY, RBX);
      const rByX = field(qX, RBY);
      const rByY = field(qY, RBY);
      const dvxX = f64x2.sub(f64x2.sub(vBxX, f64x2.mul(wBX, rByX)), f64x2.sub(vAxX, f64x2.mul(wAX, rAyX)));
      const dvxY = f64x2.sub(f64x2.sub(vBxY, f64x2.mul(wBY, rByY)), f64x2.sub(vAxY, f64x2.mul(wAY, rAyY)));
      const dvyX = f64x2.sub(f64x2.add(vByX, f64x2.mul(wBX, rBxX)), f64x2.add(vAyX, f64x2.mul(wAX, rAxX)));
      const dvyY = f64x2.sub(f64x2.add(vByY, f64x2.mul(wBY, rBxY)), f64x2.add(vAyY, f64x2.mul(wAY, rAxY)));
      const vtX = f64x2.add(f64x2.mul(dvxX, txX), f64x2.mul(dvyX, tyX));
      const vtY = f64x2.add(f64x2.mul(dvxY, txY), f64x2.mul(dvyY, tyY));
      const accumulatedX = field(qX, TANGENT_IMPULSE);
      const accumulatedY = field(qY, TANGENT_IMPULSE);
      const limitX = f64x2.mul(frictionX, field(qX, NORMAL_IMPULSE));
      const limitY = f64x2.mul(frictionY, field(qY, NORMAL_IMPULSE));
      const totalX = f64x2.max(f64x2.min(f64x2.sub(accumulatedX, f64x2.mul(field(qX, TANGENT_MASS), vtX)), limitX), f64x2.neg(limitX));
      const totalY = f64x2.max(f64x2.min(f64x2.sub(accumulatedY, f64x2.mul(field(qY, TANGENT_MASS), vtY)), limitY), f64x2.neg(limitY));
      const impulseX = f64x2.sub(totalX, accumulatedX);
      const impulseY = f64x2.sub(totalY, accumulatedY);
      put(qX, TANGENT_IMPULSE, v128.bitselect(totalX, accumulatedX, maskX));
      put(qY, TANGENT_IMPULSE, v128.bitselect(totalY, accumulatedY, maskY));
      const pxX = f64x2.mul(impulseX, txX);
      const pxY = f64x2.mul(impulseY, txY);
      const pyX = f64x2.mul(impulseX, tyX);
      const pyY = f64x2.mul(impulseY, tyY);
      vAxX = v128.bitselect(f64x2.sub(vAxX, f64x2.mul(mAX, pxX)), vAxX, maskX);
      vAxY = v128.bitselect(f64x2.sub(vAxY, f64x2.mul(mAY, pxY)), vAxY, maskY);
      vAyX = v128.bitselect(f64x2.sub(vAyX, f64x2.mul(mAX, pyX)), vAyX, maskX);
      vAyY = v128.bitselect(f64x2.sub(vAyY, f64x2.mul(mAY, pyY)), vAyY, maskY);
      wAX = v128.bitselect(f64x2.sub(wAX, f64x2.mul(iAX, f64x2.sub(f64x2.mul(rAxX, pyX), f64x2.mul(rAyX, pxX)))), wAX, maskX);
      wAY = v128.bitselect(f64x2.sub(wAY, f64x2.mul(iAY, f64x2.sub(f64x2.mul(rAxY, pyY), f64x2.mul(rAyY, pxY)))), wAY, maskY);
      vBxX = v128.bitselect(f64x2.add(vBxX, f64x2.mul(mBX, pxX)), vBxX, maskX);
      vBxY = v128.bitselect(f64x2.add(vBxY, f64x2.mul(mBY, pxY)), vBxY, maskY);
      vByX = v128.bitselect(f64x2.add(vByX, f64x2.mul(mBX, pyX)), vByX, maskX);
      vByY = v128.bitselect(f64x2.add(vByY, f64x2.mul(mBY, pyY)), vByY, maskY);
      wBX = v128.bitselect(f64x2.add(wBX, f64x2.mul(iBX, f64x2.sub(f64x2.mul(rBxX, pyX), f64x2.mul(rByX, pxX)))), wBX, maskX);
      wBY = v128.bitselect(f64x2.add(wBY, f64x2.mul(iBY, f64x2.sub(f64x2.mul(rBxY, pyY), f64x2.mul(rByY, pxY)))), wBY, maskY);
    }
    if (v128.any_true(v128.or(hasPoint(cX, 1), hasPoint(cY, 1)))) {
      const maskX = hasPoint(cX, 1);
      const maskY = hasPoint(cY, 1);
      const qX = cX + (<usize>(P + POINT) << 3);
      const qY = cY + (<usize>(P + POINT) << 3);
      const rAxX = field(qX, RAX);
      const rAxY = field(qY, RAX);
      const rAyX = field(qX, RAY);
      const rAyY = field(qY, RAY);
      const rBxX = field(qX, RBX);
      const rBxY = field(qY, RBX);
      const rByX = field(qX, RBY);
      const rByY = field(qY, RBY);
      const dvxX = f64x2.sub(f64x2.sub(vBxX, f64x2.mul(wBX, rByX)), f64x2.sub(vAxX, f64x2.mul(wAX, rAyX)));
      const dvxY = f64x2.sub(f64x2.sub(vBxY, f64x2.mul(wBY, rByY)), f64x2.sub(vAxY, f64x2.mul(wAY, rAyY)));
      const dvyX = f64x2.sub(f64x2.add(vByX, f64x2.mul(wBX, rBxX)), f64x2.add(vAyX, f64x2.mul(wAX, rAxX)));
      const dvyY = f64x2.sub(f64x2.add(vByY, f64x2.mul(wBY, rBxY)), f64x2.add(vAyY, f64x2.mul(wAY, rAxY)));
      const vtX = f64x2.add(f64x2.mul(dvxX, txX), f64x2.mul(dvyX, tyX));
      const vtY = f64x2.add(f64x2.mul(dvxY, txY), f64x2.mul(dvyY, tyY));
      const accumulatedX = field(qX, TANGENT_IMPULSE);
      const accumulatedY = field(qY, TANGENT_IMPULSE);
      const limitX = f64x2.mul(frictionX, field(qX, NORMAL_IMPULSE));
      const limitY = f64x2.mul(frictionY, field(qY, NORMAL_IMPULSE));
      const totalX = f64x2.max(f64x2.min(f64x2.sub(accumulatedX, f64x2.mul(field(qX, TANGENT_MASS), vtX)), limitX), f64x2.neg(limitX));
      const totalY = f64x2.max(f64x2.min(f64x2.sub(accumulatedY, f64x2.mul(field(qY, TANGENT_MASS), vtY)), limitY), f64x2.neg(limitY));
      const impulseX = f64x2.sub(totalX, accumulatedX);
      const impulseY = f64x2.sub(totalY, accumulatedY);
      put(qX, TANGENT_IMPULSE, v128.bitselect(totalX, accumulatedX, maskX));
      put(qY, TANGENT_IMPULSE, v128.bitselect(totalY, accumulatedY, maskY));
      const pxX = f64x2.mul(impulseX, txX);
      const pxY = f64x2.mul(impulseY, txY);
      const pyX = f64x2.mul(impulseX, tyX);
      const pyY = f64x2.mul(impulseY, tyY);
      vAxX = v128.bitselect(f64x2.sub(vAxX, f64x2.mul(mAX, pxX)), vAxX, maskX);
      vAxY = v128.bitselect(f64x2.sub(vAxY, f64x2.mul(mAY, pxY)), vAxY, maskY);
      vAyX = v128.bitselect(f64x2.sub(vAyX, f64x2.mul(mAX, pyX)), vAyX, maskX);
      vAyY = v128.bitselect(f64x2.sub(vAyY, f64x2.mul(mAY, pyY)), vAyY, maskY);
      wAX = v128.bitselect(f64x2.sub(wAX, f64x2.mul(iAX, f64x2.sub(f64x2.mul(rAxX, pyX), f64x2.mul(rAyX, pxX)))), wAX, maskX);
      wAY = v128.bitselect(f64x2.sub(wAY, f64x2.mul(iAY, f64x2.sub(f64x2.mul(rAxY, pyY), f64x2.mul(rAyY, pxY)))), wAY, maskY);
      vBxX = v128.bitselect(f64x2.add(vBxX, f64x2.mul(mBX, pxX)), vBxX, maskX);
      vBxY = v128.bitselect(f64x2.add(vBxY, f64x2.mul(mBY, pxY)), vBxY, maskY);
      vByX = v128.bitselect(f64x2.add(vByX, f64x2.mul(mBX, pyX)), vByX, maskX);
      vByY = v128.bitselect(f64x2.add(vByY, f64x2.mul(mBY, pyY)), vByY, maskY);
      wBX = v128.bitselect(f64x2.add(wBX, f64x2.mul(iBX, f64x2.sub(f64x2.mul(rBxX, pyX), f64x2.mul(rByX, pxX)))), wBX, maskX);
      wBY = v128.bitselect(f64x2.add(wBY, f64x2.mul(iBY, f64x2.sub(f64x2.mul(rBxY, pyY), f64x2.mul(rByY, pxY)))), wBY, maskY);
    }
    const resistanceX = field(cX, ROLLING);
    const resistanceY = field(cY, ROLLING);
    const rollsX = f64x2.gt(resistanceX, zero);
    const rollsY = f64x2.gt(resistanceY, zero);
    if (v128.any_true(v128.or(rollsX, rollsY))) {
      const limitX = f64x2.mul(resistanceX, totalNormalImpulseX);
      const limitY = f64x2.mul(resistanceY, totalNormalImpulseY);
      const accumulatedX = field(cX, ROLLING_IMPULSE);
      const accumulatedY = field(cY, ROLLING_IMPULSE);
      const totalX = f64x2.max(f64x2.min(f64x2.sub(accumulatedX, f64x2.mul(field(cX, ROLLING_MASS), f64x2.sub(wBX, wAX))), limitX), f64x2.neg(limitX));
      const totalY = f64x2.max(f64x2.min(f64x2.sub(accumulatedY, f64x2.mul(field(cY, ROLLING_MASS), f64x2.sub(wBY, wAY))), limitY), f64x2.neg(limitY));
      const deltaX = f64x2.sub(totalX, accumulatedX);
      const deltaY = f64x2.sub(totalY, accumulatedY);
      put(cX, ROLLING_IMPULSE, v128.bitselect(totalX, accumulatedX, rollsX));
      put(cY, ROLLING_IMPULSE, v128.bitselect(totalY, accumulatedY, rollsY));
      wAX = v128.bitselect(f64x2.sub(wAX, f64x2.mul(iAX, deltaX)), wAX, rollsX);
      wAY = v128.bitselect(f64x2.sub(wAY, f64x2.mul(iAY, deltaY)), wAY, rollsY);
      wBX = v128.bitselect(f64x2.add(wBX, f64x2.mul(iBX, deltaX)), wBX, rollsX);
      wBY = v128.bitselect(f64x2.add(wBY, f64x2.mul(iBY, deltaY)), wBY, rollsY);
    }
    scatter(sa0X, 0, vAxX, vAyX, wAX);
    scatter(sa0Y, 0, vAxY, vAyY, wAY);
    scatter(sb0X, 0, vBxX, vByX, wBX);
    scatter(sb0Y, 0, vBxY, vByY, wBY);
    scatter(sa1X, 1, vAxX, vAyX, wAX);
    scatter(sa1Y, 1, vAxY, vAyY, wAY);
    scatter(sb1X, 1, vBxX, vByX, wBX);
    scatter(sb1Y, 1, vBxY, vByY, wBY);
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
