import type { BodyStore } from './store/body-store.js';
import { TypeCode } from './store/body-types.js';

// Energy and momentum count dynamic bodies only: static and kinematic bodies are infinitely
// massive in the solver, so they carry no meaningful mass-weighted quantity.

/** Linear plus rotational: sum of m v^2 / 2 + I w^2 / 2 (the rotational part only once bodies turn). */
export function kineticEnergy(bodies: BodyStore): number {
  const { vx, vy, mass, type, slotCount } = bodies;
  let sum = 0;
  for (let i = 0; i < slotCount; i++) {
    if (type[i] === TypeCode.dynamic) sum += 0.5 * mass[i] * (vx[i] * vx[i] + vy[i] * vy[i]);
  }
  const rigid = bodies.rigid;
  if (!rigid) return sum;
  const { angularVelocity, inertia, invInertia } = rigid;
  for (let i = 0; i < slotCount; i++) {
    // A body with fixed rotation (no inverse inertia) has no rotational energy to speak of.
    if (type[i] === TypeCode.dynamic && invInertia[i] > 0) sum += 0.5 * inertia[i] * angularVelocity[i] * angularVelocity[i];
  }
  return sum;
}

/** About the origin: sum of (x vy - y vx) m + I w over dynamic bodies (x, y the centre of mass). */
export function angularMomentum(bodies: BodyStore): number {
  const { x, y, vx, vy, mass, type, slotCount } = bodies;
  const rigid = bodies.rigid;
  let sum = 0;
  for (let i = 0; i < slotCount; i++) {
    if (type[i] !== TypeCode.dynamic) continue;
    sum += mass[i] * (x[i] * vy[i] - y[i] * vx[i]);
    if (rigid && rigid.invInertia[i] > 0) sum += rigid.inertia[i] * rigid.angularVelocity[i];
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
 * position and velocity, and of its rotation (cos, sin) and angular velocity wherever a body has
 * turned or spins (a body at the identity rotation and at rest adds nothing, so worlds of
 * circles hash as they always have). Equal hashes mean bit-identical states; the tests pin one for a fixed
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
  const rigid = bodies.rigid;
  const turned = rigid ? [rigid.c, rigid.s, rigid.angularVelocity] : [];
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
    if (rigid && (rigid.c[i] !== 1 || rigid.s[i] !== 0 || rigid.angularVelocity[i] !== 0)) {
      for (const column of turned) {
        word[0] = column[i];
        mix(words[0]);
        mix(words[1]);
      }
    }
  }
  return (h1 >>> 0).toString(16).padStart(8, '0') + (h2 >>> 0).toString(16).padStart(8, '0');
}
