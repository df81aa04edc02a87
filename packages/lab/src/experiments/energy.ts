import { buildScene, type Scene } from '@maxgrid/scenes';
import { allocateState, energyOf, sceneMasses, type Engine } from '../engines/adapter.js';
import { lineChart, type ChartSpec } from '../report/charts.js';
import { csvLine, makeMeta, metaSchema, type Meta, type Profile, type RunContext } from './common.js';

/**
 * The report's accuracy test (5.13.1, 6.1), plus its many-body version: a single elastic ball
 * dropped for five simulated minutes, total energy over time; and the elastic `uniform` scene,
 * kinetic energy over time relative to the start. Energy is computed by the lab from read-back
 * state with the same masses for every engine (see `energyOf`).
 */
export interface EnergyOptions {
  dt: number;
  /** Simulated seconds of the bouncing ball (the report: 300). */
  ballSeconds: number;
  /** Circles in the many-body `uniform` scene. */
  n: number;
  /** Simulated seconds of the many-body scene. */
  seconds: number;
  /** Samples per series; each series is sampled at evenly spaced steps. */
  samples: number;
}

export function energyDefaults(profile: Profile): EnergyOptions {
  return profile === 'full'
    ? { dt: 1 / 60, ballSeconds: 300, n: 2000, seconds: 60, samples: 600 }
    : { dt: 1 / 60, ballSeconds: 300, n: 500, seconds: 10, samples: 200 };
}

export interface EnergySeries {
  engine: string;
  t: number[];
  /** Ball: total energy relative to the start. Many-body: kinetic energy relative to the start. */
  ratio: number[];
  final: number;
  min: number;
  max: number;
}

export interface EnergyResult {
  meta: Meta;
  /** Total energy at t = 0 in scene units (mass = pi r^2, pixels, seconds). */
  ballInitialEnergy: number;
  ball: EnergySeries[];
  uniform: EnergySeries[];
}

async function trace(
  engine: Engine,
  scene: Scene,
  dt: number,
  seconds: number,
  samples: number,
  measure: 'total' | 'kinetic',
  ctx: RunContext,
): Promise<EnergySeries> {
  const masses = sceneMasses(scene);
  const state = allocateState(scene.count);
  const sim = engine.create(scene);
  const steps = Math.max(1, Math.round(seconds / dt));
  const every = Math.max(1, Math.floor(steps / samples));
  const t: number[] = [];
  const ratio: number[] = [];
  try {
    sim.read(state);
    const e0 = energyOf(scene, masses, state)[measure];
    if (!(e0 > 0)) throw new RangeError(`${scene.name}: initial ${measure} energy is ${e0}; the ratio needs a positive start`);
    for (let i = 0; i <= steps; i++) {
      if (i % every === 0 || i === steps) {
        sim.read(state);
        t.push(i * dt);
        ratio.push(energyOf(scene, masses, state)[measure] / e0);
      }
      if (i < steps) sim.step(dt);
      if (i % 2000 === 1999) await ctx.yieldToHost?.();
    }
  } finally {
    sim.dispose();
  }
  return { engine: engine.info.id, t, ratio, final: ratio[ratio.length - 1], min: Math.min(...ratio), max: Math.max(...ratio) };
}

export async function runEnergy(options: EnergyOptions, ctx: RunContext): Promise<EnergyResult> {
  const ballScene = buildScene('bouncing-ball');
  const uniformScene = buildScene('uniform', { n: options.n, seed: 1 });
  const total = ctx.engines.length * 2;
  let done = 0;
  const ball: EnergySeries[] = [];
  const uniform: EnergySeries[] = [];
  for (const engine of ctx.engines) {
    ctx.progress?.(done++, total, `bouncing-ball ${engine.info.id}`);
    ball.push(await trace(engine, ballScene, options.dt, options.ballSeconds, options.samples, 'total', ctx));
    ctx.progress?.(done++, total, `uniform N=${options.n} ${engine.info.id}`);
    uniform.push(await trace(engine, uniformScene, options.dt, options.seconds, options.samples, 'kinetic', ctx));
  }
  ctx.progress?.(total, total, 'done');
  const ballInitialEnergy = energyOf(ballScene, sceneMasses(ballScene), ballScene).total;
  return { meta: makeMeta('energy', ctx, options), ballInitialEnergy, ball, uniform };
}

export function energyCsv(result: EnergyResult): string {
  const lines = [csvLine(['test', 'engine', 't_s', 'ratio'])];
  for (const [test, list] of [['bouncing-ball total/E0', result.ball], ['uniform KE/KE0', result.uniform]] as const) {
    for (const s of list) s.t.forEach((t, i) => lines.push(csvLine([test, s.engine, t, s.ratio[i]])));
  }
  return lines.join('\n') + '\n';
}

export function energyCharts(result: EnergyResult): ChartSpec[] {
  const series = (list: EnergySeries[]) =>
    list.map((s) => ({ name: s.engine, points: s.t.map((t, i) => [t, s.ratio[i]] as [number, number]) }));
  return [
    lineChart({
      id: 'energy-ball',
      title: 'Bouncing ball, restitution 1: total energy / initial',
      xName: 'simulated time (s)',
      yName: 'E(t) / E(0)',
      series: series(result.ball),
    }),
    lineChart({
      id: 'energy-uniform',
      title: `Elastic uniform scene, N = ${String(result.meta.options.n)}: kinetic energy / initial`,
      xName: 'simulated time (s)',
      yName: 'KE(t) / KE(0)',
      series: series(result.uniform),
    }),
  ];
}

const seriesSchema = {
  type: 'array',
  items: {
    type: 'object',
    required: ['engine', 't', 'ratio', 'final', 'min', 'max'],
    properties: {
      engine: { type: 'string' },
      t: { type: 'array', minItems: 2, items: { type: 'number', minimum: 0 } },
      ratio: { type: 'array', minItems: 2, items: { type: 'number' } },
      final: { type: 'number' },
      min: { type: 'number' },
      max: { type: 'number' },
    },
    additionalProperties: false,
  },
} as const;

export const energySchema = {
  $id: 'energy',
  type: 'object',
  required: ['meta', 'ballInitialEnergy', 'ball', 'uniform'],
  properties: { meta: metaSchema, ballInitialEnergy: { type: 'number', exclusiveMinimum: 0 }, ball: seriesSchema, uniform: seriesSchema },
  additionalProperties: false,
} as const;
