import type { Scene, ShapeScene } from '@maxgrid/scenes';
import type { Engine, EngineInfo } from '../engines/adapter.js';
import { bodyCentroid, placedVertices, type ShapeEngine, type ShapeEngineInfo } from '../shape-engines/adapter.js';
import { PIXELS_PER_METER as MATTER_PIXELS_PER_METER } from '../shape-engines/matter.js';

export type Profile = 'quick' | 'full';

/** Where the numbers came from; the caller fills it (Node and browsers know different things). */
export interface Environment {
  runtime: string;
  [key: string]: string | number;
}

export interface Meta {
  experiment: string;
  generatedAt: string;
  profile: Profile | 'custom';
  environment: Environment;
  engines: EngineInfo[];
  options: Record<string, unknown>;
  /** The command that reproduces this result, where the runner knows it. */
  command?: string;
}

export interface Progress {
  (done: number, total: number, label: string): void;
}

export interface RunContext {
  engines: Engine[];
  /** The engines of an experiment on shape scenes (Experiment.shapes). */
  shapeEngines?: ShapeEngine[];
  environment: Environment;
  profile?: Profile | 'custom';
  progress?: Progress;
  /** Lets long loops give the browser's event loop a turn; Node passes nothing. */
  yieldToHost?: () => Promise<void>;
  /** What only Node can do (a C compiler, a headless Chromium); absent in the browser. */
  host?: Host;
}

/** One run of the C baseline: per-step times after warm-up and the final state hash. */
export interface CRun {
  stepMs: number[];
  hash: string;
}

export interface CBaseline {
  /** The exact compile command, for the outputs. */
  command: string;
  compiler: string;
  run(scene: Scene, steps: number, warmupSteps: number, dt: number): Promise<CRun>;
}

/** A maxgrid world living in a browser tab, stepped on request. */
export interface RemoteWorld {
  /** Steps `count` times; returns each step's time in ms as the browser measured it. */
  step(count: number, dt: number): Promise<number[]>;
  hash(): Promise<string>;
  dispose(): Promise<void>;
}

export interface BrowserHost {
  /** e.g. "Chromium 156.0.1.2 (headless, Debian /usr/bin/chromium)". */
  runtime: string;
  settings: Record<string, string>;
  /** Builds the scene in the page with the lab's maxgrid options (`maxgridBuildOptions`). */
  world(scene: string, params: Record<string, number>, broadphase: string): Promise<RemoteWorld>;
  close(): Promise<void>;
}

/** What the sandbox page's `window.__sandboxFrames.read()` returns (apps/sandbox/src/frame-log.ts). */
export interface FrameSample {
  /** requestAnimationFrame timestamps (ms), one per frame, oldest first. */
  start: number[];
  /** Per frame: time spent stepping the world (all the fixed steps the frame ran). */
  stepMs: number[];
  /** Per frame: time spent drawing, CPU side (uploads and draw calls, not the GPU's own work). */
  drawMs: number[];
  /** Per frame: fixed steps run. */
  steps: number[];
  /** Steps the simulation dropped since the page loaded (it runs slow rather than spiral). */
  droppedSteps: number;
  /** Simulated seconds since the current world was built. */
  simulatedSeconds: number;
  bodies: number;
  renderer: string;
  threads: number;
}

/** One timed stretch of the live sandbox page. */
export interface SandboxRun {
  frames: FrameSample;
  /** Steps dropped during the timed stretch. */
  droppedSteps: number;
  /** The WebGL context's GPU as the browser names it; null when the page draws with canvas 2D. */
  webglDevice: string | null;
  /** The page's notice line: says when it fell back (no WebGL, workers that did not start). */
  notice: string;
  devicePixelRatio: number;
}

/** The sandbox page open in a browser tab. */
export interface SandboxHost {
  runtime: string;
  settings: Record<string, string>;
  /** Loads the sandbox with this query string, lets it run `warmupSeconds`, then times `seconds`. */
  measure(query: string, warmupSeconds: number, seconds: number): Promise<SandboxRun>;
  close(): Promise<void>;
}

/**
 * Node-only capabilities, each resolving to a skip reason (a string) where unavailable, so that
 * an experiment records "skipped: ..." rather than failing on a machine without gcc or Chromium.
 */
export interface Host {
  cBaseline(): Promise<CBaseline | string>;
  browser(): Promise<BrowserHost | string>;
  sandbox(): Promise<SandboxHost | string>;
  /** Node's host-scaling probe (node/host-scaling.ts), for T4's context; absent where not run. */
  hostScaling?(): Promise<HostScaling>;
  /** Starts `count` processes that keep a core busy each; resolves to what stops them. Node only. */
  busyProcesses?(count: number): Promise<() => void>;
}

/** Twice the work on 2 threads against once on 1, by time: 2 is perfect, 1 no gain. */
export interface HostScaling {
  /** A compute-bound loop. */
  compute: number;
  /** Streaming 128 MiB per thread, past the shared cache. */
  memory: number;
}

export const hostScalingSchema = {
  type: 'object',
  required: ['compute', 'memory'],
  properties: { compute: { type: 'number', exclusiveMinimum: 0 }, memory: { type: 'number', exclusiveMinimum: 0 } },
  additionalProperties: false,
} as const;

export function makeMeta(experiment: string, ctx: RunContext, options: object): Meta {
  return {
    experiment,
    generatedAt: new Date().toISOString(),
    profile: ctx.profile ?? 'custom',
    environment: ctx.environment,
    engines: [...ctx.engines.map((e) => e.info), ...(ctx.shapeEngines ?? []).map((e) => shapeEngineRow(e.info))],
    options: { ...options },
  };
}

export interface Spread {
  median: number;
  p25: number;
  p75: number;
  min: number;
  max: number;
  mean: number;
}

/** Quantiles by linear interpolation between order statistics (R's type 7). */
export function quantile(sorted: readonly number[], q: number): number {
  if (sorted.length === 0) return NaN;
  const h = (sorted.length - 1) * q;
  const lo = Math.floor(h);
  const hi = Math.min(lo + 1, sorted.length - 1);
  return sorted[lo] + (h - lo) * (sorted[hi] - sorted[lo]);
}

export function spread(values: readonly number[]): Spread {
  if (values.length === 0) throw new RangeError('spread of no values');
  const s = [...values].sort((a, b) => a - b);
  return {
    median: quantile(s, 0.5),
    p25: quantile(s, 0.25),
    p75: quantile(s, 0.75),
    min: s[0],
    max: s[s.length - 1],
    mean: s.reduce((a, b) => a + b, 0) / s.length,
  };
}

/**
 * A shape engine as a row of the settings table: its id marked `(shapes)` (its settings differ
 * from the circle adapter's of the same engine), both profiles' settings, units per scene.
 */
export function shapeEngineRow(info: ShapeEngineInfo): EngineInfo {
  const settings: Record<string, string | number | boolean> = {};
  for (const [profile, values] of Object.entries(info.settings)) {
    for (const [key, value] of Object.entries(values)) settings[`${profile}.${key}`] = value;
  }
  return { id: `${info.id} (shapes)`, package: info.package, version: info.version, precision: info.precision, lengthScale: 0, settings };
}

/** `engines` whose id starts with `maxgrid:`, as the maxgrid-only experiments need. */
export function maxgridOnly(engines: Engine[], experiment: string): Engine[] {
  const out = engines.filter((e) => e.info.id.startsWith('maxgrid:'));
  if (out.length === 0) {
    throw new RangeError(`${experiment} measures maxgrid broad-phases only; got engines ${engines.map((e) => e.info.id).join(', ')}`);
  }
  return out;
}

export function rotate<T>(items: readonly T[], by: number): T[] {
  const k = ((by % items.length) + items.length) % items.length;
  return [...items.slice(k), ...items.slice(0, k)];
}

/** A list of N values from start to end inclusive in steps, e.g. the report's 10..4200 by 10. */
export function nRange(start: number, end: number, step: number): number[] {
  const out: number[] = [];
  for (let n = start; n <= end; n += step) out.push(n);
  return out;
}

export const now: () => number = () => performance.now();

/**
 * Steps `count` simulations side by side in turns: at each turn a simulation takes up to
 * `turnSteps` steps, one after another, and the order rotates each turn (starting `offset` along),
 * so that the machine's noise falls on all of them alike and none always steps right after
 * another. The first step of a turn finds the caches full of the simulation before's data, which
 * costs engines unlike amounts (stepped in turn a single step at a time, Matter and p2 took twice
 * their time on shape-step-time's uniform-polygons, Box2D 1.3 times): it is taken with
 * `step(i, false)`, not to be timed, unless it is the turn's only step; the others with
 * `step(i, true)`.
 *
 * `left(i)` is asked at the start of simulation i's turn: how many more steps it takes, the
 * untimed first of this turn included (at most `turnSteps` of them are taken at this turn; 0 sits
 * it out). `more(i)`, asked before each later step of the turn, may end the turn early (a budget
 * spent). The stepping ends at the first turn in which no simulation steps; `between` runs after
 * each turn in which one did.
 */
export async function stepInTurns(
  count: number,
  turnSteps: number,
  offset: number,
  left: (i: number) => number,
  step: (i: number, timed: boolean) => void,
  more: (i: number) => boolean = () => true,
  between?: (turn: number) => unknown,
): Promise<void> {
  const turn = Math.max(1, Math.round(turnSteps));
  for (let t = 0; ; t++) {
    let stepped = false;
    for (let k = 0; k < count; k++) {
      const i = (t + offset + k) % count;
      const length = Math.min(turn, Math.floor(left(i)));
      for (let s = 0; s < length; s++) {
        if (s > 0 && !more(i)) break;
        step(i, s > 0 || length === 1);
        stepped = true;
      }
    }
    if (!stepped) return;
    await between?.(t);
  }
}

/** How many of `steps` steps taken in turns of `turnSteps` (see stepInTurns) are timed. */
export function timedInTurns(steps: number, turnSteps: number): number {
  const turn = Math.max(1, Math.round(turnSteps));
  let timed = 0;
  for (let first = 0; first < steps; first += turn) timed += Math.min(turn, steps - first) > 1 ? Math.min(turn, steps - first) - 1 : 1;
  return timed;
}

/** A simulation as every engine adapter gives one. */
export interface Steppable {
  step(dt: number): void;
  dispose(): void;
}

/**
 * How long each engine warms up on a case before it is timed (see warmUp), per profile: enough
 * for V8 to optimise the step of a small scene, the slowest to warm since its functions run few
 * times a step (docs/results.md, "How engines are timed", has the measurements behind it).
 */
export function warmUpMs(profile: Profile): number {
  return profile === 'full' ? 1500 : 400;
}

/**
 * Brings an engine's code to its steady state before it is timed, on throwaway twins of the
 * simulation about to be timed: each twin is created from the same scene and stepped through the
 * timed run's own `steps` (from the scene's start, so that the same code paths run), twin after
 * twin, until `budgetMs` have passed; a twin is cut short when the budget runs out. Returns the
 * steps the twins took.
 *
 * Why: JavaScript engines (maxgrid, planck, Matter.js, p2) start in V8's interpreter and
 * WebAssembly ones (Rapier, Box2D) in its baseline compiler, and only optimise code that has run
 * often. A large scene's step runs each loop long enough for that within a step or two; a small
 * scene's does not, and its first few hundred steps run several times slower than the rest,
 * which would rank engines by how fast they start rather than how fast they step. Warming on
 * twins rather than on the timed simulation keeps the timed run starting where it always did,
 * so figures read at its end keep their simulated time.
 */
export function warmUp(create: () => Steppable, steps: number, dt: number, budgetMs: number): number {
  let taken = 0;
  if (steps <= 0 || !(budgetMs > 0)) return 0;
  const start = now();
  while (now() - start < budgetMs) {
    const twin = create();
    try {
      for (let i = 0; i < steps && now() - start < budgetMs; i++, taken++) twin.step(dt);
    } finally {
      twin.dispose();
    }
  }
  return taken;
}

// JSON Schema pieces shared by every experiment's schema.
export const spreadSchema = {
  type: 'object',
  required: ['median', 'p25', 'p75', 'min', 'max', 'mean'],
  properties: Object.fromEntries(['median', 'p25', 'p75', 'min', 'max', 'mean'].map((k) => [k, { type: 'number' }])),
  additionalProperties: false,
} as const;

export const metaSchema = {
  type: 'object',
  required: ['experiment', 'generatedAt', 'profile', 'environment', 'engines', 'options'],
  properties: {
    experiment: { type: 'string' },
    generatedAt: { type: 'string' },
    profile: { enum: ['quick', 'full', 'custom'] },
    environment: { type: 'object', required: ['runtime'], properties: { runtime: { type: 'string' } } },
    engines: {
      type: 'array',
      minItems: 1,
      items: {
        type: 'object',
        required: ['id', 'package', 'version', 'precision', 'lengthScale', 'settings'],
        properties: {
          id: { type: 'string' },
          package: { type: 'string' },
          version: { type: 'string', pattern: '^\\d+\\.\\d+\\.\\d+' },
          precision: { enum: ['f32', 'f64'] },
          lengthScale: { type: 'number', exclusiveMinimum: 0 },
          settings: { type: 'object', minProperties: 1 },
        },
      },
    },
    options: { type: 'object' },
  },
} as const;

/**
 * metaSchema for experiments on shape scenes: their engines' rows (shapeEngineRow) have
 * lengthScale 0, which says their units are per scene (1 m = the scene's lengthUnit), where
 * metaSchema asks the circle engines for their one scale, above 0.
 */
export const shapeMetaSchema = {
  ...metaSchema,
  properties: {
    ...metaSchema.properties,
    engines: {
      ...metaSchema.properties.engines,
      items: { ...metaSchema.properties.engines.items, properties: { ...metaSchema.properties.engines.items.properties, lengthScale: { type: 'number', minimum: 0 } } },
    },
  },
} as const;

/** A shape scene's length unit (scene units per metre) and its dynamic bodies' reach, centre to rim, in metres. */
export interface SceneScale {
  lengthUnit: number;
  smallestM: number;
  largestM: number;
}

export const sceneScaleSchema = {
  type: 'object',
  required: ['lengthUnit', 'smallestM', 'largestM'],
  properties: { lengthUnit: { type: 'number', exclusiveMinimum: 0 }, smallestM: { type: 'number' }, largestM: { type: 'number' } },
  additionalProperties: false,
} as const;

export function sceneScale(scene: ShapeScene): SceneScale {
  const lengthUnit = scene.world.lengthUnit ?? 1;
  let smallest = Infinity;
  let largest = 0;
  for (const body of scene.bodies) {
    if ((body.type ?? 'dynamic') !== 'dynamic') continue;
    const c = bodyCentroid(body);
    let reach = 0;
    for (const shape of body.shapes) {
      const ox = (shape.offsetX ?? 0) - c.x;
      const oy = (shape.offsetY ?? 0) - c.y;
      if (shape.kind === 'circle') reach = Math.max(reach, Math.hypot(ox, oy) + shape.radius);
      else if (shape.kind === 'capsule') reach = Math.max(reach, Math.hypot(ox, oy) + shape.length / 2 + shape.radius);
      else for (const v of placedVertices(shape)) reach = Math.max(reach, Math.hypot(v.x - c.x, v.y - c.y));
    }
    smallest = Math.min(smallest, reach);
    largest = Math.max(largest, reach);
  }
  return { lengthUnit, smallestM: (Number.isFinite(smallest) ? smallest : 0) / lengthUnit, largestM: largest / lengthUnit };
}

/** Three significant digits (report/tables.ts's fmt, which this module cannot import: tables imports the experiments). */
function digits3(x: number): string {
  return Number(x.toPrecision(3)).toString();
}

/**
 * The sentence a shape experiment's table notes carry on units: what each peer took a scene unit
 * for, per lengthUnit among `cases`, and that Box2D 2.4's and planck's results depend on it.
 */
export function scaleNote(cases: readonly { scene: string; scale: SceneScale | undefined }[]): string {
  const known = cases.filter((c): c is { scene: string; scale: SceneScale } => c.scale !== undefined);
  if (known.length === 0) return '';
  const units = [...new Set(known.map((c) => c.scale.lengthUnit))].sort((a, b) => a - b);
  const groups = units.map((unit) => {
    const these = known.filter((c) => c.scale.lengthUnit === unit);
    const scenes = [...new Set(these.map((c) => c.scene))];
    const smallest = Math.min(...these.map((c) => c.scale.smallestM));
    const largest = Math.max(...these.map((c) => c.scale.largestM));
    return `${scenes.join(', ')} at lengthUnit ${digits3(unit)} (bodies ${digits3(smallest)} to ${digits3(largest)} m from centre to rim): Box2D 2.4.1 (WASM), planck, Rapier and p2-es ran 1 scene unit as ${digits3(1 / unit)} m, Matter.js as ${digits3(MATTER_PIXELS_PER_METER / unit)} px (1 m = ${MATTER_PIXELS_PER_METER} px)`;
  });
  return `Units: ${groups.join('; ')}; maxgrid steps scene units with its tolerances scaled by lengthUnit, so it sees the same metres. Box2D 2.4's and planck's results depend on that scale: their skins (1 cm) and slop (0.5 cm) are fixed in metres, tuned for moving shapes of 0.1 to 10 m.`;
}

export function csvLine(values: readonly (string | number)[]): string {
  return values.map((v) => (typeof v === 'number' ? String(v) : /[",\n]/.test(v) ? `"${v.replace(/"/g, '""')}"` : v)).join(',');
}
