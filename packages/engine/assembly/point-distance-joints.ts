// The point distance joints' passes (src/solver/joints/point-distance-joints.ts: warmStart and
// solve), on two joints at once, one per 64-bit SIMD lane. The lanes are stored in pairs, field
// by field, lane 0 beside lane 1; a colour is padded to whole pairs, so the two joints of a pair
// share no moving body, and solving them side by side gives each exactly the bits the TypeScript
// loop gives it one after the other. Every expression keeps the TypeScript's order of operations,
// and a lane writes a body back only when it is dynamic.

import { DPX, DYNAMIC, VX, bodyAt, field, firsts, seconds } from './lanes';

// Lane fields in doubles, per pair of lanes (each field of a pair is one v128).
const LANE_PAIR: i32 = 30;
const MA: i32 = 0;
const MB: i32 = 2;
const DCX: i32 = 4;
const DCY: i32 = 6;
const AX: i32 = 8;
const AY: i32 = 10;
const MASS: i32 = 12;
const LENGTH: i32 = 14;
const IMPULSE: i32 = 16;
const BIAS: i32 = 18;
const SCALE: i32 = 20;
const KEEP: i32 = 22;

/** Lane `lane` of (vx, vy) into body s's velocity, where s is dynamic. */
@inline function scatter(s: usize, lane: i32, vx: v128, vy: v128): void {
  if (load<f64>(s + <usize>DYNAMIC) != 1) return;
  v128.store(s + <usize>VX, lane == 0 ? firsts(vx, vy) : seconds(vx, vy));
}

/**
 * One pass over the lanes: the warm start (`warm`), applying each joint's kept impulse, or a
 * solve with the softness at `pass` (0: biased, 6: relax).
 */
@inline function sweep(states: usize, rows: usize, pairs: usize, lanes: i32, pass: i32, warm: bool): void {
  const zero = f64x2.splat(0);
  for (let p = 0; p < lanes >> 1; p++) {
    const c = rows + (<usize>(p * LANE_PAIR) << 3);
    const ix = pairs + (<usize>p << 4);
    const sa0 = bodyAt(states, load<i32>(ix));
    const sb0 = bodyAt(states, load<i32>(ix, 4));
    const sa1 = bodyAt(states, load<i32>(ix, 8));
    const sb1 = bodyAt(states, load<i32>(ix, 12));
    const pa0 = v128.load(sa0 + <usize>DPX);
    const pa1 = v128.load(sa1 + <usize>DPX);
    const pb0 = v128.load(sb0 + <usize>DPX);
    const pb1 = v128.load(sb1 + <usize>DPX);
    const dx = f64x2.add(f64x2.sub(firsts(pb0, pb1), firsts(pa0, pa1)), field(c, DCX));
    const dy = f64x2.add(f64x2.sub(seconds(pb0, pb1), seconds(pa0, pa1)), field(c, DCY));
    const length = f64x2.sqrt(f64x2.add(f64x2.mul(dx, dx), f64x2.mul(dy, dy)));
    const apart = f64x2.gt(length, zero);
    const ax = v128.bitselect(f64x2.div(dx, length), field(c, AX), apart);
    const ay = v128.bitselect(f64x2.div(dy, length), field(c, AY), apart);
    const a0 = v128.load(sa0 + <usize>VX);
    const a1 = v128.load(sa1 + <usize>VX);
    const b0 = v128.load(sb0 + <usize>VX);
    const b1 = v128.load(sb1 + <usize>VX);
    const vAx = firsts(a0, a1);
    const vAy = seconds(a0, a1);
    const vBx = firsts(b0, b1);
    const vBy = seconds(b0, b1);
    let impulse: v128;
    if (warm) {
      impulse = field(c, IMPULSE);
    } else {
      const C = f64x2.sub(length, field(c, LENGTH));
      const speed = f64x2.add(f64x2.mul(f64x2.sub(vBx, vAx), ax), f64x2.mul(f64x2.sub(vBy, vAy), ay));
      const accumulated = field(c, IMPULSE);
      const q = c + (<usize>pass << 3);
      impulse = f64x2.sub(
        f64x2.mul(f64x2.mul(f64x2.neg(field(q, SCALE)), field(c, MASS)), f64x2.add(speed, f64x2.mul(field(q, BIAS), C))),
        f64x2.mul(field(q, KEEP), accumulated),
      );
      v128.store(c + (<usize>IMPULSE << 3), f64x2.add(accumulated, impulse));
    }
    const px = f64x2.mul(impulse, ax);
    const py = f64x2.mul(impulse, ay);
    const mA = field(c, MA);
    const mB = field(c, MB);
    const nAx = f64x2.sub(vAx, f64x2.mul(mA, px));
    const nAy = f64x2.sub(vAy, f64x2.mul(mA, py));
    const nBx = f64x2.add(vBx, f64x2.mul(mB, px));
    const nBy = f64x2.add(vBy, f64x2.mul(mB, py));
    scatter(sa0, 0, nAx, nAy);
    scatter(sb0, 0, nBx, nBy);
    scatter(sa1, 1, nAx, nAy);
    scatter(sb1, 1, nBx, nBy);
  }
}

export function pointDistanceWarmStart(states: usize, rows: usize, pairs: usize, lanes: i32): void {
  sweep(states, rows, pairs, lanes, 0, true);
}

export function pointDistanceSolve(states: usize, rows: usize, pairs: usize, lanes: i32, pass: i32): void {
  sweep(states, rows, pairs, lanes, pass, false);
}
