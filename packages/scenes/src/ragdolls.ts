import type { JointOptions } from '@maxgrid/engine';
import { resolveParams, type ParamSpecs } from './params.js';
import { boxBody, type SceneBody, type SceneShape, type ShapeScene } from './shape-scene.js';

/** The parameters ragdolls takes, with their defaults and ranges (resolveParams checks them). */
export const ragdollsParams = {
  count: { default: 40, min: 1, max: 10000, integer: true, description: 'ragdolls raining down' },
  columns: { default: 10, min: 1, max: 1000, integer: true, description: 'ragdolls side by side in each row' },
} satisfies ParamSpecs;

const QUARTER = Math.PI / 4;
const HALF = Math.PI / 2;

/** One limb or the torso: a capsule along the body's y axis (the body is turned a quarter turn), from `top` to `top + length`. */
function part(x: number, top: number, length: number, radius: number): SceneBody {
  const shape: SceneShape = { kind: 'capsule', length: length - 2 * radius, radius, density: 1, friction: 0.6 };
  return { x, y: top + length / 2, angle: HALF, shapes: [shape] };
}

/**
 * A rain of ragdolls onto the ground (Box2D's ragdoll benchmark, simplified): each has a round
 * head and nine capsules (a torso, and two-part arms and legs), ten bodies joined by nine
 * revolute joints with angle limits, dropped in rows. Meters, gravity 10, y down, the ground's top at y = 0.
 */
export function ragdolls(given?: Partial<Record<keyof typeof ragdollsParams, number>>): ShapeScene {
  const p = resolveParams('ragdolls', ragdollsParams, given);
  const bodies: SceneBody[] = [boxBody(0, 1, 8 * p.columns + 40, 2, { type: 'static' }, { friction: 0.6 })];
  const joints: JointOptions[] = [];
  // Parts run along their own x axis, turned a quarter turn to point down: a part's top is at
  // x = -length/2, and its frame's +y points to the world's -x. The motor at speed 0 is the joints' friction.
  const pin = (a: number, b: number, anchorA: { x: number; y: number }, bTop: number, lower: number, upper: number) => {
    joints.push({ kind: 'revolute', bodyA: a, bodyB: b, anchorA, anchorB: { x: bTop, y: 0 }, lowerAngle: lower, upperAngle: upper, maxMotorTorque: 0.05 });
  };
  for (let k = 0; k < p.count; k++) {
    const column = k % p.columns;
    const row = Math.floor(k / p.columns);
    const x = (column - (p.columns - 1) / 2) * 3;
    const top = -4 - row * 4;
    const head = bodies.push({ x, y: top + 0.15, shapes: [{ kind: 'circle', radius: 0.15, density: 1, friction: 0.6 }] }) - 1;
    const torso = bodies.push(part(x, top + 0.3, 0.7, 0.15)) - 1;
    const upperArmL = bodies.push(part(x - 0.25, top + 0.35, 0.35, 0.06)) - 1;
    const lowerArmL = bodies.push(part(x - 0.25, top + 0.7, 0.35, 0.05)) - 1;
    const upperArmR = bodies.push(part(x + 0.25, top + 0.35, 0.35, 0.06)) - 1;
    const lowerArmR = bodies.push(part(x + 0.25, top + 0.7, 0.35, 0.05)) - 1;
    const thighL = bodies.push(part(x - 0.09, top + 1.0, 0.45, 0.08)) - 1;
    const shinL = bodies.push(part(x - 0.09, top + 1.45, 0.45, 0.07)) - 1;
    const thighR = bodies.push(part(x + 0.09, top + 1.0, 0.45, 0.08)) - 1;
    const shinR = bodies.push(part(x + 0.09, top + 1.45, 0.45, 0.07)) - 1;
    pin(head, torso, { x: 0, y: 0.15 }, -0.35, -QUARTER, QUARTER);
    pin(torso, upperArmL, { x: -0.3, y: 0.25 }, -0.175, -HALF, HALF);
    pin(upperArmL, lowerArmL, { x: 0.175, y: 0 }, -0.175, 0, HALF);
    pin(torso, upperArmR, { x: -0.3, y: -0.25 }, -0.175, -HALF, HALF);
    pin(upperArmR, lowerArmR, { x: 0.175, y: 0 }, -0.175, 0, HALF);
    pin(torso, thighL, { x: 0.35, y: 0.09 }, -0.225, -QUARTER, HALF);
    pin(thighL, shinL, { x: 0.225, y: 0 }, -0.225, -HALF, 0);
    pin(torso, thighR, { x: 0.35, y: -0.09 }, -0.225, -QUARTER, HALF);
    pin(thighR, shinR, { x: 0.225, y: 0 }, -0.225, -HALF, 0);
  }
  const width = 3 * p.columns + 10;
  const height = 4 * Math.ceil(p.count / p.columns) + 6;
  return {
    name: 'ragdolls',
    kind: 'shapes',
    params: Object.freeze({ ...p }),
    bounds: null,
    gravity: { x: 0, y: 10 },
    world: { friction: 0.6, restitution: 0, lengthUnit: 1, solver: 'soft', sleeping: true },
    bodies,
    segments: [],
    joints,
    view: { minX: -width / 2, minY: -height, maxX: width / 2, maxY: 2 },
  };
}
