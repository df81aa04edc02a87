import { SHAPE_STRIDE, SHAPE_VERTICES, VERTEX, type ShapeStore } from '../store/shape-store.js';
import { WorldShape } from '../narrowphase/world-shape.js';
import { ShapeDistance } from '../narrowphase/distance.js';

/**
 * A body's motion over a step for continuous collision: from centre (x0, y0) turned (c0, s0) to
 * (x1, y1), (c1, s1). Between them the centre moves in a line and the rotation is interpolated
 * and renormalised (as Box2D's b2Sweep); past a quarter turn, through the rotation (cm, sm)
 * midway, in two halves (see splitTurn).
 */
export interface Sweep {
  x0: number;
  y0: number;
  c0: number;
  s0: number;
  x1: number;
  y1: number;
  c1: number;
  s1: number;
  /** The farthest any point of the body's shapes lies from its centre. */
  reach: number;
  /** Whether the rotation turns through (cm, sm) at t = 1/2, each half interpolated alone. */
  split: boolean;
  cm: number;
  sm: number;
}

/**
 * Splits a sweep that turns past a quarter turn at the rotation midway: the sum of the two
 * rotations, or near a half turn, where that sum vanishes, a quarter turn from the start in the
 * sense of `spin`. Interpolated in one piece, a turn T turns fastest midway, at 2 tan(T / 2),
 * without bound towards a half turn: the time of impact then advanced by so little that it ran
 * out of iterations, and a capsule spun 179 degrees a step stood still by a wall for good. In
 * halves of at most about a quarter turn each, the bound stays under 4.4 per unit of t. (The
 * soft step turns a body at most an eighth of a turn a step: its sweeps are never split.)
 */
export function splitTurn(sweep: Sweep, spin: number): void {
  sweep.split = sweep.c0 * sweep.c1 + sweep.s0 * sweep.s1 < 0;
  if (!sweep.split) return;
  let c = sweep.c0 + sweep.c1;
  let s = sweep.s0 + sweep.s1;
  let length = Math.sqrt(c * c + s * s);
  if (length < 0.1) {
    const sense = spin >= 0 ? 1 : -1;
    c = -sense * sweep.s0;
    s = sense * sweep.c0;
    length = 1;
  }
  sweep.cm = c / length;
  sweep.sm = s / length;
}

const distance = new ShapeDistance();

/** Where the last impact found by timeOfImpact happened: the unit normal from the moving shape to the other, and a point between them. */
export const impact = { nx: 0, ny: 0, x: 0, y: 0 };
const moving = new WorldShape();

/** The rotation at fraction t of a sweep, into out[0], out[1]. */
export function sweepRotation(sweep: Sweep, t: number, out: Float64Array): void {
  if (sweep.split) {
    if (t <= 0.5) between(sweep.c0, sweep.s0, sweep.cm, sweep.sm, 2 * t, out);
    else between(sweep.cm, sweep.sm, sweep.c1, sweep.s1, 2 * t - 1, out);
    return;
  }
  between(sweep.c0, sweep.s0, sweep.c1, sweep.s1, t, out);
}

/** The rotation at fraction t from (c0, s0) to (c1, s1), interpolated and renormalised. */
function between(c0: number, s0: number, c1: number, s1: number, t: number, out: Float64Array): void {
  const c = c0 + t * (c1 - c0);
  const s = s0 + t * (s1 - s0);
  const length = Math.sqrt(c * c + s * s);
  out[0] = c / length;
  out[1] = s / length;
}

/**
 * How fast any point of the body moves from turning, per unit of t, over its reach: the larger
 * of the chord's bound, (pi / 2) chord and a fifth more for the interpolation's unevenness over
 * a quarter turn, and the interpolation's fastest, 2 tan(T / 2) = 2 sin T / (1 + cos T) for a
 * turn T, which passes the chord's from about 116 degrees.
 */
function turnRate(c0: number, s0: number, c1: number, s1: number): number {
  const chord = Math.sqrt((c1 - c0) * (c1 - c0) + (s1 - s0) * (s1 - s0));
  const cosTurn = c0 * c1 + s0 * s1;
  const sinTurn = Math.abs(c0 * s1 - s0 * c1);
  const fastest = 1 + cosTurn > 0 ? (2 * sinTurn) / (1 + cosTurn) : Infinity;
  return Math.max(1.2 * (Math.PI / 2) * chord, fastest);
}

const rotation = new Float64Array(2);

/** `moving` as vertex `vertex` of shape `slot`, a point, its body centred at (px, py) turned by `rotation`. */
function placeVertex(shapes: ShapeStore, slot: number, vertex: number, px: number, py: number): void {
  const at = slot * SHAPE_STRIDE + SHAPE_VERTICES + vertex * VERTEX;
  const vx = shapes.record[at];
  const vy = shapes.record[at + 1];
  moving.circle(px + rotation[0] * vx - rotation[1] * vy, py + rotation[1] * vx + rotation[0] * vy, 0);
}

/**
 * Whether vertex `vertex` of shape `slot` passes into or through `other` over the sweep: clear of
 * its core at the start, on its shape's side of it, and at the end within it or on its far side
 * (the direction between the closest points turned around), more than `depth` past the surface
 * it faced at the start. A vertex that merely comes to touch, as the ends of a stick spinning on
 * the ground do, is left to the contacts; so is one that starts within half of `depth` (the
 * solver's slop) of the surface, where the step's contact holds it, or ends within `depth` past
 * it. The corners of a box resting on the ground, tilted by a hair, start a rounding or a
 * micrometre above it and dip as much into it or past a segment's line from step to step
 * (between points that near, the direction is rounding): swept, they put the box back at each
 * step's start while it kept its speed, and a box sliding at 20 m/s covered 5 m in its first two
 * seconds where it covers 40. A corner that last step's sweep parked starts a slop away or more.
 * A `depth` of 0 sweeps every corner that starts clear and crosses: the elastic pass, which has
 * no speculative contact to hold a corner near a surface, resolves only the overlaps it finds.
 */
export function vertexCrosses(shapes: ShapeStore, slot: number, sweep: Sweep, other: WorldShape, vertex: number, depth: number): boolean {
  rotation[0] = sweep.c0;
  rotation[1] = sweep.s0;
  placeVertex(shapes, slot, vertex, sweep.x0, sweep.y0);
  distance.compute(moving, other);
  const d0 = distance.distance;
  if (!(d0 > 0) || (depth > 0 && d0 - other.radius < 0.5 * depth)) return false;
  const nx = distance.x2 - distance.x1;
  const ny = distance.y2 - distance.y1;
  // The closest point of the core, from which the surface faced lies other.radius back along n.
  const qx = distance.x2;
  const qy = distance.y2;
  // A vertex that starts on the far side of a thin shape from its shape's centroid, the line
  // between them crossing it (a corner a bounce left a hair past a segment of no thickness), is
  // coming back, not going through: swept, it was put back at half its gap step after step, and
  // the body stayed at the segment while its velocity carried it away. (A plank pivoting on a
  // ledge's end, its centroid hanging past the end, does not cross the ledge: swept.)
  const vx = moving.x[0];
  const vy = moving.y[0];
  const cx = shapes.centroidX[slot];
  const cy = shapes.centroidY[slot];
  moving.x[0] = sweep.x0 + sweep.c0 * cx - sweep.s0 * cy;
  moving.y[0] = sweep.y0 + sweep.s0 * cx + sweep.c0 * cy;
  moving.x[1] = vx;
  moving.y[1] = vy;
  moving.radius = 0;
  moving.asCapsule();
  if (distance.compute(moving, other).distance <= other.radius) return false;
  rotation[0] = sweep.c1;
  rotation[1] = sweep.s1;
  placeVertex(shapes, slot, vertex, sweep.x1, sweep.y1);
  // How far the vertex ends past the surface it faced, along the direction it faced it from.
  const past = (nx * (moving.x[0] - qx) + ny * (moving.y[0] - qy)) / d0 + other.radius;
  if (depth > 0 && !(past > depth)) return false;
  distance.compute(moving, other);
  if (!(distance.distance > 0)) return true;
  return nx * (distance.x2 - distance.x1) + ny * (distance.y2 - distance.y1) < 0;
}

/** timeOfImpact's answer when the shapes are already within the target at the sweep's start. */
export const TOUCHING = -2;

/**
 * The first fraction t in (0, 1) of the sweep at which shape `slot` comes within `target` of the
 * fixed shape `other`, by conservative advancement: at each trial pose, the distance between the
 * shapes (GJK on their cores, less both radii) is divided by a bound on how fast any point of the
 * moving shape can approach along the line between the closest points, and t advances by that
 * much, which can never step past the impact. -1 when there is no impact in the step; TOUCHING
 * when the shapes are already that close at its start (a contact, which the contact solver owns).
 * With `core` >= 0 the moving shape is a disc of that radius at the shape's centroid instead
 * (Box2D v3's fallback for a fast shape that starts the step touching something); with `vertex`
 * >= 0, that vertex of the shape alone (a corner of a polygon, an end of a capsule's core), as a
 * point: as a disc of the capsule's radius, an end lying on a surface would start the step
 * touching it and never be swept. With `sink` (the soft step's sweep of a whole shape), a shape
 * with rounding stops up to `target` into the surface, as Box2D v3 lets it: stopped `target`
 * short, a ball skimming the ground at 20 m/s lost a fifth of its landing step's travel, for
 * good. (The elastic pass bounces a body at its impact itself, and stops it short.)
 */
export function timeOfImpact(shapes: ShapeStore, slot: number, sweep: Sweep, other: WorldShape, target: number, tolerance: number, core = -1, vertex = -1, sink = false): number {
  if (sink && core < 0 && vertex < 0) {
    // Box2D v3's target between the cores, max(target, r - target), for the moving shape's own
    // rounding r: a round shape stops up to `target` into the surface, a sharp one `target` short
    // of it. (Box2D counts the other's rounding too; parked that deep in a thick segment, a body
    // of a centimetre started its next step with its centroid on the surface, where no sweep
    // holds it, and went on through.)
    const rounding = shapes.radius[slot];
    target = Math.max(target, rounding - target) - rounding;
  }
  const dx = sweep.x1 - sweep.x0;
  const dy = sweep.y1 - sweep.y0;
  // No point of the body moves faster than this from turning (see turnRate, splitTurn).
  const rate = sweep.split
    ? 2 * Math.max(turnRate(sweep.c0, sweep.s0, sweep.cm, sweep.sm), turnRate(sweep.cm, sweep.sm, sweep.c1, sweep.s1))
    : turnRate(sweep.c0, sweep.s0, sweep.c1, sweep.s1);
  const spin = rate * sweep.reach;
  let t = 0;
  for (let iteration = 0; iteration < 64; iteration++) {
    sweepRotation(sweep, t, rotation);
    const px = sweep.x0 + t * dx;
    const py = sweep.y0 + t * dy;
    if (vertex >= 0) placeVertex(shapes, slot, vertex, px, py);
    else if (core < 0) moving.fromStore(shapes, slot, px, py, rotation[0], rotation[1]);
    else {
      const cx = shapes.centroidX[slot];
      const cy = shapes.centroidY[slot];
      moving.circle(px + rotation[0] * cx - rotation[1] * cy, py + rotation[1] * cx + rotation[0] * cy, core);
    }
    distance.compute(moving, other);
    const gap = distance.distance - moving.radius - other.radius;
    const d = distance.distance;
    if (gap < target + tolerance) {
      if (t === 0) {
        // A corner that crosses in this step (the only corners swept) but starts nearer than the
        // target, where last step's sweep parked it: swept to half its gap rather than left to the
        // contact, whose points come from the step's start and which a fast turn carries through.
        // So is the centroid, the last resort, of a body smaller than the target (a circle of 2 mm
        // starting 0.5 mm from a wall 1 cm thick went through it at 3 m/s in the elastic pass,
        // which has no speculative contact).
        if ((vertex >= 0 || core === 0) && gap > 0 && target > gap / 2) {
          target = gap / 2;
          tolerance = gap / 4;
          continue;
        }
        return TOUCHING;
      }
      if (!(d > 0)) return -1;
      impact.nx = (distance.x2 - distance.x1) / d;
      impact.ny = (distance.y2 - distance.y1) / d;
      impact.x = distance.x1 + impact.nx * (moving.radius + gap / 2);
      impact.y = distance.y1 + impact.ny * (moving.radius + gap / 2);
      return t;
    }
    const nx = (distance.x2 - distance.x1) / d;
    const ny = (distance.y2 - distance.y1) / d;
    const approach = dx * nx + dy * ny + spin;
    if (!(approach > 0)) return -1;
    if (iteration === 63) {
      // Out of iterations (a body spun near a half turn a step advances by little): the pose
      // just tested, clear of the target, is the impact, with its own closest points. Returning
      // the next fraction left `impact` as the last impact found, in any world.
      impact.nx = nx;
      impact.ny = ny;
      impact.x = distance.x1 + nx * (moving.radius + gap / 2);
      impact.y = distance.y1 + ny * (moving.radius + gap / 2);
      return t;
    }
    t += (gap - target) / approach;
    if (t >= 1) return -1;
  }
  return -1;
}
