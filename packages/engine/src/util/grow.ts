/**
 * Capacity after geometric growth: at least double the current one, so that adding bodies one at
 * a time reallocates O(log n) times; exactly `needed` when that is more, so that a large reserve
 * or a first build of a big scene does not round up to the next power of two (up to 2x memory).
 */
export function grownCapacity(current: number, needed: number): number {
  return Math.max(needed, 2 * current, 16);
}

type Column = Float64Array | Float32Array | Int32Array | Uint32Array | Uint8Array | Int8Array;

/** A new array of the same kind with `capacity` elements, holding as much of `old` as fits. */
export function grow<T extends Column>(old: T, capacity: number): T {
  const next = new (old.constructor as new (length: number) => T)(capacity);
  next.set(old.subarray(0, Math.min(old.length, capacity)) as never);
  return next;
}
