import { Prng } from './prng.js';
import { resolveParams, type ParamSpecs } from './params.js';
import { allocateScene, type Scene } from './scene.js';
import { uniform } from './uniform.js';

/**
 * Scenes where a broad-phase or the continuous sweep used to fall off a cliff: a few far bodies,
 * an almost empty box, two crowds far apart, many static shapes, sizes over six decades. The
 * lab's `cliffs` experiment steps each with every broad-phase; the engine's tests build smaller
 * ones. All are elastic and frictionless, so they run on the report's circle engine.
 */

const common = {
  seed: { default: 1, min: 0, max: 2 ** 32 - 1, integer: true, description: 'PRNG seed' },
  maxSpeed: { default: 50, min: 0, max: 1e6, description: 'speeds are uniform in [0, maxSpeed]' },
} satisfies ParamSpecs;

const count = (fallback: number, what = 'number of circles') => ({ default: fallback, min: 1, max: 1_000_000, integer: true, description: what });

/** Lays `n` circles of radius r on a jittered lattice over the square [x0, x0 + side]², from index `first`. */
function patch(scene: Scene, rng: Prng, first: number, n: number, x0: number, y0: number, side: number, r: number, maxSpeed: number): void {
  const perRow = Math.max(1, Math.ceil(Math.sqrt(n)));
  const cell = side / perRow;
  const slack = Math.max(0, cell - 2 * r);
  for (let k = 0; k < n; k++) {
    const column = k % perRow;
    const row = (k - column) / perRow;
    const i = first + k;
    scene.x[i] = x0 + column * cell + (cell - slack) / 2 + rng.next() * slack;
    scene.y[i] = y0 + row * cell + (cell - slack) / 2 + rng.next() * slack;
    scene.radius[i] = r;
    const speed = rng.range(0, maxSpeed);
    const [dx, dy] = rng.direction();
    scene.vx[i] = speed * dx;
    scene.vy[i] = speed * dy;
  }
}

/** Side of the square that n circles of radius r fill to a quarter. */
const quarterFilled = (n: number, r: number) => Math.sqrt((n * Math.PI * r * r) / 0.25);

export const farBodiesParams = { n: count(20_000), ...common, distance: { default: 1e6, min: 1e3, max: 1e12, description: 'how far the 4 outliers are' } } satisfies ParamSpecs;

/** n circles (radius 4) in a patch filled to a quarter, and 4 more `distance` away; no box. */
export function farBodies(given?: Partial<Record<keyof typeof farBodiesParams, number>>): Scene {
  const p = resolveParams('far-bodies', farBodiesParams, given);
  const side = quarterFilled(p.n, 4);
  const scene = allocateScene('far-bodies', p, p.n + 4, { bounds: { width: side, height: side }, gravity: { x: 0, y: 0 }, restitution: 1 });
  scene.open = true;
  const rng = new Prng(p.seed);
  patch(scene, rng, 0, p.n, 0, 0, side, 4, p.maxSpeed);
  for (let k = 0; k < 4; k++) {
    scene.x[p.n + k] = p.distance + 10 * k;
    scene.y[p.n + k] = p.distance;
    scene.radius[p.n + k] = 4;
  }
  return scene;
}

export const sparseBoxParams = { n: count(20_000), ...common, box: { default: 1e5, min: 1e3, max: 1e9, description: "the box's side" } } satisfies ParamSpecs;

/** n circles (radius 3) filling a patch in the corner of a box `box` wide to a quarter. */
export function sparseBox(given?: Partial<Record<keyof typeof sparseBoxParams, number>>): Scene {
  const p = resolveParams('sparse-box', sparseBoxParams, given);
  const side = quarterFilled(p.n, 3);
  if (side + 20 > p.box) throw new RangeError(`sparse-box: ${p.n} circles need a patch ${side.toFixed(0)} wide, more than the box ${p.box} holds`);
  const scene = allocateScene('sparse-box', p, p.n, { bounds: { width: p.box, height: p.box }, gravity: { x: 0, y: 0 }, restitution: 1 });
  patch(scene, new Prng(p.seed), 0, p.n, 10, 10, side, 3, p.maxSpeed);
  return scene;
}

export const twoCrowdsParams = { n: count(20_000), ...common, distance: { default: 1e6, min: 1e3, max: 1e12, description: 'how far apart the crowds are, along each axis' } } satisfies ParamSpecs;

/** Two patches of n/2 circles (radius 2) each, `distance` apart along both axes; no box. */
export function twoCrowds(given?: Partial<Record<keyof typeof twoCrowdsParams, number>>): Scene {
  const p = resolveParams('two-crowds', twoCrowdsParams, given);
  const half = Math.floor(p.n / 2);
  const side = quarterFilled(p.n - half, 2);
  const scene = allocateScene('two-crowds', p, p.n, { bounds: { width: side, height: side }, gravity: { x: 0, y: 0 }, restitution: 1 });
  scene.open = true;
  const rng = new Prng(p.seed);
  patch(scene, rng, 0, half, 0, 0, side, 2, p.maxSpeed);
  patch(scene, rng, half, p.n - half, p.distance, p.distance, side, 2, p.maxSpeed);
  return scene;
}

export const segmentFloorParams = {
  n: count(2_000, 'number of falling circles, and of floor segments'),
  seed: common.seed,
  speed: { default: 600, min: 0, max: 1e6, description: 'starting downward speed: 600 moves a ball 2.5 radii per 1/60 s step' },
} satisfies ParamSpecs;

/**
 * The narrowest segment-floor box. Balls start 10 units clear of either wall, which a box 2n wide
 * cannot give below n = 10 (below n = 7 it put them outside the box), and barely gives just above.
 */
const FLOOR_MIN_WIDTH = 40;

/**
 * n circles (radius 4) thrown down at `speed` under gravity 300 onto a floor of n segments 2
 * long: fast enough to tunnel through it without continuous collision, which must then sweep
 * every ball each step. The box is 2n wide, and 40 wide below 20 circles, where the n segments
 * are longer so as to span it.
 */
export function segmentFloor(given?: Partial<Record<keyof typeof segmentFloorParams, number>>): Scene {
  const p = resolveParams('segment-floor', segmentFloorParams, given);
  const width = Math.max(2 * p.n, FLOOR_MIN_WIDTH);
  const height = Math.max(200, p.n);
  const scene = allocateScene('segment-floor', p, p.n, { bounds: { width, height }, gravity: { x: 0, y: 300 }, restitution: 1 });
  const rng = new Prng(p.seed);
  for (let k = 0; k < p.n; k++) {
    scene.x[k] = rng.range(10, width - 10);
    scene.y[k] = rng.range(10, 0.75 * height);
    scene.radius[k] = 4;
    scene.vy[k] = p.speed;
  }
  const floor = height - 0.05 * height;
  const length = width / p.n;
  for (let k = 0; k < p.n; k++) scene.segments.push({ x1: k * length, y1: floor, x2: (k + 1) * length, y2: floor, thickness: 0 });
  return scene;
}

export const staticWallParams = { n: count(10_000, 'number of static circles in the wall'), ...common, speed: { default: 300, min: 0, max: 1e6, description: 'speed of the moving circles, towards the wall' } } satisfies ParamSpecs;

/**
 * A wall of n static circles (radius 2, 0.39 apart, each overlapping about ten others) down the
 * middle of a box, and n/10 circles (radius 4) moving at it at `speed`.
 */
export function staticWall(given?: Partial<Record<keyof typeof staticWallParams, number>>): Scene {
  const p = resolveParams('static-wall', staticWallParams, given);
  const movers = Math.max(1, Math.floor(p.n / 10));
  const side = Math.max(200, 0.39 * p.n + 20);
  const scene = allocateScene('static-wall', p, p.n + movers, { bounds: { width: side, height: side }, gravity: { x: 0, y: 0 }, restitution: 1 });
  scene.fixed = new Uint8Array(p.n + movers);
  for (let k = 0; k < p.n; k++) {
    scene.x[k] = side / 2;
    scene.y[k] = 10 + 0.39 * k;
    scene.radius[k] = 2;
    scene.fixed[k] = 1;
  }
  const rng = new Prng(p.seed);
  for (let k = p.n; k < p.n + movers; k++) {
    scene.x[k] = rng.range(10, side / 2 - 10);
    scene.y[k] = rng.range(10, side - 10);
    scene.radius[k] = 4;
    scene.vx[k] = p.speed;
  }
  return scene;
}

export const logRadiiParams = { n: count(20_000), seed: common.seed } satisfies ParamSpecs;

/** The `uniform` scene with radii log-uniform from 0.01 to 10⁴: twenty power-of-two size classes. */
export function logRadii(given?: Partial<Record<keyof typeof logRadiiParams, number>>): Scene {
  const p = resolveParams('log-radii', logRadiiParams, given);
  const scene = uniform({ n: p.n, seed: p.seed, logRadius: 1, minRadius: 0.01, maxRadius: 1e4 });
  return { ...scene, name: 'log-radii', params: Object.freeze({ ...p }) };
}
