import type { Scene } from '@maxgrid/scenes';
import { boxWalls, METERS_PER_PIXEL, type BodyState, type Engine, type EngineProvider, type Simulation, requirePeerScene } from './adapter.js';
import { VERSIONS } from './versions.js';

type Planck = typeof import('planck');
type PlanckBody = ReturnType<InstanceType<Planck['World']>['createBody']>;

const S = METERS_PER_PIXEL;
const VELOCITY_ITERATIONS = 1;
const POSITION_ITERATIONS = 1;

class PlanckSimulation implements Simulation {
  readonly count: number;
  private readonly world: InstanceType<Planck['World']>;
  private readonly bodies: PlanckBody[] = [];

  constructor(private readonly pl: Planck, scene: Scene) {
    requirePeerScene(scene, 'planck');
    this.count = scene.count;
    this.world = new pl.World({
      gravity: { x: scene.gravity.x * S, y: scene.gravity.y * S },
      allowSleep: false,
      continuousPhysics: false,
      subStepping: false,
      warmStarting: true,
    });
    const material = { density: 1, friction: 0, restitution: scene.restitution };
    for (const w of boxWalls(scene.bounds)) {
      const wall = this.world.createBody({ type: 'static', position: { x: w.cx * S, y: w.cy * S } });
      wall.createFixture({ shape: new pl.Box((w.width / 2) * S, (w.height / 2) * S), ...material });
    }
    for (let k = 0; k < scene.count; k++) {
      const body = this.world.createBody({
        type: 'dynamic',
        position: { x: scene.x[k] * S, y: scene.y[k] * S },
        linearVelocity: { x: scene.vx[k] * S, y: scene.vy[k] * S },
        allowSleep: false,
        bullet: false,
        fixedRotation: true,
      });
      body.createFixture({ shape: new pl.Circle(scene.radius[k] * S), ...material });
      this.bodies.push(body);
    }
  }

  step(dt: number): void {
    // Process-wide in planck, and the shape adapter sets its own: set before each step.
    this.pl.Settings.velocityThreshold = 0;
    this.world.step(dt, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
  }

  read(out: BodyState): void {
    for (let k = 0; k < this.count; k++) {
      const p = this.bodies[k].getPosition();
      const v = this.bodies[k].getLinearVelocity();
      out.x[k] = p.x / S;
      out.y[k] = p.y / S;
      out.vx[k] = v.x / S;
      out.vy[k] = v.y / S;
    }
  }

  readRadii(out: Float64Array): void {
    for (let k = 0; k < this.count; k++) out[k] = this.bodies[k].getFixtureList()!.getShape().getRadius() / S;
  }

  dispose(): void {}
}

export const planckProvider: EngineProvider = {
  id: 'planck',
  async load(): Promise<Engine> {
    const pl = await import('planck');
    // A process-wide static in planck: impacts slower than this bounce inelastically. 0 is the
    // lowest, as the report set Unity's velocity threshold to its minimum.
    pl.Settings.velocityThreshold = 0;
    return {
      info: {
        id: 'planck',
        package: 'planck',
        version: VERSIONS.planck,
        precision: 'f64',
        lengthScale: S,
        settings: {
          core: 'Box2D 2.x ported to JavaScript',
          velocityIterations: VELOCITY_ITERATIONS,
          positionIterations: POSITION_ITERATIONS,
          allowSleep: false,
          continuousPhysics: false,
          bullet: false,
          subStepping: false,
          warmStarting: true,
          restitution: 'scene restitution (1)',
          velocityThreshold: 0,
          friction: 0,
          density: 1,
          fixedRotation: true,
          walls: '4 static Box fixtures, thickness max(w,h)/4',
          units: '1 m = 50 px',
        },
      },
      create: (scene) => new PlanckSimulation(pl, scene),
    };
  },
};
