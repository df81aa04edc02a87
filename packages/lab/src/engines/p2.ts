import type { Scene } from '@maxgrid/scenes';
import { boxWalls, METERS_PER_PIXEL, type BodyState, type Engine, type EngineProvider, type Simulation, requirePeerScene } from './adapter.js';
import { VERSIONS } from './versions.js';

import { loadP2, type P2Api as P2, type P2Body, type P2World } from './p2-loader.js';

const S = METERS_PER_PIXEL;
// p2 has one Gauss-Seidel solver pass count (no separate position pass): 1 is the nearest match.
const SOLVER_ITERATIONS = 1;

class P2Simulation implements Simulation {
  readonly count: number;
  private readonly world: P2World;
  private readonly bodies: P2Body[] = [];

  constructor(p2: P2, scene: Scene) {
    requirePeerScene(scene, 'p2-es');
    this.count = scene.count;
    const solver = new p2.GSSolver({ iterations: SOLVER_ITERATIONS });
    this.world = new p2.World({ gravity: [scene.gravity.x * S, scene.gravity.y * S], solver, islandSplit: false });
    this.world.sleepMode = p2.World.NO_SLEEPING;
    const contact = this.world.defaultContactMaterial;
    contact.restitution = scene.restitution;
    contact.friction = 0;
    for (const w of boxWalls(scene.bounds)) {
      const wall = new p2.Body({ mass: 0, type: p2.Body.STATIC, position: [w.cx * S, w.cy * S] });
      wall.addShape(new p2.Box({ width: w.width * S, height: w.height * S }));
      this.world.addBody(wall);
    }
    for (let k = 0; k < scene.count; k++) {
      const r = scene.radius[k] * S;
      const body = new p2.Body({
        mass: Math.PI * r * r,
        position: [scene.x[k] * S, scene.y[k] * S],
        velocity: [scene.vx[k] * S, scene.vy[k] * S],
        fixedRotation: true,
        // p2's default linear damping is 0.1 per second; the report's engines have none.
        damping: 0,
        angularDamping: 0,
        allowSleep: false,
      });
      body.addShape(new p2.Circle({ radius: r }));
      this.world.addBody(body);
      this.bodies.push(body);
    }
  }

  step(dt: number): void {
    this.world.step(dt);
  }

  read(out: BodyState): void {
    for (let k = 0; k < this.count; k++) {
      const b = this.bodies[k];
      out.x[k] = b.position[0] / S;
      out.y[k] = b.position[1] / S;
      out.vx[k] = b.velocity[0] / S;
      out.vy[k] = b.velocity[1] / S;
    }
  }

  readRadii(out: Float64Array): void {
    for (let k = 0; k < this.count; k++) out[k] = (this.bodies[k].shapes[0] as { radius?: number }).radius! / S;
  }

  dispose(): void {
    this.world.clear();
  }
}

export const p2Provider: EngineProvider = {
  id: 'p2-es',
  async load(): Promise<Engine> {
    const p2 = await loadP2();
    return {
      info: {
        id: 'p2-es',
        package: 'p2-es',
        version: VERSIONS['p2-es'],
        precision: 'f32',
        lengthScale: S,
        settings: {
          solver: 'GSSolver',
          'solver.iterations': SOLVER_ITERATIONS,
          broadphase: 'SAPBroadphase (default)',
          sleepMode: 'NO_SLEEPING',
          islandSplit: false,
          ccd: 'none (ccdSpeedThreshold -1, the default)',
          restitution: 'scene restitution (1) via defaultContactMaterial',
          restitutionThreshold: 'none (p2 has no such setting)',
          friction: 0,
          damping: 0,
          fixedRotation: true,
          contactStiffness: 'default (1e6, relaxation 4)',
          walls: '4 static Box shapes, thickness max(w,h)/4',
          units: '1 m = 50 px; vec2 are Float32Array',
        },
      },
      create: (scene) => new P2Simulation(p2, scene),
    };
  },
};
