import type { SceneBody, SceneShape, ShapeScene } from '@maxgrid/scenes';

/**
 * The lab's engines for scenes of shapes (boxes, polygons, capsules, circles that turn), beside
 * the circle adapters of ../engines. Every adapter builds the same `ShapeScene` (scene units, y
 * down, gravity along +y, angles in radians from +x towards +y) in its own units and reads it back
 * in scene units, so experiments compare like with like.
 */

/**
 * `report`: the report's Unity configuration (one velocity and one position iteration, or the
 * engine's nearest, no sleeping, discrete collision). `defaults`: each engine's recommended
 * settings for stacking (Box2D 8 velocity / 3 position iterations, Rapier's and Matter's
 * defaults, ...), sleeping off. maxgrid has one solver either way (the scene's).
 */
export type ShapeProfile = 'report' | 'defaults';
export const SHAPE_PROFILES: readonly ShapeProfile[] = ['report', 'defaults'];

export interface ShapeEngineInfo {
  id: string;
  package: string;
  version: string;
  precision: 'f64' | 'f32';
  /** The settings each profile applies, as written into every output. */
  settings: Record<ShapeProfile, Record<string, string | number | boolean>>;
}

/** Caller-owned columns that `read` fills, in scene units: body k's origin, angle and velocities. */
export interface PoseState {
  x: Float64Array;
  y: Float64Array;
  angle: Float64Array;
  vx: Float64Array;
  vy: Float64Array;
  angularVelocity: Float64Array;
}

export function allocatePoses(count: number): PoseState {
  return {
    x: new Float64Array(count),
    y: new Float64Array(count),
    angle: new Float64Array(count),
    vx: new Float64Array(count),
    vy: new Float64Array(count),
    angularVelocity: new Float64Array(count),
  };
}

/** Where the last step's time went, where the engine says (maxgrid). */
export interface StageTimes {
  broadphaseMs: number;
  narrowphaseMs: number;
  solveMs: number;
  pairTests: number;
  candidatePairs: number;
  contacts: number;
}

export interface ShapeSimulation {
  readonly count: number;
  step(dt: number): void;
  read(out: PoseState): void;
  stages?(): StageTimes;
  stateHash?(): string;
  dispose(): void;
}

export interface ShapeEngine {
  info: ShapeEngineInfo;
  create(scene: ShapeScene, profile: ShapeProfile): ShapeSimulation;
}

export interface ShapeEngineProvider {
  id: string;
  load(options?: { box2dWasmBinary?: Uint8Array; box2dLocateFile?: (file: string, prefix: string) => string }): Promise<ShapeEngine>;
}

/** Meters per scene unit for the Box2D family and Rapier: the scene's lengthUnit is scene units per meter. */
export function metersPerUnit(scene: ShapeScene): number {
  return 1 / (scene.world.lengthUnit ?? 1);
}

export function materialOf(scene: ShapeScene, shape: SceneShape): { friction: number; restitution: number; density: number } {
  return {
    friction: shape.friction ?? scene.world.friction ?? 0.6,
    restitution: shape.restitution ?? scene.world.restitution ?? 0,
    density: shape.density ?? 1,
  };
}

/**
 * A polygon's vertices counter-clockwise in the y-up sense (positive signed area), as p2 requires
 * and the others accept: scenes may list them either way.
 */
export function counterClockwise(vertices: readonly { x: number; y: number }[]): { x: number; y: number }[] {
  let area = 0;
  for (let i = 0; i < vertices.length; i++) {
    const a = vertices[i];
    const b = vertices[(i + 1) % vertices.length];
    area += a.x * b.y - b.x * a.y;
  }
  return area >= 0 ? vertices.slice() : vertices.slice().reverse();
}

/** A box's or polygon's vertices in its body's frame, with the shape's offset and offset angle applied. */
export function placedVertices(shape: SceneShape): { x: number; y: number }[] {
  let local: { x: number; y: number }[];
  if (shape.kind === 'box') {
    const hx = shape.width / 2;
    const hy = shape.height / 2;
    local = [{ x: -hx, y: -hy }, { x: hx, y: -hy }, { x: hx, y: hy }, { x: -hx, y: hy }];
  } else if (shape.kind === 'polygon') {
    local = shape.vertices.map((v) => ({ x: v.x, y: v.y }));
  } else {
    throw new RangeError(`placedVertices: shape kind '${shape.kind}' has no vertices`);
  }
  const ox = shape.offsetX ?? 0;
  const oy = shape.offsetY ?? 0;
  const a = shape.offsetAngle ?? 0;
  const c = Math.cos(a);
  const s = Math.sin(a);
  return counterClockwise(local.map((v) => ({ x: ox + c * v.x - s * v.y, y: oy + s * v.x + c * v.y })));
}

/** The scene's box as four thick static rectangles just outside it (as the circle adapters build it). */
export function shapeWalls(bounds: { width: number; height: number }): { cx: number; cy: number; width: number; height: number }[] {
  const { width: w, height: h } = bounds;
  const t = Math.max(w, h) / 4;
  return [
    { cx: w / 2, cy: -t / 2, width: w + 2 * t, height: t },
    { cx: w / 2, cy: h + t / 2, width: w + 2 * t, height: t },
    { cx: -t / 2, cy: h / 2, width: t, height: h },
    { cx: w + t / 2, cy: h / 2, width: t, height: h },
  ];
}

/** Mass and rotational inertia about the body's origin of a body's shapes at density `density` (their own), summed. */
export function bodyMass(body: SceneBody): { mass: number; inertia: number } {
  let mass = 0;
  let inertia = 0;
  for (const shape of body.shapes) {
    const density = shape.density ?? 1;
    const { area, cx, cy, polar } = shapeArea(shape);
    mass += density * area;
    inertia += density * (polar + area * (cx * cx + cy * cy));
  }
  return { mass, inertia };
}

/** Area, centroid and polar moment of area about the centroid, of one shape in its body's frame. */
function shapeArea(shape: SceneShape): { area: number; cx: number; cy: number; polar: number } {
  const ox = shape.offsetX ?? 0;
  const oy = shape.offsetY ?? 0;
  if (shape.kind === 'circle') {
    const r = shape.radius;
    return { area: Math.PI * r * r, cx: ox, cy: oy, polar: (Math.PI * r ** 4) / 2 };
  }
  if (shape.kind === 'capsule') {
    const r = shape.radius;
    const l = shape.length;
    const rect = 2 * r * l;
    const disc = Math.PI * r * r;
    // The rectangle's moment, plus the two half discs moved out to the ends (parallel axis on
    // each half disc's own centroid, 4r/3pi from the flat side).
    const rectPolar = (rect * (l * l + 4 * r * r)) / 12;
    const d = l / 2 + (4 * r) / (3 * Math.PI);
    const halfPolarAboutCentroid = (disc / 2) * (r * r / 2) - (disc / 2) * ((4 * r) / (3 * Math.PI)) ** 2;
    return { area: rect + disc, cx: ox, cy: oy, polar: rectPolar + 2 * (halfPolarAboutCentroid + (disc / 2) * d * d) };
  }
  const v = placedVertices(shape);
  let area = 0;
  let cx = 0;
  let cy = 0;
  let polar = 0;
  for (let i = 0; i < v.length; i++) {
    const a = v[i];
    const b = v[(i + 1) % v.length];
    const cross = a.x * b.y - b.x * a.y;
    area += cross / 2;
    cx += ((a.x + b.x) * cross) / 6;
    cy += ((a.y + b.y) * cross) / 6;
    polar += (cross * (a.x * a.x + a.x * b.x + b.x * b.x + a.y * a.y + a.y * b.y + b.y * b.y)) / 12;
  }
  cx /= area;
  cy /= area;
  return { area, cx, cy, polar: polar - area * (cx * cx + cy * cy) };
}
