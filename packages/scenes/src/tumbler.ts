import { resolveParams, type ParamSpecs } from './params.js';
import { boxBody, type SceneBody, type ShapeScene } from './shape-scene.js';

/** The parameters tumbler takes, with their defaults and ranges (resolveParams checks them). */
export const tumblerParams = {
  grid: { default: 45, min: 1, max: 200, integer: true, description: 'boxes per side of the square they start in (45: 2,025 boxes)' },
  speed: {
    default: 25,
    min: -2700,
    max: 2700,
    description: "the drum's angular velocity, degrees a second; at most 2,700, the fastest the engine turns a body at 60 steps a second (45 degrees a step)",
  },
  friction: { default: 0.6, min: 0, max: 10, description: 'friction of the boxes and the drum' },
} satisfies ParamSpecs;

/**
 * Box2D v3's `tumbler` benchmark (Box2D's own shared/benchmarks.c): small boxes (0.25 m) tumbling in a hollow
 * square drum 20 m wide that turns at a constant speed. Box2D drives its drum with a revolute
 * motor; here the drum is a kinematic body given that angular velocity, which turns it the same
 * way without a joint. Meters, gravity 10. y points down: the drum's centre is at (0, -10).
 *
 * The engine turns no body more than 45 degrees in a step, so a faster drum would turn no faster:
 * at 60 steps a second, 2,700 degrees a second is the most `speed` may ask. The engine's rotation
 * update (Box2D's) turns a body tan⁻¹(h w) a sub-step rather than h w, so at that speed the drum
 * turns 1.3 % short of it, 2,666 degrees in a second (0.02 % short at 360).
 */
export function tumbler(given?: Partial<Record<keyof typeof tumblerParams, number>>): ShapeScene {
  const p = resolveParams('tumbler', tumblerParams, given);
  const drum: SceneBody = {
    x: 0,
    y: -10,
    type: 'kinematic',
    angularVelocity: (p.speed * Math.PI) / 180,
    shapes: [
      { kind: 'box', width: 1, height: 20, offsetX: 10, friction: p.friction },
      { kind: 'box', width: 1, height: 20, offsetX: -10, friction: p.friction },
      { kind: 'box', width: 20, height: 1, offsetY: 10, friction: p.friction },
      { kind: 'box', width: 20, height: 1, offsetY: -10, friction: p.friction },
    ],
  };
  const bodies: SceneBody[] = [drum];
  for (let i = 0; i < p.grid; i++) {
    const y = -(-0.2 * p.grid + 10 + 0.4 * i);
    for (let j = 0; j < p.grid; j++) bodies.push(boxBody(-0.2 * p.grid + 0.4 * j, y, 0.25, 0.25, {}, { density: 1, friction: p.friction }));
  }
  return {
    name: 'tumbler',
    kind: 'shapes',
    params: Object.freeze({ ...p }),
    bounds: null,
    gravity: { x: 0, y: 10 },
    world: { friction: p.friction, restitution: 0, lengthUnit: 1, solver: 'soft', sleeping: false },
    bodies,
    segments: [],
    view: { minX: -15, minY: -25, maxX: 15, maxY: 5 },
  };
}
