import type { Scene } from '@maxgrid/scenes';
import type * as MatterTypes from 'matter-js';
import { boxWalls, type BodyState, type Engine, type EngineProvider, type Simulation, requirePeerScene } from './adapter.js';
import { VERSIONS } from './versions.js';

type Matter = typeof MatterTypes;

const ITERATIONS = 1;
// Matter steps in milliseconds and keeps velocities as pixels per 1000/60 ms ("base delta").
const BASE_DELTA_MS = 1000 / 60;
// Matter's acceleration is gravity * gravity.scale in px/ms^2; scene gravity is px/s^2.
const GRAVITY_SCALE = 1e-6;

class MatterSimulation implements Simulation {
  readonly count: number;
  private readonly engine: MatterTypes.Engine;
  private readonly bodies: MatterTypes.Body[] = [];

  constructor(private readonly M: Matter, scene: Scene) {
    requirePeerScene(scene, 'matter-js');
    this.count = scene.count;
    this.engine = M.Engine.create({
      gravity: { x: scene.gravity.x, y: scene.gravity.y, scale: GRAVITY_SCALE },
      enableSleeping: false,
      positionIterations: ITERATIONS,
      velocityIterations: ITERATIONS,
      constraintIterations: ITERATIONS,
    });
    const material = { restitution: scene.restitution, friction: 0, frictionStatic: 0, frictionAir: 0 };
    const all: MatterTypes.Body[] = [];
    for (const w of boxWalls(scene.bounds)) {
      all.push(M.Bodies.rectangle(w.cx, w.cy, w.width, w.height, { isStatic: true, ...material }));
    }
    for (let k = 0; k < scene.count; k++) {
      // Infinite inertia: maxgrid circles do not rotate, and Matter's polygon "circles" could
      // otherwise pick up spin from off-centre polygon contacts.
      const body = M.Bodies.circle(scene.x[k], scene.y[k], scene.radius[k], { ...material, inertia: Infinity });
      M.Body.setVelocity(body, { x: (scene.vx[k] * BASE_DELTA_MS) / 1000, y: (scene.vy[k] * BASE_DELTA_MS) / 1000 });
      this.bodies.push(body);
      all.push(body);
    }
    M.Composite.add(this.engine.world, all);
  }

  step(dt: number): void {
    // Module-wide in Matter, and the shape adapter sets its own: set before each step.
    (this.M.Resolver as unknown as { _restingThresh: number })._restingThresh = 0;
    this.M.Engine.update(this.engine, dt * 1000);
  }

  read(out: BodyState): void {
    // Engine.update ends with Body.updateVelocities, so velocity is px per base delta.
    const toPerSecond = 1000 / BASE_DELTA_MS;
    for (let k = 0; k < this.count; k++) {
      const b = this.bodies[k];
      out.x[k] = b.position.x;
      out.y[k] = b.position.y;
      out.vx[k] = b.velocity.x * toPerSecond;
      out.vy[k] = b.velocity.y * toPerSecond;
    }
  }

  readRadii(out: Float64Array): void {
    for (let k = 0; k < this.count; k++) out[k] = this.bodies[k].circleRadius ?? NaN;
  }

  dispose(): void {
    this.M.Engine.clear(this.engine);
  }
}

export const matterProvider: EngineProvider = {
  id: 'matter-js',
  async load(): Promise<Engine> {
    const M = ((await import('matter-js')) as unknown as { default: Matter }).default;
    // Module-wide in Matter: contacts approaching slower than this (px per base delta) get no
    // restitution. 0 is the lowest, as the report set Unity's velocity threshold to its minimum.
    (M.Resolver as unknown as { _restingThresh: number })._restingThresh = 0;
    return {
      info: {
        id: 'matter-js',
        package: 'matter-js',
        version: VERSIONS['matter-js'],
        precision: 'f64',
        lengthScale: 1,
        settings: {
          positionIterations: ITERATIONS,
          velocityIterations: ITERATIONS,
          constraintIterations: ITERATIONS,
          enableSleeping: false,
          ccd: 'none (Matter has no CCD)',
          restitution: 'scene restitution (1)',
          'Resolver._restingThresh': 0,
          friction: 0,
          frictionStatic: 0,
          frictionAir: 0,
          inertia: 'Infinity',
          shapes: 'Bodies.circle: regular polygons of 10 to 26 sides',
          walls: '4 static rectangles, thickness max(w,h)/4',
          units: 'pixels; gravity.scale 1e-6 so gravity is px/s^2; Engine.update(dt * 1000 ms)',
        },
      },
      create: (scene) => new MatterSimulation(M, scene),
    };
  },
};
