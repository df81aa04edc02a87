import type { SceneShape, ShapeScene } from '@maxgrid/scenes';
import { materialOf, metersPerUnit, placedVertices, resolveSceneJoints, shapeWalls, UnsupportedSceneError, type PoseState, type ShapeEngine, type ShapeEngineProvider, type ShapeProfile, type ShapeSimulation } from './adapter.js';
import { VERSIONS } from '../engines/versions.js';

type Rapier = typeof import('@dimforge/rapier2d-simd-compat').default;
type RapierWorld = InstanceType<Rapier['World']>;
type RapierBody = ReturnType<RapierWorld['createRigidBody']>;
type ColliderDesc = InstanceType<Rapier['ColliderDesc']>;
type RevoluteJoint = InstanceType<Rapier['RevoluteImpulseJoint']>;

/** Per profile: solver iterations and internal PGS passes (Rapier's defaults are 4 and 1). */
const ITERATIONS: Record<ShapeProfile, { solver: number; pgs: number }> = { report: { solver: 1, pgs: 1 }, defaults: { solver: 4, pgs: 1 } };

class RapierShapes implements ShapeSimulation {
  readonly count: number;
  private readonly world: RapierWorld;
  private readonly bodies: RapierBody[] = [];
  private readonly S: number;

  constructor(R: Rapier, scene: ShapeScene, profile: ShapeProfile) {
    const S = (this.S = metersPerUnit(scene));
    this.count = scene.bodies.length;
    this.world = new R.World({ x: scene.gravity.x * S, y: scene.gravity.y * S });
    const params = this.world.integrationParameters;
    params.numSolverIterations = ITERATIONS[profile].solver;
    params.numInternalPgsIterations = ITERATIONS[profile].pgs;
    if (scene.bounds) {
      const walls = this.world.createRigidBody(R.RigidBodyDesc.fixed());
      for (const w of shapeWalls(scene.bounds)) {
        const desc = R.ColliderDesc.cuboid((w.width / 2) * S, (w.height / 2) * S)
          .setTranslation(w.cx * S, w.cy * S)
          .setRestitution(scene.world.restitution ?? 0)
          .setFriction(scene.world.friction ?? 0.6);
        this.world.createCollider(desc, walls);
      }
    }
    for (const s of scene.segments) {
      const ground = this.world.createRigidBody(R.RigidBodyDesc.fixed());
      // A segment's thickness is the radius of the capsule around it (World.createSegment).
      const length = Math.hypot(s.x2 - s.x1, s.y2 - s.y1);
      const desc = s.thickness > 0
        ? R.ColliderDesc.capsule((length / 2) * S, s.thickness * S)
            .setTranslation(((s.x1 + s.x2) / 2) * S, ((s.y1 + s.y2) / 2) * S)
            .setRotation(Math.atan2(s.y2 - s.y1, s.x2 - s.x1) - Math.PI / 2)
        : R.ColliderDesc.segment({ x: s.x1 * S, y: s.y1 * S }, { x: s.x2 * S, y: s.y2 * S });
      this.world.createCollider(desc.setFriction(scene.world.friction ?? 0.6).setRestitution(scene.world.restitution ?? 0), ground);
    }
    for (const b of scene.bodies) {
      const type = b.type ?? 'dynamic';
      const desc = type === 'static' ? R.RigidBodyDesc.fixed() : type === 'kinematic' ? R.RigidBodyDesc.kinematicVelocityBased() : R.RigidBodyDesc.dynamic();
      desc
        .setTranslation(b.x * S, b.y * S)
        .setRotation(b.angle ?? 0)
        .setLinvel((b.vx ?? 0) * S, (b.vy ?? 0) * S)
        .setAngvel(b.angularVelocity ?? 0)
        .setCanSleep(false)
        .setCcdEnabled(false);
      const body = this.world.createRigidBody(desc);
      for (const shape of b.shapes) this.world.createCollider(this.collider(R, scene, shape), body);
      this.bodies.push(body);
    }
    try {
      this.joints(R, scene);
    } catch (error) {
      this.world.free();
      throw error;
    }
  }

  /**
   * The scene's joints as Rapier impulse joints: revolute (with limits), fixed (weld), prismatic
   * (with limits, B keeping A's angle) and rope (a distance joint with a maximum only). Rapier's
   * JavaScript API sets no largest force on a joint motor, so a motor (even a friction motor at
   * speed 0) cannot be built; it has no rigid distance joint and no wheel joint. Anchors are in
   * each body's frame from its translation (the origin), as in the scene.
   */
  private joints(R: Rapier, scene: ShapeScene): void {
    const S = this.S;
    const no = (index: number, what: string) => new UnsupportedSceneError('rapier', scene.name, `joint ${index}: ${what}`);
    for (const j of resolveSceneJoints(scene, 'rapier')) {
      const a1 = { x: j.anchorA.x * S, y: j.anchorA.y * S };
      const a2 = { x: j.anchorB.x * S, y: j.anchorB.y * S };
      let data: ReturnType<Rapier['JointData']['revolute']>;
      let limits: [number, number] | null = null;
      if (j.kind === 'revolute') {
        if (j.motor) throw no(j.index, "a revolute motor (Rapier's JavaScript API cannot cap a motor's torque)");
        if (j.hertz > 0) throw no(j.index, 'a revolute spring');
        data = R.JointData.revolute(a1, a2);
        if (j.limits) {
          // Rapier measures B's angle less A's with no reference angle: the limits move by it.
          const lower = j.limits.lower + j.referenceAngle;
          const upper = j.limits.upper + j.referenceAngle;
          if (!(lower >= -Math.PI && upper <= Math.PI)) throw no(j.index, `angle limits past ±pi once moved by the reference angle (${lower}, ${upper})`);
          limits = [lower, upper];
        }
      } else if (j.kind === 'weld') {
        if (j.linearHertz > 0 || j.angularHertz > 0) throw no(j.index, 'a soft weld (Rapier has no spring on a fixed joint)');
        // Frames rotA * frame1 = rotB * frame2: B's angle less A's is frame1 - frame2.
        data = R.JointData.fixed(a1, j.referenceAngle, a2, 0);
      } else if (j.kind === 'prismatic') {
        if (j.motor) throw no(j.index, "a prismatic motor (Rapier's JavaScript API cannot cap a motor's force)");
        if (j.hertz > 0) throw no(j.index, 'a prismatic spring');
        if (Math.abs(j.referenceAngle) > 1e-12) throw no(j.index, `a prismatic joint with reference angle ${j.referenceAngle} (Rapier's keeps B at A's angle)`);
        data = R.JointData.prismatic(a1, a2, j.axis);
        if (j.limits) limits = [Math.max(j.limits.lower * S, -1e9), Math.min(j.limits.upper * S, 1e9)];
      } else if (j.kind === 'distance') {
        if (!(j.hertz === 0 && j.minLength === 0 && Number.isFinite(j.maxLength))) throw no(j.index, 'a distance joint other than a rope (0 to a maximum): Rapier has no rigid distance joint, and its spring is not built here');
        data = R.JointData.rope(j.maxLength * S, a1, a2);
      } else {
        throw no(j.index, 'a wheel joint (Rapier has none)');
      }
      const joint = this.world.createImpulseJoint(data, this.bodies[j.bodyA], this.bodies[j.bodyB], true);
      joint.setContactsEnabled(j.collideConnected);
      if (limits) (joint as RevoluteJoint).setLimits(limits[0], limits[1]);
    }
  }

  private collider(R: Rapier, scene: ShapeScene, shape: SceneShape): ColliderDesc {
    const S = this.S;
    const m = materialOf(scene, shape);
    let desc: ColliderDesc;
    let angle = ('offsetAngle' in shape ? (shape.offsetAngle ?? 0) : 0);
    let placed = false;
    if (shape.kind === 'circle') desc = R.ColliderDesc.ball(shape.radius * S);
    else if (shape.kind === 'capsule') {
      // Rapier's capsule lies along its y axis; the scene's along the body's x axis.
      desc = R.ColliderDesc.capsule((shape.length / 2) * S, shape.radius * S);
      angle += Math.PI / 2;
    } else if (shape.kind === 'box' && !shape.radius) desc = R.ColliderDesc.cuboid((shape.width / 2) * S, (shape.height / 2) * S);
    else {
      const points = new Float32Array(placedVertices(shape).flatMap((v) => [v.x * S, v.y * S]));
      const hull = shape.radius ? R.ColliderDesc.roundConvexHull(points, shape.radius * S) : R.ColliderDesc.convexHull(points);
      if (!hull) throw new RangeError(`rapier: could not build the convex hull of a ${shape.kind}`);
      desc = hull;
      placed = true;
    }
    if (!placed) desc.setTranslation((shape.offsetX ?? 0) * S, (shape.offsetY ?? 0) * S).setRotation(angle);
    return desc.setDensity(m.density).setFriction(m.friction).setRestitution(m.restitution);
  }

  step(dt: number): void {
    this.world.timestep = dt;
    this.world.step();
  }

  read(out: PoseState): void {
    const S = this.S;
    for (let k = 0; k < this.count; k++) {
      const b = this.bodies[k];
      const p = b.translation();
      const v = b.linvel();
      out.x[k] = p.x / S;
      out.y[k] = p.y / S;
      out.angle[k] = b.rotation();
      out.vx[k] = v.x / S;
      out.vy[k] = v.y / S;
      out.angularVelocity[k] = b.angvel();
    }
  }

  dispose(): void {
    this.world.free();
  }
}

let rapierPromise: Promise<Rapier> | undefined;

export const rapierShapeProvider: ShapeEngineProvider = {
  id: 'rapier',
  async load(): Promise<ShapeEngine> {
    rapierPromise ??= import('@dimforge/rapier2d-simd-compat').then(async (m) => {
      await m.default.init();
      return m.default;
    });
    const R = await rapierPromise;
    const common = { canSleep: false, ccdEnabled: false, friction: "the scene's, combine rule average", restitution: "the scene's, combine rule average", units: '1 m = the scene lengthUnit' };
    return {
      info: {
        id: 'rapier',
        package: '@dimforge/rapier2d-simd-compat',
        version: VERSIONS['@dimforge/rapier2d-simd-compat'],
        precision: 'f32',
        settings: {
          report: { numSolverIterations: ITERATIONS.report.solver, numInternalPgsIterations: ITERATIONS.report.pgs, ...common },
          defaults: { numSolverIterations: ITERATIONS.defaults.solver, numInternalPgsIterations: ITERATIONS.defaults.pgs, ...common },
        },
      },
      create: (scene, profile) => new RapierShapes(R, scene, profile),
    };
  },
};
