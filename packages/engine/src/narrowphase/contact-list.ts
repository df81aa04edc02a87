import { grownCapacity, grow } from '../util/grow.js';
import type { Manifold } from './manifold.js';

/** `bodyB` of a contact with a world shape (a segment or a wall of the box) rather than a body. */
export const WORLD = -1;

/**
 * The step's contacts between shapes, in the canonical order: by (body A slot, body B slot), a
 * contact with a world shape after every contact of its body with bodies, then by shape pair in
 * the bodies' shape order. Each holds its manifold (normal, up to two points with anchors
 * relative to each body's centre of mass) and what the solver accumulated on it, which the next
 * step inherits point by point where the same features touch again (warm starting).
 *
 * Keys: body slots, and shape handles (ShapeStore's, with generation; for a world shape its
 * segment handle or wall code), so that a reused slot never passes its impulses to a newcomer.
 */
export class ContactList {
  count = 0;
  bodyA = new Int32Array(0);
  bodyB = new Int32Array(0);
  shapeA = new Int32Array(0);
  /** ShapeStore slot, or for a world contact the world-shape entry id. */
  shapeB = new Int32Array(0);
  keyA = new Float64Array(0);
  keyB = new Float64Array(0);
  pointCount = new Uint8Array(0);
  normalX = new Float64Array(0);
  normalY = new Float64Array(0);
  friction = new Float64Array(0);
  restitution = new Float64Array(0);
  rollingResistance = new Float64Array(0);
  rollingImpulse = new Float64Array(0);
  // Two entries per contact: point p of contact k at 2k + p.
  anchorAX = new Float64Array(0);
  anchorAY = new Float64Array(0);
  anchorBX = new Float64Array(0);
  anchorBY = new Float64Array(0);
  pointX = new Float64Array(0);
  pointY = new Float64Array(0);
  separation = new Float64Array(0);
  id = new Int32Array(0);
  normalImpulse = new Float64Array(0);
  tangentImpulse = new Float64Array(0);
  /** The largest normal impulse the point took in the step: whether it really collided (restitution, events). */
  totalNormalImpulse = new Float64Array(0);
  /** Approach speed along the normal before the solve (positive when approaching), for hit events. */
  approachSpeed = new Float64Array(0);
  /**
   * For recycling (see ShapeNarrowPhase): the two bodies' rotations when the manifold was last
   * computed, B's centre and rotation relative to A then, and each point's separation then.
   */
  cacheAC = new Float64Array(0);
  cacheAS = new Float64Array(0);
  cacheBC = new Float64Array(0);
  cacheBS = new Float64Array(0);
  relativeX = new Float64Array(0);
  relativeY = new Float64Array(0);
  relativeC = new Float64Array(0);
  relativeS = new Float64Array(0);
  baseSeparation = new Float64Array(0);
  private capacity = 0;

  clear(): void {
    this.count = 0;
  }

  /**
   * Appends a contact with its manifold; points get their anchors from the two centres of mass
   * (ax, ay) and (bx, by), and start with no impulse (see inherit).
   */
  push(
    bodyA: number,
    bodyB: number,
    shapeA: number,
    shapeB: number,
    keyA: number,
    keyB: number,
    m: Manifold,
    ax: number,
    ay: number,
    bx: number,
    by: number,
    friction: number,
    restitution: number,
    rollingResistance: number,
  ): number {
    if (this.count === this.capacity) this.grow(this.count + 1);
    const k = this.count++;
    this.bodyA[k] = bodyA;
    this.bodyB[k] = bodyB;
    this.shapeA[k] = shapeA;
    this.shapeB[k] = shapeB;
    this.keyA[k] = keyA;
    this.keyB[k] = keyB;
    const n = m.pointCount;
    this.pointCount[k] = n;
    this.normalX[k] = m.normalX;
    this.normalY[k] = m.normalY;
    this.friction[k] = friction;
    this.restitution[k] = restitution;
    this.rollingResistance[k] = rollingResistance;
    this.rollingImpulse[k] = 0;
    for (let p = 0; p < n; p++) {
      const at = 2 * k + p;
      const px = m.x[p];
      const py = m.y[p];
      this.pointX[at] = px;
      this.pointY[at] = py;
      this.anchorAX[at] = px - ax;
      this.anchorAY[at] = py - ay;
      this.anchorBX[at] = px - bx;
      this.anchorBY[at] = py - by;
      this.separation[at] = m.separation[p];
      this.id[at] = m.id[p];
      this.normalImpulse[at] = 0;
      this.tangentImpulse[at] = 0;
      this.totalNormalImpulse[at] = 0;
      this.approachSpeed[at] = 0;
      this.baseSeparation[at] = m.separation[p];
    }
    return k;
  }

  /** Notes the poses the manifold of contact k was computed at (centres and rotations of A and B). */
  cache(k: number, ax: number, ay: number, ac: number, as: number, bx: number, by: number, bc: number, bs: number): void {
    this.cacheAC[k] = ac;
    this.cacheAS[k] = as;
    this.cacheBC[k] = bc;
    this.cacheBS[k] = bs;
    const dx = bx - ax;
    const dy = by - ay;
    // B's centre and rotation in A's frame.
    this.relativeX[k] = ac * dx + as * dy;
    this.relativeY[k] = -as * dx + ac * dy;
    this.relativeC[k] = ac * bc + as * bs;
    this.relativeS[k] = ac * bs - as * bc;
  }

  /**
   * Appends a copy of contact `from` of `previous` whose manifold is kept (recycled): same normal,
   * points, ids, impulses and cache, anchors turned with their bodies since the cache (by
   * (dac, das) and (dbc, dbs)), and separations brought up to date from how the anchors moved
   * apart along the normal, as the soft step's sub-steps do.
   */
  recycle(previous: ContactList, from: number, ax: number, ay: number, dac: number, das: number, bx: number, by: number, dbc: number, dbs: number): number {
    if (this.count === this.capacity) this.grow(this.count + 1);
    const k = this.count++;
    this.bodyA[k] = previous.bodyA[from];
    this.bodyB[k] = previous.bodyB[from];
    this.shapeA[k] = previous.shapeA[from];
    this.shapeB[k] = previous.shapeB[from];
    this.keyA[k] = previous.keyA[from];
    this.keyB[k] = previous.keyB[from];
    const n = previous.pointCount[from];
    this.pointCount[k] = n;
    const nx = previous.normalX[from];
    const ny = previous.normalY[from];
    this.normalX[k] = nx;
    this.normalY[k] = ny;
    this.friction[k] = previous.friction[from];
    this.restitution[k] = previous.restitution[from];
    this.rollingResistance[k] = previous.rollingResistance[from];
    this.rollingImpulse[k] = previous.rollingImpulse[from];
    this.cacheAC[k] = previous.cacheAC[from];
    this.cacheAS[k] = previous.cacheAS[from];
    this.cacheBC[k] = previous.cacheBC[from];
    this.cacheBS[k] = previous.cacheBS[from];
    this.relativeX[k] = previous.relativeX[from];
    this.relativeY[k] = previous.relativeY[from];
    this.relativeC[k] = previous.relativeC[from];
    this.relativeS[k] = previous.relativeS[from];
    const dcx = bx - ax;
    const dcy = by - ay;
    for (let p = 0; p < n; p++) {
      const at = 2 * k + p;
      const was = 2 * from + p;
      // The anchors as they were cached (undo last step's turn), turned by the motion since.
      const base = previous.baseSeparation[was];
      const rAx0 = previous.anchorAX[was];
      const rAy0 = previous.anchorAY[was];
      const rBx0 = previous.anchorBX[was];
      const rBy0 = previous.anchorBY[was];
      const rAx = dac * rAx0 - das * rAy0;
      const rAy = das * rAx0 + dac * rAy0;
      const rBx = dbc * rBx0 - dbs * rBy0;
      const rBy = dbs * rBx0 + dbc * rBy0;
      this.anchorAX[at] = rAx0;
      this.anchorAY[at] = rAy0;
      this.anchorBX[at] = rBx0;
      this.anchorBY[at] = rBy0;
      this.separation[at] = base + (dcx + rBx - rAx) * nx + (dcy + rBy - rAy) * ny;
      this.pointX[at] = ax + rAx;
      this.pointY[at] = ay + rAy;
      this.id[at] = previous.id[was];
      this.normalImpulse[at] = previous.normalImpulse[was];
      this.tangentImpulse[at] = previous.tangentImpulse[was];
      this.totalNormalImpulse[at] = 0;
      this.approachSpeed[at] = 0;
      this.baseSeparation[at] = base;
    }
    return k;
  }

  /**
   * Gives contact k the impulses of the contact `from` in `previous` (the same shapes touching
   * last step): points with the same feature id take theirs, as does the rolling impulse.
   */
  inherit(k: number, previous: ContactList, from: number): void {
    this.rollingImpulse[k] = previous.rollingImpulse[from];
    const n = this.pointCount[k];
    const m = previous.pointCount[from];
    for (let p = 0; p < n; p++) {
      const at = 2 * k + p;
      const id = this.id[at];
      for (let q = 0; q < m; q++) {
        const was = 2 * from + q;
        if (previous.id[was] !== id) continue;
        this.normalImpulse[at] = previous.normalImpulse[was];
        this.tangentImpulse[at] = previous.tangentImpulse[was];
        break;
      }
    }
  }

  memoryBytes(): number {
    return this.capacity * (4 * 4 + 8 * 2 + 1 + 8 * 14) + 2 * this.capacity * (8 * 12 + 4);
  }

  private grow(needed: number): void {
    const c = grownCapacity(this.capacity, needed);
    this.bodyA = grow(this.bodyA, c);
    this.bodyB = grow(this.bodyB, c);
    this.shapeA = grow(this.shapeA, c);
    this.shapeB = grow(this.shapeB, c);
    this.keyA = grow(this.keyA, c);
    this.keyB = grow(this.keyB, c);
    this.pointCount = grow(this.pointCount, c);
    this.normalX = grow(this.normalX, c);
    this.normalY = grow(this.normalY, c);
    this.friction = grow(this.friction, c);
    this.restitution = grow(this.restitution, c);
    this.rollingResistance = grow(this.rollingResistance, c);
    this.rollingImpulse = grow(this.rollingImpulse, c);
    this.anchorAX = grow(this.anchorAX, 2 * c);
    this.anchorAY = grow(this.anchorAY, 2 * c);
    this.anchorBX = grow(this.anchorBX, 2 * c);
    this.anchorBY = grow(this.anchorBY, 2 * c);
    this.pointX = grow(this.pointX, 2 * c);
    this.pointY = grow(this.pointY, 2 * c);
    this.separation = grow(this.separation, 2 * c);
    this.id = grow(this.id, 2 * c);
    this.normalImpulse = grow(this.normalImpulse, 2 * c);
    this.tangentImpulse = grow(this.tangentImpulse, 2 * c);
    this.totalNormalImpulse = grow(this.totalNormalImpulse, 2 * c);
    this.approachSpeed = grow(this.approachSpeed, 2 * c);
    this.cacheAC = grow(this.cacheAC, c);
    this.cacheAS = grow(this.cacheAS, c);
    this.cacheBC = grow(this.cacheBC, c);
    this.cacheBS = grow(this.cacheBS, c);
    this.relativeX = grow(this.relativeX, c);
    this.relativeY = grow(this.relativeY, c);
    this.relativeC = grow(this.relativeC, c);
    this.relativeS = grow(this.relativeS, c);
    this.baseSeparation = grow(this.baseSeparation, 2 * c);
    this.capacity = c;
  }
}
