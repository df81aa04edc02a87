import type { SceneShape, ShapeScene } from '@maxgrid/scenes';
import { bodyMass, materialOf, metersPerUnit, placedVertices, resolveSceneJoints, shapeWalls, UnsupportedSceneError, type PoseState, type ShapeEngine, type ShapeEngineProvider, type ShapeProfile, type ShapeSimulation } from './adapter.js';
import { VERSIONS } from '../engines/versions.js';
import { loadP2, type P2Api as P2, type P2Body, type P2World } from '../engines/p2-loader.js';

/** How deep (m) the slab that stands in for a segment of no thickness reaches below it. */
const SLAB_DEPTH_M = 0.1;

/** p2's GSSolver runs 10 iterations by default. */
const ITERATIONS: Record<ShapeProfile, number> = { report: 1, defaults: 10 };

class P2Shapes implements ShapeSimulation {
  readonly count: number;
  private readonly world: P2World;
  private readonly bodies: P2Body[] = [];
  /** Where a one-shape body's p2 body lies from its origin (its shape's offset, in its frame) and how much more it is turned. */
  private readonly placement: { ox: number; oy: number; turn: number }[] = [];
  private readonly S: number;

  constructor(private readonly p2: P2, scene: ShapeScene, profile: ShapeProfile) {
    const S = (this.S = metersPerUnit(scene));
    this.count = scene.bodies.length;
    const solver = new p2.GSSolver({ iterations: ITERATIONS[profile] });
    this.world = new p2.World({ gravity: [scene.gravity.x * S, scene.gravity.y * S], solver, islandSplit: false });
    this.world.sleepMode = p2.World.NO_SLEEPING;
    // One contact material for every pair: p2 mixes materials only through ContactMaterial objects.
    const contact = this.world.defaultContactMaterial;
    contact.friction = scene.world.friction ?? 0.6;
    contact.restitution = scene.world.restitution ?? 0;
    if (scene.bounds) {
      for (const w of shapeWalls(scene.bounds)) {
        const wall = new p2.Body({ mass: 0, type: p2.Body.STATIC, position: [w.cx * S, w.cy * S] });
        wall.addShape(new p2.Box({ width: w.width * S, height: w.height * S }));
        this.world.addBody(wall);
      }
    }
    for (const s of scene.segments) {
      const dx = s.x2 - s.x1;
      const dy = s.y2 - s.y1;
      const length = Math.hypot(dx, dy) * S;
      const angle = Math.atan2(dy, dx);
      let cx = ((s.x1 + s.x2) / 2) * S;
      let cy = ((s.y1 + s.y2) / 2) * S;
      let shape;
      if (s.thickness > 0) {
        shape = new p2.Capsule({ length, radius: s.thickness * S });
      } else {
        // p2-es 1.2.3 collides a Line with nothing but circles and planes (its lineBox, convexLine
        // and lineCapsule return no contact), so a segment of no thickness is a slab hung below
        // the line, on gravity's side, its top face on the line: bodies rest where they would on
        // the segment, and the slab is deep enough that p2's soft contacts do not sink through it.
        let nx = -dy / Math.hypot(dx, dy);
        let ny = dx / Math.hypot(dx, dy);
        const along = nx * scene.gravity.x + ny * scene.gravity.y;
        if (along < 0) {
          nx = -nx;
          ny = -ny;
        }
        // A segment along gravity has no side below it: the slab is centred on it.
        const shift = along === 0 ? 0 : SLAB_DEPTH_M / 2;
        cx += nx * shift;
        cy += ny * shift;
        shape = new p2.Box({ width: length, height: SLAB_DEPTH_M });
      }
      const ground = new p2.Body({ mass: 0, type: p2.Body.STATIC, position: [cx, cy], angle });
      ground.addShape(shape);
      this.world.addBody(ground);
    }
    for (const b of scene.bodies) {
      const type = b.type ?? 'dynamic';
      const { mass } = bodyMass(b);
      // A body of one shape is placed at that shape, turned with it, so that p2's position is its
      // centre (p2 keeps the centre of mass at the body's position); the origin is read back from it.
      const single = b.shapes.length === 1 ? b.shapes[0] : null;
      const ox = single?.offsetX ?? 0;
      const oy = single?.offsetY ?? 0;
      const turn = single && 'offsetAngle' in single ? (single.offsetAngle ?? 0) : 0;
      const angle = b.angle ?? 0;
      const c = Math.cos(angle);
      const s = Math.sin(angle);
      const body = new p2.Body({
        mass: type === 'dynamic' ? mass * S * S : 0,
        type: type === 'static' ? p2.Body.STATIC : type === 'kinematic' ? p2.Body.KINEMATIC : p2.Body.DYNAMIC,
        position: [(b.x + c * ox - s * oy) * S, (b.y + s * ox + c * oy) * S],
        angle: angle + turn,
        velocity: [(b.vx ?? 0) * S, (b.vy ?? 0) * S],
        angularVelocity: b.angularVelocity ?? 0,
        damping: 0,
        angularDamping: 0,
        allowSleep: false,
      });
      if (single) this.addShape(body, scene, { ...single, offsetX: 0, offsetY: 0, ...(single.kind === 'circle' ? {} : { offsetAngle: 0 }) } as SceneShape);
      else for (const shape of b.shapes) this.addShape(body, scene, shape);
      if (type === 'dynamic') body.updateMassProperties();
      this.placement.push({ ox, oy, turn });
      this.world.addBody(body);
      this.bodies.push(body);
    }
    this.joints(scene);
  }

  /**
   * The scene's joints as p2 constraints: revolute (with limits and a motor) and rigid distance.
   * p2's other constraints (prismatic, lock) and its springs are not built here. p2 places a
   * one-shape body at its shape, so anchors move from the origin's frame into that one.
   */
  private joints(scene: ShapeScene): void {
    const { p2, S } = this;
    const no = (index: number, what: string) => new UnsupportedSceneError('p2-es', scene.name, `joint ${index}: ${what}`);
    const local = (k: number, p: { x: number; y: number }): [number, number] => {
      const { ox, oy, turn } = this.placement[k];
      const c = Math.cos(turn);
      const s = Math.sin(turn);
      const dx = p.x - ox;
      const dy = p.y - oy;
      return [(c * dx + s * dy) * S, (-s * dx + c * dy) * S];
    };
    for (const j of resolveSceneJoints(scene, 'p2-es')) {
      const a = this.bodies[j.bodyA];
      const b = this.bodies[j.bodyB];
      if (j.kind === 'revolute') {
        if (j.hertz > 0) throw no(j.index, 'a revolute spring (not built for p2)');
        const joint = new p2.RevoluteConstraint(a, b, { localPivotA: local(j.bodyA, j.anchorA), localPivotB: local(j.bodyB, j.anchorB), collideConnected: j.collideConnected });
        if (j.limits) {
          // p2's angle is B's less A's with no reference angle, and its bodies are turned with their shape.
          const shift = j.referenceAngle + this.placement[j.bodyB].turn - this.placement[j.bodyA].turn;
          joint.setLimits(Math.max(j.limits.lower, -1e9) + shift, Math.min(j.limits.upper, 1e9) + shift);
        }
        if (j.motor) {
          joint.motorEnabled = true;
          // p2's motor drives A's spin less B's to its speed: the opposite sign.
          joint.motorSpeed = -j.motor.speed;
          // Masses scale with area (S^2), so torques with S^4.
          joint.motorMaxForce = j.motor.maxTorque * S ** 4;
        }
        this.world.addConstraint(joint);
      } else if (j.kind === 'distance') {
        if (j.minLength !== j.length || j.maxLength !== j.length) throw no(j.index, 'a distance joint that is not rigid (not built for p2)');
        this.world.addConstraint(new p2.DistanceConstraint(a, b, { localAnchorA: local(j.bodyA, j.anchorA), localAnchorB: local(j.bodyB, j.anchorB), distance: j.length * S, collideConnected: j.collideConnected }));
      } else {
        throw no(j.index, `a ${j.kind} joint (not built for p2)`);
      }
    }
  }

  private addShape(body: P2Body, scene: ShapeScene, shape: SceneShape): void {
    const { p2, S } = this;
    void materialOf(scene, shape);
    const offset: [number, number] = [(shape.offsetX ?? 0) * S, (shape.offsetY ?? 0) * S];
    const angle = ('offsetAngle' in shape ? (shape.offsetAngle ?? 0) : 0);
    if (shape.kind === 'circle') body.addShape(new p2.Circle({ radius: shape.radius * S }), offset, angle);
    else if (shape.kind === 'capsule') body.addShape(new p2.Capsule({ length: shape.length * S, radius: shape.radius * S }), offset, angle);
    else if (shape.kind === 'box') body.addShape(new p2.Box({ width: shape.width * S, height: shape.height * S }), offset, angle);
    else body.addShape(new p2.Convex({ vertices: placedVertices(shape).map((v) => [v.x * S, v.y * S]) }));
  }

  step(dt: number): void {
    this.world.step(dt);
  }

  read(out: PoseState): void {
    const S = this.S;
    for (let k = 0; k < this.count; k++) {
      const b = this.bodies[k];
      const { ox, oy, turn } = this.placement[k];
      const angle = b.angle - turn;
      const c = Math.cos(angle);
      const s = Math.sin(angle);
      out.x[k] = b.position[0] / S - (c * ox - s * oy);
      out.y[k] = b.position[1] / S - (s * ox + c * oy);
      out.angle[k] = angle;
      out.vx[k] = b.velocity[0] / S;
      out.vy[k] = b.velocity[1] / S;
      out.angularVelocity[k] = b.angularVelocity;
    }
  }

  dispose(): void {
    this.world.clear();
  }
}

export const p2ShapeProvider: ShapeEngineProvider = {
  id: 'p2-es',
  async load(): Promise<ShapeEngine> {
    const p2 = await loadP2();
    const common = {
      solver: 'GSSolver',
      sleepMode: 'NO_SLEEPING',
      islandSplit: false,
      ccd: 'none (the default)',
      materials: "one default ContactMaterial with the scene's friction and restitution",
      damping: 0,
      segments: `a Capsule of the segment's thickness; of thickness 0, a Box ${SLAB_DEPTH_M} m deep hung below the line on gravity's side (p2-es's Line collides with circles and planes only)`,
      units: '1 m = the scene lengthUnit; vec2 are Float32Array',
    };
    return {
      info: {
        id: 'p2-es',
        package: 'p2-es',
        version: VERSIONS['p2-es'],
        precision: 'f32',
        settings: { report: { 'solver.iterations': ITERATIONS.report, ...common }, defaults: { 'solver.iterations': ITERATIONS.defaults, ...common } },
      },
      create: (scene, profile) => new P2Shapes(p2, scene, profile),
    };
  },
};
