/** Joint kinds, as stored in JointStore.kind and named in JointOptions.kind. */
export const JointKind = { distance: 0, revolute: 1, prismatic: 2, weld: 3, wheel: 4, target: 5, spring: 6, pressure: 7 } as const;
export type JointKindName = keyof typeof JointKind;
/** Every joint kind, indexed by the code that `JointViews.kind` holds. */
export const JOINT_KIND_NAMES = Object.keys(JointKind) as JointKindName[];

/**
 * A joint's record: JOINT_STRIDE doubles holding its definition (fixed by createJoint), what the
 * solver prepares at the start of each step, and the impulses, which persist between steps for
 * the warm start. Every kind uses the fields it needs and leaves the others 0. The fields are
 * ordered by how often a step reads them, hottest first, not by what they are.
 *
 * The solver's modules copy these into constants of their own (`const { rAX: R_AX } = J`): V8
 * folds a module's own constant numbers into the code, where a property of an imported object is
 * loaded at every use; a lattice of distance joints solved about 17 % faster for it (three
 * alternating runs against the build before).
 */
export const J = {
  // The first 32: all that a distance joint's passes read and write.
  /** Offsets of the two bodies' solver states (see SoftStep); 0 is the fixed dummy body. */
  stateA: 0,
  stateB: 1,
  invMassA: 2,
  invMassB: 3,
  invInertiaA: 4,
  invInertiaB: 5,
  /** Anchors from each centre of mass, turned into the world frame at the step's start. */
  rAX: 6,
  rAY: 7,
  rBX: 8,
  rBY: 9,
  /** Centre of B less centre of A (or less the target) at the step's start. */
  deltaCenterX: 10,
  deltaCenterY: 11,
  /** The axis in the world frame at the step's start. */
  worldAxisX: 12,
  worldAxisY: 13,
  axialMass: 14,
  length: 15,
  /** A spring's softness: bias rate, mass scale, impulse scale. */
  springBias: 16,
  springMass: 17,
  springImpulse: 18,
  springImpulseSum: 19,
  /** The distance joint's rigid impulse; the wheel's and prismatic's across the axis. */
  axialImpulse: 20,
  lowerImpulse: 21,
  upperImpulse: 22,
  enableLimit: 23,
  minLength: 24,
  maxLength: 25,
  /** Spring frequency in hertz (0: none) and damping ratio. */
  hertz: 26,
  /**
   * The joint angle (relative angle less the reference) at the step's start: within [-pi, pi],
   * but followed continuously across turns for a revolute joint with limits, from the turn
   * nearest its limits when made (see resolveJoint).
   */
  deltaAngle: 27,
  linearImpulseX: 28,
  linearImpulseY: 29,
  angularImpulse: 30,
  motorImpulse: 31,
  // Read by the other kinds in the passes, or by the preparation only.
  /** A second softness (the weld's angular part, the target joint's spin damping). */
  softBias: 32,
  softMass: 33,
  softImpulse: 34,
  perpMass: 35,
  motorMass: 36,
  /** The joint angle now, within a sub-step (measureAngle). */
  angle: 37,
  /** Limits: angles (revolute) or translations (prismatic, wheel); enableLimit 1 when on. */
  lower: 38,
  upper: 39,
  enableMotor: 40,
  motorSpeed: 41,
  /** The motor's largest torque (revolute, wheel) or force (prismatic); enableMotor 1 when on. */
  maxMotor: 42,
  /** Body B's angle less body A's at which the joint is at rest (revolute, prismatic, weld, wheel). */
  referenceAngle: 43,
  /** Unit axis in body A's frame (prismatic, wheel). */
  axisX: 44,
  axisY: 45,
  /** Weld softness: 0 for rigid. */
  linearHertz: 46,
  angularHertz: 47,
  // The definition read by the preparation, and what the step reports.
  /** The target joint's largest force, and its target in world coordinates. */
  maxForce: 48,
  targetX: 49,
  targetY: 50,
  /** Above these the joint breaks (Infinity: never). */
  breakForce: 51,
  breakTorque: 52,
  /** A force-driven spring's stiffness (force per length) and damping (force per speed); a pressure joint's gas pressure at its rest area, whose area is its `length`. */
  stiffness: 53,
  damping: 54,
  dampingRatio: 55,
  /** Anchors in each body's own frame, from its origin. */
  anchorAX: 56,
  anchorAY: 57,
  anchorBX: 58,
  anchorBY: 59,
  /** After the step: the joint's force and torque on body B (A takes the opposite). */
  forceX: 60,
  forceY: 61,
  torque: 62,
  /** 1 when the step solved the joint (some body of it moved). */
  active: 63,
} as const;

export const JOINT_STRIDE = 64;
