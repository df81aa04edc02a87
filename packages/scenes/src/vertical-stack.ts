import { resolveParams, type ParamSpecs } from './params.js';
import { boxBody, type SceneBody, type ShapeScene } from './shape-scene.js';

/** The parameters verticalStack takes, with their defaults and ranges (resolveParams checks them). */
export const verticalStackParams = {
  count: { default: 15, min: 1, max: 1000, integer: true, description: 'boxes in the stack' },
  size: { default: 1, min: 0.01, max: 100, description: 'side of each box, m' },
  friction: { default: 0.6, min: 0, max: 10, description: 'friction of the boxes and the ground' },
  massRatio: { default: 1, min: 0.001, max: 1e6, description: 'density of the top box over the others (100: a heavy box on light ones)' },
} satisfies ParamSpecs;

/**
 * A column of boxes on a static ground, each resting on the one below (Box2D v3's vertical stack),
 * meters and gravity 10; with `massRatio` the top box is that many times denser than the rest.
 * y points down: the ground's top is y = 0.
 */
export function verticalStack(given?: Partial<Record<keyof typeof verticalStackParams, number>>): ShapeScene {
  const p = resolveParams('vertical-stack', verticalStackParams, given);
  const bodies: SceneBody[] = [boxBody(0, 1, 40, 2, { type: 'static' }, { friction: p.friction })];
  for (let k = 0; k < p.count; k++) {
    const density = k === p.count - 1 ? p.massRatio : 1;
    bodies.push(boxBody(0, -(k + 0.5) * p.size, p.size, p.size, {}, { density, friction: p.friction }));
  }
  const height = p.count * p.size;
  return {
    name: 'vertical-stack',
    kind: 'shapes',
    params: Object.freeze({ ...p }),
    bounds: null,
    gravity: { x: 0, y: 10 },
    world: { friction: p.friction, restitution: 0, lengthUnit: 1, solver: 'soft' },
    bodies,
    segments: [],
    view: { minX: -height / 2 - 1, minY: -height - 1, maxX: height / 2 + 1, maxY: 2 },
  };
}
