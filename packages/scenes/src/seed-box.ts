import { Prng } from './prng.js';
import { resolveParams, type ParamSpecs } from './params.js';
import { allocateScene, clampInside, type Scene } from './scene.js';

/** The parameters seedBox takes, with their defaults and ranges (resolveParams checks them). */
export const seedBoxParams = {
  n: { default: 1000, min: 0, max: 2_000_000, integer: true, description: 'number of circles' },
  seed: { default: 1, min: 0, max: 2 ** 32 - 1, integer: true, description: 'PRNG seed' },
  width: { default: 1600, min: 1, max: 1e7, description: 'box width' },
  height: { default: 900, min: 1, max: 1e7, description: 'box height' },
  gravity: { default: 300, min: -1e5, max: 1e5, description: 'downward gravity, units/s^2' },
  elasticity: { default: 1, min: 0, max: 1, description: 'restitution of circles and walls' },
  size: { default: 6, min: 0.1, max: 200, description: 'mean radius' },
  sizeNoise: { default: 0.5, min: 0, max: 0.99, description: 'radius varies by up to this fraction' },
  velocity: { default: 100, min: 0, max: 1e5, description: 'mean initial speed, units/s' },
  velocityNoise: { default: 0.5, min: 0, max: 1, description: 'speed varies by up to this fraction' },
} satisfies ParamSpecs;

/**
 * The report's test scene (5.8, 5.13.2): circles of random size, position and velocity in a
 * 1600 x 900 box, with the gravity and elasticity sliders as parameters. Circles may start
 * overlapping, as in the report; the first steps separate them.
 */
export function seedBox(given?: Partial<Record<keyof typeof seedBoxParams, number>>): Scene {
  const p = resolveParams('seed-box', seedBoxParams, given);
  const maxRadius = p.size * (1 + p.sizeNoise);
  if (2 * maxRadius > Math.min(p.width, p.height)) {
    throw new RangeError(`seed-box: circles up to radius ${maxRadius} do not fit a ${p.width} x ${p.height} box`);
  }
  const scene = allocateScene('seed-box', p, p.n, {
    bounds: { width: p.width, height: p.height },
    gravity: { x: 0, y: p.gravity },
    restitution: p.elasticity,
  });
  const rng = new Prng(p.seed);
  for (let k = 0; k < p.n; k++) {
    const r = rng.noisy(p.size, p.sizeNoise);
    const speed = rng.noisy(p.velocity, p.velocityNoise);
    const [dx, dy] = rng.direction();
    scene.radius[k] = r;
    scene.x[k] = clampInside(rng.range(r, p.width - r), r, p.width);
    scene.y[k] = clampInside(rng.range(r, p.height - r), r, p.height);
    scene.vx[k] = speed * dx;
    scene.vy[k] = speed * dy;
  }
  return scene;
}
