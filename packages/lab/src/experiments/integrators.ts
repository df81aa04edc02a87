import { World } from '@maxgrid/engine';
import { buildShapeScene, buildShapeWorld } from '@maxgrid/scenes';
import { lineChart, type ChartSpec } from '../report/charts.js';
import { fmt, type Table } from '../report/tables.js';
import { csvLine, makeMeta, metaSchema, type Meta, type Profile, type RunContext } from './common.js';
import { OVERRIDE_FLAGS, type Experiment, type Overrides } from './registry.js';

/**
 * The report's claim (7.4) that explicit Euler fails for soft bodies and that a better method
 * ("such as Runge-Kutta") is needed, tested: an undamped spring pair and one lattice jelly
 * (`jellies` scene, no gravity, started stretched 10 %), at 60 Hz with the soft step's sub-steps,
 * over a sweep of stiffness, with force-driven springs integrated by explicit Euler, semi-implicit
 * Euler and rk4, and with the solver's soft-constraint springs (distance joints of the same
 * frequency). For each, the worst relative error of the total energy (kinetic plus elastic) over
 * the run, and the stiffness from which it blows up (the energy grows past `BLOW_UP` times its
 * start, or a speed reaches the engine's limit).
 */
export interface IntegratorsOptions {
  seconds: number;
  dt: number;
  /** Spring stiffness, N/m, between 1 kg bodies. */
  stiffnesses: number[];
}

export function integratorsDefaults(profile: Profile): IntegratorsOptions {
  const full = [10, 30, 100, 300, 1e3, 3e3, 1e4, 3e4, 1e5, 3e5, 1e6];
  return profile === 'full' ? { seconds: 10, dt: 1 / 60, stiffnesses: full } : { seconds: 5, dt: 1 / 60, stiffnesses: [10, 100, 1e3, 1e4, 1e5] };
}

export const METHODS = ['explicit-euler', 'semi-implicit-euler', 'rk4', 'soft-constraint'] as const;
export type Method = (typeof METHODS)[number];
export const SYSTEMS = ['spring pair', 'jelly'] as const;
export type System = (typeof SYSTEMS)[number];

/** Energy past this many times its start: blown up. */
const BLOW_UP = 10;

export interface IntegratorsRow {
  system: System;
  method: Method;
  stiffness: number;
  /** The spring's frequency sqrt(k / m_eff) / 2 pi, hertz; the soft constraint is given this. */
  hertz: number;
  /** Worst |E(t) / E(0) - 1| over the run; null once blown up. */
  drift: number | null;
  /** E(end) / E(0). */
  final: number | null;
  blewUp: boolean;
}

export interface IntegratorsResult {
  meta: Meta;
  rows: IntegratorsRow[];
}

/** The soft step's sub-steps, the engine's default, given explicitly for softCap. */
const SUBSTEPS = 4;

/** The stiffest a soft constraint is solved at: a quarter of the sub-step rate (docs/engine.md, Joints). */
function softCap(dt: number): number {
  return (0.25 * SUBSTEPS) / dt;
}

/** Every spring of these worlds joins two 1 kg bodies: its effective mass is 1/2 kg. */
const EFFECTIVE_MASS = 0.5;

function frequency(stiffness: number): number {
  return Math.sqrt(stiffness / EFFECTIVE_MASS) / (2 * Math.PI);
}

/** A world of the system, and the rest length of each joint (in jointHandles order) for measuring soft constraints' energy. */
function build(system: System, method: Method, stiffness: number): { world: World; rest: number[] } {
  const hertz = frequency(stiffness);
  const integrator = method === 'soft-constraint' ? 'semi-implicit-euler' : method;
  if (system === 'spring pair') {
    const world = new World({ integrator, substeps: SUBSTEPS });
    const a = world.createCircle({ x: 0, y: 0, radius: 0.1, mass: 1 });
    const b = world.createCircle({ x: 1.2, y: 0, radius: 0.1, mass: 1 });
    if (method === 'soft-constraint') world.createJoint({ kind: 'distance', bodyA: a, bodyB: b, length: 1, hertz, dampingRatio: 0 });
    else world.createJoint({ kind: 'spring', bodyA: a, bodyB: b, length: 1, stiffness });
    return { world, rest: [1] };
  }
  const scene = buildShapeScene('jellies', { count: 1, side: 5, funnel: 0, floor: 0, gravity: 0, stretch: 1.1, hertz, dampingRatio: 0, stiffness: method === 'soft-constraint' ? 0 : stiffness });
  // Particles of 1 kg, so that every spring joins 1 kg to 1 kg.
  for (const body of scene.bodies) for (const shape of body.shapes) shape.density = 1 / (Math.PI * 0.14 * 0.14);
  const rest = (scene.joints ?? []).map((j) => ('length' in j && j.length !== undefined ? j.length : 0));
  return { world: buildShapeWorld(scene, { integrator, substeps: SUBSTEPS }), rest };
}

/** Kinetic plus elastic energy: force springs' from the world, soft constraints' from their stretch at the stiffness they stand for. */
function energy(world: World, method: Method, stiffness: number, rest: number[]): number {
  let e = world.kineticEnergy() + world.potentialEnergy();
  if (method === 'soft-constraint') {
    world.jointHandles().forEach((h, k) => {
      const stretch = world.getJoint(h).length - rest[k];
      e += 0.5 * stiffness * stretch * stretch;
    });
  }
  return e;
}

export async function runIntegrators(o: IntegratorsOptions, ctx: RunContext): Promise<IntegratorsResult> {
  const steps = Math.round(o.seconds / o.dt);
  const rows: IntegratorsRow[] = [];
  const total = SYSTEMS.length * METHODS.length * o.stiffnesses.length;
  let done = 0;
  for (const system of SYSTEMS) {
    for (const method of METHODS) {
      for (const stiffness of o.stiffnesses) {
        ctx.progress?.(done++, total, `${system}, ${method}, k = ${stiffness}`);
        const { world, rest } = build(system, method, stiffness);
        const start = energy(world, method, stiffness, rest);
        let drift = 0;
        let blewUp = false;
        for (let s = 0; s < steps && !blewUp; s++) {
          world.step(o.dt);
          const e = energy(world, method, stiffness, rest);
          if (!(e <= BLOW_UP * start) || fastest(world) >= SPEED_LIMIT) blewUp = true;
          else drift = Math.max(drift, Math.abs(e / start - 1));
          if (s % 60 === 0) await ctx.yieldToHost?.();
        }
        const final = energy(world, method, stiffness, rest) / start;
        rows.push({ system, method, stiffness, hertz: frequency(stiffness), drift: blewUp ? null : drift, final: blewUp || !Number.isFinite(final) ? null : final, blewUp });
      }
    }
  }
  return { meta: makeMeta('integrators', ctx, o), rows };
}

/** Near the soft step's speed limit (400 m/s at lengthUnit 1): a run that reaches it has blown up. */
const SPEED_LIMIT = 0.99 * 400;

/** The fastest body's speed (the soft step caps speeds at 400 m/s: a blown-up run reaches it). */
function fastest(world: World): number {
  const v = world.views();
  let most = 0;
  for (let s = 0; s < v.slotCount; s++) most = Math.max(most, Math.sqrt(v.vx[s] * v.vx[s] + v.vy[s] * v.vy[s]));
  return most;
}

/** The smallest stiffness of the sweep from which a method blew up, or null. */
export function blowUpStiffness(result: IntegratorsResult, system: System, method: Method): number | null {
  const rows = result.rows.filter((r) => r.system === system && r.method === method && r.blewUp);
  return rows.length === 0 ? null : Math.min(...rows.map((r) => r.stiffness));
}

export function integratorsTables(result: IntegratorsResult): Table[] {
  const stiffnesses = [...new Set(result.rows.map((r) => r.stiffness))];
  return SYSTEMS.map((system) => ({
    title: `${system}: worst relative energy error over the run (x: blew up), and the stiffness it blows up from`,
    headers: ['method', ...stiffnesses.map((k) => `k = ${fmt(k)} (${fmt(frequency(k), 3)} Hz)`), 'blows up from k ='],
    rows: METHODS.map((method) => [
      method,
      ...stiffnesses.map((k) => {
        const row = result.rows.find((r) => r.system === system && r.method === method && r.stiffness === k);
        return row === undefined ? '' : row.blewUp ? 'x' : fmt(row.drift!, 2);
      }),
      blowUpStiffness(result, system, method) === null ? 'never' : fmt(blowUpStiffness(result, system, method)!),
    ]),
  }));
}

export function integratorsCharts(result: IntegratorsResult): ChartSpec[] {
  return SYSTEMS.map((system) =>
    lineChart({
      id: `integrators-${system.replace(' ', '-')}`,
      title: `${system}: worst relative energy error against stiffness (blown-up runs left out)`,
      xName: 'stiffness, N/m',
      yName: '|E / E(0) - 1|',
      series: METHODS.map((method) => ({
        name: method,
        points: result.rows.filter((r) => r.system === system && r.method === method && !r.blewUp).map((r) => [r.stiffness, r.drift!] as [number, number]),
      })),
    }),
  );
}

export function integratorsCsv(result: IntegratorsResult): string {
  const lines = [csvLine(['system', 'method', 'stiffness', 'hertz', 'drift', 'final', 'blew_up'])];
  for (const r of result.rows) lines.push(csvLine([r.system, r.method, r.stiffness, r.hertz, r.drift ?? '', r.final ?? '', r.blewUp ? 1 : 0]));
  return lines.join('\n') + '\n';
}

export function integratorsHeadline(result: IntegratorsResult): string[] {
  const parts = METHODS.map((m) => `${m} ${blowUpStiffness(result, 'jelly', m) === null ? 'never' : `from k = ${fmt(blowUpStiffness(result, 'jelly', m)!)}`}`);
  const softest = Math.min(...result.rows.map((r) => r.stiffness));
  const soft = result.rows.find((r) => r.system === 'jelly' && r.method === 'soft-constraint' && r.stiffness === softest);
  const rk4 = result.rows.find((r) => r.system === 'jelly' && r.method === 'rk4' && r.stiffness === softest);
  const dt = (result.meta.options as { dt: number }).dt;
  const cap = softCap(dt);
  const capped = result.rows.filter((r) => r.method === 'soft-constraint' && r.system === 'jelly' && r.hertz > cap).sort((a, b) => a.stiffness - b.stiffness);
  return [
    `A lattice jelly of 1 kg particles on undamped springs at 60 Hz blows up with ${parts.join(', ')} (over the sweep's stiffnesses).`,
    soft && rk4 && soft.final !== null && rk4.drift !== null
      ? `At k = ${fmt(softest)} rk4's energy stays within ${fmt(rk4.drift, 2)} of its start; the soft constraints, implicit, never blow up but keep only ${fmt(100 * soft.final, 3)} % of it.`
      : '',
    capped.length > 0
      ? `Soft constraints are solved at most at a quarter of the sub-step rate (${fmt(cap, 3)} Hz at ${fmt(1 / dt, 3)} Hz with ${SUBSTEPS} sub-steps): from k = ${fmt(capped[0].stiffness)} (${fmt(capped[0].hertz, 3)} Hz) the soft-constraint rows are a softer spring than the one named, which is part of why they never blow up.`
      : '',
    '',
  ];
}

export const integratorsSchema = {
  $id: 'integrators',
  type: 'object',
  required: ['meta', 'rows'],
  properties: {
    meta: metaSchema,
    rows: {
      type: 'array',
      items: {
        type: 'object',
        required: ['system', 'method', 'stiffness', 'hertz', 'drift', 'final', 'blewUp'],
        properties: {
          system: { enum: [...SYSTEMS] },
          method: { enum: [...METHODS] },
          stiffness: { type: 'number' },
          hertz: { type: 'number' },
          drift: { type: ['number', 'null'] },
          final: { type: ['number', 'null'] },
          blewUp: { type: 'boolean' },
        },
        additionalProperties: false,
      },
    },
  },
  additionalProperties: false,
} as const;

export const integrators: Experiment<IntegratorsOptions, IntegratorsResult> = {
  name: 'integrators',
  description: "Energy drift and blow-up stiffness of an undamped spring pair and a lattice jelly at 60 Hz: explicit Euler, semi-implicit Euler, rk4 and the solver's soft constraints (the report's 7.4 claim)",
  schema: integratorsSchema,
  defaultEngines: ['maxgrid:maxgrid'],
  fixedEngines: true,
  options(profile, o) {
    for (const key of Object.keys(o) as (keyof Overrides)[]) {
      if (o[key] !== undefined && key !== 'seconds' && key !== 'dt') throw new RangeError(`option ${OVERRIDE_FLAGS[key]} does not apply to experiment 'integrators' (it takes --seconds, --dt)`);
    }
    const d = integratorsDefaults(profile);
    return { ...d, seconds: o.seconds ?? d.seconds, dt: o.dt ?? d.dt };
  },
  run: runIntegrators,
  csv: integratorsCsv,
  charts: integratorsCharts,
  tables: integratorsTables,
  headline: integratorsHeadline,
};
