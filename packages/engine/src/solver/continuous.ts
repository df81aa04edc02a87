import type { BodyStore } from '../store/body-store.js';
import type { SegmentStore } from '../store/segment-store.js';
import type { ContactEvents } from '../store/contact-events.js';
import { TypeCode } from '../store/body-types.js';
import { rayCircle } from '../query/ray-circle.js';
import { rayCapsule } from '../query/ray-capsule.js';
import { closestOnSegment } from '../narrowphase/circle-segment.js';
import { mixRestitution } from './restitution.js';
import { BoxWall } from './box-walls.js';
import type { StaticTree } from '../broadphase/static-tree.js';
import { COORD_PAD, RADIUS_PAD } from '../broadphase/fat-bounds.js';
import { SEGMENT_ID, type StaticIndex } from '../broadphase/static-pairs.js';

const MAX_BOUNCES = 4;
const closest = new Float64Array(2);

/**
 * Time of impact with a circle of radius rr, for sweeping: unlike a ray query, a start on or
 * inside the circle that moves further in is an impact at t = 0, so a body resting on a shape's
 * surface (to round-off) cannot slip through it on its next fast move.
 */
function sweepCircle(fromX: number, fromY: number, pathX: number, pathY: number, cx: number, cy: number, rr: number): number {
  const fx = fromX - cx;
  const fy = fromY - cy;
  if (fx * fx + fy * fy <= rr * rr) return fx * pathX + fy * pathY < 0 ? 0 : -1;
  return rayCircle(fromX, fromY, pathX, pathY, cx, cy, rr);
}

function sweepCapsule(fromX: number, fromY: number, pathX: number, pathY: number, ax: number, ay: number, bx: number, by: number, rr: number): number {
  closestOnSegment(fromX, fromY, ax, ay, bx, by, closest);
  const fx = fromX - closest[0];
  const fy = fromY - closest[1];
  if (fx * fx + fy * fy <= rr * rr) return fx * pathX + fy * pathY < 0 ? 0 : -1;
  return rayCapsule(fromX, fromY, pathX, pathY, ax, ay, bx, by, rr);
}

/** Time at which a centre moving along the path reaches the plane coordinate `limit`, or -1. */
function sweepWall(from: number, path: number, limit: number, inward: number): number {
  // `inward` is +1 for a wall at the low end (the body must stay above it), -1 at the high end.
  const gap = (from - limit) * inward;
  const closing = -path * inward;
  if (closing <= 0) return -1;
  if (gap <= 0) return 0;
  const t = gap / closing;
  return t <= 1 ? t : -1;
}

/** The BoxWall number of the wall whose inward normal is (nx, ny). */
function wallOf(nx: number, ny: number): number {
  if (nx !== 0) return nx > 0 ? BoxWall.minX : BoxWall.maxX;
  return ny > 0 ? BoxWall.minY : BoxWall.maxY;
}

/**
 * Continuous collision against static shapes (report 3.1.6): a dynamic body that moved more than
 * its own radius this step could have passed through a static circle or segment between two
 * discrete positions. Its path from the previous position is swept against every static circle
 * (inflated by its radius) and segment capsule (thickness plus its radius); at the first time of
 * impact it bounces, as the box walls do, and the rest of its path continues reflected, up to
 * MAX_BOUNCES times. Bodies slower than that are left to the discrete contacts, which cannot miss
 * them. As the report notes, moving-moving pairs are not swept: their order would matter.
 *
 * The static circles and segments sit in the world's static index (StaticIndex), so
 * a fast body tests only those whose boxes meet its path's: thousands of static shapes cost a few
 * tree queries per fast body, not a test each. The tree lists them in the order a loop over all
 * of them would meet them (static slots ascending, then segments), and the first of equal times
 * wins, so the result is the same bits as testing every one.
 */
/**
 * The four box walls, four numbers each: axis (0 = x), and the centre's limit as
 * side * scale + offset * radius, and which way is inside (+1 above the limit, -1 below).
 */
const WALLS = new Float64Array([0, 0, 1, 1, 0, 1, -1, -1, 1, 0, 1, 1, 1, 1, -1, -1]);

export class ContinuousCollision {
  private previousX = new Float64Array(0);
  private previousY = new Float64Array(0);
  private tree: StaticTree | null = null;
  /** Fast bodies swept in the last step. */
  swept = 0;

  /** Whether sweeping can matter this step: something static to hit. */
  needed(bodies: BodyStore, segments: SegmentStore): boolean {
    return bodies.staticCount > 0 || segments.count > 0;
  }

  /** Copies whole columns: a subarray of just the used slots would be a new object every step. */
  rememberPositions(bodies: BodyStore): void {
    if (this.previousX.length !== bodies.x.length) {
      this.previousX = new Float64Array(bodies.x.length);
      this.previousY = new Float64Array(bodies.y.length);
    }
    this.previousX.set(bodies.x);
    this.previousY.set(bodies.y);
  }

  sweep(
    bodies: BodyStore,
    segments: SegmentStore,
    box: { width: number; height: number } | null,
    wallRestitution: number,
    restitutionThreshold: number,
    events: ContactEvents | null,
    hitThreshold: number,
    index: StaticIndex,
    staticVersion: number,
  ): void {
    const { x, y, radius, type, asleep, slotCount } = bodies;
    const { previousX, previousY } = this;
    this.swept = 0;
    for (let i = 0; i < slotCount; i++) {
      if (type[i] !== TypeCode.dynamic || asleep[i]) continue;
      const dx = x[i] - previousX[i];
      const dy = y[i] - previousY[i];
      const r = radius[i];
      if (dx * dx + dy * dy <= r * r) continue;
      this.tree = index.current(bodies, segments, staticVersion);
      this.swept++;
      this.sweepBody(bodies, segments, box, wallRestitution, i, restitutionThreshold, events, hitThreshold);
    }
  }

  memoryBytes(): number {
    return this.previousX.byteLength * 2;
  }

  /**
   * The box walls take part in the sweep: folding a swept path back from a wall afterwards could
   * carry the body back across a shape it had just bounced off.
   */
  private sweepBody(
    bodies: BodyStore,
    segments: SegmentStore,
    box: { width: number; height: number } | null,
    wallRestitution: number,
    i: number,
    restitutionThreshold: number,
    events: ContactEvents | null,
    hitThreshold: number,
  ): void {
    const { x, y, vx, vy, radius, restitution, category, mask } = bodies;
    const r = radius[i];
    let fromX = this.previousX[i];
    let fromY = this.previousY[i];
    let toX = x[i];
    let toY = y[i];
    let bounces = 0;
    for (; bounces <= MAX_BOUNCES; bounces++) {
      const pathX = toX - fromX;
      const pathY = toY - fromY;
      let best = Infinity;
      let hitStatic = -1;
      let hitSegment = -1;
      let hitWallX = 0;
      let hitWallY = 0;
      if (box) {
        for (let w = 0; w < WALLS.length; w += 4) {
          const axis = WALLS[w];
          const inward = WALLS[w + 3];
          const limit = (axis === 0 ? box.width : box.height) * WALLS[w + 1] + WALLS[w + 2] * r;
          const t = axis === 0 ? sweepWall(fromX, pathX, limit, inward) : sweepWall(fromY, pathY, limit, inward);
          if (t >= 0 && t < best) {
            best = t;
            hitStatic = -1;
            hitSegment = -1;
            hitWallX = axis === 0 ? inward : 0;
            hitWallY = axis === 1 ? inward : 0;
          }
        }
      }
      // The path's box, grown by the radius; it and the tree's boxes padded (fat-bounds.ts) so that
      // round-off in them never drops a shape the exact sweep below would hit: extra ones only miss.
      const reach = r * (1 + RADIUS_PAD) + (Math.abs(fromX) + Math.abs(fromY) + Math.abs(pathX) + Math.abs(pathY) + r) * COORD_PAD;
      const tree = this.tree!;
      const query = tree.box;
      query[0] = Math.min(fromX, toX) - reach;
      query[1] = Math.min(fromY, toY) - reach;
      query[2] = Math.max(fromX, toX) + reach;
      query[3] = Math.max(fromY, toY) + reach;
      const found = tree.queryBox();
      const ids = tree.found;
      for (let k = 0; k < found; k++) {
        const id = ids[k];
        if (id >= SEGMENT_ID) continue;
        const s = id;
        if ((category[i] & mask[s]) === 0 || (category[s] & mask[i]) === 0) continue;
        const t = sweepCircle(fromX, fromY, pathX, pathY, x[s], y[s], radius[s] + r);
        if (t >= 0 && t < best) {
          best = t;
          hitStatic = s;
          hitSegment = -1;
          hitWallX = hitWallY = 0;
        }
      }
      for (let k = 0; k < found; k++) {
        if (ids[k] < SEGMENT_ID) continue;
        const s = ids[k] - SEGMENT_ID;
        if ((category[i] & segments.mask[s]) === 0 || (segments.category[s] & mask[i]) === 0) continue;
        const t = sweepCapsule(fromX, fromY, pathX, pathY, segments.ax[s], segments.ay[s], segments.bx[s], segments.by[s], segments.thickness[s] + r);
        if (t >= 0 && t < best) {
          best = t;
          hitSegment = s;
          hitStatic = -1;
          hitWallX = hitWallY = 0;
        }
      }
      if (best === Infinity) break;
      if (bounces === MAX_BOUNCES) {
        // Out of bounces with yet another impact ahead: stop at the last impact point.
        toX = fromX;
        toY = fromY;
        break;
      }
      const hitX = fromX + best * pathX;
      const hitY = fromY + best * pathY;
      let nx: number;
      let ny: number;
      let e: number;
      if (hitWallX !== 0 || hitWallY !== 0) {
        nx = hitWallX;
        ny = hitWallY;
        e = mixRestitution(restitution[i], wallRestitution);
      } else if (hitStatic >= 0) {
        nx = hitX - x[hitStatic];
        ny = hitY - y[hitStatic];
        e = mixRestitution(restitution[i], restitution[hitStatic]);
      } else {
        closestOnSegment(hitX, hitY, segments.ax[hitSegment], segments.ay[hitSegment], segments.bx[hitSegment], segments.by[hitSegment], closest);
        nx = hitX - closest[0];
        ny = hitY - closest[1];
        e = mixRestitution(restitution[i], segments.restitution[hitSegment]);
      }
      const length = Math.sqrt(nx * nx + ny * ny);
      if (length === 0) break;
      nx /= length;
      ny /= length;
      const vn = vx[i] * nx + vy[i] * ny;
      if (vn < 0) {
        // Recorded as the discrete contacts and the walls stage record them: without this, the
        // fastest impacts, the swept ones, went unreported.
        if (events !== null && -vn >= hitThreshold) {
          if (hitStatic >= 0) events.recordHit(bodies, Math.min(i, hitStatic), Math.max(i, hitStatic), -vn);
          else if (hitSegment >= 0) events.recordSegmentHit(bodies, i, segments, hitSegment, -vn);
          else events.recordWallHit(bodies, i, wallOf(hitWallX, hitWallY), -vn);
        }
        const bounceE = -vn < restitutionThreshold ? 0 : e;
        vx[i] -= (1 + bounceE) * vn * nx;
        vy[i] -= (1 + bounceE) * vn * ny;
      }
      // The rest of the path, reflected like the velocity and scaled by restitution.
      const restX = (1 - best) * pathX;
      const restY = (1 - best) * pathY;
      const restN = restX * nx + restY * ny;
      const restE = restN < 0 ? e : 0;
      fromX = hitX;
      fromY = hitY;
      toX = hitX + restX - (1 + restE) * Math.min(restN, 0) * nx;
      toY = hitY + restY - (1 + restE) * Math.min(restN, 0) * ny;
    }
    x[i] = toX;
    y[i] = toY;
  }
}
