import { resolveParams, type ParamSpecs } from './params.js';
import type { SceneBody, ShapeScene } from './shape-scene.js';

/** The parameters ramp takes, with their defaults and ranges (resolveParams checks them). */
export const rampParams = {
  angle: { default: 20, min: 0, max: 44, description: 'slope of the ramp, degrees; under 45, where the box would tip over rather than stick or slide' },
  friction: { default: 0.5, min: 0, max: 10, description: 'friction of the box and the ramp' },
  length: { default: 40, min: 1, max: 1000, description: 'length of the ramp, m' },
} satisfies ParamSpecs;

/**
 * A box at rest on a static ramp tilted by `angle` (the ramp is a long static box, turned): it
 * stays when tan(angle) <= friction and otherwise slides down with acceleration
 * g (sin(angle) - friction cos(angle)). Meters, gravity 10, y down; the box starts at the ramp's
 * upper end, which is on the left. The box is a unit cube, so from 45 degrees its centre lies
 * beyond its lower edge: there, wherever friction is 1 or more, it tips over and tumbles instead
 * (measured from 45 to 80 degrees), hence the slope's range stops short of 45.
 */
export function ramp(given?: Partial<Record<keyof typeof rampParams, number>>): ShapeScene {
  const p = resolveParams('ramp', rampParams, given);
  // Rotating +x towards +y (down, on screen) by the slope makes the ramp descend to the right.
  const slope = (p.angle * Math.PI) / 180;
  // Both bodies sit at the origin turned by the slope, their shapes placed in that turned frame:
  // the ramp's top surface along the frame's x axis, the box on it near the upper end. The engine
  // turns the one angle into a rotation, so the scene needs no sine or cosine of its own.
  const bodies: SceneBody[] = [
    { x: 0, y: 0, angle: slope, type: 'static', shapes: [{ kind: 'box', width: p.length, height: 1, offsetY: 0.5, friction: p.friction }] },
    { x: 0, y: 0, angle: slope, shapes: [{ kind: 'box', width: 1, height: 1, offsetX: -p.length / 2 + 2, offsetY: -0.5, friction: p.friction, density: 1 }] },
  ];
  return {
    name: 'ramp',
    kind: 'shapes',
    params: Object.freeze({ ...p }),
    bounds: null,
    gravity: { x: 0, y: 10 },
    world: { friction: p.friction, restitution: 0, lengthUnit: 1, solver: 'soft' },
    bodies,
    segments: [],
    view: { minX: -p.length / 2 - 1, minY: -p.length / 2, maxX: p.length / 2 + 1, maxY: p.length / 2 },
  };
}
