import { BROADPHASE_NAMES, type BroadPhaseName, type World } from '@maxgrid/engine';
import { buildWorld, type BuildOptions, type Scene } from '@maxgrid/scenes';
import type { BodyState, Engine, EngineProvider, Simulation } from './adapter.js';
import { VERSIONS } from './versions.js';

class MaxgridSimulation implements Simulation {
  readonly count: number;

  constructor(private readonly world: World) {
    this.count = world.bodyCount;
    // buildWorld gives circle k handle k in slot k; read() relies on that, so check it once.
    for (const k of [0, this.count - 1]) {
      if (this.count > 0 && world.handleAtSlot(k) !== k) throw new Error(`maxgrid: scene body ${k} is not in slot ${k}`);
    }
  }

  step(dt: number): void {
    this.world.step(dt);
  }

  read(out: BodyState): void {
    const v = this.world.views();
    out.x.set(v.x.subarray(0, this.count));
    out.y.set(v.y.subarray(0, this.count));
    out.vx.set(v.vx.subarray(0, this.count));
    out.vy.set(v.vy.subarray(0, this.count));
  }

  readRadii(out: Float64Array): void {
    out.set(this.world.views().radius.subarray(0, this.count));
  }

  pairStats(): { pairTests: number; candidatePairs: number; contacts: number } {
    const s = this.world.stats;
    return { pairTests: s.pairTests, candidatePairs: s.candidatePairs, contacts: s.contacts };
  }

  phaseMs(): { broadphaseMs: number; narrowphaseMs: number } {
    const s = this.world.stats;
    return { broadphaseMs: s.broadphaseMs, narrowphaseMs: s.narrowphaseMs };
  }

  memoryBytes(): number {
    return this.world.memoryBytes();
  }

  stateHash(): string {
    return this.world.stateHash();
  }

  dispose(): void {}
}

/**
 * The lab's maxgrid settings, shared by the adapter, the C comparison and the browser page so
 * that all three step the same world: the report's Unity configuration (no sleeping, discrete).
 */
export function maxgridBuildOptions(broadphase: BroadPhaseName): BuildOptions {
  return { broadphase, sleeping: false, continuous: false, restitutionThreshold: 0 };
}

/**
 * The iterated solve for piles (docs/engine.md, "Piles"), on the Max Grid: the sandbox's Pile
 * solver toggle. Its id has no `maxgrid:` prefix, so the experiments that sweep broad-phases leave it out.
 */
export const MAXGRID_PILES_OPTIONS = { solverIterations: 4, positionCorrection: 0.2, contactSlop: 0.05 } as const;

/** maxgrid with one broad-phase; everything else at the engine's defaults, or `variant`'s. */
export function maxgridProvider(broadphase: BroadPhaseName, variant?: { id: string; options: BuildOptions; solver: string }): EngineProvider {
  const id = variant?.id ?? `maxgrid:${broadphase}`;
  return {
    id,
    async load(): Promise<Engine> {
      return {
        info: {
          id,
          package: '@maxgrid/engine',
          version: VERSIONS.maxgrid,
          precision: 'f64',
          lengthScale: 1,
          settings: {
            broadphase,
            integrator: 'semi-implicit-euler (engine default)',
            iterations: variant?.solver ?? 'one sequential impulse pass per contact in canonical order',
            restitution: 'scene restitution (1), walls included',
            friction: 'none (circle worlds have none; friction acts on the shape route)',
            sleeping: false,
            continuous: 'false (discrete, as the report configured Unity)',
            restitutionThreshold: 0,
            walls: 'built-in box bounds',
          },
        },
        create: (scene: Scene) => new MaxgridSimulation(buildWorld(scene, { ...maxgridBuildOptions(broadphase), ...variant?.options })),
      };
    },
  };
}

export const MAXGRID_PROVIDERS: EngineProvider[] = BROADPHASE_NAMES.map((name) => maxgridProvider(name));

export const maxgridPilesProvider: EngineProvider = maxgridProvider('maxgrid', {
  id: 'maxgrid-piles',
  options: MAXGRID_PILES_OPTIONS,
  solver: 'solverIterations 4 (sequential impulses, warm-started, walls as contacts), positionCorrection 0.2, contactSlop 0.05',
});
