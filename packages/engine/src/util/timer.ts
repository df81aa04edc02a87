// `performance` is global in browsers and in Node >= 16; the engine declares the one call it makes
// instead of pulling DOM or Node typings into a dependency-free library.
declare const performance: { now(): number };

/** Milliseconds from a monotonic clock; used only for `world.stats`, never for physics. */
export function nowMs(): number {
  return performance.now();
}
