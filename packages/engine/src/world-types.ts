import type { BodyType } from './store/body-types.js';

/** A circle body as getCircle reads it: the report's circle, with its motion type, material and layers. */
export interface CircleState {
  x: number;
  y: number;
  vx: number;
  vy: number;
  radius: number;
  mass: number;
  type: BodyType;
  restitution: number;
  category: number;
  mask: number;
  gravityScale: number;
  linearDamping: number;
  awake: boolean;
}

/** A body as getBody reads it: its origin and angle, the velocity of its centre of mass, its mass. */
export interface BodyState {
  /** The body's origin, where its shapes' coordinates are measured from. */
  x: number;
  y: number;
  /** Radians in [-pi, pi]; positive turns +x towards +y (clockwise on a y-down screen). */
  angle: number;
  vx: number;
  vy: number;
  angularVelocity: number;
  mass: number;
  /** Rotational inertia about the centre of mass (0 for fixed rotation). */
  inertia: number;
  /** The centre of mass in world coordinates. */
  centerX: number;
  centerY: number;
  type: BodyType;
  awake: boolean;
  fixedRotation: boolean;
  bullet: boolean;
  gravityScale: number;
  linearDamping: number;
  angularDamping: number;
  /** Handles of the body's shapes, in the order they were added. */
  shapes: number[];
}

/** A shape as getShape reads it, in its body's own frame (from the body's origin). */
export interface ShapeState {
  kind: 'circle' | 'capsule' | 'polygon';
  body: number;
  /** Circle and capsule radius, or a polygon's rounding. */
  radius: number;
  /** The circle's centre, the capsule's two ends, or the polygon's vertices (counter-clockwise). */
  vertices: { x: number; y: number }[];
  density: number;
  friction: number;
  restitution: number;
  rollingResistance: number;
  category: number;
  mask: number;
  sensor: boolean;
}

/** Filters for the point, box and ray queries. */
export interface QueryOptions {
  /** Only bodies whose category shares a bit with this mask. Default: all. */
  mask?: number | undefined;
}

/**
 * Shapes of a world that has them, indexed by shape slot: walk [0, slotCount) and skip slots
 * whose `live` is 0. Point i of a shape, for i below vertexCount[slot], is (px, py) =
 * (vertices[at], vertices[at + 1]) with at = slot * stride + vertexStart + 4 i (the next two
 * doubles are the normal of the edge from it), relative to its body's centre of mass in the body's
 * frame: the world point is (x + c px - s py, y + s px + c py) with the body's views. `kind` is 0
 * circle, 1 capsule, 2 polygon; `radius` rounds every kind.
 */
export interface ShapeViews {
  readonly slotCount: number;
  readonly stride: number;
  readonly vertexStart: number;
  readonly live: Readonly<Uint8Array>;
  readonly body: Readonly<Int32Array>;
  readonly kind: Readonly<Uint8Array>;
  readonly vertexCount: Readonly<Uint8Array>;
  readonly radius: Readonly<Float64Array>;
  readonly sensor: Readonly<Uint8Array>;
  readonly vertices: Readonly<Float64Array>;
}

/**
 * Read-only, zero-copy views of the body columns for renderers, indexed by slot. Walk slots
 * [0, slotCount) and skip those whose `type` is `BodyTypeCode.free`. The arrays are replaced when
 * the world grows, so fetch the views again after adding bodies rather than keeping them.
 */
export interface BodyViews {
  readonly slotCount: number;
  readonly liveCount: number;
  /** The centre of mass (a circle's centre). */
  readonly x: Readonly<Float64Array>;
  readonly y: Readonly<Float64Array>;
  readonly vx: Readonly<Float64Array>;
  readonly vy: Readonly<Float64Array>;
  /**
   * The broad-phase radius: a circle's radius in a world of circles; with shapes, the bounding
   * radius about the centre of mass plus the speculative margin.
   */
  readonly radius: Readonly<Float64Array>;
  readonly mass: Readonly<Float64Array>;
  readonly type: Readonly<Uint8Array>;
  /** 1 while a body sleeps. */
  readonly asleep: Readonly<Uint8Array>;
  /** Cos and sin of each body's angle, and its angular velocity; empty (length 0) until some body turns: every angle is 0 then. */
  readonly c: Readonly<Float64Array>;
  readonly s: Readonly<Float64Array>;
  readonly angularVelocity: Readonly<Float64Array>;
  /** The shapes, or null in a world of circles only, whose bodies are each a circle of `radius`. */
  readonly shapes: ShapeViews | null;
}

/**
 * The contact points of the last step, for drawing and inspection: point k at (x[k], y[k]) with
 * the normal (nx[k], ny[k]) of its manifold, pointing from the first body to the second, and the
 * signed distance between the surfaces there (negative: overlapping; positive: a speculative point
 * the soft step holds apart). Read count entries; the object and its arrays are reused.
 */
export interface ContactPointViews {
  readonly count: number;
  readonly x: Readonly<Float64Array>;
  readonly y: Readonly<Float64Array>;
  readonly nx: Readonly<Float64Array>;
  readonly ny: Readonly<Float64Array>;
  readonly separation: Readonly<Float64Array>;
}

/** A joint as it stands after the last step (see World.getJoint). */
export interface JointState {
  kind: 'distance' | 'revolute' | 'prismatic' | 'weld' | 'wheel' | 'target' | 'spring' | 'pressure';
  /** The bodies' handles; a target joint's bodyA is null (the world). */
  bodyA: number | null;
  bodyB: number;
  /** The anchors in the world (a target joint's A: its target). */
  anchorA: { x: number; y: number };
  anchorB: { x: number; y: number };
  /** The force and torque the joint put on body B in the last step it acted (A took the opposite): while its bodies sleep, what it carried as they fell asleep; 0 for a joint that never acted. */
  force: { x: number; y: number };
  torque: number;
  /** The anchors' distance apart. */
  length: number;
  /**
   * B's angle less A's, less the reference angle: within [-pi, pi], except for a revolute joint
   * with limits, which follows its angle across ±pi and may wind any number of turns the free way
   * (see docs/engine.md, Joints).
   */
  angle: number;
  /** B's anchor's distance from A's along the axis (prismatic, wheel), or 0. */
  translation: number;
  collideConnected: boolean;
  /** A pressure joint's ring of bodies and the area it encloses now; [] and 0 for the other kinds. */
  ring: number[];
  area: number;
}

/** Every joint's anchors in the world, for drawing (see World.jointViews; pressure joints, which have none, are left out); reused by every call. */
export interface JointViews {
  count: number;
  /** Joint handles, and the kind of each (JOINT_KIND_NAMES index). */
  handle: Float64Array;
  kind: Uint8Array;
  anchorAX: Float64Array;
  anchorAY: Float64Array;
  anchorBX: Float64Array;
  anchorBY: Float64Array;
}

/**
 * Joints that went in the last step (see World.jointEvents): broken ones (their force or torque
 * passed breakForce or breakTorque), and those destroyed with a body since the step before.
 */
export interface JointEventsView {
  count: number;
  /** The joints' handles, now stale. */
  joint: number[];
  reason: ('broken' | 'bodyDestroyed')[];
  /** Their bodies' handles (null for a target joint's world), which may be stale for 'bodyDestroyed'. */
  bodyA: (number | null)[];
  bodyB: number[];
}
