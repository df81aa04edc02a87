import { Prng } from './prng.js';
import { resolveParams, type ParamSpecs } from './params.js';
import type { SceneBody, SceneShape, ShapeScene } from './shape-scene.js';
import { clampInside } from './scene.js';

/** The parameters polygonBox takes, with their defaults and ranges (resolveParams checks them). */
export const polygonBoxParams = {
  n: { default: 1000, min: 0, max: 2_000_000, integer: true, description: 'number of bodies: boxes, triangles, hexagons, capsules and circles in turn' },
  seed: { default: 1, min: 0, max: 2 ** 32 - 1, integer: true, description: 'PRNG seed' },
  width: { default: 1600, min: 1, max: 1e7, description: 'box width' },
  height: { default: 900, min: 1, max: 1e7, description: 'box height' },
  gravity: { default: 300, min: -1e5, max: 1e5, description: 'downward gravity, units/s^2' },
  elasticity: { default: 0.5, min: 0, max: 1, description: 'restitution of the bodies and the walls' },
  friction: { default: 0.4, min: 0, max: 10, description: 'friction of the bodies and the walls' },
  size: { default: 6, min: 0.1, max: 200, description: 'mean circumradius' },
  sizeNoise: { default: 0.5, min: 0, max: 0.99, description: 'sizes vary by up to this fraction' },
  velocity: { default: 100, min: 0, max: 1e5, description: 'mean initial speed, units/s' },
  velocityNoise: { default: 0.5, min: 0, max: 1, description: 'speed varies by up to this fraction' },
  spin: { default: 3, min: 0, max: 1e4, description: 'angular speeds are uniform in [-spin, spin], rad/s' },
} satisfies ParamSpecs;

const SQRT3 = Math.sqrt(3);

/** A regular hexagon of circumradius r, counter-clockwise in y-up terms (either order is accepted). */
function hexagon(r: number): { x: number; y: number }[] {
  return [
    { x: r, y: 0 },
    { x: r / 2, y: (r * SQRT3) / 2 },
    { x: -r / 2, y: (r * SQRT3) / 2 },
    { x: -r, y: 0 },
    { x: -r / 2, y: (-r * SQRT3) / 2 },
    { x: r / 2, y: (-r * SQRT3) / 2 },
  ];
}

/**
 * The report's seed box (5.8) with shapes: boxes, triangles, hexagons, capsules and circles in
 * turn, of random size (circumradius), position, angle, velocity and spin, in a 1600 x 900 box
 * under gravity, with friction and some elasticity. Bodies may start overlapping, as the report's
 * circles do; the first steps separate them. Scene units are pixels (lengthUnit 50: 1 m = 50 px).
 */
export function polygonBox(given?: Partial<Record<keyof typeof polygonBoxParams, number>>): ShapeScene {
  const p = resolveParams('polygon-box', polygonBoxParams, given);
  const largest = p.size * (1 + p.sizeNoise);
  if (2 * largest > Math.min(p.width, p.height)) {
    throw new RangeError(`polygon-box: bodies up to circumradius ${largest} do not fit a ${p.width} x ${p.height} box`);
  }
  const rng = new Prng(p.seed);
  const bodies: SceneBody[] = new Array(p.n);
  for (let k = 0; k < p.n; k++) {
    const r = rng.noisy(p.size, p.sizeNoise);
    const speed = rng.noisy(p.velocity, p.velocityNoise);
    const [dx, dy] = rng.direction();
    const x = clampInside(rng.range(r, p.width - r), r, p.width);
    const y = clampInside(rng.range(r, p.height - r), r, p.height);
    const angle = rng.range(0, 2 * Math.PI);
    const angularVelocity = rng.range(-p.spin, p.spin);
    let shape: SceneShape;
    const kind = k % 5;
    if (kind === 0) shape = { kind: 'box', width: r * Math.SQRT2, height: r * Math.SQRT2 };
    else if (kind === 1) shape = { kind: 'polygon', vertices: [{ x: r, y: 0 }, { x: -r / 2, y: (r * SQRT3) / 2 }, { x: -r / 2, y: (-r * SQRT3) / 2 }] };
    else if (kind === 2) shape = { kind: 'polygon', vertices: hexagon(r) };
    else if (kind === 3) shape = { kind: 'capsule', length: r, radius: r / 2 };
    else shape = { kind: 'circle', radius: r };
    bodies[k] = { x, y, angle, vx: speed * dx, vy: speed * dy, angularVelocity, shapes: [{ ...shape, friction: p.friction, restitution: p.elasticity }] };
  }
  return {
    name: 'polygon-box',
    kind: 'shapes',
    params: Object.freeze({ ...p }),
    bounds: { width: p.width, height: p.height },
    gravity: { x: 0, y: p.gravity },
    world: { friction: p.friction, restitution: p.elasticity, lengthUnit: 50, solver: 'soft' },
    bodies,
    segments: [],
    view: { minX: 0, minY: 0, maxX: p.width, maxY: p.height },
  };
}
