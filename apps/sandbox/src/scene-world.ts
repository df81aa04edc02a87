import type { BroadPhaseName, IntegratorName, World } from '@maxgrid/engine';
import { buildShapeWorld, buildWorld, type BuildOptions, type Scene, type ShapeScene } from '@maxgrid/scenes';

/** Collision layers of the Layers toggle: two body layers that pass through each other... */
export const LAYER_A = 1;
export const LAYER_B = 2;
/** ...and one for static shapes, which both layers still hit. */
export const LAYER_STATIC = 4;

export interface WorldChoices {
  broadphase: BroadPhaseName;
  integrator: IntegratorName;
  sleeping: boolean;
  piles: boolean;
  continuous: boolean;
  events: boolean;
  hits: boolean;
  layers: boolean;
}

/** The Pile solver toggle's solverIterations, positionCorrection and contactSlop (px). */
export const PILE_ITERATIONS = 4;
export const PILE_CORRECTION = 0.2;
export const PILE_SLOP = 0.05;

/** Slowest approach, in px/s, that counts as a hit: under it a body moves under a pixel per step. */
export const MIN_HIT_SPEED = 50;

/**
 * The hitEventThreshold of the Hit events toggle. A hit should be a collision one can see, not a
 * body resting on another: under gravity a resting contact approaches at about g·dt every step,
 * and a settled pile jitters at up to ~7 g·dt (measured for the Sleeping toggle below), so hits
 * start at 8 g·dt. Without gravity, or with weak gravity, 50 px/s (under a pixel per 60 Hz step)
 * keeps the slowest grazes out while the seed box's default speeds (100 ± 50 px/s) all count.
 */
export function hitThreshold(scene: Scene, dt: number): number {
  return Math.max(MIN_HIT_SPEED, 8 * Math.hypot(scene.gravity.x, scene.gravity.y) * dt);
}

/** The layer of a dynamic body in slot `slot`: even and odd slots, so the seed decides who is where. */
export function layerOf(slot: number): number {
  return slot % 2 === 0 ? LAYER_A : LAYER_B;
}

/** Category and mask of a dynamic body with the Layers toggle on: its own layer and the statics. */
export function layerMask(slot: number): number {
  return layerOf(slot) | LAYER_STATIC;
}

/** The scene as a world with the sandbox's toggles: circle k gets handle (and slot) k. */
export function buildSandboxWorld(scene: Scene, dt: number, c: WorldChoices): World {
  const g = Math.hypot(scene.gravity.x, scene.gravity.y);
  const options: BuildOptions = {
    broadphase: c.broadphase,
    integrator: c.integrator,
    continuous: c.continuous,
    contactEvents: c.events,
  };
  if (c.hits) options.hitEventThreshold = hitThreshold(scene, dt);
  if (c.piles) {
    // Four passes with warm starting and the walls as contacts, a fifth of each overlap removed
    // per pass beyond 1 % of a 5 px radius: a settled 3,000-circle seed-box pile then stands
    // 250 px high and moves 1.4 px/s, against 107 px and 502 px/s with the report's single pass
    // (docs/engine.md, "Piles"), for 3.2 ms a step against 2.0. Off, the report's model stays.
    options.solverIterations = PILE_ITERATIONS;
    options.positionCorrection = PILE_CORRECTION;
    options.contactSlop = PILE_SLOP;
  }
  if (c.sleeping) {
    options.sleeping = true;
    // Both thresholds scale with g·dt, the speed gravity adds in one step. A resting contact
    // "approaches" at about g·dt every step; with restitution that is an endless micro-bounce, so
    // approaches under 2 g·dt are made inelastic. With the report's one solver pass a settled
    // pile keeps moving (median 46 px/s on seed-box at elasticity 0) and never sleeps; with the
    // Pile solver its bodies move at about 1 px/s, and at 8 g·dt a 2,000-circle pile is asleep,
    // as a whole, 6 s in (docs/engine.md, "Sleeping"). 8 g·dt stays safe in flight: a body is
    // that slow for only 16 steps around the top of its arc, under the 0.5 s (30 steps) it must
    // stay slow before sleeping.
    // Without gravity nothing rests on anything: the engine's defaults (1 px/s, elastic) apply.
    if (g > 0) {
      options.sleepSpeed = 8 * g * dt;
      options.restitutionThreshold = 2 * g * dt;
    }
  }
  if (c.layers) {
    options.layers = (k, isStatic) =>
      isStatic ? { category: LAYER_STATIC, mask: 0xffffffff } : { category: layerOf(k), mask: layerMask(k) };
    options.segmentLayers = { category: LAYER_STATIC, mask: 0xffffffff };
  }
  const world = buildWorld(scene, options);
  return world;
}

/**
 * A shape scene as a world with the sandbox's toggles: the scene's own world options (solver,
 * lengthUnit, friction), the page's broad-phase, integrator, sub-steps, sleeping, continuous
 * collision and events. The pile solver belongs to the circle route (the soft step stacks anyway)
 * and layers to circles' slot parity, so both are left out here. Body k gets handle k.
 */
export function buildSandboxShapeWorld(scene: ShapeScene, dt: number, c: WorldChoices, substeps: number): World {
  const world = { ...scene.world, sleeping: c.sleeping, substeps };
  const g = Math.hypot(scene.gravity.x, scene.gravity.y);
  return buildShapeWorld(
    { ...scene, world },
    {
      broadphase: c.broadphase,
      integrator: c.integrator,
      continuous: c.continuous,
      contactEvents: c.events,
      ...(c.hits ? { hitEventThreshold: Math.max(8 * g * dt, (scene.world.lengthUnit ?? 1) * 0.5) } : {}),
    },
  );
}

/** Segments as one flat array (x1, y1, x2, y2, thickness per segment), for the renderers. */
export function flatSegments(scene: Scene | ShapeScene): Float64Array {
  const out = new Float64Array(scene.segments.length * 5);
  scene.segments.forEach((s, i) => out.set([s.x1, s.y1, s.x2, s.y2, s.thickness], i * 5));
  return out;
}
