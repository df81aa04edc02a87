import type { SceneShape, ShapeScene } from '@maxgrid/scenes';
import { bodyCentroid, bodyMass, materialOf, metersPerUnit, placedVertices, resolveSceneJoints, shapeWalls, UnsupportedSceneError, type PoseState, type ShapeEngine, type ShapeEngineProvider, type ShapeProfile, type ShapeSimulation } from './adapter.js';
import { VERSIONS } from '../engines/versions.js';

type Planck = typeof import('planck');
type PlanckWorld = InstanceType<Planck['World']>;
type PlanckBody = ReturnType<PlanckWorld['createBody']>;

/** Per profile: iterations, continuous collision, and planck's restitution threshold (m/s; process-wide in planck, so set before each step). */
const PROFILE: Record<ShapeProfile, { velocity: number; position: number; continuous: boolean; velocityThreshold: number }> = {
  report: { velocity: 1, position: 1, continuous: false, velocityThreshold: 0 },
  defaults: { velocity: 8, position: 3, continuous: true, velocityThreshold: 1 },
};

class PlanckShapes implements ShapeSimulation {
  readonly count: number;
  private readonly world: PlanckWorld;
  private readonly bodies: PlanckBody[] = [];
  private readonly S: number;
  private readonly iterations: { velocity: number; position: number; velocityThreshold: number };

  constructor(private readonly pl: Planck, scene: ShapeScene, profile: ShapeProfile) {
    const S = (this.S = metersPerUnit(scene));
    this.count = scene.bodies.length;
    this.iterations = PROFILE[profile];
    this.world = new pl.World({
      gravity: { x: scene.gravity.x * S, y: scene.gravity.y * S },
      allowSleep: false,
      continuousPhysics: PROFILE[profile].continuous,
      subStepping: false,
      warmStarting: true,
    });
    const wall = { friction: scene.world.friction ?? 0.6, restitution: scene.world.restitution ?? 0 };
    if (scene.bounds) {
      for (const w of shapeWalls(scene.bounds)) {
        const body = this.world.createBody({ type: 'static', position: { x: w.cx * S, y: w.cy * S } });
        body.createFixture({ shape: new pl.Box((w.width / 2) * S, (w.height / 2) * S), ...wall });
      }
    }
    for (const s of scene.segments) {
      const body = this.world.createBody({ type: 'static' });
      const edge = new pl.Edge({ x: s.x1 * S, y: s.y1 * S }, { x: s.x2 * S, y: s.y2 * S });
      // A segment's thickness is the radius of the capsule around it (World.createSegment); planck,
      // as Box2D 2.4, rounds an edge by its radius in every collision and time of impact. Of no
      // thickness, the edge keeps its own skin (Settings.polygonRadius), as Box2D's does.
      if (s.thickness > 0) edge.m_radius = s.thickness * S;
      body.createFixture({ shape: edge, ...wall });
    }
    for (const b of scene.bodies) {
      const body = this.world.createBody({
        type: b.type ?? 'dynamic',
        position: { x: b.x * S, y: b.y * S },
        angle: b.angle ?? 0,
        linearVelocity: { x: (b.vx ?? 0) * S, y: (b.vy ?? 0) * S },
        angularVelocity: b.angularVelocity ?? 0,
        allowSleep: false,
        bullet: false,
      });
      for (const shape of b.shapes) this.fixtures(body, scene, shape);
      if ((b.type ?? 'dynamic') === 'dynamic' && b.shapes.some((shape) => shape.kind === 'capsule')) {
        // A capsule's stand-in (a box and two whole circles, which overlap it) weighs a disc more
        // than the capsule, 44 % more at a 1:2 radius to length, and turns with another inertia:
        // the body is given its true shapes' mass, centre and inertia (about the origin, as
        // setMassData takes it; masses scale with S^2, inertias with S^4).
        const { mass, inertia } = bodyMass(b);
        const centre = bodyCentroid(b);
        body.setMassData({ mass: mass * S ** 2, center: { x: centre.x * S, y: centre.y * S }, I: inertia * S ** 4 });
      }
      this.bodies.push(body);
    }
    this.joints(scene);
  }

  /**
   * The scene's joints as planck's (Box2D 2.3's set): springs are frequency and damping ratio as
   * in the scene, but a distance joint is either rigid, a spring, or a rope (planck's RopeJoint,
   * a maximum only); revolute and prismatic joints have no spring, a weld springs only its angle,
   * a wheel has no limits. Anchors are from each body's origin, in the scene's own frame.
   */
  private joints(scene: ShapeScene): void {
    const { pl, S } = this;
    const no = (index: number, what: string) => new UnsupportedSceneError('planck', scene.name, `joint ${index}: ${what}`);
    // Masses scale with area (S^2), so forces with S^3 and torques with S^4.
    const force = S ** 3;
    const torque = S ** 4;
    for (const j of resolveSceneJoints(scene, 'planck')) {
      const bodyA = this.bodies[j.bodyA];
      const bodyB = this.bodies[j.bodyB];
      const base = {
        localAnchorA: { x: j.anchorA.x * S, y: j.anchorA.y * S },
        localAnchorB: { x: j.anchorB.x * S, y: j.anchorB.y * S },
        collideConnected: j.collideConnected,
        bodyA,
        bodyB,
      };
      if (j.kind === 'revolute') {
        if (j.hertz > 0) throw no(j.index, 'a revolute spring (planck has none)');
        this.world.createJoint(
          new pl.RevoluteJoint({
            ...base,
            referenceAngle: j.referenceAngle,
            enableLimit: j.limits !== null,
            lowerAngle: j.limits?.lower ?? 0,
            upperAngle: j.limits?.upper ?? 0,
            enableMotor: j.motor !== null,
            motorSpeed: j.motor?.speed ?? 0,
            maxMotorTorque: (j.motor?.maxTorque ?? 0) * torque,
          }),
        );
      } else if (j.kind === 'distance') {
        const rigid = j.minLength === j.length && j.maxLength === j.length;
        const spring = j.hertz > 0 && j.minLength === 0 && j.maxLength === Infinity;
        const rope = j.hertz === 0 && j.minLength === 0 && Number.isFinite(j.maxLength);
        if (rigid || spring) {
          this.world.createJoint(new pl.DistanceJoint({ ...base, length: j.length * S, frequencyHz: spring ? j.hertz : 0, dampingRatio: spring ? j.dampingRatio : 0 }));
        } else if (rope) {
          this.world.createJoint(new pl.RopeJoint({ ...base, maxLength: j.maxLength * S }));
        } else {
          throw no(j.index, 'a distance joint with a range other than a rope (0 to a maximum), or a spring within limits (planck has neither)');
        }
      } else if (j.kind === 'prismatic') {
        if (j.hertz > 0) throw no(j.index, 'a prismatic spring (planck has none)');
        this.world.createJoint(
          new pl.PrismaticJoint({
            ...base,
            localAxisA: j.axis,
            referenceAngle: j.referenceAngle,
            enableLimit: j.limits !== null,
            lowerTranslation: (j.limits?.lower ?? 0) * S,
            upperTranslation: (j.limits?.upper ?? 0) * S,
            enableMotor: j.motor !== null,
            motorSpeed: (j.motor?.speed ?? 0) * S,
            maxMotorForce: (j.motor?.maxForce ?? 0) * force,
          }),
        );
      } else if (j.kind === 'weld') {
        if (j.linearHertz > 0) throw no(j.index, "a weld's linear spring (planck's weld springs only its angle)");
        this.world.createJoint(new pl.WeldJoint({ ...base, referenceAngle: j.referenceAngle, frequencyHz: j.angularHertz, dampingRatio: j.dampingRatio }));
      } else {
        if (j.limits) throw no(j.index, "a wheel joint's translation limits (planck's wheel joint has none)");
        // planck's wheel with no spring leaves the axis free, where maxgrid's holds it rigid.
        if (!(j.hertz > 0)) throw no(j.index, 'a wheel joint without a spring (rigid along its axis; planck leaves it free)');
        this.world.createJoint(
          new pl.WheelJoint({
            ...base,
            localAxisA: j.axis,
            frequencyHz: j.hertz,
            dampingRatio: j.dampingRatio,
            enableMotor: j.motor !== null,
            motorSpeed: j.motor?.speed ?? 0,
            maxMotorTorque: (j.motor?.maxTorque ?? 0) * torque,
          }),
        );
      }
    }
  }

  /** planck, like Box2D 2.4, has no capsule: a box between two circles stands in for one (with the capsule's mass, set in the constructor). */
  private fixtures(body: PlanckBody, scene: ShapeScene, shape: SceneShape): void {
    const { pl, S } = this;
    const material = materialOf(scene, shape);
    const ox = (shape.offsetX ?? 0) * S;
    const oy = (shape.offsetY ?? 0) * S;
    const a = ('offsetAngle' in shape ? (shape.offsetAngle ?? 0) : 0);
    if (shape.kind === 'circle') {
      body.createFixture({ shape: new pl.Circle({ x: ox, y: oy }, shape.radius * S), ...material });
    } else if (shape.kind === 'capsule') {
      const half = (shape.length / 2) * S;
      const r = shape.radius * S;
      body.createFixture({ shape: new pl.Box(half, r, { x: ox, y: oy }, a), ...material });
      for (const end of [-1, 1]) body.createFixture({ shape: new pl.Circle({ x: ox + end * half * Math.cos(a), y: oy + end * half * Math.sin(a) }, r), ...material });
    } else {
      body.createFixture({ shape: new pl.Polygon(placedVertices(shape).map((v) => ({ x: v.x * S, y: v.y * S }))), ...material });
    }
  }

  step(dt: number): void {
    this.pl.Settings.velocityThreshold = this.iterations.velocityThreshold;
    this.world.step(dt, this.iterations.velocity, this.iterations.position);
  }

  read(out: PoseState): void {
    const S = this.S;
    for (let k = 0; k < this.count; k++) {
      const b = this.bodies[k];
      const p = b.getPosition();
      const v = b.getLinearVelocity();
      out.x[k] = p.x / S;
      out.y[k] = p.y / S;
      out.angle[k] = b.getAngle();
      out.vx[k] = v.x / S;
      out.vy[k] = v.y / S;
      out.angularVelocity[k] = b.getAngularVelocity();
    }
  }

  dispose(): void {}
}

export const planckShapeProvider: ShapeEngineProvider = {
  id: 'planck',
  async load(): Promise<ShapeEngine> {
    const pl = (await import('planck')) as unknown as Planck;
    const common = { allowSleep: false, subStepping: false, warmStarting: true, capsule: "a box between two circles (planck has no capsule), the body given the true capsule's mass, centre and rotational inertia", units: '1 m = the scene lengthUnit' };
    return {
      info: {
        id: 'planck',
        package: 'planck',
        version: VERSIONS.planck,
        precision: 'f64',
        settings: {
          report: { velocityIterations: PROFILE.report.velocity, positionIterations: PROFILE.report.position, continuousPhysics: PROFILE.report.continuous, 'Settings.velocityThreshold': PROFILE.report.velocityThreshold, ...common },
          defaults: { velocityIterations: PROFILE.defaults.velocity, positionIterations: PROFILE.defaults.position, continuousPhysics: PROFILE.defaults.continuous, 'Settings.velocityThreshold': PROFILE.defaults.velocityThreshold, ...common },
        },
      },
      create: (scene, profile) => new PlanckShapes(pl, scene, profile),
    };
  },
};
