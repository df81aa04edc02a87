/**
 * A world's state as a tree of plain values, read from the live objects and written back onto a
 * freshly built world of the same configuration.
 *
 * The tree is taken field by field from the objects themselves rather than from a hand-kept list
 * of columns: a snapshot must give the same bits as the world it came from, and every cache a
 * step reads (warm-start impulses, the narrow-phase's pose cache, sleep timers, free lists, the
 * broad-phase's persistent order) takes part in those bits. A list kept by hand would go stale
 * the first time someone adds a field; walking the objects cannot miss one.
 *
 * What is not state is named here once: host resources (WebAssembly instances and memories,
 * worker threads) and functions stay those of the world being written to. Objects shared between
 * owners (one body store read by the pipeline, the queries and the solver) are written once and
 * referred to after, so that the restored world shares them the same way.
 */

export type TypedArray =
  | Float64Array
  | Float32Array
  | Int32Array
  | Uint32Array
  | Int16Array
  | Uint16Array
  | Int8Array
  | Uint8Array
  | Uint8ClampedArray
  | BigInt64Array
  | BigUint64Array;

/** A node of the tree. Objects and typed arrays carry their visit index, which refs point at. */
export type StateValue =
  | { t: 'keep' }
  | { t: 'value'; v: number | string | boolean | null | undefined }
  | { t: 'array'; id: number; items: StateValue[] }
  | { t: 'typed'; id: number; kind: number; data: TypedArray }
  | { t: 'object'; id: number; name: string; fields: [string, StateValue][] }
  | { t: 'map'; id: number; entries: [StateValue, StateValue][] }
  | { t: 'set'; id: number; items: StateValue[] }
  | { t: 'ref'; id: number };

/** Typed array kinds by the code written for them; the code is part of the format. */
export const TYPED_KINDS = [
  Float64Array,
  Float32Array,
  Int32Array,
  Uint32Array,
  Int16Array,
  Uint16Array,
  Int8Array,
  Uint8Array,
  Uint8ClampedArray,
  BigInt64Array,
  BigUint64Array,
] as const;

/** A thrown failure to restore, with the path in the world where the state did not fit. */
export class StateMismatch extends Error {}

/**
 * Classes whose instances are host resources, not state: a world's kernels are compiled
 * WebAssembly over memories that only hold what a step copies in (columns living there are
 * reached, and saved, through their owners' fields), and a parallel step is threads.
 */
export function isHostResource(value: object): boolean {
  const wasm = (globalThis as { WebAssembly?: { Memory: Function; Instance: Function; Module: Function } }).WebAssembly;
  if (wasm && (value instanceof wasm.Memory || value instanceof wasm.Instance || value instanceof wasm.Module)) return true;
  return HOST_CLASSES.has(value.constructor);
}

const HOST_CLASSES = new Set<Function>();
const TRANSIENT = new Map<Function, Set<string>>();
const PARTS = new Map<string, Function>();
const PART_NAMES = new Map<Function, string>();

/** Marks a class as a host resource (see isHostResource): its instances stay the target world's. */
export function hostResource(ctor: Function): void {
  HOST_CLASSES.add(ctor);
}

/**
 * Fields of a class that are not the world's state: scratch a step refills before it reads it
 * (often views into a kernel's memory), what reading calls fill, a cache's notes of the layout it
 * was made over, kernels, and counts of what the world's shortcuts did. Left out of snapshots,
 * and never written from one: the target world keeps its own.
 */
export function transientFields(ctor: Function, fields: string[]): void {
  const known = TRANSIENT.get(ctor);
  if (known === undefined) TRANSIENT.set(ctor, new Set(fields));
  else for (const field of fields) known.add(field);
}

/**
 * A class whose instances a world makes lazily (on first use), so that a freshly built world may
 * lack one the snapshot has: restore then makes one with its constructor and fills every field
 * the snapshot holds (the transient ones keep the new part's).
 * The key, not the class's name, goes into the snapshot: minified builds rename classes.
 */
export function lazyPart(key: string, ctor: Function): void {
  PARTS.set(key, ctor);
  PART_NAMES.set(ctor, key);
}

function typedKind(value: ArrayBufferView): number {
  for (let k = 0; k < TYPED_KINDS.length; k++) if (value instanceof TYPED_KINDS[k]) return k;
  return -1;
}

function isPlainObject(value: object): boolean {
  const proto = Object.getPrototypeOf(value);
  return proto === Object.prototype || proto === null;
}

/** Reads `root`'s state into a tree (see the module comment). Typed arrays are copied. */
export function captureState(root: object): StateValue {
  const seen = new Map<object, number>();
  let next = 0;
  const visit = (value: unknown, path: string): StateValue => {
    if (value === null || value === undefined || typeof value === 'number' || typeof value === 'string' || typeof value === 'boolean') {
      return { t: 'value', v: value };
    }
    if (typeof value === 'function') return { t: 'keep' };
    if (typeof value !== 'object') throw new StateMismatch(`cannot snapshot ${path}: a ${typeof value}`);
    const known = seen.get(value);
    if (known !== undefined) return { t: 'ref', id: known };
    if (isHostResource(value)) return { t: 'keep' };
    const id = next++;
    seen.set(value, id);
    if (ArrayBuffer.isView(value)) {
      const kind = typedKind(value);
      if (kind < 0) throw new StateMismatch(`cannot snapshot ${path}: a ${value.constructor.name}`);
      const Ctor = TYPED_KINDS[kind] as unknown as { new (source: ArrayLike<number>): TypedArray };
      return { t: 'typed', id, kind, data: new Ctor(value as unknown as ArrayLike<number>) };
    }
    if (Array.isArray(value)) return { t: 'array', id, items: value.map((item, i) => visit(item, `${path}[${i}]`)) };
    if (value instanceof Map) {
      const entries: [StateValue, StateValue][] = [];
      for (const [k, v] of value) entries.push([visit(k, `${path} key`), visit(v, `${path}.get(${String(k)})`)]);
      return { t: 'map', id, entries };
    }
    if (value instanceof Set) return { t: 'set', id, items: [...value].map((item) => visit(item, `${path} item`)) };
    const fields: [string, StateValue][] = [];
    const transient = TRANSIENT.get(value.constructor);
    for (const key of Object.keys(value)) {
      fields.push([key, transient?.has(key) ? { t: 'keep' } : visit((value as Record<string, unknown>)[key], `${path}.${key}`)]);
    }
    const name = isPlainObject(value) ? '' : (PART_NAMES.get(value.constructor) ?? value.constructor.name);
    return { t: 'object', id, name, fields };
  };
  return visit(root, 'world');
}

/**
 * Writes a captured tree onto `root`, an object of the same configuration (a world freshly built
 * with the same options and the same lazily made parts): values are assigned, typed arrays
 * refilled in place where they have the same kind and length (so that columns inside a kernel's
 * memory stay there), objects filled field by field. Throws StateMismatch, naming the path, where
 * the tree does not fit: `root` may then be half written, so it must be a scratch world.
 */
export function applyState(root: object, tree: StateValue): void {
  const made = new Map<number, unknown>();
  const apply = (target: unknown, node: StateValue, path: string): unknown => {
    switch (node.t) {
      case 'keep':
        return target;
      case 'value':
        return node.v;
      case 'ref':
        if (!made.has(node.id)) throw new StateMismatch(`${path} refers to a part not yet restored`);
        return made.get(node.id);
      case 'typed': {
        const Ctor = TYPED_KINDS[node.kind];
        let out: TypedArray;
        if (target instanceof Ctor && target.length === node.data.length) {
          (target as TypedArray).set(node.data as never);
          out = target as TypedArray;
        } else {
          if (ArrayBuffer.isView(target) && (target.byteOffset !== 0 || target.byteLength !== target.buffer.byteLength)) {
            throw new StateMismatch(`${path} is a view into a larger memory of another size (${(target as TypedArray).length}, the snapshot has ${node.data.length})`);
          }
          out = node.data;
        }
        made.set(node.id, out);
        return out;
      }
      case 'array': {
        const out: unknown[] = Array.isArray(target) ? target : [];
        made.set(node.id, out);
        const old = out.slice();
        out.length = node.items.length;
        for (let i = 0; i < node.items.length; i++) out[i] = apply(old[i], node.items[i], `${path}[${i}]`);
        return out;
      }
      case 'map': {
        const out = target instanceof Map ? target : new Map();
        made.set(node.id, out);
        out.clear();
        for (const [k, v] of node.entries) out.set(apply(undefined, k, `${path} key`), apply(undefined, v, `${path} value`));
        return out;
      }
      case 'set': {
        const out = target instanceof Set ? target : new Set();
        made.set(node.id, out);
        out.clear();
        for (const item of node.items) out.add(apply(undefined, item, `${path} item`));
        return out;
      }
      case 'object': {
        let out: Record<string, unknown>;
        if (node.name === '') {
          out = target !== null && typeof target === 'object' && isPlainObject(target) ? (target as Record<string, unknown>) : {};
        } else if (target === null || typeof target !== 'object' || isPlainObject(target) || (PARTS.has(node.name) && !(target instanceof PARTS.get(node.name)!))) {
          const part = PARTS.get(node.name);
          if (part === undefined) throw new StateMismatch(`${path} is ${target === null ? 'null' : typeof target} here, a ${node.name} in the snapshot`);
          // Made by its constructor (the parts take no arguments), so that the fields left out
          // of snapshots (see transientFields) hold a new part's values.
          out = new (part as new () => Record<string, unknown>)();
        } else {
          out = target as Record<string, unknown>;
        }
        made.set(node.id, out);
        const keys = Object.keys(out);
        if (node.name !== '') {
          const saved = new Set(node.fields.map(([key]) => key));
          if (keys.length !== saved.size || keys.some((key) => !saved.has(key))) {
            // The fields that differ, not both lists: a class holds dozens of fields.
            const here = keys.filter((key) => !saved.has(key));
            const there = [...saved].filter((key) => !keys.includes(key));
            const parts = [here.length > 0 ? `${here.join(', ')} here but not in the snapshot` : '', there.length > 0 ? `${there.join(', ')} in the snapshot but not here` : ''];
            throw new StateMismatch(`${path} has ${parts.filter((part) => part !== '').join('; ')}`);
          }
        }
        if (node.name === '') for (const key of keys) if (!node.fields.some(([k]) => k === key)) delete out[key];
        // A transient field keeps the target's value even where the bytes hold one (an image from
        // a build that saved it, rewritten under a new hash): a note of a layout the target's
        // memory does not have would make a cache skip its remaking.
        const transient = TRANSIENT.get(out.constructor);
        for (const [key, value] of node.fields) {
          if (transient !== undefined && transient.has(key)) continue;
          out[key] = apply(out[key], value, `${path}.${key}`);
        }
        return out;
      }
    }
  };
  apply(root, tree, 'world');
}
