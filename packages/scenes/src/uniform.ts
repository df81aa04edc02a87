import { Prng } from './prng.js';
import { resolveParams, type ParamSpecs } from './params.js';
import { allocateScene, clampInside, type Scene } from './scene.js';

/** The parameters uniform takes, with their defaults and ranges (resolveParams checks them). */
export const uniformParams = {
  n: { default: 1000, min: 0, max: 4_000_000, integer: true, description: 'number of circles' },
  seed: { default: 1, min: 0, max: 2 ** 32 - 1, integer: true, description: 'PRNG seed' },
  minRadius: { default: 4, min: 0.01, max: 1e4, description: 'smallest radius' },
  maxRadius: { default: 8, min: 0.01, max: 1e4, description: 'largest radius' },
  fill: { default: 0.25, min: 0.001, max: 0.6, description: "circles' total area over the box area" },
  maxSpeed: { default: 100, min: 0, max: 1e6, description: 'speeds are uniform in [0, maxSpeed]' },
  logRadius: {
    default: 0,
    min: 0,
    max: 1,
    integer: true,
    description: '1: radii log-uniform (as many circles per size octave), 0: uniform in [minRadius, maxRadius]',
  },
  shuffle: {
    default: 0,
    min: 0,
    max: 1,
    integer: true,
    description: '1: circles listed in a random order, as a world spawning at random creates them; 0: row by row, as they lie',
  },
} satisfies ParamSpecs;

/**
 * N circles with radius uniform in [minRadius, maxRadius] (or log-uniform, for wide size spreads
 * where small circles should outnumber large ones, as in the report's worst case for Max Grid) in a
 * square box sized so that their total
 * area is `fill` of it: density stays constant as N grows, which is what a per-body cost needs.
 * No gravity, restitution 1. Circles start on a jittered lattice, one per lattice cell, so they do
 * not overlap where the cell is wide enough (always, at the default sizes and fill).
 *
 * They are listed row by row, so an engine that stores bodies in creation order finds neighbours
 * near each other in memory. `shuffle` lists the same circles in a random order (the same bits
 * otherwise), which is what a world whose bodies spawn at random positions looks like in memory.
 */
export function uniform(given?: Partial<Record<keyof typeof uniformParams, number>>): Scene {
  const p = resolveParams('uniform', uniformParams, given);
  if (p.minRadius > p.maxRadius) {
    throw new RangeError(`uniform: minRadius ${p.minRadius} is larger than maxRadius ${p.maxRadius}`);
  }
  const rng = new Prng(p.seed);
  const radius = new Float64Array(p.n);
  let area = 0;
  for (let k = 0; k < p.n; k++) {
    radius[k] = p.logRadius
      ? rng.logRange(p.minRadius, p.maxRadius)
      : rng.range(p.minRadius, p.maxRadius);
    area += Math.PI * radius[k] * radius[k];
  }
  const side = Math.max(Math.sqrt(area / p.fill), 2 * p.maxRadius);
  const scene = allocateScene('uniform', p, p.n, {
    bounds: { width: side, height: side },
    gravity: { x: 0, y: 0 },
    restitution: 1,
  });
  scene.radius.set(radius);
  const perRow = Math.max(1, Math.ceil(Math.sqrt(p.n)));
  const cell = side / perRow;
  for (let k = 0; k < p.n; k++) {
    const r = radius[k];
    const column = k % perRow;
    const row = (k - column) / perRow;
    const slack = Math.max(0, cell - 2 * r);
    const x = column * cell + (cell - slack) / 2 + rng.next() * slack;
    const y = row * cell + (cell - slack) / 2 + rng.next() * slack;
    scene.x[k] = clampInside(x, r, side);
    scene.y[k] = clampInside(y, r, side);
    const speed = rng.range(0, p.maxSpeed);
    const [dx, dy] = rng.direction();
    scene.vx[k] = speed * dx;
    scene.vy[k] = speed * dy;
  }
  if (p.shuffle) shuffleCircles(scene, new Prng(p.seed ^ SHUFFLE_SALT));
  return scene;
}

/** Salts the shuffle's generator, so that its draws are not the placement's draws again. */
const SHUFFLE_SALT = 0x5bd1e995;

/** Fisher-Yates over the circles, every column moved together. */
function shuffleCircles(scene: Scene, rng: Prng): void {
  const columns = [scene.x, scene.y, scene.vx, scene.vy, scene.radius];
  for (let k = scene.count - 1; k > 0; k--) {
    const other = Math.floor(rng.next() * (k + 1));
    for (const column of columns) {
      const kept = column[k];
      column[k] = column[other];
      column[other] = kept;
    }
  }
}
