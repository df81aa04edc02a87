import { seedBox, seedBoxParams } from './seed-box.js';
import { uniform, uniformParams } from './uniform.js';
import { bouncingBall, bouncingBallParams } from './bouncing-ball.js';
import { mixed, mixedParams } from './mixed.js';
import { funnel, funnelParams } from './funnel.js';
import type { ParamSpecs } from './params.js';
import type { Scene } from './scene.js';

export { Prng } from './prng.js';
export { buildWorld, type Scene, type SceneSegment, type BuildOptions, type Layers } from './scene.js';
export { resolveParams, type ParamSpec, type ParamSpecs } from './params.js';
export { seedBox, seedBoxParams, uniform, uniformParams, bouncingBall, bouncingBallParams, mixed, mixedParams, funnel, funnelParams };

export interface SceneDefinition {
  description: string;
  params: ParamSpecs;
  build(params?: Partial<Record<string, number>>): Scene;
}

/** Every scene by name: the lab's `--scene`, the sandbox's scene list and the tests use this. */
export const SCENES = {
  'seed-box': {
    description: "The report's test: random circles in a 1600x900 box, with gravity and elasticity",
    params: seedBoxParams,
    build: seedBox,
  },
  uniform: {
    description: 'Constant density: radius uniform in [4, 8], 25% of a square box filled, elastic, no gravity',
    params: uniformParams,
    build: uniform,
  },
  mixed: {
    description: "The report's worst case for Max Grid: many small circles and a few 100x larger ones",
    params: mixedParams,
    build: mixed,
  },
  funnel: {
    description: 'Static shapes: circles fall through a funnel of segments and a field of static pegs',
    params: funnelParams,
    build: funnel,
  },
  'bouncing-ball': {
    description: "The report's accuracy test: one elastic ball dropped in a box",
    params: bouncingBallParams,
    build: bouncingBall,
  },
} satisfies Record<string, SceneDefinition>;

export type SceneName = keyof typeof SCENES;
export const SCENE_NAMES = Object.keys(SCENES) as SceneName[];

export function buildScene(name: string, params?: Partial<Record<string, number>>): Scene {
  if (!(name in SCENES)) {
    throw new RangeError(`unknown scene '${name}'; scenes: ${SCENE_NAMES.join(', ')}`);
  }
  return SCENES[name as SceneName].build(params);
}
