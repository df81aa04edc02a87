import { buildScene, type Scene } from '@maxgrid/scenes';
import { allocateState } from '../engines/adapter.js';
import { fmt, type Table } from '../report/tables.js';
import { csvLine, makeMeta, metaSchema, now, spread, type Meta, type Profile, type RunContext } from './common.js';

/**
 * How each engine holds up a pile: the report's seed box with elasticity 0, stepped until its
 * circles lie on the floor, then measured in place. A pile that cannot carry its weight sinks into
 * itself (circles overlap, and it stands lower than their own area allows); one that cannot hold
 * still boils (circles keep moving). Every engine gets the same scene and the settings the lab
 * gives it elsewhere (the report's Unity configuration: no friction, no sleeping, discrete).
 */
export interface PilesOptions {
  n: number;
  seed: number;
  /** Seconds stepped before measuring: long enough to fall 900 px (2.4 s at g = 300) and settle. */
  settleSeconds: number;
  /** Steps measured for motion and step time. */
  measureSteps: number;
  dt: number;
}

export function pilesDefaults(profile: Profile): PilesOptions {
  return profile === 'full'
    ? { n: 3000, seed: 1, settleSeconds: 10, measureSteps: 60, dt: 1 / 60 }
    : { n: 1000, seed: 1, settleSeconds: 10, measureSteps: 60, dt: 1 / 60 };
}

export interface PilesRow {
  engine: string;
  n: number;
  /** Mean overlap of the overlapping pairs, as a fraction of their summed radii. */
  meanOverlap: number;
  deepestOverlap: number;
  overlappingPairs: number;
  /** Floor to the top of the highest circle. */
  pileHeight: number;
  /** The circles' area spread over the floor: no pile of circles that do not overlap is lower. */
  areaHeight: number;
  /** Mean distance a circle travels per second while measured. */
  motion: number;
  /** Circles whose centre ended outside the box. */
  escaped: number;
  medianStepMs: number;
}

export interface PilesResult {
  meta: Meta;
  rows: PilesRow[];
}

export async function runPiles(o: PilesOptions, ctx: RunContext): Promise<PilesResult> {
  const scene = buildScene('seed-box', { n: o.n, seed: o.seed, elasticity: 0 });
  const rows: PilesRow[] = [];
  for (const [index, engine] of ctx.engines.entries()) {
    ctx.progress?.(index, ctx.engines.length, `piles: ${engine.info.id}, N=${o.n}`);
    const sim = engine.create(scene);
    try {
      const settle = Math.round(o.settleSeconds / o.dt);
      for (let s = 0; s < settle; s++) {
        sim.step(o.dt);
        if (s % 60 === 0) await ctx.yieldToHost?.();
      }
      const before = allocateState(sim.count);
      const after = allocateState(sim.count);
      const times: number[] = [];
      let moved = 0;
      sim.read(after);
      for (let s = 0; s < o.measureSteps; s++) {
        before.x.set(after.x);
        before.y.set(after.y);
        const t = now();
        sim.step(o.dt);
        times.push(now() - t);
        sim.read(after);
        for (let k = 0; k < sim.count; k++) moved += Math.hypot(after.x[k] - before.x[k], after.y[k] - before.y[k]);
      }
      const radii = new Float64Array(sim.count);
      sim.readRadii(radii);
      rows.push({
        engine: engine.info.id,
        n: sim.count,
        ...measurePile(scene, after.x, after.y, radii),
        motion: moved / sim.count / (o.measureSteps * o.dt),
        medianStepMs: spread(times).median,
      });
    } finally {
      sim.dispose();
    }
  }
  return { meta: makeMeta('piles', ctx, o), rows };
}

/** Overlaps on a grid of cells as wide as the largest circle, so N in the thousands stays cheap. */
function measurePile(scene: Scene, x: Float64Array, y: Float64Array, r: Float64Array) {
  const { width, height } = scene.bounds;
  const n = x.length;
  let maxR = 0;
  let area = 0;
  let top = height;
  let escaped = 0;
  for (let k = 0; k < n; k++) {
    maxR = Math.max(maxR, r[k]);
    area += Math.PI * r[k] * r[k];
    top = Math.min(top, y[k] - r[k]);
    if (!(x[k] >= 0 && x[k] <= width && y[k] >= 0 && y[k] <= height)) escaped++;
  }
  const cell = 2 * maxR;
  const columns = Math.ceil(width / cell) + 1;
  const cells = new Map<number, number[]>();
  const cellOf = (k: number) => Math.floor(Math.min(Math.max(y[k], 0), height) / cell) * columns + Math.floor(Math.min(Math.max(x[k], 0), width) / cell);
  for (let k = 0; k < n; k++) {
    const c = cellOf(k);
    const list = cells.get(c);
    if (list) list.push(k);
    else cells.set(c, [k]);
  }
  let sum = 0;
  let deepest = 0;
  let pairs = 0;
  for (let i = 0; i < n; i++) {
    const c = cellOf(i);
    for (const dc of [0, 1, columns - 1, columns, columns + 1]) {
      for (const j of cells.get(c + dc) ?? []) {
        // Each unordered pair once: within a cell by index, across cells from one side only.
        if (dc === 0 && j <= i) continue;
        const reach = r[i] + r[j];
        const d = Math.hypot(x[j] - x[i], y[j] - y[i]);
        if (d >= reach) continue;
        const overlap = (reach - d) / reach;
        sum += overlap;
        deepest = Math.max(deepest, overlap);
        pairs++;
      }
    }
  }
  return {
    meanOverlap: pairs > 0 ? sum / pairs : 0,
    deepestOverlap: deepest,
    overlappingPairs: pairs,
    pileHeight: height - top,
    areaHeight: area / width,
    escaped,
  };
}

export function pilesCsv(result: PilesResult): string {
  const lines = [csvLine(['engine', 'n', 'mean_overlap', 'deepest_overlap', 'overlapping_pairs', 'pile_height', 'area_height', 'motion_px_per_s', 'escaped', 'median_step_ms'])];
  for (const r of result.rows) {
    lines.push(csvLine([r.engine, r.n, r.meanOverlap, r.deepestOverlap, r.overlappingPairs, r.pileHeight, r.areaHeight, r.motion, r.escaped, r.medianStepMs]));
  }
  return lines.join('\n') + '\n';
}

const percent = (x: number) => `${fmt(100 * x)} %`;

export function pilesTables(result: PilesResult): Table[] {
  const o = result.meta.options as unknown as PilesOptions;
  return [
    {
      title: `A settled pile: seed-box, elasticity 0, N = ${o.n}, after ${o.settleSeconds} s`,
      headers: ['engine', 'mean overlap', 'deepest', 'overlapping pairs', 'pile height px', 'area height px', 'motion px/s', 'escaped', 'median step ms'],
      rows: result.rows.map((r) => [
        r.engine,
        percent(r.meanOverlap),
        percent(r.deepestOverlap),
        String(r.overlappingPairs),
        fmt(r.pileHeight),
        fmt(r.areaHeight),
        fmt(r.motion),
        String(r.escaped),
        fmt(r.medianStepMs),
      ]),
      note: `Overlaps are fractions of the pair's summed radii. Area height is the circles' area over the floor's width: a pile lower than that has sunk into itself. Motion is the mean distance a circle travels per second over the ${o.measureSteps} measured steps, when the step time is taken. Each engine with the lab's settings (see its settings in the JSON); maxgrid-piles is maxgrid with solverIterations 4, positionCorrection 0.2, contactSlop 0.05.`,
    },
  ];
}

export function pilesHeadline(result: PilesResult): string[] {
  const line = (r: PilesRow) => `${r.engine} ${percent(r.meanOverlap)} overlap, ${fmt(r.pileHeight)} px high, ${fmt(r.motion)} px/s`;
  const area = result.rows[0]?.areaHeight ?? NaN;
  return [`Settled pile of ${result.rows[0]?.n ?? 0} circles (their area fills ${fmt(area)} px of the floor): ${result.rows.map(line).join('; ')}.`, ''];
}

export const pilesSchema = {
  type: 'object',
  required: ['meta', 'rows'],
  properties: {
    meta: metaSchema,
    rows: {
      type: 'array',
      minItems: 1,
      items: {
        type: 'object',
        required: ['engine', 'n', 'meanOverlap', 'deepestOverlap', 'overlappingPairs', 'pileHeight', 'areaHeight', 'motion', 'escaped', 'medianStepMs'],
        properties: {
          engine: { type: 'string' },
          n: { type: 'integer', minimum: 1 },
          meanOverlap: { type: 'number', minimum: 0 },
          deepestOverlap: { type: 'number', minimum: 0 },
          overlappingPairs: { type: 'integer', minimum: 0 },
          pileHeight: { type: 'number' },
          areaHeight: { type: 'number', exclusiveMinimum: 0 },
          motion: { type: 'number', minimum: 0 },
          escaped: { type: 'integer', minimum: 0 },
          medianStepMs: { type: 'number', minimum: 0 },
        },
        additionalProperties: false,
      },
    },
  },
  additionalProperties: false,
} as const;
