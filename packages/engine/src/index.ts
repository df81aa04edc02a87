/**
 * A deterministic 2D physics engine: a {@link World} holds bodies, shapes, segments and joints and
 * steps them. Everything else here is what its methods take (options), what they return (states,
 * views, statistics), or the names an option accepts.
 *
 * @module @maxgrid/engine
 */
export { World } from './world.js';
export type { CircleState, BodyState, ShapeState, BodyViews, ShapeViews, ContactPointViews, QueryOptions, JointState, JointViews, JointEventsView } from './world-types.js';
export type { JointOptions, JointBaseOptions, DistanceJointOptions, RevoluteJointOptions, PrismaticJointOptions, WeldJointOptions, WheelJointOptions, TargetJointOptions, SpringJointOptions, PressureJointOptions } from './joints/joint-options.js';
export { JOINT_KIND_NAMES } from './joints/joint-layout.js';
export type { BodyOptions, BoxOptions, PolygonOptions, CapsuleOptions, ShapeOptions, MaterialOptions, OffsetOptions } from './shapes/shape-options.js';
export { MAX_POLYGON_VERTICES, SHAPE_KIND_NAMES } from './shapes/geometry.js';
export type { RayHit } from './query/queries.js';
export type { BodyContact } from './query/body-contacts.js';
export type { ContactEventsView } from './store/contact-events.js';
export { BoxWall } from './solver/box-walls.js';
export type { WorldOptions, CircleOptions, SegmentOptions, ChainOptions, Vector } from './options.js';
export type { StepStats } from './step/stats.js';
export type { WorldBackend, KernelUse } from './backend.js';
export type { BodyType } from './store/body-types.js';
export { BODY_TYPES, TypeCode as BodyTypeCode } from './store/body-types.js';
export type { BroadPhaseName } from './broadphase/registry.js';
export { BROADPHASE_NAMES } from './broadphase/registry.js';
export type { IntegratorName } from './integrate/integrator.js';
export { INTEGRATOR_NAMES } from './integrate/integrator.js';
export type { GridGeometry } from './broadphase/maxgrid.js';
export type { DebugRenderBuffers, DebugRenderOptions } from './debug-draw.js';
export { DEBUG_COLORS } from './debug-draw.js';
