/** Capacity after geometric growth: at least `needed`, at least double the current one. */
export function grownCapacity(current: number, needed: number): number {
  let capacity = Math.max(current, 16);
  while (capacity < needed) capacity *= 2;
  return capacity;
}

export function growFloat64(old: Float64Array, capacity: number) {
  const next = new Float64Array(capacity);
  next.set(old.subarray(0, Math.min(old.length, capacity)));
  return next;
}

export function growInt32(old: Int32Array, capacity: number) {
  const next = new Int32Array(capacity);
  next.set(old.subarray(0, Math.min(old.length, capacity)));
  return next;
}

export function growUint32(old: Uint32Array, capacity: number) {
  const next = new Uint32Array(capacity);
  next.set(old.subarray(0, Math.min(old.length, capacity)));
  return next;
}

export function growUint8(old: Uint8Array, capacity: number) {
  const next = new Uint8Array(capacity);
  next.set(old.subarray(0, Math.min(old.length, capacity)));
  return next;
}

export function growFloat32(old: Float32Array, capacity: number) {
  const next = new Float32Array(capacity);
  next.set(old.subarray(0, Math.min(old.length, capacity)));
  return next;
}
