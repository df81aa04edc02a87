import type { Mark } from './history.js';

/**
 * A sandbox save (.mxgs): the engine's world.snapshot() bytes, untouched, behind a small header
 * with what the page needs to show that world again (the scene's settings, whose segments and
 * region the page draws, the view and tools, the clock, whether it was running).
 *
 *   offset 0   8 bytes  magic "MXSANDBX"
 *          8   u32      header length H in bytes, little-endian
 *         12   H bytes  header: UTF-8 JSON, a SaveHeader
 *     12 + H            the snapshot, to the end of the file: World.restore(bytes.subarray(12 + H))
 */
export interface SaveHeader {
  /** This layout's version. */
  sandboxSave: 1;
  /** The settings as the page's URL query (serializeSettings), which parseSettings checks. */
  settings: string;
  /** The world's step count when saved: for the file's name and a check against the snapshot. */
  step: number;
  paused: boolean;
  mark: Mark;
}

const MAGIC = 'MXSANDBX';
const PREFIX_BYTES = MAGIC.length + 4;
/** Headers are a few hundred bytes; a larger length means the file is something else. */
const MAX_HEADER_BYTES = 1 << 16;

export function encodeSave(header: SaveHeader, snapshot: Uint8Array): Uint8Array<ArrayBuffer> {
  const json = new TextEncoder().encode(JSON.stringify(header));
  const out = new Uint8Array(PREFIX_BYTES + json.length + snapshot.length);
  for (let i = 0; i < MAGIC.length; i++) out[i] = MAGIC.charCodeAt(i);
  new DataView(out.buffer).setUint32(MAGIC.length, json.length, true);
  out.set(json, PREFIX_BYTES);
  out.set(snapshot, PREFIX_BYTES + json.length);
  return out;
}

/**
 * The header and the snapshot's bytes (a view into `bytes`), or a RangeError saying why this is no
 * sandbox save. The snapshot itself is checked by World.restore.
 */
export function decodeSave(bytes: Uint8Array): { header: SaveHeader; snapshot: Uint8Array } {
  const start = String.fromCharCode(...bytes.subarray(0, MAGIC.length));
  if (start !== MAGIC) {
    if (start.startsWith('MXGS')) throw new RangeError('this is a bare world.snapshot(), without the sandbox\'s header naming its scene; save one from the sandbox');
    throw new RangeError(`not a maxgrid sandbox save: its first bytes are not "${MAGIC}"`);
  }
  if (bytes.length < PREFIX_BYTES) throw new RangeError(`the save is truncated: ${bytes.length} bytes`);
  const length = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength).getUint32(MAGIC.length, true);
  if (length > MAX_HEADER_BYTES || PREFIX_BYTES + length > bytes.length) throw new RangeError(`the save is truncated or corrupt: its header length, ${length} bytes, runs past the file's ${bytes.length}`);
  let parsed: unknown;
  try {
    parsed = JSON.parse(new TextDecoder('utf-8', { fatal: true }).decode(bytes.subarray(PREFIX_BYTES, PREFIX_BYTES + length)));
  } catch (error) {
    throw new RangeError(`the save's header is corrupt (${error instanceof Error ? error.message : String(error)})`);
  }
  return { header: checkHeader(parsed), snapshot: bytes.subarray(PREFIX_BYTES + length) };
}

function checkHeader(value: unknown): SaveHeader {
  const h = value as Partial<SaveHeader> | null;
  const m = (h?.mark ?? null) as Partial<Mark> | null;
  const finite = (v: unknown) => typeof v === 'number' && Number.isFinite(v);
  const integer = (v: unknown) => Number.isSafeInteger(v);
  if (h === null || typeof h !== 'object' || h.sandboxSave !== 1) throw new RangeError(`the save's header is of an unknown version (${JSON.stringify(h?.sandboxSave)}); this page reads version 1`);
  if (typeof h.settings !== 'string' || !integer(h.step) || typeof h.paused !== 'boolean' || m === null || !finite(m.time) || !finite(m.boxX) || !integer(m.pinAnchor) || !integer(m.held)) {
    throw new RangeError("the save's header is corrupt: a field is missing or of the wrong type");
  }
  return h as SaveHeader;
}

/** The file's name: the scene and the step, e.g. maxgrid-pyramid-step1234.mxgs. */
export function saveName(scene: string, step: number): string {
  return `maxgrid-${scene}-step${step}.mxgs`;
}
