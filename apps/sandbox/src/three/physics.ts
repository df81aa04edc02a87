import * as CANNON from 'cannon-es';

/**
 * The cannon-es side of the report's early exploration (5.3.2): a world with gravity, a plane body
 * as the floor, cube bodies matching the rendered cubes, and the two optimisations of 5.3.3:
 * sleeping objects (built into Cannon) and mutable physics object types (ours, below).
 */

/** Fixed physics step. Both the live page and the experiment use it, so their timings compare. */
export const DT = 1 / 60;
export const CUBE_SIZE = 1;
export const CUBE_MASS = 1;

const cubeShape = new CANNON.Box(new CANNON.Vec3(CUBE_SIZE / 2, CUBE_SIZE / 2, CUBE_SIZE / 2));

/**
 * A world with the floor plane. Cannon's default (naive) broad-phase and solver settings are kept
 * on purpose: the report explored Cannon as shipped, before adding optimisations on top of it.
 * Restitution is zero so cubes settle rather than bounce, which the "landed" rule relies on.
 */
export function createWorld(): CANNON.World {
  const world = new CANNON.World({ gravity: new CANNON.Vec3(0, -9.82, 0) });
  world.defaultContactMaterial.friction = 0.4;
  world.defaultContactMaterial.restitution = 0;
  const floor = new CANNON.Body({ type: CANNON.Body.STATIC, shape: new CANNON.Plane() });
  // A Cannon plane faces +z; turn it so it faces +y (up).
  floor.quaternion.setFromEuler(-Math.PI / 2, 0, 0);
  world.addBody(floor);
  return world;
}

/** Adds a dynamic cube at (x, y, z), turned by yaw radians about the vertical axis. */
export function addCube(world: CANNON.World, x: number, y: number, z: number, yaw = 0): CANNON.Body {
  const body = new CANNON.Body({ mass: CUBE_MASS, shape: cubeShape, position: new CANNON.Vec3(x, y, z) });
  body.quaternion.setFromEuler(0, yaw, 0);
  world.addBody(body);
  return body;
}

/**
 * Sleeping objects (3.1.4, 5.3.3). Cannon's own per-body defaults are kept (speed limit 0.1 m/s,
 * 1 s below it). Turning sleeping off wakes every body: otherwise a body that fell asleep would
 * stay frozen for ever, because Cannon only runs its sleep bookkeeping while allowSleep is on.
 */
export function setSleeping(world: CANNON.World, on: boolean): void {
  world.allowSleep = on;
  if (!on) for (const body of world.bodies) body.wakeUp();
}

export function isStatic(body: CANNON.Body): boolean {
  return (body.type & CANNON.Body.STATIC) !== 0;
}

export function isSleeping(body: CANNON.Body): boolean {
  return body.sleepState === CANNON.Body.SLEEPING;
}

/**
 * "Landed", precisely: a cube has landed when, for LANDED_STEPS consecutive steps, its linear speed
 * is below LANDED_SPEED, its angular speed below LANDED_SPIN, and it touches a static body (the
 * floor or an already-static cube) underneath it (contact normal within ~45° of vertical).
 *
 * Why each part:
 * - several consecutive steps, not one: a cube at the top of a bounce, or tipping over an edge,
 *   is momentarily still; freezing it there would leave it hanging in mid-air or mid-topple;
 * - the support must be static, not just any cube: figure 9 freezes each layer once it landed on
 *   the previous (already static) layer or on the floor. Freezing a cube that rests on a moving
 *   one would leave it floating when its support slides away;
 * - "underneath" (normal pointing up at the cube): a cube merely brushing a static neighbour's
 *   side is not resting on anything.
 * The speed limit matches Cannon's default sleepSpeedLimit, so both techniques judge "at rest" alike;
 * the step count is much shorter than Cannon's 1 s sleepTimeLimit, which is the technique's point:
 * the application knows cubes only come to rest by landing, so it can decide sooner.
 */
export const LANDED_SPEED = 0.1;
export const LANDED_SPIN = 0.1;
export const LANDED_STEPS = 10;
const SUPPORT_NORMAL_Y = 0.7;

/**
 * Mutable physics object types: cubes are switched to STATIC (mass 0) once landed, so Cannon skips
 * static-static pairs and stops integrating them. Call afterStep() after every world.step().
 */
export class MutableTypes {
  enabled = false;
  /** Consecutive at-rest steps per body id. */
  private readonly restSteps = new Map<number, number>();
  private readonly supported = new Set<number>();

  constructor(private readonly world: CANNON.World) {}

  afterStep(): void {
    if (!this.enabled) return;
    this.supported.clear();
    // world.contacts holds the contacts of the step just taken. ni points out of bi towards bj.
    for (const c of this.world.contacts) {
      if (isStatic(c.bi) && !isStatic(c.bj) && c.ni.y > SUPPORT_NORMAL_Y) this.supported.add(c.bj.id);
      if (isStatic(c.bj) && !isStatic(c.bi) && c.ni.y < -SUPPORT_NORMAL_Y) this.supported.add(c.bi.id);
    }
    for (const body of this.world.bodies) {
      if (isStatic(body)) continue;
      const atRest =
        this.supported.has(body.id) &&
        body.velocity.length() < LANDED_SPEED &&
        body.angularVelocity.length() < LANDED_SPIN;
      const steps = atRest ? (this.restSteps.get(body.id) ?? 0) + 1 : 0;
      this.restSteps.set(body.id, steps);
      if (steps >= LANDED_STEPS) makeStatic(body);
    }
  }

  /** Turning the technique off gives every frozen cube its mass back (the floor stays static). */
  disable(): void {
    this.enabled = false;
    this.restSteps.clear();
    for (const body of this.world.bodies) {
      if (isStatic(body) && body.shapes[0] instanceof CANNON.Box) makeDynamic(body);
    }
  }
}

function makeStatic(body: CANNON.Body): void {
  body.type = CANNON.Body.STATIC;
  body.mass = 0;
  body.updateMassProperties();
  body.velocity.setZero();
  body.angularVelocity.setZero();
}

function makeDynamic(body: CANNON.Body): void {
  body.type = CANNON.Body.DYNAMIC;
  body.mass = CUBE_MASS;
  body.updateMassProperties();
  // updateMassProperties approximates inertia from the world-space AABB, which a turned cube
  // inflates; use the cube's exact inertia so a thawed cube tumbles like a fresh one.
  cubeShape.calculateLocalInertia(CUBE_MASS, body.inertia);
  body.invInertia.set(1 / body.inertia.x, 1 / body.inertia.y, 1 / body.inertia.z);
  body.updateInertiaWorld(true);
  body.wakeUp();
}
