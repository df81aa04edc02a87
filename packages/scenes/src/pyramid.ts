import { resolveParams, type ParamSpecs } from './params.js';
import { boxBody, type SceneBody, type ShapeScene } from './shape-scene.js';

/** The parameters pyramid takes, with their defaults and ranges (resolveParams checks them). */
export const pyramidParams = {
  base: { default: 100, min: 1, max: 1000, integer: true, description: 'boxes in the bottom row (base 100: 5,050 boxes)' },
  friction: { default: 0.6, min: 0, max: 10, description: 'friction of the boxes and the ground' },
  gravity: { default: 10, min: 0, max: 1000, description: 'downward gravity, m/s^2' },
} satisfies ParamSpecs;

/**
 * Box2D v3's `large_pyramid` benchmark (Box2D's own shared/benchmarks.c): a triangle of unit boxes, `base` in
 * the bottom row and one fewer in each row above, each resting on two below, every box touching
 * its neighbours, on a static ground 200 x 2 m; density 1, gravity 10, meters. y points down, as
 * in every scene: the ground's top is y = 0 and the pyramid rises towards negative y.
 */
export function pyramid(given?: Partial<Record<keyof typeof pyramidParams, number>>): ShapeScene {
  const p = resolveParams('pyramid', pyramidParams, given);
  const a = 0.5;
  const bodies: SceneBody[] = [boxBody(0, 1, 200, 2, { type: 'static' }, { friction: p.friction })];
  for (let i = 0; i < p.base; i++) {
    const y = -(2 * i + 1) * a;
    for (let j = i; j < p.base; j++) {
      const x = (i + 1) * a + 2 * (j - i) * a - a * p.base;
      bodies.push(boxBody(x, y, 1, 1, {}, { density: 1, friction: p.friction }));
    }
  }
  return {
    name: 'pyramid',
    kind: 'shapes',
    params: Object.freeze({ ...p }),
    bounds: null,
    gravity: { x: 0, y: p.gravity },
    world: { friction: p.friction, restitution: 0, lengthUnit: 1, solver: 'soft' },
    bodies,
    segments: [],
    view: { minX: -a * p.base - 1, minY: -2 * a * p.base - 1, maxX: a * p.base + 1, maxY: 2 },
  };
}
