import { World, type JointOptions, type ShapeOptions, type WorldOptions } from '@maxgrid/engine';

/** One shape of a scene body: the engine's ShapeOptions, as plain data. */
export type SceneShape = ShapeOptions;

/** One body of a shape scene, in the scene's units (y pointing down, as on screen). */
export interface SceneBody {
  x: number;
  y: number;
  angle?: number;
  vx?: number;
  vy?: number;
  angularVelocity?: number;
  type?: 'static' | 'kinematic' | 'dynamic';
  shapes: SceneShape[];
}

/**
 * A scene of bodies with shapes, as plain data, like `Scene` is for circles: the engine builds it
 * with buildShapeWorld, and the lab's adapters build the same bodies in each peer engine. Angles
 * are radians, positive from +x towards +y (clockwise on a y-down screen). Scenes draw no angle
 * through Math.sin or Math.cos (their rounding is each runtime's own): only the engine turns an
 * angle into a rotation, with its own functions.
 */
export interface ShapeScene {
  name: string;
  kind: 'shapes';
  params: Readonly<Record<string, number>>;
  /** A box that contains every body, or null for an open world. */
  bounds: { width: number; height: number } | null;
  gravity: { x: number; y: number };
  /** The World options the scene is meant for (friction, restitution, lengthUnit, solver, sleeping...). */
  world: Pick<WorldOptions, 'friction' | 'restitution' | 'restitutionThreshold' | 'lengthUnit' | 'solver' | 'sleeping' | 'substeps'>;
  bodies: SceneBody[];
  /** Static walls besides the bodies, as for createSegment. */
  segments: { x1: number; y1: number; x2: number; y2: number; thickness: number }[];
  /**
   * Joints, as for createJoint, with bodies named by their index in `bodies` (bodyA, bodyB, or a
   * target joint's body). Absent for scenes without joints.
   */
  joints?: JointOptions[];
  /** Where to look: the region the interesting bodies occupy, for renderers. */
  view: { minX: number; minY: number; maxX: number; maxY: number };
}

/** World options a caller may add to the scene's own (the scene's win where both are given). */
export type ShapeBuildOptions = Omit<WorldOptions, 'bounds' | 'gravity'>;

/** A maxgrid world holding the scene; body k gets handle k. */
export function buildShapeWorld(scene: ShapeScene, options: ShapeBuildOptions = {}): World {
  const world = new World({ ...options, ...scene.world, bounds: scene.bounds, gravity: scene.gravity });
  world.reserve(scene.bodies.length);
  for (const body of scene.bodies) {
    const handle = world.createBody({
      x: body.x,
      y: body.y,
      angle: body.angle,
      vx: body.vx,
      vy: body.vy,
      angularVelocity: body.angularVelocity,
      type: body.type,
    });
    for (const shape of body.shapes) world.addShape(handle, shape);
  }
  for (const s of scene.segments) world.createSegment(s);
  // Body k has handle k in a fresh world, so the scene's indices are the handles.
  for (const joint of scene.joints ?? []) world.createJoint(joint);
  return world;
}

/** A box body (width x height) as scene data. */
export function boxBody(x: number, y: number, width: number, height: number, extra: Omit<SceneBody, 'x' | 'y' | 'shapes'> = {}, material: Partial<SceneShape> = {}): SceneBody {
  return { x, y, ...extra, shapes: [{ kind: 'box', width, height, ...material } as SceneShape] };
}

/** The half-width of funnelAndFloor's walls. */
const WALL_THICKNESS = 0.1;

/**
 * Static walls for soft bodies poured from above: a funnel of `width` whose outlet, `outlet` wide,
 * is at y = 0, and below it a floor at y = 8 with walls at its ends (circles roll, and a soft body
 * on a bare floor rolls away like a wheel). Either part may be left out.
 */
export function funnelAndFloor(width: number, outlet: number, funnel: boolean, floor: boolean): ShapeScene['segments'] {
  const segments: ShapeScene['segments'] = [];
  const thickness = WALL_THICKNESS;
  if (funnel) {
    segments.push({ x1: -width / 2, y1: -width / 2, x2: -outlet / 2, y2: 0, thickness });
    segments.push({ x1: width / 2, y1: -width / 2, x2: outlet / 2, y2: 0, thickness });
  }
  if (floor) {
    segments.push({ x1: -width, y1: 8, x2: width, y2: 8, thickness });
    segments.push({ x1: -width, y1: 8, x2: -width, y2: -4, thickness });
    segments.push({ x1: width, y1: 8, x2: width, y2: -4, thickness });
  }
  return segments;
}

/**
 * How far to move bodies poured from above up (towards -y) so that each, `reach` in radius, starts
 * clear above the funnelAndFloor funnel's walls (`width` wide at the top, `outlet` at y = 0), with
 * `gap` to spare: 0 where all already are. A grid of soft bodies as wide as the funnel has its
 * lower corners below the walls' slopes, and a body that starts across a wall stays caught on it.
 */
export function liftAboveFunnel(bodies: readonly SceneBody[], width: number, outlet: number, reach: number, gap: number): number {
  const half = width / 2;
  const slope = half / (half - outlet / 2);
  // A circle clears a wall y = slope (x - outlet/2) (the right one, mirrored for the left) when its
  // centre is its reach and the wall's thickness, measured along the wall's normal, above it.
  const rise = (reach + WALL_THICKNESS + gap) * Math.sqrt(1 + slope * slope);
  let lift = 0;
  for (const body of bodies) {
    const x = Math.abs(body.x);
    if (x + reach <= outlet / 2) continue;
    const wall = -slope * (Math.min(x, half) - outlet / 2);
    lift = Math.max(lift, body.y - (wall - rise));
  }
  return lift;
}
