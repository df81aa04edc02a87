import { type BroadPhaseName, type World } from '@maxgrid/engine';
import { buildShapeWorld, type ShapeScene } from '@maxgrid/scenes';
import type { PoseState, ShapeEngine, ShapeEngineProvider, ShapeProfile, ShapeSimulation, StageTimes } from './adapter.js';
import { VERSIONS } from '../engines/versions.js';

class MaxgridShapes implements ShapeSimulation {
  readonly count: number;

  constructor(private readonly world: World) {
    this.count = world.bodyCount;
  }

  step(dt: number): void {
    this.world.step(dt);
  }

  read(out: PoseState): void {
    // buildShapeWorld gives scene body k handle k.
    for (let k = 0; k < this.count; k++) {
      const b = this.world.getBody(k);
      out.x[k] = b.x;
      out.y[k] = b.y;
      out.angle[k] = b.angle;
      out.vx[k] = b.vx;
      out.vy[k] = b.vy;
      out.angularVelocity[k] = b.angularVelocity;
    }
  }

  stages(): StageTimes {
    const s = this.world.stats;
    return {
      broadphaseMs: s.broadphaseMs,
      narrowphaseMs: s.narrowphaseMs,
      solveMs: s.solveMs,
      pairTests: s.pairTests,
      candidatePairs: s.candidatePairs,
      contacts: s.contacts,
    };
  }

  stateHash(): string {
    return this.world.stateHash();
  }

  dispose(): void {}
}

/** maxgrid on a shape scene with one broad-phase: the scene's own world options (solver, sub-steps), sleeping off. */
export function maxgridShapeProvider(broadphase: BroadPhaseName): ShapeEngineProvider {
  const id = `maxgrid:${broadphase}`;
  const settings = {
    broadphase,
    solver: "the scene's ('soft': Box2D v3's soft step, 4 sub-steps; 'elastic': the report's single pass)",
    sleeping: false,
    continuous: true,
    precision: 'f64',
  };
  return {
    id,
    async load(): Promise<ShapeEngine> {
      return {
        info: { id, package: '@maxgrid/engine', version: VERSIONS.maxgrid, precision: 'f64', settings: { report: settings, defaults: settings } },
        create: (scene: ShapeScene, _profile: ShapeProfile) => {
          // The scene's world options win over the caller's, and a scene may ask for sleeping
          // (ragdolls): the peers run awake, so maxgrid does too.
          const world = buildShapeWorld({ ...scene, world: { ...scene.world, sleeping: false } }, { broadphase, sleeping: false });
          return new MaxgridShapes(world);
        },
      };
    },
  };
}
