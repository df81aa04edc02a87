import { Prng } from './prng.js';
import { resolveParams, type ParamSpecs } from './params.js';
import type { SceneBody, SceneShape, ShapeScene } from './shape-scene.js';
import { clampInside } from './scene.js';

/** The parameters uniformPolygons takes, with their defaults and ranges (resolveParams checks them). */
export const uniformPolygonsParams = {
  n: { default: 1000, min: 0, max: 4_000_000, integer: true, description: 'number of bodies, boxes and hexagons in turn' },
  seed: { default: 1, min: 0, max: 2 ** 32 - 1, integer: true, description: 'PRNG seed' },
  minRadius: { default: 4, min: 0.01, max: 1e4, description: 'smallest circumradius' },
  maxRadius: { default: 8, min: 0.01, max: 1e4, description: 'largest circumradius' },
  fill: { default: 0.25, min: 0.001, max: 0.6, description: "bodies' total area over the box area" },
  maxSpeed: { default: 100, min: 0, max: 1e6, description: 'speeds are uniform in [0, maxSpeed]' },
  maxSpin: { default: 0, min: 0, max: 1e4, description: 'angular speeds are uniform in [-maxSpin, maxSpin], rad/s' },
} satisfies ParamSpecs;

const SQRT3 = Math.sqrt(3);

/**
 * The `uniform` scene with shapes (the report's noisy scene, as its section 7.4 asks of general
 * polygons): squares and regular hexagons in turn, circumradius uniform in [minRadius, maxRadius],
 * at random angles, filling `fill` of a square box, elastic (restitution 1), frictionless, no
 * gravity, on the report's single elastic pass; pixels (lengthUnit 50). Bodies start on a jittered lattice, one per cell,
 * apart at the default sizes and fill; listed row by row.
 */
export function uniformPolygons(given?: Partial<Record<keyof typeof uniformPolygonsParams, number>>): ShapeScene {
  const p = resolveParams('uniform-polygons', uniformPolygonsParams, given);
  if (p.minRadius > p.maxRadius) {
    throw new RangeError(`uniform-polygons: minRadius ${p.minRadius} is larger than maxRadius ${p.maxRadius}`);
  }
  const rng = new Prng(p.seed);
  const radius = new Float64Array(p.n);
  let area = 0;
  for (let k = 0; k < p.n; k++) {
    const r = rng.range(p.minRadius, p.maxRadius);
    radius[k] = r;
    area += k % 2 === 0 ? 2 * r * r : 1.5 * SQRT3 * r * r;
  }
  const side = Math.max(Math.sqrt(area / p.fill), 2 * p.maxRadius);
  const perRow = Math.max(1, Math.ceil(Math.sqrt(p.n)));
  const cell = side / perRow;
  const bodies: SceneBody[] = new Array(p.n);
  for (let k = 0; k < p.n; k++) {
    const r = radius[k];
    const column = k % perRow;
    const row = (k - column) / perRow;
    const slack = Math.max(0, cell - 2 * r);
    const x = clampInside(column * cell + (cell - slack) / 2 + rng.next() * slack, r, side);
    const y = clampInside(row * cell + (cell - slack) / 2 + rng.next() * slack, r, side);
    const speed = rng.range(0, p.maxSpeed);
    const [dx, dy] = rng.direction();
    const angle = rng.range(0, Math.PI);
    const angularVelocity = p.maxSpin === 0 ? 0 : rng.range(-p.maxSpin, p.maxSpin);
    const shape: SceneShape =
      k % 2 === 0
        ? { kind: 'box', width: r * Math.SQRT2, height: r * Math.SQRT2 }
        : {
            kind: 'polygon',
            vertices: [
              { x: r, y: 0 },
              { x: r / 2, y: (r * SQRT3) / 2 },
              { x: -r / 2, y: (r * SQRT3) / 2 },
              { x: -r, y: 0 },
              { x: -r / 2, y: (-r * SQRT3) / 2 },
              { x: r / 2, y: (-r * SQRT3) / 2 },
            ],
          };
    bodies[k] = { x, y, angle, vx: speed * dx, vy: speed * dy, angularVelocity, shapes: [shape] };
  }
  return {
    name: 'uniform-polygons',
    kind: 'shapes',
    params: Object.freeze({ ...p }),
    bounds: { width: side, height: side },
    gravity: { x: 0, y: 0 },
    world: { friction: 0, restitution: 1, solver: 'elastic', lengthUnit: 50, sleeping: false },
    bodies,
    segments: [],
    view: { minX: 0, minY: 0, maxX: side, maxY: side },
  };
}
