// What the soft step's kernels share (soft-step.ts, point-distance-joints.ts): the layout of a
// body's solver state (src/solver/solver-body.ts, 8 doubles a body), as byte offsets, and the
// loads and stores of a field of two lanes stored side by side.

export const BODY: i32 = 8;
export const VX: i32 = 0;
export const VY: i32 = 8;
export const W: i32 = 16;
export const DPX: i32 = 24;
export const DPY: i32 = 32;
export const DQC: i32 = 40;
export const DQS: i32 = 48;
export const DYNAMIC: i32 = 56;

/** Field `f` (in doubles) of the lane pair at `c`: lane 0 and lane 1 in one v128. */
@inline export function field(c: usize, f: i32): v128 {
  return v128.load(c + (<usize>f << 3));
}

@inline export function put(c: usize, f: i32, v: v128): void {
  v128.store(c + (<usize>f << 3), v);
}

/** Two bodies' field at byte offset `at`, one per lane. */
@inline export function gather(s0: usize, s1: usize, at: i32): v128 {
  return f64x2.replace_lane(f64x2.splat(load<f64>(s0 + <usize>at)), 1, load<f64>(s1 + <usize>at));
}

/** The first of each of two (field, next field) pairs: lane 0 from a, lane 1 from b. */
@inline export function firsts(a: v128, b: v128): v128 {
  return v128.shuffle<f64>(a, b, 0, 2);
}

/** The second of each. */
@inline export function seconds(a: v128, b: v128): v128 {
  return v128.shuffle<f64>(a, b, 1, 3);
}

/** Where body `index`'s state starts. */
@inline export function bodyAt(states: usize, index: i32): usize {
  return states + (<usize>(index * BODY) << 3);
}
