import { resolveParams, type ParamSpecs } from './params.js';
import { boxBody, type SceneBody, type ShapeScene } from './shape-scene.js';

/** The parameters manyPyramids takes, with their defaults and ranges (resolveParams checks them). */
export const manyPyramidsParams = {
  rows: { default: 20, min: 1, max: 100, integer: true, description: 'rows of pyramids, each on its own floor' },
  columns: { default: 20, min: 1, max: 100, integer: true, description: 'pyramids per row' },
  base: { default: 10, min: 1, max: 100, integer: true, description: 'boxes in the bottom row of each pyramid (10: 55 boxes)' },
  friction: { default: 0.6, min: 0, max: 10, description: 'friction of the boxes and the floors' },
} satisfies ParamSpecs;

/**
 * Box2D v3's `many_pyramids` benchmark (Box2D's own shared/benchmarks.c): rows x columns small pyramids of
 * unit boxes, each row of pyramids on its own floor (a static segment), 22,000 boxes at the
 * defaults; meters, gravity 10, sleeping off. y points down, so the floors step upwards (towards
 * negative y) from y = 0.
 */
export function manyPyramids(given?: Partial<Record<keyof typeof manyPyramidsParams, number>>): ShapeScene {
  const p = resolveParams('many-pyramids', manyPyramidsParams, given);
  const extent = 0.5;
  const floorStep = 2 * extent * (p.base + 1);
  const floorWidth = 2 * extent * p.columns * (p.base + 1);
  const baseWidth = 2 * extent * p.base;
  const bodies: SceneBody[] = [];
  const segments: ShapeScene['segments'] = [];
  for (let row = 0; row < p.rows; row++) {
    const floorY = -row * floorStep;
    segments.push({ x1: -floorWidth / 2, y1: floorY, x2: floorWidth / 2, y2: floorY, thickness: 0 });
    for (let column = 0; column < p.columns; column++) {
      const centerX = -floorWidth / 2 + column * (baseWidth + 2 * extent) + 2 * extent;
      for (let i = 0; i < p.base; i++) {
        const y = floorY - (2 * i + 1) * extent;
        for (let j = i; j < p.base; j++) {
          const x = (i + 1) * extent + 2 * (j - i) * extent + centerX - 0.5;
          bodies.push(boxBody(x, y, 2 * extent, 2 * extent, {}, { density: 1, friction: p.friction }));
        }
      }
    }
  }
  return {
    name: 'many-pyramids',
    kind: 'shapes',
    params: Object.freeze({ ...p }),
    bounds: null,
    gravity: { x: 0, y: 10 },
    world: { friction: p.friction, restitution: 0, lengthUnit: 1, solver: 'soft', sleeping: false },
    bodies,
    segments,
    view: { minX: -floorWidth / 2 - 1, minY: -p.rows * floorStep - 1, maxX: floorWidth / 2 + 1, maxY: 1 },
  };
}
