import type { Scene } from '@maxgrid/scenes';
import { boxWalls, METERS_PER_PIXEL, type BodyState, type Engine, type EngineProvider, type Simulation, requirePeerScene } from './adapter.js';
import { VERSIONS } from './versions.js';

type Rapier = typeof import('@dimforge/rapier2d-simd-compat').default;
type RapierWorld = InstanceType<Rapier['World']>;
type RapierBody = ReturnType<RapierWorld['createRigidBody']>;

const S = METERS_PER_PIXEL;
// Rapier's nearest equivalent of Unity's 1 velocity + 1 position iteration: one solver
// iteration with one internal PGS pass (its defaults are 4 and 1).
const SOLVER_ITERATIONS = 1;
const INTERNAL_PGS_ITERATIONS = 1;

class RapierSimulation implements Simulation {
  readonly count: number;
  private readonly world: RapierWorld;
  private readonly bodies: RapierBody[] = [];

  constructor(R: Rapier, scene: Scene) {
    requirePeerScene(scene, 'rapier');
    this.count = scene.count;
    this.world = new R.World({ x: scene.gravity.x * S, y: scene.gravity.y * S });
    const params = this.world.integrationParameters;
    params.numSolverIterations = SOLVER_ITERATIONS;
    params.numInternalPgsIterations = INTERNAL_PGS_ITERATIONS;
    const walls = this.world.createRigidBody(R.RigidBodyDesc.fixed());
    for (const w of boxWalls(scene.bounds)) {
      const desc = R.ColliderDesc.cuboid((w.width / 2) * S, (w.height / 2) * S)
        .setTranslation(w.cx * S, w.cy * S)
        .setRestitution(scene.restitution)
        .setFriction(0);
      this.world.createCollider(desc, walls);
    }
    for (let k = 0; k < scene.count; k++) {
      const body = this.world.createRigidBody(
        R.RigidBodyDesc.dynamic()
          .setTranslation(scene.x[k] * S, scene.y[k] * S)
          .setLinvel(scene.vx[k] * S, scene.vy[k] * S)
          .setCanSleep(false)
          .setCcdEnabled(false)
          .lockRotations(),
      );
      const collider = R.ColliderDesc.ball(scene.radius[k] * S)
        .setDensity(1)
        .setRestitution(scene.restitution)
        .setFriction(0);
      this.world.createCollider(collider, body);
      this.bodies.push(body);
    }
  }

  step(dt: number): void {
    this.world.timestep = dt;
    this.world.step();
  }

  read(out: BodyState): void {
    for (let k = 0; k < this.count; k++) {
      const p = this.bodies[k].translation();
      const v = this.bodies[k].linvel();
      out.x[k] = p.x / S;
      out.y[k] = p.y / S;
      out.vx[k] = v.x / S;
      out.vy[k] = v.y / S;
    }
  }

  readRadii(out: Float64Array): void {
    for (let k = 0; k < this.count; k++) out[k] = this.bodies[k].collider(0).radius() / S;
  }

  dispose(): void {
    this.world.free();
  }
}

let rapierPromise: Promise<Rapier> | undefined;

export const rapierProvider: EngineProvider = {
  id: 'rapier',
  async load(): Promise<Engine> {
    // The -compat build inlines its WASM as base64, so the same code loads in Node and browsers.
    rapierPromise ??= import('@dimforge/rapier2d-simd-compat').then(async (m) => {
      await m.default.init();
      return m.default;
    });
    const R = await rapierPromise;
    return {
      info: {
        id: 'rapier',
        package: '@dimforge/rapier2d-simd-compat',
        version: VERSIONS['@dimforge/rapier2d-simd-compat'],
        precision: 'f32',
        lengthScale: S,
        settings: {
          numSolverIterations: SOLVER_ITERATIONS,
          numInternalPgsIterations: INTERNAL_PGS_ITERATIONS,
          canSleep: false,
          ccdEnabled: false,
          softCcdPrediction: 0,
          restitution: 'scene restitution (1), combine rule default (average)',
          restitutionThreshold: 'none (Rapier has no such setting)',
          friction: 0,
          density: 1,
          lockRotations: true,
          walls: '4 cuboid colliders on one fixed body, thickness max(w,h)/4',
          units: '1 m = 50 px, lengthUnit 1',
        },
      },
      create: (scene) => new RapierSimulation(R, scene),
    };
  },
};
