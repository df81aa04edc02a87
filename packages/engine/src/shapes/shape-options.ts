import type { BodyType } from '../store/body-types.js';
import { TypeCode } from '../store/body-types.js';
import { BodyFlag } from '../store/rigid-columns.js';
import type { NewShape } from '../store/shape-store.js';
import { cosSin } from '../math/trig.js';
import { areaProperties, checkPolygon, emptyAreaProperties, Geometry, MAX_POLYGON_VERTICES, POLYGON_TOLERANCE } from './geometry.js';
import { boundedNonNegative, boundedNumber, boundedPositive, describeValue, finiteNumber, nonNegativeNumber, plainObject, knownKeys, MAX_SHAPE_REACH } from '../util/validate.js';
import { bodyType, flag, layerBits, restitutionNumber, staticVelocity, type Vector } from '../options.js';

/** Where a body starts and how it moves. Angles in radians; see docs/engine.md for their sense. */
export interface BodyOptions {
  /** The body's origin, where its shapes' coordinates are measured from. */
  x: number;
  y: number;
  /** Default 0. Positive turns +x towards +y: clockwise on the engine's y-down screens. */
  angle?: number | undefined;
  /** Velocity of the centre of mass. Default (0, 0). */
  vx?: number | undefined;
  vy?: number | undefined;
  /** Radians per second, in the sense of `angle`. Default 0. */
  angularVelocity?: number | undefined;
  /** Default 'dynamic'. */
  type?: BodyType | undefined;
  /** The body never turns (infinite rotational inertia). Default false. */
  fixedRotation?: boolean | undefined;
  /** Swept against other moving bodies too, not just static ones, so that it cannot pass through them at speed. Default false. */
  bullet?: boolean | undefined;
  /** Multiplies the world's gravity for this body. Default 1. */
  gravityScale?: number | undefined;
  /** Velocity decays as v / (1 + h * linearDamping) over each solver step h, as in Box2D v3: the step's dt on the circle route, each of its sub-steps (dt / substeps) on the shape route. Default 0. */
  linearDamping?: number | undefined;
  /** Angular velocity decays likewise. Default 0. */
  angularDamping?: number | undefined;
}

/** A shape's material and collision filter. */
export interface MaterialOptions {
  /** Mass per unit area. Default 1. */
  density?: number | undefined;
  /** Coulomb friction coefficient; a pair uses the geometric mean of its two. Default: the world's `friction`. */
  friction?: number | undefined;
  /** Default: the world's `restitution`. A pair uses the larger of its two. */
  restitution?: number | undefined;
  /** Resists rolling: a torque up to this times the normal force times the rolling radius. Default 0. */
  rollingResistance?: number | undefined;
  /** Collision layers the shape belongs to, a 32-bit set. Default 1. */
  category?: number | undefined;
  /** Layers it collides with, a 32-bit set. Default 0xffffffff (all). */
  mask?: number | undefined;
  /** Reports overlaps (sensor events) and never collides. Default false. */
  sensor?: boolean | undefined;
}

/** Where a shape sits on its body: moved by (offsetX, offsetY) and turned by offsetAngle from the body's origin. */
export interface OffsetOptions {
  offsetX?: number | undefined;
  offsetY?: number | undefined;
  offsetAngle?: number | undefined;
}

/** One shape to attach to a body (createBody, addShape), told apart by `kind`; its offset places it in the body's frame. */
export type ShapeOptions =
  | ({ kind: 'circle'; radius: number } & Omit<OffsetOptions, 'offsetAngle'> & MaterialOptions)
  | ({ kind: 'box'; width: number; height: number; radius?: number | undefined } & OffsetOptions & MaterialOptions)
  | ({ kind: 'polygon'; vertices: readonly Vector[]; radius?: number | undefined } & OffsetOptions & MaterialOptions)
  | ({ kind: 'capsule'; length: number; radius: number } & OffsetOptions & MaterialOptions);

/** `mass` instead of `density`: the shape's density is then mass / area. */
interface MassOption {
  mass?: number | undefined;
}

/** A rectangle of width x height centred on the body's origin, its corners rounded by `radius` (inside that size). */
export interface BoxOptions extends BodyOptions, MaterialOptions, MassOption {
  width: number;
  height: number;
  radius?: number | undefined;
}

/** A convex polygon of 3 to 8 vertices in the body's frame, in either winding, optionally rounded by `radius`. */
export interface PolygonOptions extends BodyOptions, MaterialOptions, MassOption {
  vertices: readonly Vector[];
  radius?: number | undefined;
}

/** A capsule: the segment of `length` along the body's x axis, centred on its origin, with `radius` around it. */
export interface CapsuleOptions extends BodyOptions, MaterialOptions, MassOption {
  length: number;
  radius: number;
}

export const BODY_KEYS = ['x', 'y', 'angle', 'vx', 'vy', 'angularVelocity', 'type', 'fixedRotation', 'bullet', 'gravityScale', 'linearDamping', 'angularDamping'];
export const MATERIAL_KEYS = ['density', 'friction', 'restitution', 'rollingResistance', 'category', 'mask', 'sensor'];
const OFFSET_KEYS = ['offsetX', 'offsetY', 'offsetAngle'];

/** A validated body, ready for the stores. */
export interface ResolvedBody {
  x: number;
  y: number;
  c: number;
  s: number;
  vx: number;
  vy: number;
  angularVelocity: number;
  type: number;
  flags: number;
  gravityScale: number;
  linearDamping: number;
  angularDamping: number;
}

export interface MaterialDefaults {
  friction: number;
  restitution: number;
}

const rotation = new Float64Array(2);

export function resolveBody(o: Record<string, unknown>): ResolvedBody {
  const angle = o.angle === undefined ? 0 : finiteNumber('angle', o.angle);
  cosSin(angle, rotation);
  const fixedRotation = o.fixedRotation === undefined ? false : flag('fixedRotation', o.fixedRotation);
  const bullet = o.bullet === undefined ? false : flag('bullet', o.bullet);
  const type = TypeCode[o.type === undefined ? 'dynamic' : bodyType(o.type)];
  return {
    x: boundedNumber('x', o.x),
    y: boundedNumber('y', o.y),
    c: rotation[0],
    s: rotation[1],
    vx: o.vx === undefined ? 0 : type === TypeCode.static ? staticVelocity('vx', o.vx) : boundedNumber('vx', o.vx),
    vy: o.vy === undefined ? 0 : type === TypeCode.static ? staticVelocity('vy', o.vy) : boundedNumber('vy', o.vy),
    angularVelocity:
      o.angularVelocity === undefined ? 0 : type === TypeCode.static ? staticVelocity('angularVelocity', o.angularVelocity) : boundedNumber('angularVelocity', o.angularVelocity),
    type,
    flags: (fixedRotation ? BodyFlag.fixedRotation : 0) | (bullet ? BodyFlag.bullet : 0),
    gravityScale: o.gravityScale === undefined ? 1 : boundedNumber('gravityScale', o.gravityScale),
    linearDamping: o.linearDamping === undefined ? 0 : nonNegativeNumber('linearDamping', o.linearDamping),
    angularDamping: o.angularDamping === undefined ? 0 : nonNegativeNumber('angularDamping', o.angularDamping),
  };
}

export function resolveMaterial(o: Record<string, unknown>, defaults: MaterialDefaults, geometry: Geometry): NewShape {
  return {
    geometry,
    density: o.density === undefined ? 1 : boundedNonNegative('density', o.density),
    friction: o.friction === undefined ? defaults.friction : boundedNonNegative('friction', o.friction),
    restitution: o.restitution === undefined ? defaults.restitution : restitutionNumber('restitution', o.restitution),
    rollingResistance: o.rollingResistance === undefined ? 0 : boundedNonNegative('rollingResistance', o.rollingResistance),
    category: o.category === undefined ? 1 : layerBits('category', o.category),
    mask: o.mask === undefined ? 0xffffffff : layerBits('mask', o.mask),
    sensor: o.sensor === undefined ? false : flag('sensor', o.sensor),
  };
}

/**
 * Replaces the density by mass / area when `mass` is given (and refuses both at once), so that
 * a helper like createBox({ mass }) makes a body of exactly that mass to round-off.
 */
export function applyMassOption(o: Record<string, unknown>, shape: NewShape): void {
  if (o.mass === undefined) return;
  if (o.density !== undefined) throw new TypeError(`give mass or density, not both (mass ${describeValue(o.mass)}, density ${describeValue(o.density)})`);
  const mass = boundedPositive('mass', o.mass);
  const area = areaProperties(shape.geometry, areaScratch).area;
  shape.density = mass / area;
  if (!(shape.density > 0) || !Number.isFinite(shape.density)) throw new RangeError(`mass ${mass} over the shape's area ${area} gives density ${shape.density}`);
}

const areaScratch = emptyAreaProperties();
const px = new Float64Array(MAX_POLYGON_VERTICES);
const py = new Float64Array(MAX_POLYGON_VERTICES);

/** The geometry of a shape described by `o` (`kind` read from it or given), in the body's frame. */
export function resolveGeometry(kind: string, o: Record<string, unknown>, out: Geometry): Geometry {
  const offsetX = o.offsetX === undefined ? 0 : boundedNumber('offsetX', o.offsetX);
  const offsetY = o.offsetY === undefined ? 0 : boundedNumber('offsetY', o.offsetY);
  const offsetAngle = o.offsetAngle === undefined ? 0 : finiteNumber('offsetAngle', o.offsetAngle);
  if (kind === 'circle') {
    const radius = boundedPositive('radius', o.radius);
    checkReach(kind, o, out.setCircle(offsetX, offsetY, radius));
    return out;
  }
  if (kind === 'capsule') {
    const length = boundedPositive('length', o.length);
    const radius = boundedPositive('radius', o.radius);
    out.setCapsule(-length / 2, 0, length / 2, 0, radius);
  } else if (kind === 'box') {
    const width = boundedPositive('width', o.width);
    const height = boundedPositive('height', o.height);
    const radius = o.radius === undefined ? 0 : boundedNonNegative('radius', o.radius);
    if (!(2 * radius < Math.min(width, height))) {
      throw new RangeError(`radius must be less than half the smaller side of the box (${Math.min(width, height) / 2}), got ${radius}`);
    }
    const hw = width / 2 - radius;
    const hh = height / 2 - radius;
    px[0] = -hw;
    py[0] = -hh;
    px[1] = hw;
    py[1] = -hh;
    px[2] = hw;
    py[2] = hh;
    px[3] = -hw;
    py[3] = hh;
    out.setPolygon(px, py, 4, radius);
  } else if (kind === 'polygon') {
    const radius = o.radius === undefined ? 0 : boundedNonNegative('radius', o.radius);
    polygonPoints(o.vertices);
    out.setPolygon(px, py, (o.vertices as unknown[]).length, radius);
  } else {
    throw new RangeError(`kind must be one of 'circle', 'box', 'polygon', 'capsule', got ${describeValue(kind)}`);
  }
  if (offsetAngle !== 0 || offsetX !== 0 || offsetY !== 0) {
    cosSin(offsetAngle, rotation);
    out.transform(rotation[0], rotation[1], offsetX, offsetY);
    if (kind !== 'capsule') checkPlaced(kind, o, out);
  }
  checkReach(kind, o, out);
  return out;
}

/**
 * A RangeError where a polygon or box, moved to its offset, is no longer the polygon it was: its
 * vertices round to the offset's precision, and a shape small beside its offset (a unit box 1e17
 * out) collapses to a line or a point, with no area or mass. A capsule whose core so rounds to a
 * point is a circle, and collides as one.
 */
function checkPlaced(kind: string, o: Record<string, unknown>, g: Geometry): void {
  const check = checkPolygon(g.x, g.y, g.count);
  // Moving a polygon keeps its winding: one that rounded into the other has no outline left.
  if (check.problem === null && !check.reversed) return;
  const sizes = ['width', 'height', 'radius'].filter((k) => o[k] !== undefined).map((k) => `${k} ${describeValue(o[k])}`);
  if (o.vertices !== undefined) sizes.push('its vertices');
  const offset = ['offsetX', 'offsetY', 'offsetAngle'].filter((k) => o[k] !== undefined).map((k) => `${k} ${describeValue(o[k])}`);
  throw new RangeError(
    `a ${kind} shape with ${sizes.join(', ')} at ${offset.join(', ')} rounds to an outline that is no longer that polygon (${check.problem ?? 'turned over'}): it is too small beside its offset for a double to place its vertices; move the body there instead, or make the shape larger`,
  );
}

/** A RangeError naming the shape's sizes where it reaches farther than MAX_SHAPE_REACH from its body's origin. */
export function checkReach(kind: string, o: Record<string, unknown>, g: Geometry): void {
  const reach = g.extentFrom(0, 0);
  if (reach <= MAX_SHAPE_REACH) return;
  const sizes = ['width', 'height', 'length', 'radius', 'offsetX', 'offsetY'].filter((k) => o[k] !== undefined).map((k) => `${k} ${describeValue(o[k])}`);
  if (o.vertices !== undefined) sizes.push('its vertices');
  throw new RangeError(`a ${kind} shape with ${sizes.join(', ')} reaches ${reach} from its body's origin, beyond ${MAX_SHAPE_REACH} (so that its rotational inertia stays finite)`);
}

/** Reads and checks `vertices` into px, py in counter-clockwise order (either winding is accepted). */
function polygonPoints(input: unknown): void {
  if (!Array.isArray(input)) throw new TypeError(`vertices must be an array of { x, y } points, got ${describeValue(input)}`);
  const n = input.length;
  if (n < 3 || n > MAX_POLYGON_VERTICES) throw new RangeError(`vertices must hold 3 to ${MAX_POLYGON_VERTICES} points, got ${n}`);
  for (let i = 0; i < n; i++) {
    const p = plainObject(`vertices[${i}]`, input[i]);
    knownKeys(`vertices[${i}]`, p, ['x', 'y']);
    px[i] = boundedNumber(`vertices[${i}].x`, p.x);
    py[i] = boundedNumber(`vertices[${i}].y`, p.y);
  }
  const original = (k: number): string => `vertices[${k}] (${(input[k] as Vector).x}, ${(input[k] as Vector).y})`;
  const check = checkPolygon(px, py, n);
  switch (check.problem) {
    case null:
      return;
    case 'count':
      throw new RangeError(`vertices must hold 3 to ${MAX_POLYGON_VERTICES} points, got ${n}`);
    case 'area':
      throw new RangeError(`vertices enclose no area: the points ${input.map((_, k) => `(${(input[k] as Vector).x}, ${(input[k] as Vector).y})`).join(', ')} lie on one line or one spot, or their outline crosses itself so that its parts cancel`);
    case 'duplicate':
      throw new RangeError(
        `vertices must be distinct, farther apart than ${POLYGON_TOLERANCE} of the polygon's size (${check.size}): ${original(check.index)} lies ${check.distance} from vertices[${check.other}]`,
      );
    case 'collinear':
      throw new RangeError(
        `vertices must not be collinear, each farther than ${POLYGON_TOLERANCE} of the polygon's size (${check.size}) from the line through its neighbours: ${original(check.index)} lies ${check.distance} from it; remove it`,
      );
    case 'concave':
      throw new RangeError(
        `vertices must form a convex polygon in order: ${original(check.index)} lies on the inner side of the line through vertices[${check.edge}] and its neighbour (a reflex corner, or edges that cross)`,
      );
  }
}

export { OFFSET_KEYS };
