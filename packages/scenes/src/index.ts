/**
 * Seeded scene builders for `@maxgrid/engine`, as plain data, so that the same scene builds the
 * same bodies in maxgrid and in the engines the lab measures it against: {@link buildScene} and
 * {@link buildWorld} for circle scenes, {@link buildShapeScene} and {@link buildShapeWorld} for
 * scenes of bodies with shapes and joints.
 *
 * @module @maxgrid/scenes
 */
import { seedBox, seedBoxParams } from './seed-box.js';
import { uniform, uniformParams } from './uniform.js';
import { bouncingBall, bouncingBallParams } from './bouncing-ball.js';
import { mixed, mixedParams } from './mixed.js';
import { funnel, funnelParams } from './funnel.js';
import type { ParamSpecs } from './params.js';
import type { Scene } from './scene.js';
import type { ShapeScene } from './shape-scene.js';
import { pyramid, pyramidParams } from './pyramid.js';
import { verticalStack, verticalStackParams } from './vertical-stack.js';
import { cardHouse, cardHouseParams } from './card-house.js';
import { ramp, rampParams } from './ramp.js';
import { uniformPolygons, uniformPolygonsParams } from './uniform-polygons.js';
import { manyPyramids, manyPyramidsParams } from './many-pyramids.js';
import { tumbler, tumblerParams } from './tumbler.js';
import { polygonBox, polygonBoxParams } from './polygon-box.js';
import { chain, chainParams } from './chain.js';
import { bridge, bridgeParams } from './bridge.js';
import { jointGrid, jointGridParams } from './joint-grid.js';
import { ragdolls, ragdollsParams } from './ragdolls.js';
import { car, carParams } from './car.js';
import { jellies, jelliesParams } from './soft-bodies.js';
import { blobs, blobsParams } from './blobs.js';
import { farBodies, farBodiesParams, sparseBox, sparseBoxParams, twoCrowds, twoCrowdsParams, segmentFloor, segmentFloorParams, staticWall, staticWallParams, logRadii, logRadiiParams } from './cliffs.js';

export { Prng } from './prng.js';
export { buildWorld, type Scene, type SceneSegment, type BuildOptions, type Layers } from './scene.js';
export { buildShapeWorld, boxBody, type ShapeScene, type SceneBody, type SceneShape, type ShapeBuildOptions } from './shape-scene.js';
export { pyramid, pyramidParams, verticalStack, verticalStackParams, cardHouse, cardHouseParams, ramp, rampParams, uniformPolygons, uniformPolygonsParams };
export { manyPyramids, manyPyramidsParams, tumbler, tumblerParams, polygonBox, polygonBoxParams };
export { chain, chainParams, bridge, bridgeParams, jointGrid, jointGridParams, ragdolls, ragdollsParams, car, carParams, jellies, jelliesParams, blobs, blobsParams };
export { resolveParams, type ParamSpec, type ParamSpecs, type ParamValues } from './params.js';
export { seedBox, seedBoxParams, uniform, uniformParams, bouncingBall, bouncingBallParams, mixed, mixedParams, funnel, funnelParams };

/** A circle scene by name: what it shows, the parameters it takes, and its builder. */
export interface SceneDefinition {
  /** What the scene shows, in one line. */
  description: string;
  params: ParamSpecs;
  /** Builds the scene; parameters left out take their defaults. */
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

/**
 * Scenes where a broad-phase or the continuous sweep used to fall off a cliff (see cliffs.ts):
 * the lab's `cliffs` experiment and the engine's tests use these. Two have no box (`open`).
 */
export const CLIFF_SCENES = {
  'far-bodies': { description: '20,000 circles in a patch and 4 more a million units away, no box', params: farBodiesParams, build: farBodies },
  'sparse-box': { description: '20,000 circles in a corner of a box 100,000 wide', params: sparseBoxParams, build: sparseBox },
  'two-crowds': { description: 'Two crowds of 10,000 circles a million units apart along each axis, no box', params: twoCrowdsParams, build: twoCrowds },
  'segment-floor': { description: '2,000 circles falling onto a floor of 2,000 segments (continuous collision sweeps them)', params: segmentFloorParams, build: segmentFloor },
  'static-wall': { description: 'A wall of 10,000 overlapping static circles and 1,000 circles moving at it at 300 units/s', params: staticWallParams, build: staticWall },
  'log-radii': { description: 'uniform with radii log-uniform from 0.01 to 10,000 (six decades)', params: logRadiiParams, build: logRadii },
} satisfies Record<string, SceneDefinition>;

/** The name of a cliff scene. */
export type CliffSceneName = keyof typeof CLIFF_SCENES;
/** Every cliff scene's name, in the order CLIFF_SCENES lists them. */
export const CLIFF_SCENE_NAMES = Object.keys(CLIFF_SCENES) as CliffSceneName[];

/** The name of a circle scene. */
export type SceneName = keyof typeof SCENES;
/** Every circle scene's name, in the order SCENES lists them. */
export const SCENE_NAMES = Object.keys(SCENES) as SceneName[];

/** Builds a circle scene of SCENES by name; an unknown name throws a RangeError that lists the known ones. */
export function buildScene(name: string, params?: Partial<Record<string, number>>): Scene {
  if (!Object.hasOwn(SCENES, name)) {
    throw new RangeError(`unknown scene '${name}'; scenes: ${SCENE_NAMES.join(', ')}`);
  }
  return SCENES[name as SceneName].build(params);
}

/** A scene of bodies with shapes by name: what it shows, the parameters it takes, and its builder. */
export interface ShapeSceneDefinition {
  /** What the scene shows, in one line. */
  description: string;
  params: ParamSpecs;
  /** Builds the scene; parameters left out take their defaults. */
  build(params?: Partial<Record<string, number>>): ShapeScene;
}

/** Scenes of bodies with shapes, by name (see ShapeScene). */
export const SHAPE_SCENES = {
  pyramid: {
    description: "Box2D v3's large_pyramid: 5,050 unit boxes (base 100) on a static ground, friction 0.6",
    params: pyramidParams,
    build: pyramid,
  },
  'many-pyramids': {
    description: "Box2D v3's many_pyramids: 20 x 20 pyramids of base 10 (22,000 boxes), each row on its own floor",
    params: manyPyramidsParams,
    build: manyPyramids,
  },
  'vertical-stack': {
    description: 'A column of 15 boxes on the ground; massRatio makes the top one heavy',
    params: verticalStackParams,
    build: verticalStack,
  },
  'card-house': {
    description: "Box2D v3's card house: thin cards leaning in pairs, five storeys, friction 0.7",
    params: cardHouseParams,
    build: cardHouse,
  },
  ramp: {
    description: 'A box on a static ramp tilted up to 44 degrees: it sticks while tan(angle) <= friction, else slides',
    params: rampParams,
    build: ramp,
  },
  'uniform-polygons': {
    description: "The uniform scene with shapes: squares and hexagons, circumradius in [4, 8], 25% filled, elastic, frictionless, no gravity",
    params: uniformPolygonsParams,
    build: uniformPolygons,
  },
  'polygon-box': {
    description: "The report's seed box with shapes: boxes, triangles, hexagons, capsules and circles, spinning, under gravity",
    params: polygonBoxParams,
    build: polygonBox,
  },
  tumbler: {
    description: "Box2D v3's tumbler: 2,025 small boxes in a hollow square drum turned kinematically",
    params: tumblerParams,
    build: tumbler,
  },
  chain: {
    description: 'A 100-link chain of capsules on revolute joints, hanging from a pin (horizontal: 1 lets it swing down; rope: 1 makes it a rope of beads on distance joints)',
    params: chainParams,
    build: chain,
  },
  bridge: {
    description: 'A bridge of 30 planks on revolute joints between two posts, with boxes dropped on it',
    params: bridgeParams,
    build: bridge,
  },
  'joint-grid': {
    description: "Box2D v3's joint_grid: 100 x 100 circles pinned to their neighbours by revolute joints, hanging",
    params: jointGridParams,
    build: jointGrid,
  },
  ragdolls: {
    description: 'A rain of ragdolls (a round head and nine capsules on revolute joints with limits) onto the ground',
    params: ragdollsParams,
    build: ragdolls,
  },
  car: {
    description: 'A car on two sprung wheel joints with motors, driving over a bumpy road of segments',
    params: carParams,
    build: car,
  },
  jellies: {
    description: 'Soft bodies: lattice jellies of circles on distance springs (shear springs included) falling into a funnel',
    params: jelliesParams,
    build: jellies,
  },
  blobs: {
    description: 'Soft bodies: pressure blobs, rings of circles on distance springs around a gas (a pressure joint), falling into a funnel',
    params: blobsParams,
    build: blobs,
  },
} satisfies Record<string, ShapeSceneDefinition>;

/** The name of a scene with shapes. */
export type ShapeSceneName = keyof typeof SHAPE_SCENES;
/** Every shape scene's name, in the order SHAPE_SCENES lists them. */
export const SHAPE_SCENE_NAMES = Object.keys(SHAPE_SCENES) as ShapeSceneName[];

/** Builds a scene with shapes by name; an unknown name throws a RangeError that lists the known ones. */
export function buildShapeScene(name: string, params?: Partial<Record<string, number>>): ShapeScene {
  if (!Object.hasOwn(SHAPE_SCENES, name)) throw new RangeError(`unknown shape scene '${name}'; shape scenes: ${SHAPE_SCENE_NAMES.join(', ')}`);
  return SHAPE_SCENES[name as ShapeSceneName].build(params);
}
