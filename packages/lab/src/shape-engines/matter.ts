import type { SceneBody, SceneShape, ShapeScene } from '@maxgrid/scenes';
import type * as MatterTypes from 'matter-js';
import { materialOf, placedVertices, resolveSceneJoints, shapeWalls, UnsupportedSceneError, type PoseState, type ShapeEngine, type ShapeEngineProvider, type ShapeProfile, type ShapeSimulation } from './adapter.js';
import { VERSIONS } from '../engines/versions.js';

type Matter = typeof MatterTypes;

/**
 * Matter's defaults are 6 position, 4 velocity and 2 constraint iterations, and a resting
 * threshold (contacts approaching slower get no restitution) of 2 px per base delta, Matter
 * 0.20's Resolver._restingThresh. The report's profile sets it to its minimum, as
 * the report set Unity's velocity threshold. Module-wide in Matter, so set before each step.
 */
const PROFILE: Record<ShapeProfile, { position: number; velocity: number; constraint: number; restingThreshold: number }> = {
  report: { position: 1, velocity: 1, constraint: 1, restingThreshold: 0 },
  defaults: { position: 6, velocity: 4, constraint: 2, restingThreshold: 2 },
};
const BASE_DELTA_S = 1 / 60;
const GRAVITY_SCALE = 1e-6;
/** Matter is tuned for pixels: 1 m = 50 px, as the lab's circle adapters scale the Box2D family the other way. */
export const PIXELS_PER_METER = 50;

class MatterShapes implements ShapeSimulation {
  readonly count: number;
  private readonly engine: MatterTypes.Engine;
  private readonly bodies: MatterTypes.Body[] = [];
  /** Kinematic bodies (Matter has none): static bodies turned and moved by hand each step. */
  private readonly kinematic: { body: MatterTypes.Body; vx: number; vy: number; w: number }[] = [];
  /** Matter pixels per scene unit. */
  private readonly F: number;
  /** Each body's centre of mass from its origin, in its own frame. */
  private readonly centre: [number, number][] = [];

  constructor(private readonly M: Matter, scene: ShapeScene, private readonly profile: ShapeProfile) {
    const F = (this.F = PIXELS_PER_METER / (scene.world.lengthUnit ?? 1));
    this.count = scene.bodies.length;
    const p = PROFILE[profile];
    this.engine = M.Engine.create({
      gravity: { x: scene.gravity.x * F, y: scene.gravity.y * F, scale: GRAVITY_SCALE },
      enableSleeping: false,
      positionIterations: p.position,
      velocityIterations: p.velocity,
      constraintIterations: p.constraint,
    });
    const all: MatterTypes.Body[] = [];
    const wall = { friction: scene.world.friction ?? 0.6, restitution: scene.world.restitution ?? 0, frictionAir: 0, isStatic: true };
    if (scene.bounds) for (const w of shapeWalls(scene.bounds)) all.push(M.Bodies.rectangle(w.cx * F, w.cy * F, w.width * F, w.height * F, wall));
    for (const s of scene.segments) {
      const length = Math.hypot(s.x2 - s.x1, s.y2 - s.y1) * F;
      const thick = Math.max(2 * s.thickness * F, 1);
      all.push(M.Bodies.rectangle(((s.x1 + s.x2) / 2) * F, ((s.y1 + s.y2) / 2) * F + (s.thickness > 0 ? 0 : thick / 2), length, thick, { ...wall, angle: Math.atan2(s.y2 - s.y1, s.x2 - s.x1) }));
    }
    for (const b of scene.bodies) {
      const body = this.body(scene, b);
      this.bodies.push(body);
      all.push(body);
    }
    M.Composite.add(this.engine.world, [...all, ...this.constraints(scene)]);
  }

  /**
   * The scene's joints as Matter constraints, its only joint: a revolute joint is a pin (a
   * constraint of length 0), a rigid distance joint a constraint of its length, both at stiffness
   * 1. Matter has no limits, motors or joints that fix an angle or an axis, and its springs are a
   * stiffness fraction per iteration rather than a frequency, so those are not built.
   */
  private constraints(scene: ShapeScene): MatterTypes.Constraint[] {
    const { M, F } = this;
    const no = (index: number, what: string) => new UnsupportedSceneError('matter-js', scene.name, `joint ${index}: ${what}`);
    const out: MatterTypes.Constraint[] = [];
    for (const j of resolveSceneJoints(scene, 'matter-js')) {
      let length: number;
      if (j.kind === 'revolute') {
        if (j.limits) throw no(j.index, 'revolute angle limits (Matter has none)');
        if (j.motor) throw no(j.index, 'a revolute motor, or joint friction (Matter has none)');
        if (j.hertz > 0) throw no(j.index, 'a revolute spring (Matter has none)');
        length = 0;
      } else if (j.kind === 'distance') {
        if (j.minLength !== j.length || j.maxLength !== j.length) throw no(j.index, "a distance joint that is not rigid (a range or a spring: Matter's constraints are rigid or a stiffness fraction)");
        length = j.length * F;
      } else {
        throw no(j.index, `a ${j.kind} joint (Matter has only distance constraints)`);
      }
      const bodyA = this.bodies[j.bodyA];
      const bodyB = this.bodies[j.bodyB];
      if (!j.collideConnected) keepApart(M, bodyA, bodyB);
      out.push(M.Constraint.create({ bodyA, bodyB, pointA: this.offset(scene, j.bodyA, j.anchorA), pointB: this.offset(scene, j.bodyB, j.anchorB), length, stiffness: 1, damping: 0 }));
    }
    return out;
  }

  /** Matter's constraint point: from the body's position (its centre of mass), in world axes, in pixels. */
  private offset(scene: ShapeScene, k: number, anchor: { x: number; y: number }): { x: number; y: number } {
    const [cx, cy] = this.centre[k];
    const angle = scene.bodies[k].angle ?? 0;
    const c = Math.cos(angle);
    const s = Math.sin(angle);
    const dx = anchor.x - cx;
    const dy = anchor.y - cy;
    return { x: (c * dx - s * dy) * this.F, y: (s * dx + c * dy) * this.F };
  }

  private body(scene: ShapeScene, b: SceneBody): MatterTypes.Body {
    const { M, F } = this;
    const type = b.type ?? 'dynamic';
    const parts = b.shapes.map((shape) => this.part(scene, b, shape));
    const body = parts.length === 1 ? parts[0] : M.Body.create({ parts });
    // Matter places a body at its centre of mass: remember the origin from there, in the body's frame.
    const angle = b.angle ?? 0;
    const c = Math.cos(angle);
    const s = Math.sin(angle);
    const dx = body.position.x / F - b.x;
    const dy = body.position.y / F - b.y;
    this.centre.push([c * dx + s * dy, -s * dx + c * dy]);
    if (type !== 'dynamic') {
      M.Body.setStatic(body, true);
      if (type === 'kinematic') this.kinematic.push({ body, vx: (b.vx ?? 0) * F, vy: (b.vy ?? 0) * F, w: b.angularVelocity ?? 0 });
    } else {
      M.Body.setVelocity(body, { x: (b.vx ?? 0) * F * BASE_DELTA_S, y: (b.vy ?? 0) * F * BASE_DELTA_S });
      M.Body.setAngularVelocity(body, (b.angularVelocity ?? 0) * BASE_DELTA_S);
    }
    return body;
  }

  /** One shape as a Matter body at the body's position; a capsule is a rectangle with fully rounded corners. */
  private part(scene: ShapeScene, b: SceneBody, shape: SceneShape): MatterTypes.Body {
    const { M, F } = this;
    const m = materialOf(scene, shape);
    const options = { friction: m.friction, restitution: m.restitution, frictionAir: 0, density: 0.001 * m.density };
    // Each part at its place in the world: the body's origin plus its offset turned by the body's angle.
    const angle = b.angle ?? 0;
    const c = Math.cos(angle);
    const s = Math.sin(angle);
    const ox = shape.offsetX ?? 0;
    const oy = shape.offsetY ?? 0;
    const x = (b.x + c * ox - s * oy) * F;
    const y = (b.y + s * ox + c * oy) * F;
    const turn = angle + ('offsetAngle' in shape ? (shape.offsetAngle ?? 0) : 0);
    if (shape.kind === 'circle') return M.Bodies.circle(x, y, shape.radius * F, options);
    if (shape.kind === 'capsule') {
      const r = shape.radius * F;
      return M.Bodies.rectangle(x, y, shape.length * F + 2 * r, 2 * r, { ...options, angle: turn, chamfer: { radius: r * 0.999 } });
    }
    const vertices = placedVertices({ ...shape, offsetX: 0, offsetY: 0, offsetAngle: 0 }).map((v) => ({ x: v.x * F, y: v.y * F }));
    const part = M.Bodies.fromVertices(x, y, [vertices], options);
    M.Body.setAngle(part, turn);
    return part;
  }

  step(dt: number): void {
    const M = this.M;
    (M.Resolver as unknown as { _restingThresh: number })._restingThresh = PROFILE[this.profile].restingThreshold;
    for (const k of this.kinematic) {
      M.Body.setPosition(k.body, { x: k.body.position.x + k.vx * dt, y: k.body.position.y + k.vy * dt });
      M.Body.setAngle(k.body, k.body.angle + k.w * dt);
    }
    M.Engine.update(this.engine, dt * 1000);
  }

  read(out: PoseState): void {
    const { F } = this;
    for (let k = 0; k < this.count; k++) {
      const b = this.bodies[k];
      const [dx, dy] = this.centre[k];
      const c = Math.cos(b.angle);
      const s = Math.sin(b.angle);
      out.x[k] = b.position.x / F - (c * dx - s * dy);
      out.y[k] = b.position.y / F - (s * dx + c * dy);
      out.angle[k] = b.angle;
      // Engine.update ends with Body.updateVelocities, which scales each step's displacement to
      // Matter's base delta (1/60 s) whatever the step's length: px per 1/60 s at any dt.
      out.vx[k] = b.velocity.x / F / BASE_DELTA_S;
      out.vy[k] = b.velocity.y / F / BASE_DELTA_S;
      out.angularVelocity[k] = b.angularVelocity / BASE_DELTA_S;
    }
  }

  dispose(): void {
    this.M.Engine.clear(this.engine);
  }
}

type JoinedFilter = MatterTypes.ICollisionFilter & { joined?: Set<MatterTypes.ICollisionFilter> };

/**
 * Matter's constraints do not stop the bodies they join from colliding, and its collision groups
 * can only keep whole groups apart, not pairs; so a joined pair's filters name each other, and
 * Matter's canCollide (looked up on every detection) is wrapped, once, to refuse such a pair.
 * Filters without `joined` (every other Matter world) are judged as before.
 */
function keepApart(M: Matter, a: MatterTypes.Body, b: MatterTypes.Body): void {
  const detector = M.Detector as unknown as { canCollide: (a: JoinedFilter, b: JoinedFilter) => boolean; joinedPairs?: boolean };
  if (!detector.joinedPairs) {
    const base = detector.canCollide;
    detector.canCollide = (fa, fb) => !(fa.joined?.has(fb) ?? false) && base(fa, fb);
    detector.joinedPairs = true;
  }
  for (const body of [a, b]) if (!(body.collisionFilter as JoinedFilter).joined) body.collisionFilter = { ...body.collisionFilter, joined: new Set() } as JoinedFilter;
  (a.collisionFilter as JoinedFilter).joined!.add(b.collisionFilter);
  (b.collisionFilter as JoinedFilter).joined!.add(a.collisionFilter);
}

export const matterShapeProvider: ShapeEngineProvider = {
  id: 'matter-js',
  async load(): Promise<ShapeEngine> {
    const M = ((await import('matter-js')) as unknown as { default: Matter }).default;
    const common = {
      enableSleeping: false,
      ccd: 'none (Matter has no CCD)',
      frictionAir: 0,
      density: '0.001 x the scene density',
      capsule: 'a rectangle with corners rounded by the radius (chamfer)',
      kinematic: 'static bodies moved and turned by hand each step (Matter has no kinematic bodies)',
      joints: 'constraints at stiffness 1 (a revolute joint: length 0); joined bodies kept from colliding by a wrapped Detector.canCollide',
      units: 'pixels, 1 m = 50 px; gravity.scale 1e-6 so gravity is px/s^2; Engine.update(dt * 1000 ms)',
    };
    const settings = (p: ShapeProfile) => ({ positionIterations: PROFILE[p].position, velocityIterations: PROFILE[p].velocity, constraintIterations: PROFILE[p].constraint, 'Resolver._restingThresh': PROFILE[p].restingThreshold, ...common });
    return {
      info: { id: 'matter-js', package: 'matter-js', version: VERSIONS['matter-js'], precision: 'f64', settings: { report: settings('report'), defaults: settings('defaults') } },
      create: (scene, profile) => new MatterShapes(M, scene, profile),
    };
  },
};
