import type { JointOptions } from '@maxgrid/engine';
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

/**
 * Thrown by `create` when a scene needs something the engine does not have (a joint kind, a
 * joint's spring, limit or motor): an experiment then skips that engine on that scene, and says
 * why, rather than timing a scene with part of it left out.
 */
export class UnsupportedSceneError extends Error {
  constructor(
    readonly engine: string,
    readonly scene: string,
    readonly reason: string,
  ) {
    super(`${engine} cannot build scene '${scene}': ${reason}`);
    this.name = 'UnsupportedSceneError';
  }
}

type Point = { x: number; y: number };
/** Angle limits or translation limits; an unbounded side is ±Infinity. */
export type JointRange = { lower: number; upper: number };

interface ResolvedBase {
  /** The joint's index in scene.joints, for messages. */
  index: number;
  bodyA: number;
  bodyB: number;
  /** In each body's frame from its origin, scene units (defaults filled in: the centre of mass). */
  anchorA: Point;
  anchorB: Point;
  collideConnected: boolean;
}

/**
 * A scene joint with every default resolved the way maxgrid's createJoint resolves it
 * (packages/engine/src/joints/joint-options.ts), so that each peer adapter only maps values, and
 * all of them read one interpretation of the options.
 */
export type ResolvedJoint =
  | (ResolvedBase & { kind: 'distance'; length: number; minLength: number; maxLength: number; hertz: number; dampingRatio: number })
  | (ResolvedBase & { kind: 'revolute'; referenceAngle: number; limits: JointRange | null; motor: { speed: number; maxTorque: number } | null; hertz: number; dampingRatio: number })
  | (ResolvedBase & { kind: 'prismatic'; axis: Point; referenceAngle: number; limits: JointRange | null; motor: { speed: number; maxForce: number } | null; hertz: number; dampingRatio: number })
  | (ResolvedBase & { kind: 'weld'; referenceAngle: number; linearHertz: number; angularHertz: number; dampingRatio: number })
  | (ResolvedBase & { kind: 'wheel'; axis: Point; limits: JointRange | null; motor: { speed: number; maxTorque: number } | null; hertz: number; dampingRatio: number });

/** A body's centre of mass in its own frame, from its origin (the shapes' own densities). */
export function bodyCentroid(body: SceneBody): Point {
  let mass = 0;
  let x = 0;
  let y = 0;
  for (const shape of body.shapes) {
    const { area, cx, cy } = shapeArea(shape);
    const m = (shape.density ?? 1) * area;
    mass += m;
    x += m * cx;
    y += m * cy;
  }
  return mass > 0 ? { x: x / mass, y: y / mass } : { x: 0, y: 0 };
}

/** A point given in body `body`'s frame, in the scene. */
export function scenePoint(body: SceneBody, p: Point): Point {
  const a = body.angle ?? 0;
  const c = Math.cos(a);
  const s = Math.sin(a);
  return { x: body.x + c * p.x - s * p.y, y: body.y + s * p.x + c * p.y };
}

function unitAxis(v: Point | undefined, fallback: Point): Point {
  const a = v ?? fallback;
  const length = Math.hypot(a.x, a.y);
  return { x: a.x / length, y: a.y / length };
}

function rangeOf(lower: number | undefined, upper: number | undefined): JointRange | null {
  return lower === undefined && upper === undefined ? null : { lower: lower ?? -Infinity, upper: upper ?? Infinity };
}

/**
 * The scene's joints resolved for a peer engine, or an UnsupportedSceneError for what no peer
 * adapter builds: target (mouse) joints, which need a moving target the experiments do not drive,
 * and breakable joints, which only maxgrid destroys.
 */
export function resolveSceneJoints(scene: ShapeScene, engine: string): ResolvedJoint[] {
  return (scene.joints ?? []).map((given, index) => {
    if (given.kind === 'target') throw new UnsupportedSceneError(engine, scene.name, `joint ${index} is a target joint, which the lab's peer adapters do not build`);
    // maxgrid's force-driven spring between centres has no counterpart these adapters build (the peers' springs are soft constraints).
    if ((given.kind as string) === 'spring') throw new UnsupportedSceneError(engine, scene.name, `joint ${index} is a force spring (kind 'spring'), which the lab's peer adapters do not build`);
    // Gas in a ring of bodies: no peer engine has one.
    if (given.kind === 'pressure') throw new UnsupportedSceneError(engine, scene.name, `joint ${index} is a pressure joint (gas in a ring of bodies), which no peer engine has`);
    const joint = given as Exclude<JointOptions, { kind: 'target' | 'spring' | 'pressure' }>;
    const breakable = (joint.breakForce ?? Infinity) !== Infinity || (joint.breakTorque ?? Infinity) !== Infinity;
    if (breakable) throw new UnsupportedSceneError(engine, scene.name, `joint ${index} is breakable (breakForce/breakTorque), which the lab's peer adapters do not build`);
    const a = scene.bodies[joint.bodyA];
    const b = scene.bodies[joint.bodyB];
    const base: ResolvedBase = {
      index,
      bodyA: joint.bodyA,
      bodyB: joint.bodyB,
      anchorA: joint.anchorA ?? bodyCentroid(a),
      anchorB: joint.anchorB ?? bodyCentroid(b),
      collideConnected: joint.collideConnected ?? false,
    };
    const relative = (b.angle ?? 0) - (a.angle ?? 0);
    switch (joint.kind) {
      case 'distance': {
        const pa = scenePoint(a, base.anchorA);
        const pb = scenePoint(b, base.anchorB);
        const length = joint.length ?? Math.hypot(pb.x - pa.x, pb.y - pa.y);
        const hertz = joint.hertz ?? 0;
        // As createJoint: rigid at `length` unless a range or a spring is given; a spring alone has no limits.
        const free = joint.minLength !== undefined || joint.maxLength !== undefined || hertz > 0;
        return { ...base, kind: 'distance', length, minLength: joint.minLength ?? (free ? 0 : length), maxLength: joint.maxLength ?? (free ? Infinity : length), hertz, dampingRatio: joint.dampingRatio ?? 0 };
      }
      case 'revolute':
        return {
          ...base,
          kind: 'revolute',
          referenceAngle: joint.referenceAngle ?? relative,
          limits: rangeOf(joint.lowerAngle, joint.upperAngle),
          motor: (joint.maxMotorTorque ?? 0) > 0 ? { speed: joint.motorSpeed ?? 0, maxTorque: joint.maxMotorTorque! } : null,
          hertz: joint.hertz ?? 0,
          dampingRatio: joint.dampingRatio ?? 0,
        };
      case 'prismatic':
        return {
          ...base,
          kind: 'prismatic',
          axis: unitAxis(joint.axis, { x: 1, y: 0 }),
          referenceAngle: joint.referenceAngle ?? relative,
          limits: rangeOf(joint.lowerTranslation, joint.upperTranslation),
          motor: (joint.maxMotorForce ?? 0) > 0 ? { speed: joint.motorSpeed ?? 0, maxForce: joint.maxMotorForce! } : null,
          hertz: joint.hertz ?? 0,
          dampingRatio: joint.dampingRatio ?? 0,
        };
      case 'weld':
        return { ...base, kind: 'weld', referenceAngle: joint.referenceAngle ?? relative, linearHertz: joint.linearHertz ?? 0, angularHertz: joint.angularHertz ?? 0, dampingRatio: joint.dampingRatio ?? 0 };
      case 'wheel':
        return {
          ...base,
          kind: 'wheel',
          axis: unitAxis(joint.axis, { x: 0, y: 1 }),
          limits: rangeOf(joint.lowerTranslation, joint.upperTranslation),
          motor: (joint.maxMotorTorque ?? 0) > 0 ? { speed: joint.motorSpeed ?? 0, maxTorque: joint.maxMotorTorque! } : null,
          hertz: joint.hertz ?? 1,
          dampingRatio: joint.dampingRatio ?? 0.7,
        };
      default:
        // A kind added to the engine after these adapters: refused until they learn it.
        throw new UnsupportedSceneError(engine, scene.name, `joint ${index} is a '${(joint as { kind: string }).kind}' joint, which the lab's peer adapters do not build`);
    }
  });
}

/**
 * A spring's stiffness and damping from its frequency and damping ratio, for engines that take
 * those (Box2D 2.4's b2LinearStiffness and b2AngularStiffness do the same): `mass` is the pair's
 * reduced mass (or inertia), the other's where one body is static.
 */
export function springConstants(hertz: number, dampingRatio: number, massA: number, massB: number): { stiffness: number; damping: number } {
  const mass = massA > 0 && massB > 0 ? (massA * massB) / (massA + massB) : massA > 0 ? massA : massB;
  const omega = 2 * Math.PI * hertz;
  return { stiffness: mass * omega * omega, damping: 2 * mass * dampingRatio * omega };
}
