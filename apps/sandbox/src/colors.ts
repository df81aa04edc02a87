/**
 * Per-body colours. The report gave every circle a random colour; here "random" is a hash of
 * (seed, slot), so the URL reproduces the picture too. Colours come from a small palette so the
 * canvas renderer can fill each palette entry as one path (one fill call per colour instead of
 * one per circle), and both renderers show the same colour for a body.
 */
export const PALETTE_SIZE = 48;
const HALF = PALETTE_SIZE / 2;

/** Static circles and segments: a neutral grey no palette entry comes near (palette saturation ≥ 0.55). */
export const STATIC_COLOR = '#c3ccd6';
export const STATIC_RGB = [0xc3, 0xcc, 0xd6] as const;
/**
 * Joints: a pale cyan of lightness 0.81, above every palette entry's (0.5 to 0.65), so a joint
 * never takes a body's colour and the tests can count its pixels.
 */
export const JOINT_COLOR = '#9ef0ff';
export const JOINT_RGB = [0x9e, 0xf0, 0xff] as const;

function hash32(a: number, b: number): number {
  let h = Math.imul(a ^ 0x9e3779b9, 0x85ebca6b) ^ Math.imul(b + 0x632be5ab, 0xc2b2ae35);
  h ^= h >>> 16;
  h = Math.imul(h, 0x7feb352d);
  h ^= h >>> 15;
  h = Math.imul(h, 0x846ca68b);
  return (h ^ (h >>> 16)) >>> 0;
}

function hslToRgb(h: number, s: number, l: number, out: Uint8Array, at: number): void {
  const k = (n: number) => (n + h * 12) % 12;
  const a = s * Math.min(l, 1 - l);
  const f = (n: number) => l - a * Math.max(-1, Math.min(k(n) - 3, 9 - k(n), 1));
  out[at] = Math.round(255 * f(0));
  out[at + 1] = Math.round(255 * f(8));
  out[at + 2] = Math.round(255 * f(4));
}

export class BodyColors {
  /** CSS colour of each palette entry. */
  readonly css: string[] = [];
  /** RGB of each palette entry. */
  readonly paletteRgb = new Uint8Array(PALETTE_SIZE * 3);
  /** RGBA per slot, for the WebGL renderer's per-instance colour attribute. */
  rgba = new Uint8Array(0);
  /** Slots grouped by palette entry: entry p owns order[start[p] .. start[p + 1]). */
  order = new Int32Array(0);
  readonly start = new Int32Array(PALETTE_SIZE + 1);
  /** Bumped whenever the per-slot data changes, so renderers know to re-upload. */
  version = 0;
  private slots = 0;
  private seed = 0;
  private layers = false;

  /**
   * Assigns colours for `slotCount` slots from `seed`. With `layers`, the two collision layers
   * (even and odd slots) take the cool and the warm half of the hues, so who passes through whom
   * can be seen.
   */
  reset(seed: number, slotCount: number, layers = false): void {
    this.seed = seed >>> 0;
    this.layers = layers;
    this.css.length = 0;
    for (let p = 0; p < PALETTE_SIZE; p++) {
      // Hues spread evenly and then shuffled by the seed keep neighbours distinguishable.
      let hue = ((p * 0.618033988749895 + hash32(this.seed, p) / 2 ** 34) % 1 + 1) % 1;
      if (layers) hue = p < HALF ? 0.5 + 0.17 * hue : 0.02 + 0.12 * hue;
      const sat = 0.55 + (hash32(this.seed, p + 1000) % 1000) / 1000 * 0.35;
      const light = 0.5 + (hash32(this.seed, p + 2000) % 1000) / 1000 * 0.15;
      hslToRgb(hue, sat, light, this.paletteRgb, p * 3);
      const r = this.paletteRgb[p * 3], g = this.paletteRgb[p * 3 + 1], b = this.paletteRgb[p * 3 + 2];
      this.css.push(`rgb(${r},${g},${b})`);
    }
    this.slots = 0;
    this.ensure(slotCount);
  }

  /** Makes sure every slot below `slotCount` has a colour; cheap when nothing is new. */
  ensure(slotCount: number): void {
    if (slotCount <= this.slots) return;
    if (this.rgba.length < slotCount * 4) {
      const grown = new Uint8Array(Math.max(slotCount, this.rgba.length / 2) * 4);
      grown.set(this.rgba.subarray(0, this.slots * 4));
      this.rgba = grown;
    }
    for (let s = this.slots; s < slotCount; s++) {
      const p = this.paletteOf(s);
      this.rgba[s * 4] = this.paletteRgb[p * 3];
      this.rgba[s * 4 + 1] = this.paletteRgb[p * 3 + 1];
      this.rgba[s * 4 + 2] = this.paletteRgb[p * 3 + 2];
      this.rgba[s * 4 + 3] = 255;
    }
    this.slots = slotCount;
    this.groupByPalette();
    this.version++;
  }

  paletteOf(slot: number): number {
    const h = hash32(this.seed, slot + 0x10000);
    return this.layers ? (slot % 2) * HALF + (h % HALF) : h % PALETTE_SIZE;
  }

  // A counting sort of slots by palette entry.
  private groupByPalette(): void {
    const n = this.slots;
    if (this.order.length < n) this.order = new Int32Array(Math.max(n, this.order.length * 2));
    const start = this.start;
    start.fill(0);
    for (let s = 0; s < n; s++) start[this.paletteOf(s) + 1]++;
    for (let p = 0; p < PALETTE_SIZE; p++) start[p + 1] += start[p];
    const fill = start.slice(0, PALETTE_SIZE);
    for (let s = 0; s < n; s++) this.order[fill[this.paletteOf(s)]++] = s;
  }
}
