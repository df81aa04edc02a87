import { Prng } from './prng.js';
import { resolveParams, type ParamSpecs } from './params.js';
import { allocateScene, type Scene } from './scene.js';

/** The parameters funnel takes, with their defaults and ranges (resolveParams checks them). */
export const funnelParams = {
  n: {
    default: 500,
    min: 0,
    max: 7962,
    integer: true,
    description: 'number of falling circles; no more than fit above the funnel: 7,962 of size 1, 992 of size 4, 127 of size 12',
  },
  seed: { default: 1, min: 0, max: 2 ** 32 - 1, integer: true, description: 'PRNG seed' },
  gravity: { default: 400, min: 0, max: 1e5, description: 'downward gravity, units/s^2' },
  elasticity: { default: 0.5, min: 0, max: 1, description: 'restitution of circles, pegs, walls and segments' },
  size: { default: 4, min: 1, max: 12, description: 'mean radius of the falling circles' },
} satisfies ParamSpecs;

const WIDTH = 800;
const HEIGHT = 900;
const PEG_RADIUS = 6;

/**
 * A pinball-like board for the engine's static shapes (issue 6): circles fall from the top into a
 * funnel of two thick segments, drop through a field of static pegs, and slide off a ramp. The
 * first circles are the pegs (static); the rest start on a jittered lattice above the funnel. The
 * lattice's cell grows with `size`, so fewer fit the larger they are: n's range is what the
 * smallest size holds, and more than a larger size holds is refused by name.
 */
export function funnel(given?: Partial<Record<keyof typeof funnelParams, number>>): Scene {
  const p = resolveParams('funnel', funnelParams, given);
  const pegs: [number, number][] = [];
  for (let row = 0; row < 6; row++) {
    for (let column = 0; column < 9 - (row % 2); column++) {
      pegs.push([120 + column * 70 + (row % 2) * 35, 470 + row * 55]);
    }
  }
  const count = pegs.length + p.n;
  const scene = allocateScene('funnel', p, count, {
    bounds: { width: WIDTH, height: HEIGHT },
    gravity: { x: 0, y: p.gravity },
    restitution: p.elasticity,
  });
  scene.fixed = new Uint8Array(count);
  pegs.forEach(([x, y], k) => {
    scene.x[k] = x;
    scene.y[k] = y;
    scene.radius[k] = PEG_RADIUS;
    scene.fixed![k] = 1;
  });
  scene.segments = [
    { x1: 20, y1: 120, x2: 360, y2: 380, thickness: 4 },
    { x1: 780, y1: 120, x2: 440, y2: 380, thickness: 4 },
    { x1: 60, y1: 820, x2: 620, y2: 870, thickness: 3 },
  ];
  const rng = new Prng(p.seed);
  const maxRadius = 1.5 * p.size;
  const cell = 2 * maxRadius + 2;
  // Lattice points from the top down, kept while they sit clear above both funnel walls.
  const wallY = (x: number): number => (x <= 400 ? 120 + ((x - 20) * 260) / 340 : 120 + ((780 - x) * 260) / 340);
  let placed = 0;
  for (let row = 0; placed < p.n; row++) {
    const y = maxRadius + 1 + row * cell;
    if (y > 380) {
      throw new RangeError(`funnel: only ${placed} circles of size ${p.size} fit above the funnel, asked for ${p.n}`);
    }
    for (let x = cell; x <= WIDTH - cell && placed < p.n; x += cell) {
      if (y + maxRadius + 6 > wallY(x)) continue;
      const i = pegs.length + placed++;
      const r = rng.noisy(p.size, 0.5);
      scene.radius[i] = r;
      scene.x[i] = x + (rng.next() - 0.5) * (cell - 2 * r);
      scene.y[i] = y;
      scene.vx[i] = (rng.next() - 0.5) * 40;
      scene.vy[i] = 0;
    }
  }
  return scene;
}
