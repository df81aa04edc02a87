import { SCENES } from '@maxgrid/scenes';
import { ENGINE_IDS } from '../engines/registry.js';
import type { ChartSpec } from '../report/charts.js';
import { energyTables, falsePositiveTables, scaleTables, stepTimeTables, type Table } from '../report/tables.js';
import { cMaxgridHeadline, cMaxgridTables, sapSleepHeadline, sapSleepTables, targetsHeadline, targetsTables } from '../report/tables-targets.js';
import { energyHeadline, falsePositiveHeadline, scaleHeadline, stepTimeHeadline } from '../report/headlines.js';
import type { Profile, RunContext } from './common.js';
import { energyCharts, energyCsv, energyDefaults, energySchema, runEnergy, type EnergyOptions, type EnergyResult } from './energy.js';
import {
  falsePositiveCharts,
  falsePositiveCsv,
  falsePositiveDefaults,
  falsePositiveSchema,
  runFalsePositives,
  type FalsePositiveOptions,
  type FalsePositiveResult,
} from './false-positives.js';
import { cMaxgridCharts, cMaxgridCsv, cMaxgridDefaults, cMaxgridSchema, runCMaxgrid, type CMaxgridOptions, type CMaxgridResult } from './c-maxgrid.js';
import {
  runSandboxRender,
  sandboxRenderCsv,
  sandboxRenderDefaults,
  sandboxRenderHeadline,
  sandboxRenderSchema,
  sandboxRenderTables,
  type SandboxRenderOptions,
  type SandboxRenderResult,
} from './sandbox-render.js';
import { runSapSleep, sapSleepCharts, sapSleepCsv, sapSleepDefaults, sapSleepSchema, type SapSleepOptions, type SapSleepResult } from './sap-sleep.js';
import { pilesCsv, pilesDefaults, pilesHeadline, pilesSchema, pilesTables, runPiles, type PilesOptions, type PilesResult } from './piles.js';
import { runThreads, threadsCsv, threadsDefaults, threadsHeadline, threadsSchema, threadsTables, type ThreadsOptions, type ThreadsResult } from './threads.js';
import { runTargets, targetsDefaults, targetsSchema, type TargetsOptions, type TargetsResult } from './targets.js';
import { targetsCsv } from './targets-csv.js';
import { runScale, scaleCharts, scaleCsv, scaleDefaults, scaleSchema, type ScaleOptions, type ScaleResult } from './scale.js';
import { runStepTime, stepTimeCharts, stepTimeCsv, stepTimeDefaults, stepTimeSchema, type StepTimeOptions, type StepTimeResult } from './step-time.js';

import {
  runShapeStepTime,
  shapeStepTimeCharts,
  shapeStepTimeCsv,
  shapeStepTimeDefaults,
  shapeStepTimeHeadline,
  shapeStepTimeSchema,
  shapeStepTimeTables,
  type ShapeStepTimeOptions,
  type ShapeStepTimeResult,
} from './shape-step-time.js';
import { runStability, stabilityCsv, stabilityDefaults, stabilityHeadline, stabilitySchema, stabilityTables, type StabilityOptions, type StabilityResult } from './stability.js';
import { runShapeEnergy, shapeEnergyCharts, shapeEnergyCsv, shapeEnergyDefaults, shapeEnergyHeadline, shapeEnergySchema, shapeEnergyTables, type ShapeEnergyOptions, type ShapeEnergyResult } from './shape-energy.js';
import {
  runShapeFalsePositives,
  shapeFalsePositiveCsv,
  shapeFalsePositiveDefaults,
  shapeFalsePositiveHeadline,
  shapeFalsePositiveSchema,
  shapeFalsePositiveTables,
  type ShapeFalsePositiveOptions,
  type ShapeFalsePositiveResult,
} from './shape-false-positives.js';
import { SHAPE_ENGINE_IDS } from '../shape-engines/registry.js';
import { runThreadsLoad, threadsLoadCsv, threadsLoadDefaults, threadsLoadHeadline, threadsLoadSchema, threadsLoadTables, type ThreadsLoadOptions, type ThreadsLoadResult } from './threads-load.js';
import { joints } from './joints.js';
import { integrators } from './integrators.js';
import { cliffsCsv, cliffsDefaults, cliffsHeadline, cliffsSchema, cliffsTables, runCliffs, type CliffsOptions, type CliffsResult } from './cliffs.js';

/** Command-line style overrides; each experiment takes the ones that mean something to it. */
export interface Overrides {
  ns?: number[];
  runs?: number;
  seconds?: number;
  scenes?: string[];
  dt?: number;
}

export interface Experiment<O extends object, R> {
  name: string;
  description: string;
  schema: object;
  defaultEngines: string[];
  /** Needs Node (a C compiler, a headless Chromium), or runs too long for the browser lab page, which leaves it out. */
  nodeOnly?: boolean;
  /** Measures its default engines whatever --engines says: the option is refused. */
  fixedEngines?: boolean;
  /** Runs shape scenes: its engine ids name shape engines (src/shape-engines), loaded into RunContext.shapeEngines. */
  shapes?: boolean;
  options(profile: Profile, overrides: Overrides): O;
  run(options: O, ctx: RunContext): Promise<R>;
  csv(result: R): string;
  charts(result: R): ChartSpec[];
  /** Tables for the markdown and the HTML report alike. */
  tables(result: R): Table[];
  /** The sentences that open its section of docs/results.md. */
  headline(result: R): string[];
}

/** The command-line option behind each override. */
export const OVERRIDE_FLAGS: Record<keyof Overrides, string> = { ns: '--n', runs: '--runs', seconds: '--seconds', scenes: '--scene', dt: '--dt' };

function reject(experiment: string, overrides: Overrides, allowed: (keyof Overrides)[]): void {
  const flags = OVERRIDE_FLAGS;
  for (const key of Object.keys(overrides) as (keyof Overrides)[]) {
    if (overrides[key] !== undefined && !allowed.includes(key)) {
      throw new RangeError(`option ${flags[key]} does not apply to experiment '${experiment}' (it takes ${allowed.map((k) => flags[k]).join(', ')})`);
    }
  }
}

const MAXGRID_IDS = ENGINE_IDS.filter((id) => id.startsWith('maxgrid:'));

/** The sandbox page's largest circle count (QUANTITY_MAX in apps/sandbox/src/scene-specs.ts): it clamps larger ones. */
const SANDBOX_MAX_N = 200_000;

export const stepTime: Experiment<StepTimeOptions, StepTimeResult> = {
  name: 'step-time',
  description: 'Step time vs N per engine, scenes seed-box and uniform (report 5.13.2, 6.2)',
  schema: stepTimeSchema,
  defaultEngines: ENGINE_IDS,
  options(profile, o) {
    reject('step-time', o, ['ns', 'runs', 'seconds', 'scenes', 'dt']);
    for (const scene of o.scenes ?? []) {
      const params = SCENES[scene as keyof typeof SCENES]?.params as Record<string, unknown> | undefined;
      if (!params) throw new RangeError(`--scene: unknown scene '${scene}'; scenes: ${Object.keys(SCENES).join(', ')}`);
      if (!('n' in params) || !('seed' in params)) throw new RangeError(`--scene ${scene} has no parameters n and seed, so step-time cannot sweep it over N`);
    }
    const d = stepTimeDefaults(profile);
    return { ...d, ns: o.ns ?? d.ns, runs: o.runs ?? d.runs, seconds: o.seconds ?? d.seconds, scenes: o.scenes ?? d.scenes, dt: o.dt ?? d.dt };
  },
  run: runStepTime,
  csv: stepTimeCsv,
  tables: stepTimeTables,
  headline: stepTimeHeadline,
  charts: stepTimeCharts,
};

export const energy: Experiment<EnergyOptions, EnergyResult> = {
  name: 'energy',
  description: 'Bouncing ball total energy over 5 simulated minutes, and KE(T)/KE(0) of the elastic uniform scene (report 5.13.1, 6.1)',
  schema: energySchema,
  defaultEngines: ENGINE_IDS,
  options(profile, o) {
    reject('energy', o, ['ns', 'seconds', 'dt']);
    if (o.ns && o.ns.length !== 1) throw new RangeError(`option --n takes one value for experiment 'energy' (the uniform scene's N), got ${o.ns.join(',')}`);
    const d = energyDefaults(profile);
    return { ...d, n: o.ns?.[0] ?? d.n, seconds: o.seconds ?? d.seconds, dt: o.dt ?? d.dt };
  },
  run: runEnergy,
  csv: energyCsv,
  tables: energyTables,
  headline: energyHeadline,
  charts: energyCharts,
};

export const falsePositives: Experiment<FalsePositiveOptions, FalsePositiveResult> = {
  name: 'false-positives',
  description: 'Broad-phase pairs examined per true contact, across N and radius spread 1:1..1:100 (mixed and log-uniform radii) (report 7.4)',
  schema: falsePositiveSchema,
  defaultEngines: MAXGRID_IDS,
  options(profile, o) {
    reject('false-positives', o, ['ns', 'dt']);
    const d = falsePositiveDefaults(profile);
    return { ...d, ns: o.ns ?? d.ns, dt: o.dt ?? d.dt };
  },
  run: runFalsePositives,
  csv: falsePositiveCsv,
  tables: falsePositiveTables,
  headline: falsePositiveHeadline,
  charts: falsePositiveCharts,
};

export const scale: Experiment<ScaleOptions, ScaleResult> = {
  name: 'scale',
  description: 'maxgrid alone up to 1,000,000 circles: ns per body per step and bytes per body',
  schema: scaleSchema,
  defaultEngines: ['maxgrid:maxgrid'],
  options(profile, o) {
    reject('scale', o, ['ns', 'dt']);
    const d = scaleDefaults(profile);
    return { ...d, ns: o.ns ?? d.ns, dt: o.dt ?? d.dt };
  },
  run: runScale,
  csv: scaleCsv,
  tables: scaleTables,
  headline: scaleHeadline,
  charts: scaleCharts,
};

export const cMaxgrid: Experiment<CMaxgridOptions, CMaxgridResult> = {
  name: 'c-maxgrid',
  description: 'maxgrid vs the same Max Grid step in plain C (gcc -O3 -march=native), hashes checked (issue 5, target 2)',
  schema: cMaxgridSchema,
  defaultEngines: ['maxgrid:maxgrid'],
  nodeOnly: true,
  options(profile, o) {
    reject('c-maxgrid', o, ['ns', 'runs', 'scenes', 'dt']);
    const supported = ['uniform', 'seed-box', 'mixed'];
    if (o.scenes && (o.scenes.length !== 1 || !supported.includes(o.scenes[0]))) {
      throw new RangeError(`--scene for experiment 'c-maxgrid' takes one of ${supported.join(', ')} (the C program's all-dynamic boxed scenes), got ${o.scenes.join(',')}`);
    }
    const d = cMaxgridDefaults(profile);
    return { ...d, ns: o.ns ?? d.ns, rounds: o.runs ?? d.rounds, scene: o.scenes?.[0] ?? d.scene, dt: o.dt ?? d.dt };
  },
  run: runCMaxgrid,
  csv: cMaxgridCsv,
  tables: cMaxgridTables,
  headline: cMaxgridHeadline,
  charts: cMaxgridCharts,
};

export const sapSleep: Experiment<SapSleepOptions, SapSleepResult> = {
  name: 'sap-sleep',
  description: 'sap vs sap-persistent on an all-moving and on mostly-sleeping scenes (issue 6, item 2)',
  schema: sapSleepSchema,
  defaultEngines: ['maxgrid:sap', 'maxgrid:sap-persistent'],
  options(profile, o) {
    reject('sap-sleep', o, ['ns', 'runs', 'dt']);
    if (o.ns && o.ns.length !== 1) throw new RangeError(`option --n takes one value for experiment 'sap-sleep', got ${o.ns.join(',')}`);
    const d = sapSleepDefaults(profile);
    return { ...d, n: o.ns?.[0] ?? d.n, rounds: o.runs ?? d.rounds, dt: o.dt ?? d.dt };
  },
  run: runSapSleep,
  csv: sapSleepCsv,
  tables: sapSleepTables,
  headline: sapSleepHeadline,
  charts: sapSleepCharts,
};

export const targets: Experiment<TargetsOptions, TargetsResult> = {
  name: 'targets',
  description: "Issue 5's performance targets T1-T7 from one run: peers, C, a million bodies, mixed sizes, Chromium vs Node",
  schema: targetsSchema,
  defaultEngines: ['maxgrid:maxgrid', 'maxgrid:hgrid', 'maxgrid:auto', 'rapier', 'box2d-wasm'],
  nodeOnly: true,
  options(profile, o) {
    reject('targets', o, ['runs', 'dt']);
    const d = targetsDefaults(profile);
    return { ...d, rounds: o.runs ?? d.rounds, dt: o.dt ?? d.dt };
  },
  run: runTargets,
  csv: (r: TargetsResult) => targetsCsv(r),
  charts: () => [],
  tables: targetsTables,
  headline: targetsHeadline,
};

export const sandboxRender: Experiment<SandboxRenderOptions, SandboxRenderResult> = {
  name: 'sandbox-render',
  description: "Issue 5's T7: the sandbox page live in headless Chromium (100,000 circles unless --n says otherwise), WebGL and canvas 2D, frame by frame",
  schema: sandboxRenderSchema,
  defaultEngines: ['maxgrid:maxgrid'],
  nodeOnly: true,
  fixedEngines: true,
  options(profile, o) {
    reject('sandbox-render', o, ['ns', 'seconds']);
    if (o.ns && o.ns.length !== 1) throw new RangeError(`option --n takes one value for experiment 'sandbox-render' (the page's circle count), got ${o.ns.join(',')}`);
    if (o.ns && o.ns[0] > SANDBOX_MAX_N) throw new RangeError(`option --n for experiment 'sandbox-render' is at most ${SANDBOX_MAX_N} (the page's limit), got ${o.ns[0]}`);
    const d = sandboxRenderDefaults(profile);
    return { ...d, n: o.ns?.[0] ?? d.n, seconds: o.seconds ?? d.seconds };
  },
  run: runSandboxRender,
  csv: sandboxRenderCsv,
  charts: () => [],
  tables: sandboxRenderTables,
  headline: sandboxRenderHeadline,
};

export const threads: Experiment<ThreadsOptions, ThreadsResult> = {
  name: 'threads',
  description: 'The parallel step (1,000,000 circles unless --n says otherwise) on 1, 2, 4, ... threads up to the cores, state hashes checked (--runs: timed steps)',
  schema: threadsSchema,
  defaultEngines: ['maxgrid:maxgrid'],
  nodeOnly: true,
  fixedEngines: true,
  options(profile, o) {
    reject('threads', o, ['ns', 'runs', 'dt']);
    if (o.ns && o.ns.length !== 1) throw new RangeError(`option --n takes one value for experiment 'threads', got ${o.ns.join(',')}`);
    const d = threadsDefaults(profile);
    return { ...d, n: o.ns?.[0] ?? d.n, steps: o.runs ?? d.steps, dt: o.dt ?? d.dt };
  },
  run: runThreads,
  csv: threadsCsv,
  charts: () => [],
  tables: threadsTables,
  headline: threadsHeadline,
};

export const piles: Experiment<PilesOptions, PilesResult> = {
  name: 'piles',
  description: 'A settled pile under gravity (seed-box, elasticity 0): how far circles sink into each other and how much they keep moving, per engine',
  schema: pilesSchema,
  defaultEngines: ['maxgrid:maxgrid', 'maxgrid-piles', 'box2d-wasm', 'planck', 'rapier', 'matter-js', 'p2-es'],
  options(profile, o) {
    reject('piles', o, ['ns', 'seconds', 'dt']);
    if (o.ns && o.ns.length !== 1) throw new RangeError(`option --n takes one value for experiment 'piles', got ${o.ns.join(',')}`);
    const d = pilesDefaults(profile);
    return { ...d, n: o.ns?.[0] ?? d.n, settleSeconds: o.seconds ?? d.settleSeconds, dt: o.dt ?? d.dt };
  },
  run: runPiles,
  csv: pilesCsv,
  charts: () => [],
  tables: pilesTables,
  headline: pilesHeadline,
};

/** The peers for shape scenes, after maxgrid's report broad-phase and its default. */
const SHAPE_PEERS = SHAPE_ENGINE_IDS.filter((id) => !id.startsWith('maxgrid:'));

export const shapeStepTime: Experiment<ShapeStepTimeOptions, ShapeStepTimeResult> = {
  name: 'shape-step-time',
  description: "Step time on shape scenes per engine: Box2D v3's pyramid, many pyramids and tumbler, and N sweeps of uniform-polygons and polygon-box; the answer to the report's 7.4",
  schema: shapeStepTimeSchema,
  defaultEngines: ['maxgrid:maxgrid', 'maxgrid:auto', ...SHAPE_PEERS],
  nodeOnly: true,
  shapes: true,
  options(profile, o) {
    reject('shape-step-time', o, ['runs', 'dt']);
    const d = shapeStepTimeDefaults(profile);
    return { ...d, runs: o.runs ?? d.runs, dt: o.dt ?? d.dt };
  },
  run: runShapeStepTime,
  csv: shapeStepTimeCsv,
  tables: shapeStepTimeTables,
  headline: shapeStepTimeHeadline,
  charts: shapeStepTimeCharts,
};

export const stability: Experiment<StabilityOptions, StabilityResult> = {
  name: 'stability',
  description: 'Stacks and friction per engine and settings profile: the pyramid, a 15-box stack of 1 m and of 5 cm boxes, a 100:1 stack, the card house, a box on a ramp above and below its friction angle',
  schema: stabilitySchema,
  defaultEngines: ['maxgrid:maxgrid', ...SHAPE_PEERS],
  nodeOnly: true,
  shapes: true,
  options(profile, o) {
    reject('stability', o, ['seconds', 'dt']);
    const d = stabilityDefaults(profile);
    return { ...d, seconds: o.seconds ?? d.seconds, dt: o.dt ?? d.dt };
  },
  run: runStability,
  csv: stabilityCsv,
  charts: () => [],
  tables: stabilityTables,
  headline: stabilityHeadline,
};

export const shapeEnergy: Experiment<ShapeEnergyOptions, ShapeEnergyResult> = {
  name: 'shape-energy',
  description: 'Kinetic energy (linear + rotational) of elastic frictionless squares and hexagons over time, per engine and settings profile (report 5.13.1 with shapes)',
  schema: shapeEnergySchema,
  defaultEngines: ['maxgrid:maxgrid', ...SHAPE_PEERS],
  nodeOnly: true,
  shapes: true,
  options(profile, o) {
    reject('shape-energy', o, ['ns', 'seconds', 'dt']);
    if (o.ns && o.ns.length !== 1) throw new RangeError(`option --n takes one value for experiment 'shape-energy', got ${o.ns.join(',')}`);
    const d = shapeEnergyDefaults(profile);
    return { ...d, n: o.ns?.[0] ?? d.n, seconds: o.seconds ?? d.seconds, dt: o.dt ?? d.dt };
  },
  run: runShapeEnergy,
  csv: shapeEnergyCsv,
  charts: shapeEnergyCharts,
  tables: shapeEnergyTables,
  headline: shapeEnergyHeadline,
};

export const shapeFalsePositives: Experiment<ShapeFalsePositiveOptions, ShapeFalsePositiveResult> = {
  name: 'shape-false-positives',
  description: "Broad-phase pairs examined, bounding-circle candidates and manifolds per body, and the narrow-phase's share of the step, per maxgrid broad-phase on shape mixes (report 7.4)",
  schema: shapeFalsePositiveSchema,
  defaultEngines: SHAPE_ENGINE_IDS.filter((id) => id.startsWith('maxgrid:')),
  nodeOnly: true,
  shapes: true,
  options(profile, o) {
    reject('shape-false-positives', o, ['dt']);
    const d = shapeFalsePositiveDefaults(profile);
    return { ...d, dt: o.dt ?? d.dt };
  },
  run: runShapeFalsePositives,
  csv: shapeFalsePositiveCsv,
  charts: () => [],
  tables: shapeFalsePositiveTables,
  headline: shapeFalsePositiveHeadline,
};

export const cliffs: Experiment<CliffsOptions, CliffsResult> = {
  name: 'cliffs',
  description: 'Scenes where a broad-phase or the continuous sweep used to fall off a cliff, with every broad-phase: ms per step, pairs per body, the default against the fastest (issue 22)',
  schema: cliffsSchema,
  defaultEngines: MAXGRID_IDS,
  // A minute or more at the scenes' sizes: longer than the lab page's whole run.
  nodeOnly: true,
  options(profile, o) {
    reject('cliffs', o, ['runs', 'dt']);
    const d = cliffsDefaults(profile);
    return { ...d, steps: o.runs ?? d.steps, dt: o.dt ?? d.dt };
  },
  run: runCliffs,
  csv: cliffsCsv,
  charts: () => [],
  tables: cliffsTables,
  headline: cliffsHeadline,
};

export const threadsLoad: Experiment<ThreadsLoadOptions, ThreadsLoadResult> = {
  name: 'threads-load',
  description: 'The parallel step (40,000 circles unless --n says otherwise) against one thread with background processes spinning on the cores, the thread governor on and off (issue 22)',
  schema: threadsLoadSchema,
  defaultEngines: ['maxgrid:maxgrid'],
  nodeOnly: true,
  fixedEngines: true,
  options(profile, o) {
    reject('threads-load', o, ['ns', 'runs', 'dt']);
    if (o.ns && o.ns.length !== 1) throw new RangeError(`option --n takes one value for experiment 'threads-load', got ${o.ns.join(',')}`);
    const d = threadsLoadDefaults(profile);
    return { ...d, n: o.ns?.[0] ?? d.n, steps: o.runs ?? d.steps, dt: o.dt ?? d.dt };
  },
  run: runThreadsLoad,
  csv: threadsLoadCsv,
  charts: () => [],
  tables: threadsLoadTables,
  headline: threadsLoadHeadline,
};

// The registry stores experiments of different option and result types side by side.
// eslint-disable-next-line @typescript-eslint/no-explicit-any
export type AnyExperiment = Experiment<any, any>;

export const EXPERIMENTS: Record<string, AnyExperiment> = {
  'step-time': stepTime,
  energy,
  'false-positives': falsePositives,
  scale,
  'sap-sleep': sapSleep,
  cliffs,
  'c-maxgrid': cMaxgrid,
  targets,
  'sandbox-render': sandboxRender,
  threads,
  'threads-load': threadsLoad,
  piles,
  'shape-step-time': shapeStepTime,
  stability,
  'shape-energy': shapeEnergy,
  'shape-false-positives': shapeFalsePositives,
  joints,
  integrators,
};

/** Every experiment; `results` (Node only) runs them all and writes docs/results.md. */
export const EXPERIMENT_NAMES = [...Object.keys(EXPERIMENTS), 'results'];

export interface AnyResult {
  meta: { experiment: string };
}
