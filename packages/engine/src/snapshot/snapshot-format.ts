import { TYPED_KINDS, type StateValue, type TypedArray } from './state-graph.js';

/**
 * The bytes of a snapshot:
 *
 *   offset 0   4 bytes  magic "MXGS"
 *          4   u16      format version (FORMAT_VERSION)
 *          6   u16      0 (reserved)
 *          8   u32      payload length in bytes
 *         12   u32      FNV-1a hash of the payload's 32-bit words
 *         16            payload: the writing engine's version, then the world's state, as tagged values
 *
 * Numbers are little-endian; typed arrays are their elements' bytes, little-endian on every host
 * that runs JavaScript engines today, written as runs of zeros and literal bytes. A value is a tag
 * byte and its body: strings and typed arrays carry a u32 length, objects their field names, and an object met a second time is a reference
 * to its first appearance, so that parts shared by several owners stay shared.
 *
 * A snapshot is read whole, hash checked, before anything is built from it: a corrupt or cut
 * image is refused with the reason and never half applied.
 */

export const FORMAT_VERSION = 1;
const MAGIC = [0x4d, 0x58, 0x47, 0x53]; // "MXGS"
const HEADER_BYTES = 16;
/** Zero bytes in a row that end a literal stretch of a typed array (see Writer.runs). */
const MIN_ZERO_RUN = 16;

const enum Tag {
  undefined = 0,
  null = 1,
  false = 2,
  true = 3,
  number = 4,
  string = 5,
  typed = 6,
  array = 7,
  object = 8,
  map = 9,
  set = 10,
  ref = 11,
  keep = 12,
}

export interface SnapshotContent {
  engineVersion: string;
  state: StateValue;
}

class Writer {
  private bytes = new Uint8Array(1 << 16);
  private view = new DataView(this.bytes.buffer);
  length = HEADER_BYTES;

  private room(extra: number): void {
    if (this.length + extra <= this.bytes.length) return;
    let size = this.bytes.length * 2;
    while (size < this.length + extra) size *= 2;
    const next = new Uint8Array(size);
    next.set(this.bytes.subarray(0, this.length));
    this.bytes = next;
    this.view = new DataView(next.buffer);
  }

  u8(value: number): void {
    this.room(1);
    this.bytes[this.length++] = value;
  }

  u32(value: number): void {
    this.room(4);
    this.view.setUint32(this.length, value, true);
    this.length += 4;
  }

  f64(value: number): void {
    this.room(8);
    this.view.setFloat64(this.length, value, true);
    this.length += 8;
  }

  /** UTF-16 code units: field names and option values, short, in any language. */
  string(value: string): void {
    this.u32(value.length);
    this.room(2 * value.length);
    for (let i = 0; i < value.length; i++) {
      this.view.setUint16(this.length, value.charCodeAt(i), true);
      this.length += 2;
    }
  }

  raw(data: Uint8Array): void {
    this.room(data.length);
    this.bytes.set(data, this.length);
    this.length += data.length;
  }

  /**
   * Bytes as runs of zeros and literal bytes: arrays are kept at their capacity, and the part
   * past what is in use (zeros, mostly) would otherwise be most of a snapshot.
   */
  runs(data: Uint8Array): void {
    const n = data.length;
    // Word by word where the bytes allow it (every array of 4-byte or wider elements): a quarter
    // of the steps. The runs are byte counts either way, so the reader does not know which.
    const words = data.byteOffset % 4 === 0 && n % 4 === 0 ? new Uint32Array(data.buffer, data.byteOffset, n >> 2) : null;
    const unit = words ? 4 : 1;
    const count = words ? n >> 2 : n;
    const zero = (k: number) => (words ? words[k] === 0 : data[k] === 0);
    const runEnd = MIN_ZERO_RUN / unit;
    let at = 0;
    while (at < count) {
      let zeros = at;
      while (zeros < count && zero(zeros)) zeros++;
      // A literal stretch ends at the first run of MIN_ZERO_RUN zero bytes, or at the end.
      let end = zeros;
      let run = 0;
      while (end < count) {
        run = zero(end) ? run + 1 : 0;
        end++;
        if (run === runEnd) {
          end -= run;
          break;
        }
      }
      this.u32((zeros - at) * unit);
      this.u32((end - zeros) * unit);
      this.raw(data.subarray(zeros * unit, end * unit));
      at = end;
    }
  }

  value(node: StateValue): void {
    switch (node.t) {
      case 'keep':
        return this.u8(Tag.keep);
      case 'ref':
        this.u8(Tag.ref);
        return this.u32(node.id);
      case 'value': {
        const v = node.v;
        if (v === undefined) return this.u8(Tag.undefined);
        if (v === null) return this.u8(Tag.null);
        if (v === false) return this.u8(Tag.false);
        if (v === true) return this.u8(Tag.true);
        if (typeof v === 'number') {
          this.u8(Tag.number);
          return this.f64(v);
        }
        this.u8(Tag.string);
        return this.string(v);
      }
      case 'typed':
        this.u8(Tag.typed);
        this.u32(node.id);
        this.u8(node.kind);
        this.u32(node.data.length);
        return this.runs(new Uint8Array(node.data.buffer, node.data.byteOffset, node.data.byteLength));
      case 'array':
      case 'set':
        this.u8(node.t === 'array' ? Tag.array : Tag.set);
        this.u32(node.id);
        this.u32(node.items.length);
        for (const item of node.items) this.value(item);
        return;
      case 'map':
        this.u8(Tag.map);
        this.u32(node.id);
        this.u32(node.entries.length);
        for (const [k, v] of node.entries) {
          this.value(k);
          this.value(v);
        }
        return;
      case 'object':
        this.u8(Tag.object);
        this.u32(node.id);
        this.string(node.name);
        this.u32(node.fields.length);
        for (const [key, value] of node.fields) {
          this.string(key);
          this.value(value);
        }
    }
  }

  finish(): Uint8Array {
    const out = this.bytes.slice(0, this.length);
    const view = new DataView(out.buffer);
    out.set(MAGIC, 0);
    view.setUint16(4, FORMAT_VERSION, true);
    view.setUint16(6, 0, true);
    view.setUint32(8, this.length - HEADER_BYTES, true);
    view.setUint32(12, fnv1a(out, HEADER_BYTES, this.length), true);
    return out;
  }
}

/**
 * FNV-1a over the 32-bit little-endian words of bytes [from, to) (the last one zero-padded): any
 * one changed word changes the result, since each step is a bijection of the running hash, so
 * a flipped, lost or reordered byte of a stored image is caught; word by word, it reads a large
 * world's snapshot in a quarter of the steps.
 */
function fnv1a(bytes: Uint8Array, from: number, to: number): number {
  let hash = 0x811c9dc5;
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  let i = from;
  for (; i + 4 <= to; i += 4) hash = Math.imul(hash ^ view.getUint32(i, true), 0x01000193);
  if (i < to) {
    let last = 0;
    for (let k = 0; i + k < to; k++) last |= bytes[i + k] << (8 * k);
    hash = Math.imul(hash ^ last, 0x01000193);
  }
  return hash >>> 0;
}

export function encodeSnapshot(content: SnapshotContent): Uint8Array {
  const writer = new Writer();
  writer.string(content.engineVersion);
  writer.value(content.state);
  return writer.finish();
}

class Reader {
  private at = HEADER_BYTES;
  private readonly view: DataView;
  private readonly ids = new Set<number>();

  constructor(
    private readonly bytes: Uint8Array,
    private readonly end: number,
  ) {
    this.view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  }

  private need(count: number): void {
    if (this.at + count > this.end) throw corrupt(`a value at byte ${this.at} runs past the payload's end (${this.end})`);
  }

  u8(): number {
    this.need(1);
    return this.bytes[this.at++];
  }

  u32(): number {
    this.need(4);
    const value = this.view.getUint32(this.at, true);
    this.at += 4;
    return value;
  }

  f64(): number {
    this.need(8);
    const value = this.view.getFloat64(this.at, true);
    this.at += 8;
    return value;
  }

  string(): string {
    const length = this.u32();
    this.need(2 * length);
    let out = '';
    for (let i = 0; i < length; i++, this.at += 2) out += String.fromCharCode(this.view.getUint16(this.at, true));
    return out;
  }

  private id(): number {
    const id = this.u32();
    if (this.ids.has(id)) throw corrupt(`part ${id} appears twice`);
    this.ids.add(id);
    return id;
  }

  private count(what: string): number {
    const n = this.u32();
    // Each item takes a byte at least: a larger count is damage, not a large world.
    if (n > this.end - this.at) throw corrupt(`${what} of ${n} items at byte ${this.at} cannot fit in the payload`);
    return n;
  }

  value(depth: number): StateValue {
    if (depth > 64) throw corrupt('values nest more than 64 deep');
    const tag = this.u8();
    switch (tag) {
      case Tag.undefined:
        return { t: 'value', v: undefined };
      case Tag.null:
        return { t: 'value', v: null };
      case Tag.false:
        return { t: 'value', v: false };
      case Tag.true:
        return { t: 'value', v: true };
      case Tag.number:
        return { t: 'value', v: this.f64() };
      case Tag.string:
        return { t: 'value', v: this.string() };
      case Tag.keep:
        return { t: 'keep' };
      case Tag.ref: {
        const id = this.u32();
        if (!this.ids.has(id)) throw corrupt(`a reference to part ${id}, which does not come before it`);
        return { t: 'ref', id };
      }
      case Tag.typed: {
        const id = this.id();
        const kind = this.u8();
        if (kind >= TYPED_KINDS.length) throw corrupt(`typed array kind ${kind} is unknown`);
        const Ctor = TYPED_KINDS[kind] as unknown as { new (buffer: ArrayBuffer): TypedArray; BYTES_PER_ELEMENT: number };
        const length = this.u32();
        const bytes = length * Ctor.BYTES_PER_ELEMENT;
        if (!(bytes <= MAX_ARRAY_BYTES)) throw corrupt(`a typed array of ${length} elements at byte ${this.at}`);
        const out = new Uint8Array(bytes);
        for (let filled = 0; filled < bytes; ) {
          const zeros = this.u32();
          const literal = this.u32();
          if (zeros + literal === 0 || filled + zeros + literal > bytes) throw corrupt(`a typed array's runs at byte ${this.at} do not add up to its ${bytes} bytes`);
          filled += zeros;
          this.need(literal);
          out.set(this.bytes.subarray(this.at, this.at + literal), filled);
          this.at += literal;
          filled += literal;
        }
        return { t: 'typed', id, kind, data: new Ctor(out.buffer) };
      }
      case Tag.array:
      case Tag.set: {
        const id = this.id();
        const n = this.count('an array');
        const items: StateValue[] = [];
        for (let i = 0; i < n; i++) items.push(this.value(depth + 1));
        return tag === Tag.array ? { t: 'array', id, items } : { t: 'set', id, items };
      }
      case Tag.map: {
        const id = this.id();
        const n = this.count('a map');
        const entries: [StateValue, StateValue][] = [];
        for (let i = 0; i < n; i++) entries.push([this.value(depth + 1), this.value(depth + 1)]);
        return { t: 'map', id, entries };
      }
      case Tag.object: {
        const id = this.id();
        const name = this.string();
        const n = this.count('an object');
        const fields: [string, StateValue][] = [];
        for (let i = 0; i < n; i++) fields.push([this.string(), this.value(depth + 1)]);
        return { t: 'object', id, name, fields };
      }
      default:
        throw corrupt(`unknown value tag ${tag} at byte ${this.at - 1}`);
    }
  }

  finished(): void {
    if (this.at !== this.end) throw corrupt(`${this.end - this.at} bytes are left over after the state`);
  }
}

/** Larger than any array a world holds (2^24 slots of the widest record), so a damaged length fails here. */
const MAX_ARRAY_BYTES = 2 ** 34;

function corrupt(reason: string): RangeError {
  return new RangeError(`snapshot is corrupt: ${reason}`);
}

/** Checks and reads a snapshot's bytes whole; a RangeError says what is wrong with them. */
export function decodeSnapshot(bytes: Uint8Array, engineVersion: string): SnapshotContent {
  // The magic of what bytes there are first: a short file of another kind is not a truncated snapshot.
  for (let i = 0; i < MAGIC.length && i < bytes.length; i++) {
    if (bytes[i] !== MAGIC[i]) throw new RangeError('snapshot is not a maxgrid snapshot: its first bytes are not "MXGS"');
  }
  if (bytes.length < HEADER_BYTES) throw new RangeError(`snapshot is truncated: ${bytes.length} bytes, shorter than its ${HEADER_BYTES}-byte header`);
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const version = view.getUint16(4, true);
  if (version > FORMAT_VERSION) {
    throw new RangeError(`snapshot format version ${version} is newer than this engine (${engineVersion}) reads (${FORMAT_VERSION}); restore it with the engine that wrote it or a later one`);
  }
  if (version < 1) throw new RangeError(`snapshot format version ${version} does not exist`);
  // Outside the hash, as the rest of the header is: checked, so that no flipped byte passes.
  const reserved = view.getUint16(6, true);
  if (reserved !== 0) throw corrupt(`its reserved header field is ${reserved}, not 0`);
  const length = view.getUint32(8, true);
  if (bytes.length < HEADER_BYTES + length) throw new RangeError(`snapshot is truncated: ${bytes.length} bytes, its header says ${HEADER_BYTES + length}`);
  if (bytes.length > HEADER_BYTES + length) throw new RangeError(`snapshot has ${bytes.length - HEADER_BYTES - length} bytes past its end (${HEADER_BYTES + length} bytes)`);
  const stored = view.getUint32(12, true);
  const actual = fnv1a(bytes, HEADER_BYTES, HEADER_BYTES + length);
  if (stored !== actual) throw corrupt(`its hash is ${actual.toString(16)}, the header says ${stored.toString(16)}`);
  const reader = new Reader(bytes, HEADER_BYTES + length);
  const writtenBy = reader.string();
  const state = reader.value(0);
  reader.finished();
  return { engineVersion: writtenBy, state };
}
