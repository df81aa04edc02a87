// Every public entry point validates its whole input before it touches any state, so a thrown
// error always leaves the world exactly as it was.

function show(value: unknown): string {
  if (typeof value === 'string') return JSON.stringify(value);
  if (typeof value === 'bigint') return `${value}n`;
  if (typeof value === 'object' && value !== null) {
    try {
      return JSON.stringify(value);
    } catch {
      return Object.prototype.toString.call(value);
    }
  }
  return String(value);
}

export function finiteNumber(field: string, value: unknown): number {
  if (typeof value !== 'number' || !Number.isFinite(value)) {
    throw new TypeError(`${field} must be a finite number, got ${show(value)}`);
  }
  return value;
}

/**
 * The largest magnitude a coordinate, size, speed, gravity or mass may have (and 1 / it the
 * smallest mass): with every input within 1e100, with dt within MAX_DT and restitution within
 * MAX_RESTITUTION, no product a step forms comes near the largest double, so no step can make an
 * infinity or a NaN from finite input.
 */
export const MAX_MAGNITUDE = 1e100;
/**
 * How far a shape may reach from its body's origin. Its second moment of area grows as the fourth
 * power of its size, so this keeps that, times any density, within the largest double.
 */
export const MAX_SHAPE_REACH = 1e50;
/** The longest step: a million seconds. */
export const MAX_DT = 1e6;
/**
 * The shortest step but 0: 1 / MAX_MAGNITUDE. A spring's bias rate is 1 / its sub-step, infinite
 * below 1 / the largest double, and a sub-step rounded to 0 makes a damped one 0 / 0.
 */
export const MIN_DT = 1 / MAX_MAGNITUDE;
/** The most a restitution may multiply an approach speed by. */
export const MAX_RESTITUTION = 1000;

/** A finite number within MAX_MAGNITUDE of 0: a TypeError when not a finite number, a RangeError beyond. */
export function boundedNumber(field: string, value: unknown): number {
  const n = finiteNumber(field, value);
  if (!(Math.abs(n) <= MAX_MAGNITUDE)) throw new RangeError(`${field} must be within ±${MAX_MAGNITUDE} (so that no step can overflow), got ${show(value)}`);
  return n;
}

/** A positive bounded number, at least 1 / MAX_MAGNITUDE. */
export function boundedPositive(field: string, value: unknown): number {
  const n = positiveNumber(field, value);
  if (!(n <= MAX_MAGNITUDE && n >= 1 / MAX_MAGNITUDE)) throw new RangeError(`${field} must be within [${1 / MAX_MAGNITUDE}, ${MAX_MAGNITUDE}] (so that no step can overflow), got ${show(value)}`);
  return n;
}

/** A non-negative bounded number. */
export function boundedNonNegative(field: string, value: unknown): number {
  const n = nonNegativeNumber(field, value);
  if (!(n <= MAX_MAGNITUDE)) throw new RangeError(`${field} must be at most ${MAX_MAGNITUDE} (so that no step can overflow), got ${show(value)}`);
  return n;
}

export function positiveNumber(field: string, value: unknown): number {
  const n = finiteNumber(field, value);
  if (!(n > 0)) throw new RangeError(`${field} must be > 0, got ${show(value)}`);
  return n;
}

export function nonNegativeNumber(field: string, value: unknown): number {
  const n = finiteNumber(field, value);
  if (!(n >= 0)) throw new RangeError(`${field} must be >= 0, got ${show(value)}`);
  return n;
}

/** A whole number >= 0: a TypeError when not a finite number, a RangeError when fractional or negative. */
export function nonNegativeInteger(field: string, value: unknown): number {
  const n = finiteNumber(field, value);
  if (!Number.isSafeInteger(n) || n < 0) throw new RangeError(`${field} must be a non-negative integer, got ${show(value)}`);
  return n;
}

export function oneOf<T extends string>(field: string, value: unknown, allowed: readonly T[]): T {
  if (typeof value !== 'string' || !(allowed as readonly string[]).includes(value)) {
    throw new RangeError(`${field} must be one of ${allowed.map((a) => `'${a}'`).join(', ')}, got ${show(value)}`);
  }
  return value as T;
}

export function plainObject(field: string, value: unknown, copy = true): Record<string, unknown> {
  if (typeof value !== 'object' || value === null || Array.isArray(value)) {
    throw new TypeError(`${field} must be an object, got ${show(value)}`);
  }
  // Only own keys are checked against the known names, so a Map or an object inheriting options
  // would pass its misspellings (or all its entries) unread.
  // A plain object's prototype is null or an Object.prototype (of any realm: its own is null).
  if (!hasPlainPrototype(value)) throw new TypeError(`${field} must be a plain object, got ${describeInstance(value)}`);
  return copy ? (copyOwn(value, 0) as Record<string, unknown>) : (value as Record<string, unknown>);
}

function hasPlainPrototype(value: object): boolean {
  const prototype: unknown = Object.getPrototypeOf(value);
  return prototype === null || Object.getPrototypeOf(prototype) === null;
}

/** How deep copyOwn copies: options hold a vertex list of points at most, two levels down. */
const COPY_DEPTH = 3;
/**
 * Longer arrays are left as they are: a list of 65,536 is longer than any a check accepts but a
 * pressure ring's (whose bodies are then read where they are), and an array of a billion holes
 * is refused by its length before it is read.
 */
const COPY_LENGTH = 65536;

/**
 * A copy of an options object, each own key read once (a getter runs once), and the plain
 * objects and arrays in it copied the same way: the checks and the world then read the copy, so
 * the value checked is the value used. Anything else (class instances) is kept as it is, for the
 * checks to refuse.
 */
function copyOwn(value: object, depth: number): Record<string, unknown> | unknown[] {
  const copyItem = (item: unknown): unknown =>
    depth + 1 < COPY_DEPTH && typeof item === 'object' && item !== null && (Array.isArray(item) ? item.length <= COPY_LENGTH : hasPlainPrototype(item)) ? copyOwn(item, depth + 1) : item;
  if (Array.isArray(value)) {
    const out: unknown[] = [];
    for (let i = 0; i < value.length; i++) out.push(copyItem(value[i]));
    return out;
  }
  const out: Record<string, unknown> = {};
  for (const key of Object.keys(value)) out[key] = copyItem((value as Record<string, unknown>)[key]);
  return out;
}

/** Rejects misspelt option names, which would otherwise be ignored without a word. */
export function knownKeys(field: string, value: Record<string, unknown>, allowed: readonly string[]): void {
  for (const key of Object.keys(value)) {
    if (!allowed.includes(key)) {
      throw new TypeError(`${field} has unknown option '${key}'; known options: ${allowed.join(', ')}`);
    }
  }
}

export { show as describeValue };

function describeInstance(value: object): string {
  const name = (value as { constructor?: { name?: unknown } }).constructor?.name;
  return typeof name === 'string' && name !== 'Object' ? `a ${name}` : 'an object with a prototype of its own';
}
