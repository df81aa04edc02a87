/** Joint kinds, as stored in JointStore.kind and named in JointOptions.kind. */
export const JointKind = { distance: 0, revolute: 1, prismatic: 2, weld: 3, wheel: 4, target: 5, spring: 6, pressure: 7 } as const;
export type JointKindName = keyof typeof JointKind;
/** Every joint kind, indexed by the code that `JointViews.kind` holds. */
export const JOINT_KIND_NAMES = Object.keys(JointKind) as JointKindName[];

/**
 * A joint's record: JOINT_STRIDE doubles, its definition first (fixed by createJoint), then what
 * the solver prepares at the start of each step, then the impulses, which persist between steps
 * for the warm start. Every kind uses the fields it needs and leaves the others 0.
 *
 * The solver's modules copy these into constants of their own (`const { rAX: R_AX } = J`): V8
 * folds a module's own constant numbers into the code, where a property of an imported object is
 * loaded at every use; a lattice of distance joints solved about 17 % faster for it (three
 * alternating runs against the build before).
 */
export const J = {
  // Definition. Anchors in each body's own frame, from its origin.
  anchorAX: 0,
  anchorAY: 1,
  anchorBX: 2,
  anchorBY: 3,
  /** Body B's angle less body A's at which the joint is at rest (revolute, prismatic, weld, wheel). */
  referenceAngle: 4,
  /** Unit axis in body A's frame (prismatic, wheel). */
  axisX: 5,
  axisY: 6,
  length: 7,
  minLength: 8,
  maxLength: 9,
  /** Spring frequency in hertz (0: none) and damping ratio. */
  hertz: 10,
  dampingRatio: 11,
  /** Limits: angles (revolute) or translations (prismatic, wheel); enableLimit 1 when on. */
  lower: 12,
  upper: 13,
  enableLimit: 14,
  motorSpeed: 15,
  /** The motor's largest torque (revolute, wheel) or force (prismatic); enableMotor 1 when on. */
  maxMotor: 16,
  enableMotor: 17,
  /** Weld softness: 0 for rigid. */
  linearHertz: 18,
  angularHertz: 19,
  /** The target joint's largest force, and its target in world coordinates. */
  maxForce: 20,
  targetX: 21,
  targetY: 22,
  /** Above these the joint breaks (Infinity: never). */
  breakForce: 23,
  breakTorque: 24,
  /** A force-driven spring's stiffness (force per length) and damping (force per speed); a pressure joint's gas pressure at its rest area, whose area is its `length`. */
  stiffness: 25,
  damping: 62,

  // Prepared each step.
  /** Anchors from each centre of mass, turned into the world frame at the step's start. */
  rAX: 26,
  rAY: 27,
  rBX: 28,
  rBY: 29,
  /** Centre of B less centre of A (or less the target) at the step's start. */
  deltaCenterX: 30,
  deltaCenterY: 31,
  /** The axis in the world frame at the step's start. */
  worldAxisX: 32,
  worldAxisY: 33,
  /** The joint angle (relative angle less the reference) at the step's start. */
  deltaAngle: 34,
  invMassA: 35,
  invMassB: 36,
  invInertiaA: 37,
  invInertiaB: 38,
  /** Offsets of the two bodies' solver states (see SoftStep); 0 is the fixed dummy body. */
  stateA: 39,
  stateB: 40,
  axialMass: 41,
  /** A spring's softness: bias rate, mass scale, impulse scale. */
  springBias: 42,
  springMass: 43,
  springImpulse: 44,
  /** A second softness (the weld's angular part, the target joint's spin damping). */
  softBias: 45,
  softMass: 46,
  softImpulse: 47,

  // Accumulated impulses, kept between steps.
  linearImpulseX: 48,
  linearImpulseY: 49,
  angularImpulse: 50,
  springImpulseSum: 51,
  motorImpulse: 52,
  lowerImpulse: 53,
  upperImpulse: 54,
  /** The distance joint's rigid impulse; the wheel's and prismatic's across the axis. */
  axialImpulse: 55,

  // After the step: the joint's force and torque on body B (A takes the opposite).
  forceX: 56,
  forceY: 57,
  torque: 58,
  /** 1 when the step solved the joint (some body of it moved). */
  active: 59,
  perpMass: 60,
  motorMass: 61,
  /** The joint angle now, within a sub-step (measureAngle). */
  angle: 63,
} as const;

export const JOINT_STRIDE = 64;
