import { buildShapeScene } from '@maxgrid/scenes';
import { lineChart, type ChartSpec } from '../report/charts.js';
import { engineLabel, fmt, type Table } from '../report/tables.js';
import { allocatePoses, bodyMass, SHAPE_PROFILES, type PoseState, type ShapeProfile } from '../shape-engines/adapter.js';
import { csvLine, makeMeta, scaleNote, sceneScale, sceneScaleSchema, shapeMetaSchema, type Meta, type Profile, type RunContext, type SceneScale } from './common.js';

/**
 * Kinetic energy, linear plus rotational, of elastic frictionless polygons in a box (the
 * uniform-polygons scene: restitution 1, no gravity) over time, per engine: the report's energy
 * experiment (5.13.1) for shapes. Masses and inertias come from the scene's own geometry at
 * density 1 for every engine, as the circle experiment uses pi r^2.
 */
export interface ShapeEnergyOptions {
  n: number;
  seconds: number;
  dt: number;
  /** Samples of KE(t) / KE(0) per run. */
  samples: number;
  profiles: ShapeProfile[];
}

export function shapeEnergyDefaults(profile: Profile): ShapeEnergyOptions {
  return profile === 'full' ? { n: 4000, seconds: 30, dt: 1 / 60, samples: 60, profiles: [...SHAPE_PROFILES] } : { n: 1000, seconds: 10, dt: 1 / 60, samples: 20, profiles: [...SHAPE_PROFILES] };
}

export interface ShapeEnergyRow {
  engine: string;
  profile: ShapeProfile;
  /** [seconds, KE(t) / KE(0)] */
  series: [number, number][];
}

export interface ShapeEnergyResult {
  meta: Meta;
  /** The scene's lengthUnit and body sizes in metres, which the Box2D family's tolerances depend on. */
  scale: SceneScale;
  rows: ShapeEnergyRow[];
}

function kinetic(p: PoseState, mass: Float64Array, inertia: Float64Array): number {
  let e = 0;
  for (let k = 0; k < mass.length; k++) e += 0.5 * mass[k] * (p.vx[k] * p.vx[k] + p.vy[k] * p.vy[k]) + 0.5 * inertia[k] * p.angularVelocity[k] * p.angularVelocity[k];
  return e;
}

export async function runShapeEnergy(o: ShapeEnergyOptions, ctx: RunContext): Promise<ShapeEnergyResult> {
  const engines = ctx.shapeEngines ?? [];
  const scene = buildShapeScene('uniform-polygons', { n: o.n, maxSpin: 2 });
  const mass = new Float64Array(scene.bodies.length);
  const inertia = new Float64Array(scene.bodies.length);
  scene.bodies.forEach((b, k) => {
    const m = bodyMass(b);
    mass[k] = m.mass;
    inertia[k] = m.inertia;
  });
  const steps = Math.round(o.seconds / o.dt);
  const every = Math.max(1, Math.round(steps / o.samples));
  const rows: ShapeEnergyRow[] = [];
  let done = 0;
  for (const engine of engines) {
    for (const profile of o.profiles) {
      ctx.progress?.(done++, engines.length * o.profiles.length, `${engine.info.id} (${profile})`);
      const sim = engine.create(scene, profile);
      try {
        const poses = allocatePoses(sim.count);
        sim.read(poses);
        const e0 = kinetic(poses, mass, inertia);
        const series: [number, number][] = [[0, 1]];
        for (let s = 1; s <= steps; s++) {
          sim.step(o.dt);
          if (s % every === 0 || s === steps) {
            sim.read(poses);
            series.push([s * o.dt, kinetic(poses, mass, inertia) / e0]);
            await ctx.yieldToHost?.();
          }
        }
        rows.push({ engine: engine.info.id, profile, series });
      } finally {
        sim.dispose();
      }
    }
  }
  return { meta: makeMeta('shape-energy', ctx, o), scale: sceneScale(scene), rows };
}

function at(row: ShapeEnergyRow, t: number): number {
  let best = row.series[0];
  for (const p of row.series) if (Math.abs(p[0] - t) < Math.abs(best[0] - t)) best = p;
  return best[1];
}

export function shapeEnergyTables(result: ShapeEnergyResult): Table[] {
  const end = Math.max(...result.rows.flatMap((r) => r.series.map((p) => p[0])));
  const times = [1, end / 2, end].filter((t, i, a) => a.indexOf(t) === i && t <= end);
  return [
    {
      title: 'Elastic frictionless polygons: kinetic energy (linear + rotational) over its start',
      headers: ['engine', 'profile', ...times.map((t) => `t = ${fmt(t)} s`)],
      rows: result.rows.map((r) => [engineLabel(r.engine), r.profile, ...times.map((t) => fmt(at(r, t), 6))]),
      note: scaleNote([{ scene: 'uniform-polygons', scale: result.scale }]) || undefined,
    },
  ];
}

export function shapeEnergyCharts(result: ShapeEnergyResult): ChartSpec[] {
  return SHAPE_PROFILES.filter((p) => result.rows.some((r) => r.profile === p)).map((profile) =>
    lineChart({
      id: `shape-energy-${profile}`,
      title: `Elastic polygons, ${profile} settings: KE(t) / KE(0)`,
      xName: 'simulated seconds',
      yName: 'KE / KE(0)',
      series: result.rows.filter((r) => r.profile === profile).map((r) => ({ name: engineLabel(r.engine), points: r.series })),
    }),
  );
}

export function shapeEnergyCsv(result: ShapeEnergyResult): string {
  const lines = [csvLine(['engine', 'profile', 'seconds', 'ke_ratio'])];
  for (const r of result.rows) for (const [t, e] of r.series) lines.push(csvLine([r.engine, r.profile, t, e]));
  return lines.join('\n') + '\n';
}

export function shapeEnergyHeadline(result: ShapeEnergyResult): string[] {
  const end = Math.max(...result.rows.flatMap((r) => r.series.map((p) => p[0])));
  return [`Kinetic energy kept after ${fmt(end)} s of elastic collisions between squares and hexagons: ${result.rows.map((r) => `${engineLabel(r.engine)} (${r.profile}) ${fmt(100 * at(r, end), 4)} %`).join(', ')}.`, ''];
}

export const shapeEnergySchema = {
  $id: 'shape-energy',
  type: 'object',
  required: ['meta', 'scale', 'rows'],
  properties: {
    meta: shapeMetaSchema,
    scale: sceneScaleSchema,
    rows: {
      type: 'array',
      items: {
        type: 'object',
        required: ['engine', 'profile', 'series'],
        properties: { engine: { type: 'string' }, profile: { enum: ['report', 'defaults'] }, series: { type: 'array', items: { type: 'array', items: { type: ['number', 'null'] } } } },
        additionalProperties: false,
      },
    },
  },
  additionalProperties: false,
} as const;
