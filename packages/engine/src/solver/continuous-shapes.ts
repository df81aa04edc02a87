import type { BodyStore } from '../store/body-store.js';
import type { ShapeStore } from '../store/shape-store.js';
import { TypeCode } from '../store/body-types.js';
import { ShapeKind } from '../shapes/geometry.js';
import { BodyFlag } from '../store/rigid-columns.js';
import type { StaticTree } from '../broadphase/static-tree.js';
import { SlotList, type Queries } from '../query/queries.js';
import { WorldShape } from '../narrowphase/world-shape.js';
import { SegmentDistance } from '../narrowphase/segment-distance.js';
import { SEGMENT_ENTRY, type WorldShapes } from '../narrowphase/shape-narrowphase.js';
import { grow, grownCapacity } from '../util/grow.js';
import { Manifold } from '../narrowphase/manifold.js';
import { collide } from '../narrowphase/dispatch.js';
import { twoPointImpulses } from './two-point-impulses.js';
import { coulombImpulse } from './coulomb-friction.js';
import type { ContactEvents } from '../store/contact-events.js';
import { impact, splitTurn, sweepRotation, timeOfImpact, TOUCHING, vertexCrosses, type Sweep } from './time-of-impact.js';

/** A body moving less than this fraction of its smallest extent in a step is left to the contacts (Box2D's safety factor). */
const SAFETY = 0.5;
/**
 * A fast shape that starts the step touching something is swept again as a disc of this fraction
 * of its body's smallest extent at its centroid (Box2D v3's core fraction): the contact found at
 * the step's start holds only the points then near, and a long body turning about one of them
 * could carry its far end, and then its centre, through a thin wall within the step.
 */
const CORE = 0.25;

/**
 * Points of the manifold at an impact within this many slops of the first to meet the surface
 * meet it together in the elastic pass's bounce: a box arriving flat bounces on both corners.
 */
const TOGETHER = 1;
/**
 * How far, in slops, the bounce's contact looks for points: the sweep leaves the body one slop
 * (give or take a quarter) from what it met, and a flat face's far corner a little farther.
 */
const BOUNCE_REACH = 4;

const rotation = new Float64Array(2);
const other = new WorldShape();
// The best impact's other shape as it was swept against, and the body's shape at the impact.
const hitOther = new WorldShape();
const moving = new WorldShape();
const manifold = new Manifold();
const impulses = new Float64Array(2);
const segmentDistance = new SegmentDistance();

/**
 * Continuous collision for worlds with shapes (report 3.1.6; Box2D v3's b2SolveContinuous). After
 * the solve, a dynamic body that moved more than half its smallest extent could have passed
 * through something thin. Its motion over the step (centre in a line, rotation interpolated) is
 * swept against every static thing its swept box overlaps in the static tree, shape by shape, and
 * it is put back at the earliest time of impact, keeping its velocity: the next step's contact,
 * found at that pose, stops or bounces it. Bullets are swept against moving bodies too, so that a
 * fast projectile cannot pass through a thin dynamic plank, even one coming at it: against a body
 * that moved, the bullet's sweep is its motion relative to that body's travel, with the body
 * held where it ended the step (its turn within the step is not swept), and a bullet stopped by
 * it is put where that relative sweep meets it. Other pairs of moving bodies are not swept, nor
 * two bullets against each other, as in Box2D and as the report argues, since their order would
 * matter.
 * The box's walls need no sweep: each is as thick as the box is wide, so nothing passes through
 * one in a step, and the route's containment puts a body that went into one back at its face.
 *
 * The elastic pass, which integrates before it collides (the report's order), sweeps right after
 * integration and bounces a body at its impact itself (`bounce`): an elastic impulse along the
 * impact normal with the pair's restitution, as the circle route's sweep does.
 */
export class ContinuousShapes {
  private x0 = new Float64Array(0);
  private y0 = new Float64Array(0);
  private c0 = new Float64Array(0);
  private s0 = new Float64Array(0);
  private readonly sweep: Sweep = { x0: 0, y0: 0, c0: 1, s0: 0, x1: 0, y1: 0, c1: 1, s1: 0, reach: 0, split: false, cm: 1, sm: 0 };
  private readonly found = new SlotList();
  /** The box a bullet's sweep looks for moving bodies in (Queries.slotsInBox). */
  private readonly around = new Float64Array(4);
  /** Bodies swept in the last step. */
  swept = 0;
  hits = new Int32Array(16);
  hitCount = 0;
  // The elastic pass's bounces of the last run at or above the hit threshold: the body's slot, its
  // shape, what it met (as hitEntry), the approach speed.
  private bounceBody = new Int32Array(8);
  private bounceShape = new Int32Array(8);
  private bounceEntry = new Int32Array(8);
  private bounceSpeed = new Float64Array(8);
  private bounceCount = 0;
  // The best impact of the body being swept: normal (moving -> other), point, the other's
  // restitution and friction, the moving shape, and what it met (a shape slot, or a segment as
  // SEGMENT_ENTRY + its slot).
  private hitNx = 0;
  private hitNy = 0;
  private hitX = 0;
  private hitY = 0;
  private hitRestitution = 0;
  private hitFriction = 0;
  private hitShape = -1;
  private hitEntry = -1;
  // The material and entry of the thing being tested against (note takes them for an impact).
  private otherRestitution = 0;
  private otherFriction = 0;
  private otherEntry = -1;
  // Where the body being swept goes at its best impact: its centre on the sweep that found it.
  private hitCentreX = 0;
  private hitCentreY = 0;

  /** Keeps every body's pose at the start of the step. */
  remember(bodies: BodyStore): void {
    const n = bodies.slotCount;
    if (this.x0.length < n) {
      const capacity = grownCapacity(this.x0.length, n);
      this.x0 = new Float64Array(capacity);
      this.y0 = new Float64Array(capacity);
      this.c0 = new Float64Array(capacity);
      this.s0 = new Float64Array(capacity);
    }
    const rigid = bodies.rigid!;
    for (let i = 0; i < n; i++) {
      this.x0[i] = bodies.x[i];
      this.y0[i] = bodies.y[i];
      this.c0[i] = rigid.c[i];
      this.s0[i] = rigid.s[i];
    }
  }

  /** Sweeps the fast bodies; returns how many were put back. */
  run(
    bodies: BodyStore,
    shapes: ShapeStore,
    tree: StaticTree,
    world: WorldShapes,
    queries: Queries | null,
    queryVersion: number,
    margin: number,
    slop: number,
    bounce: boolean,
    restitutionThreshold: number,
    hitThreshold = Infinity,
  ): number {
    const { x, y, type, asleep, radius, slotCount } = bodies;
    const rigid = bodies.rigid!;
    const { c, s, minExtent, flags } = rigid;
    const sweep = this.sweep;
    this.swept = 0;
    this.hitCount = 0;
    this.bounceCount = 0;
    const { x0, y0, c0, s0 } = this;
    // How far past a surface a corner must end to be swept (see vertexCrosses): the soft step's
    // contacts hold what ends within a slop; the elastic pass has none that would.
    const cornerDepth = bounce ? 0 : slop;
    // How far any moving body travelled in the step (-1: not yet measured): bullets look this much
    // farther around their own sweep for bodies that came at them.
    let travel = -1;
    // Bullets go second, against the others where they ended up.
    const passes = queries !== null ? 2 : 1;
    for (let pass = 0; pass < passes; pass++) {
      for (let i = 0; i < slotCount; i++) {
        if (type[i] !== TypeCode.dynamic || asleep[i]) continue;
        const reach = radius[i] - margin;
        const dx = x[i] - x0[i];
        const dy = y[i] - y0[i];
        const dc = c[i] - c0[i];
        const ds = s[i] - s0[i];
        // How far any point moved, bounded: the centre's path plus the turn at the rim; first
        // with |dx| + |dy| >= the length, which settles most bodies without a square root.
        const slow = SAFETY * minExtent[i];
        if (Math.abs(dx) + Math.abs(dy) + 2 * (Math.abs(dc) + Math.abs(ds)) * reach < slow) continue;
        const moved = Math.sqrt(dx * dx + dy * dy) + 2 * Math.sqrt(dc * dc + ds * ds) * reach;
        if (moved < slow) continue;
        const bullet = (flags[i] & BodyFlag.bullet) !== 0;
        if (bullet !== (pass === 1)) continue;
        this.swept++;
        sweep.x0 = this.x0[i];
        sweep.y0 = this.y0[i];
        sweep.c0 = this.c0[i];
        sweep.s0 = this.s0[i];
        sweep.x1 = x[i];
        sweep.y1 = y[i];
        sweep.c1 = c[i];
        sweep.s1 = s[i];
        sweep.reach = reach;
        splitTurn(sweep, rigid.angularVelocity[i]);
        const minX = Math.min(sweep.x0, sweep.x1) - reach;
        const minY = Math.min(sweep.y0, sweep.y1) - reach;
        const maxX = Math.max(sweep.x0, sweep.x1) + reach;
        const maxY = Math.max(sweep.y0, sweep.y1) + reach;
        let best = 1;
        this.hitShape = -1;
        const box = tree.box;
        box[0] = minX;
        box[1] = minY;
        box[2] = maxX;
        box[3] = maxY;
        const found = tree.queryBox();
        for (let f = 0; f < found; f++) {
          const entry = tree.found[f];
          if (entry < SEGMENT_ENTRY) {
            const owner = shapes.body[entry];
            if (!this.layers(bodies, i, shapes, entry)) continue;
            other.fromStore(shapes, entry, x[owner], y[owner], c[owner], s[owner]);
            this.otherRestitution = shapes.restitution[entry];
            this.otherFriction = shapes.friction[entry];
          } else {
            const g = entry - SEGMENT_ENTRY;
            const seg = world.segments;
            if ((bodies.category[i] & seg.mask[g]) === 0 || (seg.category[g] & bodies.mask[i]) === 0) continue;
            other.segment(seg, g);
            this.otherRestitution = seg.restitution[g];
            this.otherFriction = seg.friction[g];
          }
          if (this.outOfReach(slop + 0.25 * slop)) continue;
          this.otherEntry = entry;
          best = this.earliest(shapes, rigid.firstShape[i], best, slop, CORE * minExtent[i], cornerDepth);
        }
        if (bullet && queries) {
          if (travel < 0) travel = this.largestTravel(bodies);
          const around = this.around;
          around[0] = minX - travel;
          around[1] = minY - travel;
          around[2] = maxX + travel;
          around[3] = maxY + travel;
          const found = queries.slotsInBox(queryVersion, around, this.found);
          for (let f = 0; f < found.count; f++) {
            const j = found.slots[f];
            if (j === i || type[j] === TypeCode.static || (flags[j] & BodyFlag.bullet) !== 0) continue;
            if ((bodies.category[i] & bodies.mask[j]) === 0 || (bodies.category[j] & bodies.mask[i]) === 0) continue;
            // In the frame that travels with j: the bullet starts where it stood relative to j.
            sweep.x0 = x0[i] + (x[j] - x0[j]);
            sweep.y0 = y0[i] + (y[j] - y0[j]);
            for (let t = rigid.firstShape[j]; t >= 0; t = shapes.next[t]) {
              if (shapes.sensor[t]) continue;
              other.fromStore(shapes, t, x[j], y[j], c[j], s[j]);
              this.otherRestitution = shapes.restitution[t];
              this.otherFriction = shapes.friction[t];
              this.otherEntry = t;
              best = this.earliest(shapes, rigid.firstShape[i], best, slop, CORE * minExtent[i], cornerDepth);
            }
          }
          sweep.x0 = x0[i];
          sweep.y0 = y0[i];
        }
        if (best < 1) {
          x[i] = this.hitCentreX;
          y[i] = this.hitCentreY;
          sweepRotation(sweep, best, rotation);
          c[i] = rotation[0];
          s[i] = rotation[1];
          this.noteHit(i);
          if (bounce && this.hitShape >= 0) this.bounce(bodies, shapes, i, restitutionThreshold, slop, hitThreshold);
        }
      }
    }
    return this.hitCount;
  }

  memoryBytes(): number {
    return this.x0.byteLength * 4 + this.hits.byteLength;
  }

  /**
   * Whether the swept body stays farther than `target` from `other` (a circle or a capsule, whose
   * core is a point or a segment) all through the step: every point of the body lies within
   * `reach` of its centre, which moves along the segment from its start to its end, so a gap
   * between that segment and the core wider than both reaches and the target leaves the time of
   * impact nothing to find. A pile's particles falling past a long diagonal wall's bounding box
   * are then one closed-form distance each rather than a conservative advancement. The bound is
   * widened by a millionth so that rounding never skips an impact the advancement would find.
   */
  private outOfReach(target: number): boolean {
    if (other.count > 2) return false;
    const sweep = this.sweep;
    const last = other.count - 1;
    const g = segmentDistance.segments;
    g[0] = sweep.x0;
    g[1] = sweep.y0;
    g[2] = sweep.x1;
    g[3] = sweep.y1;
    g[4] = other.x[0];
    g[5] = other.y[0];
    g[6] = other.x[last];
    g[7] = other.y[last];
    segmentDistance.compute();
    const limit = (sweep.reach + other.radius + target) * (1 + 1e-6) + 1e-9;
    return segmentDistance.distanceSquared > limit * limit;
  }

  /** The earliest impact of the body's shapes with `other` before `best`, noting where it happened; `cornerDepth` as vertexCrosses's depth. */
  private earliest(shapes: ShapeStore, first: number, best: number, slop: number, core: number, cornerDepth: number): number {
    for (let t = first; t >= 0; t = shapes.next[t]) {
      if (shapes.sensor[t]) continue;
      const toi = timeOfImpact(shapes, t, this.sweep, other, slop, 0.25 * slop, -1, -1, cornerDepth > 0);
      if (toi !== TOUCHING) {
        best = this.note(toi, best, t);
        continue;
      }
      // The core disc too may start the step touching, where a contact's push left the body deep
      // in a thin wall (the elastic pass pushes each contact's bodies apart forgetting the others):
      // then its centroid alone, as a point, so that the body cannot go on through.
      const coreImpact = timeOfImpact(shapes, t, this.sweep, other, slop, 0.25 * slop, core);
      best = this.note(coreImpact !== TOUCHING ? coreImpact : timeOfImpact(shapes, t, this.sweep, other, slop, 0.25 * slop, 0), best, t);
      // The corners of a polygon, and the ends of a capsule's core, that start the step clear
      // and end it inside the other shape or past it: the contact holds only the points near at
      // the step's start, and a long body turning about one of them can carry the far ones
      // through a thin wall within the step, which then pushes the body on through.
      if (shapes.kind[t] === ShapeKind.circle) continue;
      for (let v = 0; v < shapes.vertexCount[t]; v++) {
        if (vertexCrosses(shapes, t, this.sweep, other, v, cornerDepth)) best = this.note(timeOfImpact(shapes, t, this.sweep, other, slop, 0.25 * slop, -1, v), best, t);
      }
    }
    return best;
  }

  /** The earlier of `best` and an impact at `toi` (< 0: none) of shape `shape`, noting where the impact happened. */
  private note(toi: number, best: number, shape: number): number {
    if (!(toi >= 0 && toi < best)) return best;
    this.hitFriction = this.otherFriction;
    this.hitEntry = this.otherEntry;
    this.hitNx = impact.nx;
    this.hitNy = impact.ny;
    this.hitX = impact.x;
    this.hitY = impact.y;
    this.hitRestitution = this.otherRestitution;
    this.hitShape = shape;
    hitOther.copy(other);
    const sweep = this.sweep;
    this.hitCentreX = sweep.x0 + toi * (sweep.x1 - sweep.x0);
    this.hitCentreY = sweep.y0 + toi * (sweep.y1 - sweep.y0);
    return toi;
  }

  /**
   * The elastic pass's bounce at an impact: the contact of the body's shape at its put-back pose
   * with the thing it met, its points within TOGETHER slops of the first to meet the surface, as
   * the elastic pass solves a contact (one point, or two as a block, see twoPointImpulses), each
   * leaving with -e times its approach speed (e the pair's restitution, 0 below the threshold),
   * then Coulomb friction at each. The impact's own witness point alone where that contact has no
   * point (the impact found by a corner's crossing, say, then already past the surface's end).
   * A static thing is immovable; a body a bullet met takes its share, with its mass, and speeds are
   * relative to it (a kinematic one is immovable, at its velocity): treated as a wall, a plank took
   * none of a bullet's momentum, and one coming at a bullet left it behind and passed through it.
   *
   * Not the witness point alone: a body that starts a step within the slop of a face is swept as a
   * core disc and by its corners, whose impact is a single point, and an impulse there alone would
   * spin a body that meets the face flat.
   */
  private bounce(bodies: BodyStore, shapes: ShapeStore, i: number, threshold: number, slop: number, hitThreshold: number): void {
    const rigid = bodies.rigid!;
    const px = bodies.x[i];
    const py = bodies.y[i];
    moving.fromStore(shapes, this.hitShape, px, py, rigid.c[i], rigid.s[i]);
    manifold.margin = BOUNCE_REACH * slop;
    manifold.slop = slop;
    collide(moving, hitOther, manifold);
    let n = 1;
    // The normal from the body towards the other thing, and each point's arm.
    let nx = this.hitNx;
    let ny = this.hitNy;
    let r0x = this.hitX - px;
    let r0y = this.hitY - py;
    let r1x = 0;
    let r1y = 0;
    if (manifold.pointCount > 0) {
      nx = manifold.normalX;
      ny = manifold.normalY;
      const first = manifold.pointCount === 2 && manifold.separation[1] < manifold.separation[0] ? 1 : 0;
      r0x = manifold.x[first] - px;
      r0y = manifold.y[first] - py;
      if (manifold.pointCount === 2 && manifold.separation[1 - first] <= manifold.separation[first] + TOGETHER * slop) {
        r1x = manifold.x[1 - first] - px;
        r1y = manifold.y[1 - first] - py;
        n = 2;
      }
    }
    // The body met, where it moves (a bullet's catch): its arms to the same points.
    const entry = this.hitEntry;
    const j = entry < SEGMENT_ENTRY && bodies.type[shapes.body[entry]] !== TypeCode.static ? shapes.body[entry] : -1;
    const m = bodies.invMass[i];
    const inertia = rigid.invInertia[i];
    const vx = bodies.vx[i];
    const vy = bodies.vy[i];
    const w = rigid.angularVelocity[i];
    let mj = 0;
    let ij = 0;
    let vjx = 0;
    let vjy = 0;
    let wj = 0;
    let q0x = 0;
    let q0y = 0;
    let q1x = 0;
    let q1y = 0;
    if (j >= 0) {
      if (bodies.type[j] === TypeCode.dynamic) {
        mj = bodies.invMass[j];
        ij = rigid.invInertia[j];
      }
      vjx = bodies.vx[j];
      vjy = bodies.vy[j];
      wj = rigid.angularVelocity[j];
      q0x = px + r0x - bodies.x[j];
      q0y = py + r0y - bodies.y[j];
      q1x = px + r1x - bodies.x[j];
      q1y = py + r1y - bodies.y[j];
    }
    // Each point's speed along the normal, the other's less the body's: negative when closing.
    let u0 = -((vx - w * r0y) * nx + (vy + w * r0x) * ny);
    let u1 = n === 2 ? -((vx - w * r1y) * nx + (vy + w * r1x) * ny) : 0;
    if (j >= 0) {
      u0 += (vjx - wj * q0y) * nx + (vjy + wj * q0x) * ny;
      if (n === 2) u1 += (vjx - wj * q1y) * nx + (vjy + wj * q1x) * ny;
    }
    const approach = Math.max(-u0, n === 2 ? -u1 : -Infinity);
    if (!(approach > 0)) return;
    const e = approach < threshold ? 0 : Math.max(shapes.restitution[this.hitShape], this.hitRestitution);
    const scale = 1 + e;
    const rn0 = r0x * ny - r0y * nx;
    const rn1 = r1x * ny - r1y * nx;
    const sn0 = q0x * ny - q0y * nx;
    const sn1 = q1x * ny - q1y * nx;
    let k00 = m + inertia * rn0 * rn0;
    if (j >= 0) k00 += mj + ij * sn0 * sn0;
    let p0 = 0;
    let p1 = 0;
    if (n === 1) {
      if (u0 < 0 && k00 > 0) p0 = (-scale * u0) / k00;
    } else {
      let k11 = m + inertia * rn1 * rn1;
      let k01 = m + inertia * rn0 * rn1;
      if (j >= 0) {
        k11 += mj + ij * sn1 * sn1;
        k01 += mj + ij * sn0 * sn1;
      }
      twoPointImpulses(k00, k11, k01, scale * u0, scale * u1, impulses);
      p0 = impulses[0];
      p1 = impulses[1];
    }
    // The body takes -p along the normal at each point, the body met +p.
    let wx = vx - m * (p0 + p1) * nx;
    let wy = vy - m * (p0 + p1) * ny;
    let ww = w - inertia * (p0 * rn0 + p1 * rn1);
    vjx += mj * (p0 + p1) * nx;
    vjy += mj * (p0 + p1) * ny;
    wj += ij * (p0 * sn0 + p1 * sn1);
    // Then Coulomb friction at each point, at most mu times its normal impulse, as the pass does (coulombImpulse).
    const mu = Math.sqrt(shapes.friction[this.hitShape] * this.hitFriction);
    if (mu > 0) {
      const tx = ny;
      const ty = -nx;
      for (let p = 0; p < n; p++) {
        const limit = mu * (p === 0 ? p0 : p1);
        if (!(limit > 0)) continue;
        const rx = p === 0 ? r0x : r1x;
        const ry = p === 0 ? r0y : r1y;
        const sx = p === 0 ? q0x : q1x;
        const sy = p === 0 ? q0y : q1y;
        let slip = (wx - ww * ry) * tx + (wy + ww * rx) * ty;
        const rt = rx * ty - ry * tx;
        let kt = m + inertia * rt * rt;
        const st = sx * ty - sy * tx;
        if (j >= 0) {
          slip -= (vjx - wj * sy) * tx + (vjy + wj * sx) * ty;
          kt += mj + ij * st * st;
        }
        const jt = coulombImpulse(slip, kt, limit);
        wx += m * jt * tx;
        wy += m * jt * ty;
        ww += inertia * jt * rt;
        vjx -= mj * jt * tx;
        vjy -= mj * jt * ty;
        wj -= ij * jt * st;
      }
    }
    bodies.vx[i] = wx;
    bodies.vy[i] = wy;
    rigid.angularVelocity[i] = ww;
    if (j >= 0 && bodies.type[j] === TypeCode.dynamic) {
      bodies.vx[j] = vjx;
      bodies.vy[j] = vjy;
      rigid.angularVelocity[j] = wj;
      bodies.wake(j);
    }
    if (approach >= hitThreshold && p0 + p1 > 0) this.noteBounce(i, approach);
  }

  /** The bounce of the body in slot i at `speed`: a hit event once the step's contacts have given theirs (reportBounces). */
  private noteBounce(i: number, speed: number): void {
    if (this.bounceCount === this.bounceBody.length) {
      const capacity = 2 * this.bounceBody.length;
      this.bounceBody = grow(this.bounceBody, capacity);
      this.bounceShape = grow(this.bounceShape, capacity);
      this.bounceEntry = grow(this.bounceEntry, capacity);
      this.bounceSpeed = grow(this.bounceSpeed, capacity);
    }
    const k = this.bounceCount++;
    this.bounceBody[k] = i;
    this.bounceShape[k] = this.hitShape;
    this.bounceEntry[k] = this.hitEntry;
    this.bounceSpeed[k] = speed;
  }

  /**
   * The last run's bounces as hit events, after the step's contacts gave theirs: one entry per
   * pair of bodies (or body and segment) and step, however many of a compound's shapes met it.
   */
  reportBounces(bodies: BodyStore, shapes: ShapeStore, world: WorldShapes, events: ContactEvents): void {
    for (let k = 0; k < this.bounceCount; k++) {
      const i = this.bounceBody[k];
      const entry = this.bounceEntry[k];
      const speed = this.bounceSpeed[k];
      const shape = shapes.handleOf(this.bounceShape[k]);
      if (entry >= SEGMENT_ENTRY) {
        events.noteSweptSegmentHit(bodies.handleOf(i), shape, world.segments.handleOf(entry - SEGMENT_ENTRY), speed);
        continue;
      }
      const j = shapes.body[entry];
      if (i < j) events.noteSweptHit(bodies.handleOf(i), bodies.handleOf(j), shape, shapes.handleOf(entry), speed);
      else events.noteSweptHit(bodies.handleOf(j), bodies.handleOf(i), shapes.handleOf(entry), shape, speed);
    }
  }

  /** The longest travel, along x or y, of a moving body that is not a bullet in this step. */
  private largestTravel(bodies: BodyStore): number {
    const { x, y, type, slotCount } = bodies;
    const flags = bodies.rigid!.flags;
    const { x0, y0 } = this;
    let travel = 0;
    for (let j = 0; j < slotCount; j++) {
      if ((type[j] !== TypeCode.dynamic && type[j] !== TypeCode.kinematic) || (flags[j] & BodyFlag.bullet) !== 0) continue;
      travel = Math.max(travel, Math.abs(x[j] - x0[j]), Math.abs(y[j] - y0[j]));
    }
    return travel;
  }

  private layers(bodies: BodyStore, i: number, shapes: ShapeStore, shape: number): boolean {
    if (shapes.sensor[shape]) return false;
    return (bodies.category[i] & shapes.mask[shape]) !== 0 && (shapes.category[shape] & bodies.mask[i]) !== 0;
  }

  private noteHit(i: number): void {
    if (this.hitCount === this.hits.length) {
      const next = new Int32Array(2 * this.hits.length);
      next.set(this.hits);
      this.hits = next;
    }
    this.hits[this.hitCount++] = i;
  }
}
