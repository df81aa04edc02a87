import type { JointOptions } from '@maxgrid/engine';
import { resolveParams, type ParamSpecs } from './params.js';
import type { SceneBody, ShapeScene } from './shape-scene.js';

/** The parameters car takes, with their defaults and ranges (resolveParams checks them). */
export const carParams = {
  speed: { default: 10, min: -200, max: 200, description: 'wheel motor speed, radians per second (positive drives right)' },
  torque: { default: 10, min: 0, max: 1e6, description: 'largest motor torque of each wheel' },
  hertz: { default: 4, min: 0, max: 100, description: 'suspension spring frequency' },
  bumps: { default: 40, min: 0, max: 10000, integer: true, description: 'bumps in the road' },
} satisfies ParamSpecs;

/**
 * A car on wheel joints (Box2D's car sample, simplified): a chassis box on two wheels, each on a
 * sprung wheel joint whose motor drives it, over a road of segments with bumps. Meters, gravity
 * 10, y down, the road's level at y = 0.
 */
export function car(given?: Partial<Record<keyof typeof carParams, number>>): ShapeScene {
  const p = resolveParams('car', carParams, given);
  const bodies: SceneBody[] = [
    { x: 0, y: -1.6, shapes: [{ kind: 'polygon', vertices: [{ x: -1.5, y: 0.3 }, { x: 1.5, y: 0.3 }, { x: 1.5, y: -0.1 }, { x: 0.4, y: -0.6 }, { x: -1.3, y: -0.5 }], density: 1, friction: 0.6 }] },
    { x: -1, y: -0.4, shapes: [{ kind: 'circle', radius: 0.4, density: 1, friction: 0.9 }] },
    { x: 1, y: -0.4, shapes: [{ kind: 'circle', radius: 0.4, density: 1, friction: 0.9 }] },
  ];
  const wheel = (index: number, x: number): JointOptions => ({
    kind: 'wheel',
    bodyA: 0,
    bodyB: index,
    anchorA: { x, y: 1.2 },
    axis: { x: 0, y: 1 },
    hertz: p.hertz,
    dampingRatio: 0.7,
    lowerTranslation: -0.25,
    upperTranslation: 0.25,
    motorSpeed: p.speed,
    maxMotorTorque: p.torque,
  });
  const segments: ShapeScene['segments'] = [{ x1: -20, y1: 0, x2: 10, y2: 0, thickness: 0 }];
  let x = 10;
  for (let k = 0; k < p.bumps; k++) {
    // A bump every 6 m, alternately a ramp up and down, 0.1 to 0.5 high.
    const height = 0.1 + ((k * 7) % 5) * 0.1;
    segments.push({ x1: x, y1: 0, x2: x + 2, y2: -height, thickness: 0 });
    segments.push({ x1: x + 2, y1: -height, x2: x + 4, y2: 0, thickness: 0 });
    segments.push({ x1: x + 4, y1: 0, x2: x + 6, y2: 0, thickness: 0 });
    x += 6;
  }
  return {
    name: 'car',
    kind: 'shapes',
    params: Object.freeze({ ...p }),
    bounds: null,
    gravity: { x: 0, y: 10 },
    world: { friction: 0.6, restitution: 0, lengthUnit: 1, solver: 'soft' },
    bodies,
    segments,
    joints: [wheel(1, -1), wheel(2, 1)],
    view: { minX: -10, minY: -8, maxX: 20, maxY: 2 },
  };
}
