import { resolveParams, type ParamSpecs } from './params.js';
import { allocateScene, type Scene } from './scene.js';

/** The parameters bouncingBall takes, with their defaults and ranges (resolveParams checks them). */
export const bouncingBallParams = {
  width: { default: 400, min: 1, max: 1e6, description: 'box width' },
  height: { default: 900, min: 1, max: 1e6, description: 'box height' },
  radius: { default: 20, min: 0.1, max: 1e5, description: 'ball radius' },
  dropHeight: { default: 700, min: 0, max: 1e6, description: "height of the ball's lowest point above the floor" },
  gravity: { default: 500, min: 0, max: 1e6, description: 'downward gravity, units/s^2' },
  elasticity: { default: 1, min: 0, max: 1, description: 'restitution of ball and walls' },
} satisfies ParamSpecs;

/** The report's accuracy test (5.13.1, 6.1): one ball dropped from rest in a box, restitution 1. */
export function bouncingBall(given?: Partial<Record<keyof typeof bouncingBallParams, number>>): Scene {
  const p = resolveParams('bouncing-ball', bouncingBallParams, given);
  if (2 * p.radius > p.width || p.dropHeight + 2 * p.radius > p.height) {
    throw new RangeError(`bouncing-ball: a ball of radius ${p.radius} dropped from ${p.dropHeight} does not fit a ${p.width} x ${p.height} box`);
  }
  const scene = allocateScene('bouncing-ball', p, 1, {
    bounds: { width: p.width, height: p.height },
    gravity: { x: 0, y: p.gravity },
    restitution: p.elasticity,
  });
  scene.radius[0] = p.radius;
  scene.x[0] = p.width / 2;
  scene.y[0] = p.height - p.radius - p.dropHeight;
  return scene;
}
