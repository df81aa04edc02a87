import type { BodyStore } from './store/body-store.js';
import { TypeCode } from './store/body-types.js';

// Energy and momentum count dynamic bodies only: static and kinematic bodies are infinitely
// massive in the solver, so they carry no meaningful mass-weighted quantity.

export function kineticEnergy(bodies: BodyStore): number {
  const { vx, vy, mass, type, slotCount } = bodies;
  let sum = 0;
  for (let i = 0; i < slotCount; i++) {
    if (type[i] === TypeCode.dynamic) sum += 0.5 * mass[i] * (vx[i] * vx[i] + vy[i] * vy[i]);
  }
  return sum;
}

/** -m g.p summed: zero at the origin, and zero everywhere when gravity is zero. */
export function potentialEnergy(bodies: BodyStore, gx: number, gy: number): number {
  if (gx === 0 && gy === 0) return 0;
  const { x, y, mass, type, slotCount } = bodies;
  let sum = 0;
  for (let i = 0; i < slotCount; i++) {
    if (type[i] === TypeCode.dynamic) sum -= mass[i] * (gx * x[i] + gy * y[i]);
  }
  return sum;
}

export function momentum(bodies: BodyStore): { x: number; y: number } {
  const { vx, vy, mass, type, slotCount } = bodies;
  let px = 0;
  let py = 0;
  for (let i = 0; i < slotCount; i++) {
    if (type[i] === TypeCode.dynamic) {
      px += mass[i] * vx[i];
      py += mass[i] * vy[i];
    }
  }
  return { x: px, y: py };
}

const word = new Float64Array(1);
const words = new Uint32Array(word.buffer);

/**
 * A 64-bit digest (16 hex digits) of every live body's slot, type and the exact bits of its
 * position and velocity. Equal hashes mean bit-identical states; the tests pin one for a fixed
 * scene, and the lab compares it across runtimes. Two FNV-1a lanes with different seeds.
 */
export function stateHash(bodies: BodyStore): string {
  let h1 = 0x811c9dc5;
  let h2 = 0x01000193 ^ 0x5bd1e995;
  const mix = (v: number): void => {
    h1 = Math.imul(h1 ^ v, 0x01000193);
    h2 = Math.imul(h2 ^ v, 0x5bd1e995) ^ (h2 >>> 13);
  };
  const columns = [bodies.x, bodies.y, bodies.vx, bodies.vy];
  for (let i = 0; i < bodies.slotCount; i++) {
    const t = bodies.type[i];
    if (t === TypeCode.free) continue;
    mix(i);
    mix(t);
    for (const column of columns) {
      word[0] = column[i];
      mix(words[0]);
      mix(words[1]);
    }
  }
  return (h1 >>> 0).toString(16).padStart(8, '0') + (h2 >>> 0).toString(16).padStart(8, '0');
}
