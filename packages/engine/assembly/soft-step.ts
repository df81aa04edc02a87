// The soft step's three hot passes (src/solver/soft-step.ts: warmStart, solveContacts,
// relaxContacts), run on two constraints at once in 64-bit SIMD lanes. The constraints are stored
// in pairs, field by field, lane 0 beside lane 1, and the two of a pair share no moving body (they
// are of one colour), so solving them side by side gives each exactly the bits the TypeScript loop
// gives it one after the other. Every expression below keeps the TypeScript's order of operations;
// a lane without a point (a one-point manifold's second, or the empty lane closing a colour) keeps
// its old values through a select, and a lane writes its bodies back only when they are dynamic.

// Body state fields (8 doubles a body) and constraint field offsets in doubles, per lane pair: the
// TypeScript's offsets, each even, are 2 x the field's index, so a field of a pair is one v128.
const BODY: i32 = 8;
const VX: i32 = 0;
const VY: i32 = 8;
const W: i32 = 16;
const DPX: i32 = 24;
const DPY: i32 = 32;
const DQC: i32 = 40;
const DQS: i32 = 48;
const DYNAMIC: i32 = 56;

const PAIR: i32 = 80;
const NX: i32 = 0;
const NY: i32 = 2;
const FRICTION: i32 = 4;
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

@inline function field(c: usize, f: i32): v128 {
  return v128.load(c + (<usize>f << 3));
}

@inline function put(c: usize, f: i32, v: v128): void {
  v128.store(c + (<usize>f << 3), v);
}

/** Two bodies' field at byte offset `at`, one per lane. */
@inline function gather(s0: usize, s1: usize, at: i32): v128 {
  return f64x2.replace_lane(f64x2.splat(load<f64>(s0 + <usize>at)), 1, load<f64>(s1 + <usize>at));
}

@inline function bodyAt(states: usize, index: i32): usize {
  return states + (<usize>(index * BODY) << 3);
}

@inline function scatter(s: usize, lane: i32, vx: v128, vy: v128, w: v128): void {
  if (load<f64>(s + <usize>DYNAMIC) != 1) return;
  if (lane == 0) {
    store<f64>(s + <usize>VX, f64x2.extract_lane(vx, 0));
    store<f64>(s + <usize>VY, f64x2.extract_lane(vy, 0));
    store<f64>(s + <usize>W, f64x2.extract_lane(w, 0));
  } else {
    store<f64>(s + <usize>VX, f64x2.extract_lane(vx, 1));
    store<f64>(s + <usize>VY, f64x2.extract_lane(vy, 1));
    store<f64>(s + <usize>W, f64x2.extract_lane(w, 1));
  }
}

/** Lanes whose constraint has more than `p` points. */
@inline function hasPoint(c: usize, p: i32): v128 {
  return f64x2.gt(field(c, POINTS), f64x2.splat(<f64>p));
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
    let vAx = gather(sa0, sa1, VX);
    let vAy = gather(sa0, sa1, VY);
    let wA = gather(sa0, sa1, W);
    let vBx = gather(sb0, sb1, VX);
    let vBy = gather(sb0, sb1, VY);
    let wB = gather(sb0, sb1, W);
    for (let p = 0; p < 2; p++) {
      const mask = hasPoint(c, p);
      if (!v128.any_true(mask)) break;
      const q = c + (<usize>(P + p * POINT) << 3);
      const rAx = field(q, RAX);
      const rAy = field(q, RAY);
      const rBx = field(q, RBX);
      const rBy = field(q, RBY);
      const pn = field(q, NORMAL_IMPULSE);
      const pt = field(q, TANGENT_IMPULSE);
      const px = f64x2.add(f64x2.mul(pn, nx), f64x2.mul(pt, ny));
      const py = f64x2.sub(f64x2.mul(pn, ny), f64x2.mul(pt, nx));
      wA = v128.bitselect(f64x2.sub(wA, f64x2.mul(iA, f64x2.sub(f64x2.mul(rAx, py), f64x2.mul(rAy, px)))), wA, mask);
      vAx = v128.bitselect(f64x2.sub(vAx, f64x2.mul(mA, px)), vAx, mask);
      vAy = v128.bitselect(f64x2.sub(vAy, f64x2.mul(mA, py)), vAy, mask);
      wB = v128.bitselect(f64x2.add(wB, f64x2.mul(iB, f64x2.sub(f64x2.mul(rBx, py), f64x2.mul(rBy, px)))), wB, mask);
      vBx = v128.bitselect(f64x2.add(vBx, f64x2.mul(mB, px)), vBx, mask);
      vBy = v128.bitselect(f64x2.add(vBy, f64x2.mul(mB, py)), vBy, mask);
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

export function solve(states: usize, constraints: usize, pairs: usize, lanes: i32, inverseH: f64, pushSpeed: f64): void {
  const zero = f64x2.splat(0);
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
    let vAx = gather(sa0, sa1, VX);
    let vAy = gather(sa0, sa1, VY);
    let wA = gather(sa0, sa1, W);
    const qAc = gather(sa0, sa1, DQC);
    const qAs = gather(sa0, sa1, DQS);
    let vBx = gather(sb0, sb1, VX);
    let vBy = gather(sb0, sb1, VY);
    let wB = gather(sb0, sb1, W);
    const qBc = gather(sb0, sb1, DQC);
    const qBs = gather(sb0, sb1, DQS);
    const dpx = f64x2.sub(gather(sb0, sb1, DPX), gather(sa0, sa1, DPX));
    const dpy = f64x2.sub(gather(sb0, sb1, DPY), gather(sa0, sa1, DPY));
    const nx = field(c, NX);
    const ny = field(c, NY);
    const biasRate = field(c, BIAS_RATE);
    const softMassScale = field(c, MASS_SCALE);
    const softImpulseScale = field(c, IMPULSE_SCALE);
    // The second point's normal speed before this constraint's impulses, for noting its impact.
    const second = c + (<usize>(P + POINT) << 3);
    const before1 = f64x2.add(
      f64x2.mul(f64x2.sub(f64x2.sub(vBx, f64x2.mul(wB, field(second, RBY))), f64x2.sub(vAx, f64x2.mul(wA, field(second, RAY)))), nx),
      f64x2.mul(f64x2.sub(f64x2.add(vBy, f64x2.mul(wB, field(second, RBX))), f64x2.add(vAy, f64x2.mul(wA, field(second, RAX)))), ny),
    );
    for (let p = 0; p < 2; p++) {
      const mask = hasPoint(c, p);
      if (!v128.any_true(mask)) break;
      const q = c + (<usize>(P + p * POINT) << 3);
      const rAx = field(q, RAX);
      const rAy = field(q, RAY);
      const rBx = field(q, RBX);
      const rBy = field(q, RBY);
      const dsx = f64x2.sub(f64x2.add(dpx, f64x2.sub(f64x2.mul(qBc, rBx), f64x2.mul(qBs, rBy))), f64x2.sub(f64x2.mul(qAc, rAx), f64x2.mul(qAs, rAy)));
      const dsy = f64x2.sub(f64x2.add(dpy, f64x2.add(f64x2.mul(qBs, rBx), f64x2.mul(qBc, rBy))), f64x2.add(f64x2.mul(qAs, rAx), f64x2.mul(qAc, rAy)));
      const s = f64x2.add(f64x2.add(field(q, BASE_SEPARATION), f64x2.mul(dsx, nx)), f64x2.mul(dsy, ny));
      const speculative = f64x2.gt(s, zero);
      const bias = v128.bitselect(f64x2.mul(s, invH), f64x2.max(f64x2.mul(f64x2.mul(biasRate, softMassScale), s), floor), speculative);
      const massScale = v128.bitselect(one, softMassScale, speculative);
      const impulseScale = v128.bitselect(zero, softImpulseScale, speculative);
      const dvx = f64x2.sub(f64x2.sub(vBx, f64x2.mul(wB, rBy)), f64x2.sub(vAx, f64x2.mul(wA, rAy)));
      const dvy = f64x2.sub(f64x2.add(vBy, f64x2.mul(wB, rBx)), f64x2.add(vAy, f64x2.mul(wA, rAx)));
      const vn = f64x2.add(f64x2.mul(dvx, nx), f64x2.mul(dvy, ny));
      const accumulated = field(q, NORMAL_IMPULSE);
      let impulse = f64x2.sub(f64x2.mul(f64x2.neg(field(q, NORMAL_MASS)), f64x2.add(f64x2.mul(massScale, vn), bias)), f64x2.mul(impulseScale, accumulated));
      const total = f64x2.max(f64x2.add(accumulated, impulse), zero);
      impulse = f64x2.sub(total, accumulated);
      put(q, NORMAL_IMPULSE, v128.bitselect(total, accumulated, mask));
      noteImpact(q, mask, total, p == 0 ? vn : before1, zero);
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

/** The largest impulse so far, and the approach speed at the first one (the moment of impact), for the lanes in `mask`. */
@inline function noteImpact(q: usize, mask: v128, total: v128, approach: v128, zero: v128): void {
  const most = field(q, MAX_NORMAL_IMPULSE);
  const grows = v128.and(mask, f64x2.gt(total, most));
  const first = v128.and(v128.and(grows, f64x2.eq(most, zero)), f64x2.lt(approach, zero));
  put(q, IMPACT_VELOCITY, v128.bitselect(approach, field(q, IMPACT_VELOCITY), first));
  put(q, MAX_NORMAL_IMPULSE, v128.bitselect(total, most, grows));
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
    let vAx = gather(sa0, sa1, VX);
    let vAy = gather(sa0, sa1, VY);
    let wA = gather(sa0, sa1, W);
    const qAc = gather(sa0, sa1, DQC);
    const qAs = gather(sa0, sa1, DQS);
    let vBx = gather(sb0, sb1, VX);
    let vBy = gather(sb0, sb1, VY);
    let wB = gather(sb0, sb1, W);
    const qBc = gather(sb0, sb1, DQC);
    const qBs = gather(sb0, sb1, DQS);
    const dpx = f64x2.sub(gather(sb0, sb1, DPX), gather(sa0, sa1, DPX));
    const dpy = f64x2.sub(gather(sb0, sb1, DPY), gather(sa0, sa1, DPY));
    const nx = field(c, NX);
    const ny = field(c, NY);
    let totalNormalImpulse = zero;
    const second = c + (<usize>(P + POINT) << 3);
    const before1 = f64x2.add(
      f64x2.mul(f64x2.sub(f64x2.sub(vBx, f64x2.mul(wB, field(second, RBY))), f64x2.sub(vAx, f64x2.mul(wA, field(second, RAY)))), nx),
      f64x2.mul(f64x2.sub(f64x2.add(vBy, f64x2.mul(wB, field(second, RBX))), f64x2.add(vAy, f64x2.mul(wA, field(second, RAX)))), ny),
    );
    for (let p = 0; p < 2; p++) {
      const mask = hasPoint(c, p);
      if (!v128.any_true(mask)) break;
      const q = c + (<usize>(P + p * POINT) << 3);
      const rAx = field(q, RAX);
      const rAy = field(q, RAY);
      const rBx = field(q, RBX);
      const rBy = field(q, RBY);
      const dsx = f64x2.sub(f64x2.add(dpx, f64x2.sub(f64x2.mul(qBc, rBx), f64x2.mul(qBs, rBy))), f64x2.sub(f64x2.mul(qAc, rAx), f64x2.mul(qAs, rAy)));
      const dsy = f64x2.sub(f64x2.add(dpy, f64x2.add(f64x2.mul(qBs, rBx), f64x2.mul(qBc, rBy))), f64x2.add(f64x2.mul(qAs, rAx), f64x2.mul(qAc, rAy)));
      const s = f64x2.add(f64x2.add(field(q, BASE_SEPARATION), f64x2.mul(dsx, nx)), f64x2.mul(dsy, ny));
      const bias = v128.bitselect(f64x2.mul(s, invH), zero, f64x2.gt(s, zero));
      const dvx = f64x2.sub(f64x2.sub(vBx, f64x2.mul(wB, rBy)), f64x2.sub(vAx, f64x2.mul(wA, rAy)));
      const dvy = f64x2.sub(f64x2.add(vBy, f64x2.mul(wB, rBx)), f64x2.add(vAy, f64x2.mul(wA, rAx)));
      const vn = f64x2.add(f64x2.mul(dvx, nx), f64x2.mul(dvy, ny));
      const accumulated = field(q, NORMAL_IMPULSE);
      let impulse = f64x2.mul(f64x2.neg(field(q, NORMAL_MASS)), f64x2.add(vn, bias));
      const total = f64x2.max(f64x2.add(accumulated, impulse), zero);
      impulse = f64x2.sub(total, accumulated);
      put(q, NORMAL_IMPULSE, v128.bitselect(total, accumulated, mask));
      noteImpact(q, mask, total, p == 0 ? vn : before1, zero);
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
    for (let p = 0; p < 2; p++) {
      const mask = hasPoint(c, p);
      if (!v128.any_true(mask)) break;
      const q = c + (<usize>(P + p * POINT) << 3);
      const rAx = field(q, RAX);
      const rAy = field(q, RAY);
      const rBx = field(q, RBX);
      const rBy = field(q, RBY);
      const dvx = f64x2.sub(f64x2.sub(vBx, f64x2.mul(wB, rBy)), f64x2.sub(vAx, f64x2.mul(wA, rAy)));
      const dvy = f64x2.sub(f64x2.add(vBy, f64x2.mul(wB, rBx)), f64x2.add(vAy, f64x2.mul(wA, rAx)));
      const vt = f64x2.add(f64x2.mul(dvx, tx), f64x2.mul(dvy, ty));
      const accumulated = field(q, TANGENT_IMPULSE);
      const limit = f64x2.mul(friction, field(q, NORMAL_IMPULSE));
      // total < -limit ? -limit : total > limit ? limit : total, for limit >= 0 (signed zeros included).
      const total = f64x2.max(f64x2.min(f64x2.sub(accumulated, f64x2.mul(field(q, TANGENT_MASS), vt)), limit), f64x2.neg(limit));
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
      const total = f64x2.max(f64x2.min(f64x2.sub(accumulated, f64x2.mul(field(c, ROLLING_MASS), f64x2.sub(wB, wA))), limit), f64x2.neg(limit));
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
