import { resolveParams, type ParamSpecs } from './params.js';
import { boxBody, type SceneBody, type ShapeScene } from './shape-scene.js';

/** The parameters cardHouse takes, with their defaults and ranges (resolveParams checks them). */
export const cardHouseParams = {
  levels: { default: 5, min: 1, max: 20, integer: true, description: 'storeys of the house' },
  friction: { default: 0.7, min: 0, max: 10, description: 'friction of the cards and the ground' },
} satisfies ParamSpecs;

const TILT = (25 * Math.PI) / 180;

/**
 * Box2D v3's card house (samples/sample_stacking.cpp): cards 0.4 m by 2 mm leaning on each other
 * in pairs at 25 degrees, with flat cards across each storey's pairs, `levels` storeys, friction
 * 0.7. It stands only if friction holds every card and thin shapes keep their contacts. y down.
 */
export function cardHouse(given?: Partial<Record<keyof typeof cardHouseParams, number>>): ShapeScene {
  const p = resolveParams('card-house', cardHouseParams, given);
  const height = 0.2;
  const thickness = 0.001;
  const bodies: SceneBody[] = [boxBody(0, 2, 80, 4, { type: 'static' }, { friction: p.friction })];
  const card = (x: number, y: number, angle: number): SceneBody => boxBody(x, -y, 2 * thickness, 2 * height, { angle }, { friction: p.friction });
  let n = p.levels;
  let z0 = 0;
  let y = height - 0.02;
  while (n > 0) {
    let z = z0;
    for (let i = 0; i < n; i++) {
      if (i !== n - 1) bodies.push(card(z + 0.25, y + height - 0.015, -Math.PI / 2));
      // Box2D's y-up angles, mirrored for y down.
      bodies.push(card(z, y, TILT));
      z += 0.175;
      bodies.push(card(z, y, -TILT));
      z += 0.175;
    }
    y += height * 2 - 0.03;
    z0 += 0.175;
    n--;
  }
  const width = 0.35 * p.levels;
  return {
    name: 'card-house',
    kind: 'shapes',
    params: Object.freeze({ ...p }),
    bounds: null,
    gravity: { x: 0, y: 10 },
    world: { friction: p.friction, restitution: 0, lengthUnit: 1, solver: 'soft' },
    bodies,
    segments: [],
    view: { minX: -0.3, minY: -y - 0.2, maxX: width + 0.3, maxY: 0.1 },
  };
}
