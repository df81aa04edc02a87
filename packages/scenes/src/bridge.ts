import type { JointOptions } from '@maxgrid/engine';
import { resolveParams, type ParamSpecs } from './params.js';
import { boxBody, type SceneBody, type ShapeScene } from './shape-scene.js';

/** The parameters bridge takes, with their defaults and ranges (resolveParams checks them). */
export const bridgeParams = {
  planks: { default: 30, min: 2, max: 10000, integer: true, description: 'planks in the bridge' },
  load: { default: 10, min: 0, max: 1000, integer: true, description: 'boxes dropped on the bridge' },
  jointFriction: { default: 50, min: 0, max: 1e6, description: 'friction torque in each pin (a motor at speed 0), which damps the swing' },
} satisfies ParamSpecs;

/**
 * A bridge of planks pinned end to end by revolute joints between two static posts (Box2D's
 * bridge sample, friction in the pins included), with boxes dropped on it: meters, gravity 10, y down, the deck at y = 0.
 */
export function bridge(given?: Partial<Record<keyof typeof bridgeParams, number>>): ShapeScene {
  const p = resolveParams('bridge', bridgeParams, given);
  const width = 1;
  const span = p.planks * width;
  const bodies: SceneBody[] = [boxBody(-0.5, 0.5, 1, 1, { type: 'static' }), boxBody(span + 0.5, 0.5, 1, 1, { type: 'static' })];
  const joints: JointOptions[] = [];
  for (let k = 0; k < p.planks; k++) {
    bodies.push(boxBody((k + 0.5) * width, 0.125, width, 0.25, {}, { density: 20, friction: 0.6 }));
    const index = bodies.length - 1;
    const previous = k === 0 ? 0 : index - 1;
    joints.push({ kind: 'revolute', bodyA: previous, bodyB: index, anchorA: k === 0 ? { x: 0.5, y: -0.5 } : { x: width / 2, y: 0 }, anchorB: { x: -width / 2, y: 0 }, maxMotorTorque: p.jointFriction });
  }
  joints.push({ kind: 'revolute', bodyA: bodies.length - 1, bodyB: 1, anchorA: { x: width / 2, y: 0 }, anchorB: { x: -0.5, y: -0.5 }, maxMotorTorque: p.jointFriction });
  for (let k = 0; k < p.load; k++) {
    const x = ((k + 0.5) / p.load) * span;
    bodies.push(boxBody(x, -3 - (k % 3), 0.8, 0.8, {}, { density: 1, friction: 0.6 }));
  }
  return {
    name: 'bridge',
    kind: 'shapes',
    params: Object.freeze({ ...p }),
    bounds: null,
    gravity: { x: 0, y: 10 },
    world: { friction: 0.6, restitution: 0, lengthUnit: 1, solver: 'soft' },
    bodies,
    segments: [],
    joints,
    view: { minX: -2, minY: -span / 2, maxX: span + 2, maxY: span / 4 },
  };
}
