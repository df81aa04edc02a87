import type { BodyStore } from '../store/body-store.js';
import type { ShapeStore } from '../store/shape-store.js';
import type { SegmentStore } from '../store/segment-store.js';
import type { JointStore } from '../joints/joint-store.js';
import { TypeCode } from '../store/body-types.js';
import { WorldShape } from '../narrowphase/world-shape.js';
import { Manifold } from '../narrowphase/manifold.js';
import { collide } from '../narrowphase/dispatch.js';
import { smoothSegment } from '../narrowphase/smooth-segment.js';
import { boxWall, type WorldShapes } from '../narrowphase/shape-narrowphase.js';
import { bodyBounds } from '../shapes/bounds.js';
import { closestOnSegment, segmentNormal } from '../narrowphase/circle-segment.js';
import { SlotList, type Queries } from './queries.js';
import { sortFew } from '../util/sort-by-key.js';

/** One contact of a body (see World.bodyContacts). */
export interface BodyContact {
  /**
   * What the body touches: another body's handle, a static segment's handle (`hasBody` tells the
   * two apart), or -1 for a wall of the world's box (see `wall`).
   */
  other: number;
  /** The wall of the box touched (a BoxWall), or -1. */
  wall: number;
  /** The body's shape in the contact, and the other body's (handles); -1 where there is none: a segment, a wall, or a world of circles. */
  shape: number;
  otherShape: number;
  /** The unit normal from this body towards what it touches. */
  normalX: number;
  normalY: number;
  /** One or two points (`points[0, pointCount)`). */
  pointCount: number;
  /**
   * Each point midway between the surfaces, with the signed distance between them there
   * (negative: overlapping; positive: a speculative point, within the soft step's margin, or the
   * slop under the elastic pass). The objects are reused with the contact object.
   */
  points: { x: number; y: number; separation: number }[];
}

/** What bodyContacts reads: the world's stores, its queries' grid and, on the shape route, its world shapes and margins. */
export interface ContactSources {
  bodies: BodyStore;
  segments: SegmentStore;
  queries: Queries;
  /** The queries' version for the bodies' current positions. */
  version: number;
  /** The shape route's stores, or null in a world of circles. */
  shapes: ShapeStore | null;
  world: WorldShapes | null;
  joints: JointStore | null;
  /** The speculative margin (0 for the elastic pass) and the slop, on the shape route. */
  margin: number;
  slop: number;
  /** The box of a world of circles, or null. */
  box: { width: number; height: number } | null;
  /** The overlap a world of circles leaves in place (its contactSlop). */
  contactSlop: number;
}

/**
 * A body's contacts at its pose, found as the narrow-phase finds them: the bodies, segments and
 * walls near it (the queries' grid, the segments' tree), each shape pair that may collide
 * (filters, joints that keep their bodies apart, at least one of the two dynamic) through the
 * pair functions with the step's margin. Computed on demand rather than read from the step's
 * contact list, which lists only the pairs with an awake body and names bodies by slots that a
 * destroyed body frees: so a sleeping body keeps its contacts, and a body made since has its own.
 */
export class BodyContacts {
  private readonly found = new SlotList();
  private readonly box = new Float64Array(4);
  /** This body's pose (x, y, cosine, sine) at 0, the other body's at 4, for WorldShape.fromPose. */
  private readonly pose = new Float64Array(8);
  private readonly shapeA = new WorldShape();
  private readonly shapeB = new WorldShape();
  private readonly manifold = new Manifold();
  private readonly closest = new Float64Array(2);
  private readonly normal = new Float64Array(2);
  private count = 0;

  /** The contacts of the live body in `slot` into `out` (reusing its objects), cut to their number. */
  read(slot: number, from: ContactSources, out: BodyContact[]): BodyContact[] {
    this.count = 0;
    if (from.shapes !== null && from.bodies.rigid !== null) this.ofShapes(slot, from, from.shapes, out);
    else this.ofCircle(slot, from, out);
    out.length = this.count;
    return out;
  }

  private next(out: BodyContact[]): BodyContact {
    const k = this.count++;
    return out[k] ?? (out[k] = { other: -1, wall: -1, shape: -1, otherShape: -1, normalX: 0, normalY: 0, pointCount: 0, points: [] });
  }

  private ofShapes(i: number, from: ContactSources, shapes: ShapeStore, out: BodyContact[]): void {
    const { bodies, segments, queries, joints, world } = from;
    const { x, y, type, category: bodyCategory } = bodies;
    const rigid = bodies.rigid!;
    const { c, s, firstShape } = rigid;
    const pose = this.pose;
    const m = this.manifold;
    m.margin = from.margin;
    m.slop = from.slop;
    // The points listed: within the margin, or the slop under the elastic pass (margin 0).
    const within = Math.max(from.margin, from.slop);
    pose[0] = x[i];
    pose[1] = y[i];
    pose[2] = c[i];
    pose[3] = s[i];
    if (firstShape[i] < 0) return;
    const box = bodyBounds(shapes, firstShape[i], pose, this.box);
    box[0] -= from.margin;
    box[1] -= from.margin;
    box[2] += from.margin;
    box[3] += from.margin;
    const dynamicI = type[i] === TypeCode.dynamic;
    // Other bodies, in ascending slot order.
    const found = queries.slotsInBox(from.version, box, this.found);
    sortFew(found.slots, found.count);
    for (let f = 0; f < found.count; f++) {
      const j = found.slots[f];
      if (j === i || (!dynamicI && type[j] !== TypeCode.dynamic) || (bodyCategory[i] & bodies.mask[j]) === 0 || (bodyCategory[j] & bodies.mask[i]) === 0) continue;
      if (joints !== null && joints.nonColliding > 0 && joints.joined(i, j)) continue;
      pose[4] = x[j];
      pose[5] = y[j];
      pose[6] = c[j];
      pose[7] = s[j];
      for (let sa = firstShape[i]; sa >= 0; sa = shapes.next[sa]) {
        if (shapes.sensor[sa] === 1) continue;
        const a = this.shapeA.fromPose(shapes, sa, pose, 0);
        for (let sb = firstShape[j]; sb >= 0; sb = shapes.next[sb]) {
          if (shapes.sensor[sb] === 1 || (shapes.category[sa] & shapes.mask[sb]) === 0 || (shapes.category[sb] & shapes.mask[sa]) === 0) continue;
          collide(a, this.shapeB.fromPose(shapes, sb, pose, 4), m);
          if (m.pointCount > 0) this.put(out, bodies.handleOf(j), -1, shapes.handleOf(sa), shapes.handleOf(sb), within);
        }
      }
    }
    if (!dynamicI) return;
    // Segments, in slot order, then the box's walls.
    const near = queries.segmentsInBox(box);
    for (let k = 0; k < near; k++) {
      const g = queries.segmentFound(k);
      for (let sa = firstShape[i]; sa >= 0; sa = shapes.next[sa]) {
        if (shapes.sensor[sa] === 1 || (shapes.category[sa] & segments.mask[g]) === 0 || (segments.category[g] & shapes.mask[sa]) === 0) continue;
        const a = this.shapeA.fromPose(shapes, sa, pose, 0);
        collide(a, this.shapeB.segment(segments, g), m);
        if (segments.smooth[g] !== 0) smoothSegment(a, segments, g, m);
        if (m.pointCount > 0) this.put(out, segments.handleOf(g), -1, shapes.handleOf(sa), -1, within);
      }
    }
    if (world === null || world.box === null) return;
    for (let w = 0; w < 4; w++) {
      for (let sa = firstShape[i]; sa >= 0; sa = shapes.next[sa]) {
        if (shapes.sensor[sa] === 1) continue;
        collide(this.shapeA.fromPose(shapes, sa, pose, 0), boxWall(world, w, this.shapeB), m);
        if (m.pointCount > 0) this.put(out, -1, w, shapes.handleOf(sa), -1, within);
      }
    }
  }

  /**
   * The manifold as a contact of this body, its points within `within` of touching: a face's
   * manifold keeps both clipped points for the solver, the far one even beyond the margin (a
   * capsule standing on its end: its top, 0.8 m up), which is not a contact to a game. None
   * within: no contact.
   */
  private put(out: BodyContact[], other: number, wall: number, shape: number, otherShape: number, within: number): void {
    const m = this.manifold;
    let kept = 0;
    for (let p = 0; p < m.pointCount; p++) if (m.separation[p] <= within) kept++;
    if (kept === 0) return;
    const contact = this.next(out);
    contact.other = other;
    contact.wall = wall;
    contact.shape = shape;
    contact.otherShape = otherShape;
    contact.normalX = m.normalX;
    contact.normalY = m.normalY;
    contact.pointCount = kept;
    let n = 0;
    for (let p = 0; p < m.pointCount; p++) if (m.separation[p] <= within) setPoint(contact, n++, m.x[p], m.y[p], m.separation[p]);
    contact.points.length = kept;
  }

  /**
   * A circle's contacts in a world of circles: the circles it overlaps or touches (none between two
   * bodies neither of which is dynamic), the segments within their thickness of it and the walls it
   * reaches. Touching is within the world's contactSlop, or within the rounding of the positions:
   * the circle engine parts a colliding pair to a distance that rounds a little either side of
   * touching (3.0000000000000013 apart for radii 2 and 1).
   */
  private ofCircle(i: number, from: ContactSources, out: BodyContact[]): void {
    const { bodies, segments, queries } = from;
    const { x, y, radius, type, category, mask } = bodies;
    const px = x[i];
    const py = y[i];
    const r = radius[i];
    // Widened past every gap that counts as touching (see touching), so that the search finds them all.
    const search = r + from.contactSlop + 1e-6 * (r + bodies.maxRadius() + Math.abs(px) + Math.abs(py));
    const box = this.box;
    box[0] = px - search;
    box[1] = py - search;
    box[2] = px + search;
    box[3] = py + search;
    const dynamicI = type[i] === TypeCode.dynamic;
    const found = queries.slotsInBox(from.version, box, this.found);
    sortFew(found.slots, found.count);
    for (let f = 0; f < found.count; f++) {
      const j = found.slots[f];
      if (j === i || (!dynamicI && type[j] !== TypeCode.dynamic) || (category[i] & mask[j]) === 0 || (category[j] & mask[i]) === 0) continue;
      const dx = x[j] - px;
      const dy = y[j] - py;
      const d = Math.sqrt(dx * dx + dy * dy);
      const gap = d - r - radius[j];
      if (gap > touching(from.contactSlop, r + radius[j], px, py, x[j], y[j])) continue;
      // Concentric circles: a normal along +x, as contactPoints gives them.
      this.putRound(out, bodies.handleOf(j), -1, d > 0 ? dx / d : 1, d > 0 ? dy / d : 0, px, py, r, gap);
    }
    if (!dynamicI) return;
    const near = queries.segmentsInBox(box);
    for (let k = 0; k < near; k++) {
      const g = queries.segmentFound(k);
      if ((category[i] & segments.mask[g]) === 0 || (segments.category[g] & mask[i]) === 0) continue;
      const q = this.closest;
      closestOnSegment(px, py, segments.ax[g], segments.ay[g], segments.bx[g], segments.by[g], q);
      const dx = q[0] - px;
      const dy = q[1] - py;
      const d = Math.sqrt(dx * dx + dy * dy);
      const gap = d - r - segments.thickness[g];
      if (gap > touching(from.contactSlop, r + segments.thickness[g], px, py, q[0], q[1])) continue;
      // A centre on the segment itself: pushed along its left normal, as the circle engine pushes it.
      segmentNormal(-dx, -dy, d, segments.ax[g], segments.ay[g], segments.bx[g], segments.by[g], this.normal);
      this.putRound(out, segments.handleOf(g), -1, -this.normal[0], -this.normal[1], px, py, r, gap);
    }
    const walls = from.box;
    if (walls === null) return;
    const reach = touching(from.contactSlop, r, px, py, walls.width, walls.height);
    if (px - r <= reach) this.putRound(out, -1, 0, -1, 0, px, py, r, px - r);
    if (walls.width - px - r <= reach) this.putRound(out, -1, 1, 1, 0, px, py, r, walls.width - px - r);
    if (py - r <= reach) this.putRound(out, -1, 2, 0, -1, px, py, r, py - r);
    if (walls.height - py - r <= reach) this.putRound(out, -1, 3, 0, 1, px, py, r, walls.height - py - r);
  }

  /** A circle's contact along (nx, ny) at gap `gap`: one point midway between the surfaces. */
  private putRound(out: BodyContact[], other: number, wall: number, nx: number, ny: number, px: number, py: number, r: number, gap: number): void {
    const contact = this.next(out);
    contact.other = other;
    contact.wall = wall;
    contact.shape = -1;
    contact.otherShape = -1;
    contact.normalX = nx;
    contact.normalY = ny;
    contact.pointCount = 1;
    const along = r + gap / 2;
    setPoint(contact, 0, px + nx * along, py + ny * along, gap);
    contact.points.length = 1;
  }
}

/** The largest gap that counts as touching: contactSlop, or the rounding of sizes `size` and of positions (px, py), (qx, qy). */
function touching(slop: number, size: number, px: number, py: number, qx: number, qy: number): number {
  return Math.max(slop, 1e-9 * size + 1e-12 * (Math.abs(px) + Math.abs(py) + Math.abs(qx) + Math.abs(qy)));
}

function setPoint(contact: BodyContact, p: number, x: number, y: number, separation: number): void {
  const point = contact.points[p] ?? (contact.points[p] = { x: 0, y: 0, separation: 0 });
  point.x = x;
  point.y = y;
  point.separation = separation;
}
