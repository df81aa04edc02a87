import type { Scene } from '@maxgrid/scenes';
import { boxWalls, METERS_PER_PIXEL, type BodyState, type Engine, type EngineProvider, type LoadOptions, type Simulation, requirePeerScene } from './adapter.js';
import { VERSIONS } from './versions.js';

type Box2DModule = typeof Box2D & EmscriptenModule;

const S = METERS_PER_PIXEL;
const VELOCITY_ITERATIONS = 1;
const POSITION_ITERATIONS = 1;

class Box2DSimulation implements Simulation {
  readonly count: number;
  private readonly world: Box2D.b2World;
  private readonly bodies: Box2D.b2Body[] = [];

  constructor(private readonly b2: Box2DModule, scene: Scene) {
    requirePeerScene(scene, 'box2d-wasm');
    this.count = scene.count;
    const vec = new b2.b2Vec2(scene.gravity.x * S, scene.gravity.y * S);
    this.world = new b2.b2World(vec);
    this.world.SetAllowSleeping(false);
    this.world.SetContinuousPhysics(false);
    this.world.SetSubStepping(false);
    this.world.SetWarmStarting(true);

    const fixture = new b2.b2FixtureDef();
    fixture.set_density(1);
    fixture.set_friction(0);
    fixture.set_restitution(scene.restitution);
    // Box2D 2.4 treats slower impacts as inelastic; 0 is the lowest threshold (Unity's minimum).
    fixture.set_restitutionThreshold(0);

    const wallDef = new b2.b2BodyDef();
    wallDef.set_type(b2.b2_staticBody);
    const box = new b2.b2PolygonShape();
    for (const w of boxWalls(scene.bounds)) {
      vec.Set(w.cx * S, w.cy * S);
      wallDef.set_position(vec);
      const body = this.world.CreateBody(wallDef);
      box.SetAsBox((w.width / 2) * S, (w.height / 2) * S);
      fixture.set_shape(box);
      body.CreateFixture(fixture);
    }

    const def = new b2.b2BodyDef();
    def.set_type(b2.b2_dynamicBody);
    def.set_allowSleep(false);
    def.set_bullet(false);
    // maxgrid circles do not rotate; with zero friction no torque arises, so this changes nothing.
    def.set_fixedRotation(true);
    const circle = new b2.b2CircleShape();
    fixture.set_shape(circle);
    for (let k = 0; k < scene.count; k++) {
      vec.Set(scene.x[k] * S, scene.y[k] * S);
      def.set_position(vec);
      vec.Set(scene.vx[k] * S, scene.vy[k] * S);
      def.set_linearVelocity(vec);
      const body = this.world.CreateBody(def);
      circle.set_m_radius(scene.radius[k] * S);
      body.CreateFixture(fixture);
      this.bodies.push(body);
    }
    for (const o of [vec, fixture, wallDef, box, def, circle]) b2.destroy(o);
  }

  step(dt: number): void {
    this.world.Step(dt, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
  }

  read(out: BodyState): void {
    for (let k = 0; k < this.count; k++) {
      const body = this.bodies[k];
      const p = body.GetPosition();
      const v = body.GetLinearVelocity();
      out.x[k] = p.get_x() / S;
      out.y[k] = p.get_y() / S;
      out.vx[k] = v.get_x() / S;
      out.vy[k] = v.get_y() / S;
    }
  }

  readRadii(out: Float64Array): void {
    for (let k = 0; k < this.count; k++) out[k] = this.bodies[k].GetFixtureList().GetShape().get_m_radius() / S;
  }

  dispose(): void {
    this.b2.destroy(this.world);
  }
}

/** The test box2d-wasm's entry uses to choose its SIMD build (from wasm-feature-detect). */
export function box2dUsesSimd(): boolean {
  return WebAssembly.validate(new Uint8Array([0, 97, 115, 109, 1, 0, 0, 0, 1, 5, 1, 96, 0, 1, 123, 3, 2, 1, 0, 10, 10, 1, 8, 0, 65, 0, 253, 15, 253, 98, 11]));
}

let modulePromise: Promise<Box2DModule> | undefined;

async function loadBox2D(options: LoadOptions): Promise<Box2DModule> {
  modulePromise ??= import('box2d-wasm').then((m) => {
    const factory = (m as unknown as { default: (o?: object) => Promise<Box2DModule> }).default;
    const moduleOptions: Record<string, unknown> = {};
    if (options.box2dLocateFile) moduleOptions.locateFile = options.box2dLocateFile;
    if (options.box2dWasmBinary) moduleOptions.wasmBinary = options.box2dWasmBinary;
    return factory(moduleOptions);
  });
  return modulePromise;
}

export const box2dProvider: EngineProvider = {
  id: 'box2d-wasm',
  async load(options: LoadOptions = {}): Promise<Engine> {
    const b2 = await loadBox2D(options);
    return {
      info: {
        id: 'box2d-wasm',
        package: 'box2d-wasm',
        version: VERSIONS['box2d-wasm'],
        precision: 'f32',
        lengthScale: S,
        settings: {
          core: 'Box2D 2.4 compiled to WebAssembly (SIMD build where the runtime validates it)',
          velocityIterations: VELOCITY_ITERATIONS,
          positionIterations: POSITION_ITERATIONS,
          allowSleeping: false,
          continuousPhysics: false,
          bullet: false,
          subStepping: false,
          warmStarting: true,
          restitution: 'scene restitution (1)',
          restitutionThreshold: 0,
          friction: 0,
          density: 1,
          fixedRotation: true,
          walls: '4 static b2PolygonShape boxes, thickness max(w,h)/4',
          units: '1 m = 50 px',
        },
      },
      create: (scene) => new Box2DSimulation(b2, scene),
    };
  },
};
