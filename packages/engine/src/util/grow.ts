/**
 * Capacity after geometric growth: at least double the current one, so that adding bodies one at
 * a time reallocates O(log n) times; exactly `needed` when that is more, so that a large reserve
 * or a first build of a big scene does not round up to the next power of two (up to 2x memory).
 */
export function grownCapacity(current: number, needed: number): number {
  return Math.max(needed, 2 * current, 16);
}

export type Column = Float64Array | Float32Array | Int32Array | Uint32Array | Uint8Array | Int8Array;

type ColumnConstructor<T extends Column> = {
  new (length: number): T;
  new (buffer: SharedArrayBuffer): T;
  readonly BYTES_PER_ELEMENT: number;
};

/**
 * A zeroed array of `old`'s kind with `length` elements. `shared` puts it on a SharedArrayBuffer,
 * which worker threads of a parallel step can see; plain memory otherwise, because shared memory
 * needs cross-origin isolation in browsers and a single-threaded world has no use for it.
 */
export function allocateLike<T extends Column>(old: T, length: number, shared = false): T {
  const Ctor = old.constructor as ColumnConstructor<T>;
  return shared ? new Ctor(new SharedArrayBuffer(length * Ctor.BYTES_PER_ELEMENT)) : new Ctor(length);
}

/** A new array of the same kind with `capacity` elements, holding as much of `old` as fits. */
export function grow<T extends Column>(old: T, capacity: number, shared = false): T {
  const next = allocateLike(old, capacity, shared);
  next.set(old.subarray(0, Math.min(old.length, capacity)) as never);
  return next;
}
