import type { SceneBody, SceneShape, ShapeScene } from '@maxgrid/scenes';
import { bodyCentroid, bodyMass, materialOf, metersPerUnit, placedVertices, resolveSceneJoints, shapeWalls, springConstants, UnsupportedSceneError, type PoseState, type ShapeEngine, type ShapeEngineProvider, type ShapeProfile, type ShapeSimulation } from './adapter.js';
import { VERSIONS } from '../engines/versions.js';
import { box2dUsesSimd } from '../engines/box2d.js';

type Box2DModule = typeof Box2D & EmscriptenModule;

/** Per profile: velocity and position iterations, continuous collision. */
/** Per profile: velocity and position iterations, continuous collision, the restitution threshold (m/s; the report set Unity's to its minimum). */
const PROFILE: Record<ShapeProfile, { velocity: number; position: number; continuous: boolean; restitutionThreshold: number }> = {
  report: { velocity: 1, position: 1, continuous: false, restitutionThreshold: 0 },
  defaults: { velocity: 8, position: 3, continuous: true, restitutionThreshold: 1 },
};

class Box2DShapes implements ShapeSimulation {
  readonly count: number;
  private readonly world: Box2D.b2World;
  private readonly bodies: Box2D.b2Body[] = [];
  private readonly S: number;
  private readonly iterations: { velocity: number; position: number };
  private readonly restitutionThreshold: number;

  constructor(private readonly b2: Box2DModule, scene: ShapeScene, profile: ShapeProfile) {
    const S = (this.S = metersPerUnit(scene));
    this.count = scene.bodies.length;
    this.iterations = PROFILE[profile];
    this.restitutionThreshold = PROFILE[profile].restitutionThreshold;
    // Box2D copies every b2Vec2 it is given: these two carry each value in, and are freed at the end.
    const vec = new b2.b2Vec2(scene.gravity.x * S, scene.gravity.y * S);
    const vec2 = new b2.b2Vec2(0, 0);
    this.world = new b2.b2World(vec);
    this.world.SetAllowSleeping(false);
    this.world.SetContinuousPhysics(PROFILE[profile].continuous);
    this.world.SetSubStepping(false);
    this.world.SetWarmStarting(true);
    const fixture = new b2.b2FixtureDef();
    const def = new b2.b2BodyDef();
    try {
      const wallFriction = scene.world.friction ?? 0.6;
      const wallRestitution = scene.world.restitution ?? 0;
      const statics: { shape: SceneShape; x: number; y: number }[] = [];
      if (scene.bounds) for (const w of shapeWalls(scene.bounds)) statics.push({ shape: { kind: 'box', width: w.width, height: w.height, friction: wallFriction, restitution: wallRestitution }, x: w.cx, y: w.cy });
      def.set_type(b2.b2_staticBody);
      for (const w of statics) {
        vec.Set(w.x * S, w.y * S);
        def.set_position(vec);
        const body = this.world.CreateBody(def);
        this.fixtures(body, scene, w.shape, fixture, vec);
      }
      for (const s of scene.segments) {
        vec.Set(0, 0);
        def.set_position(vec);
        const body = this.world.CreateBody(def);
        const edge = new b2.b2EdgeShape();
        vec.Set(s.x1 * S, s.y1 * S);
        vec2.Set(s.x2 * S, s.y2 * S);
        edge.SetTwoSided(vec, vec2);
        // A segment of no thickness keeps the edge's own skin (b2_polygonRadius, 1 cm), which
        // Box2D 2.4's contacts and time of impact are built around: at radius 0 resting boxes sit
        // where the time of impact fires every step.
        if (s.thickness > 0) edge.set_m_radius(s.thickness * S);
        fixture.set_shape(edge);
        fixture.set_friction(wallFriction);
        fixture.set_restitution(wallRestitution);
        fixture.set_density(0);
        body.CreateFixture(fixture);
        b2.destroy(edge);
      }
      for (const b of scene.bodies) {
        const type = b.type ?? 'dynamic';
        def.set_type(type === 'static' ? b2.b2_staticBody : type === 'kinematic' ? b2.b2_kinematicBody : b2.b2_dynamicBody);
        vec.Set(b.x * S, b.y * S);
        def.set_position(vec);
        def.set_angle(b.angle ?? 0);
        vec.Set((b.vx ?? 0) * S, (b.vy ?? 0) * S);
        def.set_linearVelocity(vec);
        def.set_angularVelocity(b.angularVelocity ?? 0);
        def.set_allowSleep(false);
        def.set_bullet(false);
        const body = this.world.CreateBody(def);
        for (const shape of b.shapes) this.fixtures(body, scene, shape, fixture, vec);
        if (type === 'dynamic' && b.shapes.some((shape) => shape.kind === 'capsule')) this.trueMass(body, b, vec);
        this.bodies.push(body);
      }
      this.joints(scene, vec);
    } catch (error) {
      b2.destroy(this.world);
      throw error;
    } finally {
      for (const o of [vec, vec2, fixture, def]) b2.destroy(o);
    }
  }

  /**
   * The scene's joints as Box2D 2.4 joints, which have every kind but springs on revolute and
   * prismatic joints and on a weld's translation. Anchors are from each body's origin in both,
   * and Box2D's frame is the scene's (y down, angles towards +y), so they map by the scale alone.
   */
  private joints(scene: ShapeScene, vec: Box2D.b2Vec2): void {
    const { b2, S } = this;
    const no = (index: number, what: string) => new UnsupportedSceneError('box2d-wasm', scene.name, `joint ${index}: ${what}`);
    // Masses scale with area (S^2), so forces with S^3 and torques with S^4.
    const force = S ** 3;
    const torque = S ** 4;
    const huge = 1e9;
    const clamp = (v: number) => Math.max(-huge, Math.min(huge, v));
    for (const j of resolveSceneJoints(scene, 'box2d-wasm')) {
      const a = this.bodies[j.bodyA];
      const b = this.bodies[j.bodyB];
      let def: Box2D.b2JointDef;
      if (j.kind === 'revolute') {
        if (j.hertz > 0) throw no(j.index, 'a revolute spring (Box2D 2.4 has none)');
        const d = new b2.b2RevoluteJointDef();
        d.set_referenceAngle(j.referenceAngle);
        if (j.limits) {
          d.set_enableLimit(true);
          d.set_lowerAngle(clamp(j.limits.lower));
          d.set_upperAngle(clamp(j.limits.upper));
        }
        if (j.motor) {
          d.set_enableMotor(true);
          d.set_motorSpeed(j.motor.speed);
          d.set_maxMotorTorque(j.motor.maxTorque * torque);
        }
        def = d;
      } else if (j.kind === 'distance') {
        const d = new b2.b2DistanceJointDef();
        d.set_length(j.length * S);
        d.set_minLength(j.minLength * S);
        d.set_maxLength(Math.min(j.maxLength * S, huge));
        if (j.hertz > 0) {
          const k = springConstants(j.hertz, j.dampingRatio, a.GetMass(), b.GetMass());
          d.set_stiffness(k.stiffness);
          d.set_damping(k.damping);
        }
        def = d;
      } else if (j.kind === 'prismatic') {
        if (j.hertz > 0) throw no(j.index, 'a prismatic spring (Box2D 2.4 has none)');
        const d = new b2.b2PrismaticJointDef();
        vec.Set(j.axis.x, j.axis.y);
        d.set_localAxisA(vec);
        d.set_referenceAngle(j.referenceAngle);
        if (j.limits) {
          d.set_enableLimit(true);
          d.set_lowerTranslation(clamp(j.limits.lower * S));
          d.set_upperTranslation(clamp(j.limits.upper * S));
        }
        if (j.motor) {
          d.set_enableMotor(true);
          d.set_motorSpeed(j.motor.speed * S);
          d.set_maxMotorForce(j.motor.maxForce * force);
        }
        def = d;
      } else if (j.kind === 'weld') {
        if (j.linearHertz > 0) throw no(j.index, "a weld's linear spring (Box2D 2.4's weld springs only its angle)");
        const d = new b2.b2WeldJointDef();
        d.set_referenceAngle(j.referenceAngle);
        if (j.angularHertz > 0) {
          const k = springConstants(j.angularHertz, j.dampingRatio, centralInertia(a), centralInertia(b));
          d.set_stiffness(k.stiffness);
          d.set_damping(k.damping);
        }
        def = d;
      } else {
        // Box2D 2.4's wheel with no spring leaves the axis free, where maxgrid's holds it rigid.
        if (!(j.hertz > 0)) throw no(j.index, 'a wheel joint without a spring (rigid along its axis; Box2D 2.4 leaves it free)');
        const d = new b2.b2WheelJointDef();
        vec.Set(j.axis.x, j.axis.y);
        d.set_localAxisA(vec);
        const k = springConstants(j.hertz, j.dampingRatio, a.GetMass(), b.GetMass());
        d.set_stiffness(k.stiffness);
        d.set_damping(k.damping);
        if (j.limits) {
          d.set_enableLimit(true);
          d.set_lowerTranslation(clamp(j.limits.lower * S));
          d.set_upperTranslation(clamp(j.limits.upper * S));
        }
        if (j.motor) {
          d.set_enableMotor(true);
          d.set_motorSpeed(j.motor.speed);
          d.set_maxMotorTorque(j.motor.maxTorque * torque);
        }
        def = d;
      }
      const anchored = def as Box2D.b2RevoluteJointDef;
      vec.Set(j.anchorA.x * S, j.anchorA.y * S);
      anchored.set_localAnchorA(vec);
      vec.Set(j.anchorB.x * S, j.anchorB.y * S);
      anchored.set_localAnchorB(vec);
      def.set_bodyA(a);
      def.set_bodyB(b);
      def.set_collideConnected(j.collideConnected);
      this.world.CreateJoint(def);
      b2.destroy(def);
    }
  }

  /**
   * A capsule's stand-in (a box and two whole circles, which overlap it) weighs a disc more than
   * the capsule, 44 % more at a 1:2 radius to length, and turns with another inertia: the body is
   * given the mass, centre and rotational inertia of its true shapes instead.
   */
  private trueMass(body: Box2D.b2Body, b: SceneBody, vec: Box2D.b2Vec2): void {
    const { b2, S } = this;
    const { mass, inertia } = bodyMass(b);
    const centre = bodyCentroid(b);
    const data = new b2.b2MassData();
    data.set_mass(mass * S ** 2);
    vec.Set(centre.x * S, centre.y * S);
    data.set_center(vec);
    // About the body's origin, as b2MassData takes it; masses scale with S^2, inertias with S^4.
    data.set_I(inertia * S ** 4);
    body.SetMassData(data);
    b2.destroy(data);
  }

  /** Box2D 2.4 has no capsule: a box between two circles stands in for one (with the capsule's mass: trueMass). */
  private fixtures(body: Box2D.b2Body, scene: ShapeScene, shape: SceneShape, fixture: Box2D.b2FixtureDef, vec: Box2D.b2Vec2): void {
    const { b2, S } = this;
    const m = materialOf(scene, shape);
    fixture.set_density(m.density);
    fixture.set_friction(m.friction);
    fixture.set_restitution(m.restitution);
    fixture.set_restitutionThreshold(this.restitutionThreshold);
    const ox = (shape.offsetX ?? 0) * S;
    const oy = (shape.offsetY ?? 0) * S;
    const a = ('offsetAngle' in shape ? (shape.offsetAngle ?? 0) : 0);
    if (shape.kind === 'circle') {
      const circle = new b2.b2CircleShape();
      circle.set_m_radius(shape.radius * S);
      vec.Set(ox, oy);
      circle.set_m_p(vec);
      fixture.set_shape(circle);
      body.CreateFixture(fixture);
      b2.destroy(circle);
      return;
    }
    if (shape.kind === 'capsule') {
      const half = (shape.length / 2) * S;
      const r = shape.radius * S;
      const c = Math.cos(a);
      const s = Math.sin(a);
      const box = new b2.b2PolygonShape();
      vec.Set(ox, oy);
      box.SetAsBox(half, r, vec, a);
      fixture.set_shape(box);
      body.CreateFixture(fixture);
      b2.destroy(box);
      for (const end of [-1, 1]) {
        const circle = new b2.b2CircleShape();
        circle.set_m_radius(r);
        vec.Set(ox + end * half * c, oy + end * half * s);
        circle.set_m_p(vec);
        fixture.set_shape(circle);
        body.CreateFixture(fixture);
        b2.destroy(circle);
      }
      return;
    }
    const vertices = placedVertices(shape);
    const ptr = b2._malloc(8 * vertices.length);
    try {
      for (let i = 0; i < vertices.length; i++) {
        b2.HEAPF32[(ptr >> 2) + 2 * i] = vertices[i].x * S;
        b2.HEAPF32[(ptr >> 2) + 2 * i + 1] = vertices[i].y * S;
      }
      const polygon = new b2.b2PolygonShape();
      polygon.Set(ptr, vertices.length);
      fixture.set_shape(polygon);
      body.CreateFixture(fixture);
      b2.destroy(polygon);
    } finally {
      b2._free(ptr);
    }
  }

  step(dt: number): void {
    this.world.Step(dt, this.iterations.velocity, this.iterations.position);
  }

  read(out: PoseState): void {
    const S = this.S;
    for (let k = 0; k < this.count; k++) {
      const body = this.bodies[k];
      const p = body.GetPosition();
      const v = body.GetLinearVelocity();
      out.x[k] = p.get_x() / S;
      out.y[k] = p.get_y() / S;
      out.angle[k] = body.GetAngle();
      out.vx[k] = v.get_x() / S;
      out.vy[k] = v.get_y() / S;
      out.angularVelocity[k] = body.GetAngularVelocity();
    }
  }

  dispose(): void {
    this.b2.destroy(this.world);
  }
}

/** GetInertia is about the body's origin; springs, as b2AngularStiffness, take it about the centre of mass. */
function centralInertia(body: Box2D.b2Body): number {
  const c = body.GetLocalCenter();
  return body.GetInertia() - body.GetMass() * (c.get_x() ** 2 + c.get_y() ** 2);
}

let modulePromise: Promise<Box2DModule> | undefined;

/** The Box2D module the shape adapter built its worlds in, once loaded (tests count its live objects). */
export function box2dShapeModule(): Promise<Box2DModule> | undefined {
  return modulePromise;
}

export const box2dShapeProvider: ShapeEngineProvider = {
  id: 'box2d-wasm',
  async load(options = {}): Promise<ShapeEngine> {
    modulePromise ??= import('box2d-wasm').then((m) => {
      const factory = (m as unknown as { default: (o?: object) => Promise<Box2DModule> }).default;
      const moduleOptions: Record<string, unknown> = {};
      if (options.box2dLocateFile) moduleOptions.locateFile = options.box2dLocateFile;
      if (options.box2dWasmBinary) moduleOptions.wasmBinary = options.box2dWasmBinary;
      return factory(moduleOptions);
    });
    const b2 = await modulePromise;
    const common = {
      core: `Box2D 2.4 compiled to WebAssembly (${box2dUsesSimd() ? 'SIMD' : 'scalar'} build)`,
      allowSleeping: false,
      subStepping: false,
      warmStarting: true,
      capsule: "a box between two circles (Box2D 2.4 has no capsule), the body given the true capsule's mass, centre and rotational inertia",
      units: '1 m = the scene lengthUnit',
    };
    return {
      info: {
        id: 'box2d-wasm',
        package: 'box2d-wasm',
        version: VERSIONS['box2d-wasm'],
        precision: 'f32',
        settings: {
          report: { velocityIterations: PROFILE.report.velocity, positionIterations: PROFILE.report.position, continuousPhysics: PROFILE.report.continuous, restitutionThreshold: PROFILE.report.restitutionThreshold, ...common },
          defaults: { velocityIterations: PROFILE.defaults.velocity, positionIterations: PROFILE.defaults.position, continuousPhysics: PROFILE.defaults.continuous, restitutionThreshold: PROFILE.defaults.restitutionThreshold, ...common },
        },
      },
      create: (scene, profile) => new Box2DShapes(b2, scene, profile),
    };
  },
};
