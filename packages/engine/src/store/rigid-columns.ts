import { grow } from '../util/grow.js';

/** Body flags in RigidColumns.flags. */
export const BodyFlag = { fixedRotation: 1, bullet: 2 } as const;

/**
 * The rotational half of a body, indexed by the body's slot like the BodyStore columns, allocated
 * only once some body turns or holds shapes: a world of the report's circles never does, and so
 * keeps today's memory per body and its hot loops, which read none of these.
 *
 * The orientation is a unit (cos, sin) pair, advanced algebraically and renormalised each step
 * (Box2D v3's b2Rot), so the step needs no trigonometry and its bits cannot depend on a runtime's
 * Math.sin. Positions in the BodyStore (x, y) are the centre of mass; the body's origin, where
 * its shapes' coordinates are given, lies at centre - rotate(localCenter).
 */
export class RigidColumns {
  capacity = 0;
  /** Orientation: cos and sin of the body's angle. */
  c = new Float64Array(0);
  s = new Float64Array(0);
  /** Radians per second; positive turns +x towards +y (clockwise on a y-down screen). */
  angularVelocity = new Float64Array(0);
  /** Rotational inertia about the centre of mass, and its inverse (0 for static, kinematic and fixed-rotation bodies). */
  inertia = new Float64Array(0);
  invInertia = new Float64Array(0);
  /** Torque accumulated by applyTorque until the next step. */
  torque = new Float64Array(0);
  angularDamping = new Float64Array(0);
  /** The centre of mass in the body's own frame (relative to its origin). */
  localCenterX = new Float64Array(0);
  localCenterY = new Float64Array(0);
  /** The body's first shape (a ShapeStore slot) and how many it has; -1 and 0 for a circle of the report's kind, whose shape the body columns hold. */
  firstShape = new Int32Array(0);
  shapeCount = new Int32Array(0);
  flags = new Uint8Array(0);
  /** The smallest distance from the centre of one of the body's shapes to its surface: moving less than half this in a step, it cannot pass through anything. */
  minExtent = new Float64Array(0);
  /**
   * The next body of the island this body fell asleep with, around a ring, or -1: waking one
   * body of a sleeping island wakes the whole ring (see BodyStore.wake).
   */
  islandNext = new Int32Array(0);

  /** Grows every column to `capacity` slots; new slots get the identity rotation. */
  reserve(capacity: number): void {
    if (capacity <= this.capacity) return;
    const old = this.capacity;
    this.c = grow(this.c, capacity);
    this.s = grow(this.s, capacity);
    this.angularVelocity = grow(this.angularVelocity, capacity);
    this.inertia = grow(this.inertia, capacity);
    this.invInertia = grow(this.invInertia, capacity);
    this.torque = grow(this.torque, capacity);
    this.angularDamping = grow(this.angularDamping, capacity);
    this.localCenterX = grow(this.localCenterX, capacity);
    this.localCenterY = grow(this.localCenterY, capacity);
    this.firstShape = grow(this.firstShape, capacity);
    this.shapeCount = grow(this.shapeCount, capacity);
    this.flags = grow(this.flags, capacity);
    this.islandNext = grow(this.islandNext, capacity);
    this.minExtent = grow(this.minExtent, capacity);
    this.c.fill(1, old, capacity);
    this.islandNext.fill(-1, old, capacity);
    this.firstShape.fill(-1, old, capacity);
    this.capacity = capacity;
  }

  /** Resets a slot to a body at rest with no shapes and the identity rotation. */
  clear(slot: number): void {
    this.c[slot] = 1;
    this.s[slot] = 0;
    this.angularVelocity[slot] = 0;
    this.inertia[slot] = 0;
    this.invInertia[slot] = 0;
    this.torque[slot] = 0;
    this.angularDamping[slot] = 0;
    this.localCenterX[slot] = 0;
    this.localCenterY[slot] = 0;
    this.firstShape[slot] = -1;
    this.shapeCount[slot] = 0;
    this.flags[slot] = 0;
    this.islandNext[slot] = -1;
    this.minExtent[slot] = 0;
  }

  memoryBytes(): number {
    return this.c.byteLength * 10 + this.firstShape.byteLength * 3 + this.flags.byteLength;
  }
}
