import type * as CANNON from 'cannon-es';
import { CUBE_SIZE, DT, MutableTypes, addCube, createWorld, isSleeping, isStatic, setSleeping } from './physics.js';
import { jitter, mulberry32 } from './rng.js';

/**
 * The layered-drop experiment of 5.3.3 / figure 9: layers of cubes are dropped on top of one
 * another, and the same simulation is run three separate times: as a control experiment (no
 * sleeping, no mutable types), with sleeping objects, and with mutable physics object types
 * (each cube set to static once it landed on the previous layer, or on the floor).
 *
 * Fairness rules, so the three averages compare:
 * - the layout comes from a seeded PRNG, so every variant drops the very same cubes;
 * - physics runs at the fixed dt of 1/60 s for the same number of steps in every variant;
 * - only world.step() is timed; building layers, bookkeeping and drawing are not. The mutable
 *   types' own bookkeeping (finding landed cubes) is timed separately and shown on its own row.
 */

export type Variant = 'control' | 'sleeping' | 'mutable';

export const VARIANTS: readonly { readonly id: Variant; readonly label: string }[] = [
  { id: 'control', label: 'Control experiment' },
  { id: 'sleeping', label: 'Sleeping objects' },
  { id: 'mutable', label: 'Mutable physics object types' },
];

export interface LayeredDropSettings {
  /** Number of layers dropped. */
  layers: number;
  /** Each layer is side × side cubes. */
  side: number;
  /** Steps between one layer's drop and the next (60 = one simulated second). */
  dropInterval: number;
  /** Steps simulated after the last layer is dropped. */
  settleSteps: number;
  seed: number;
}

export const DEFAULT_SETTINGS: LayeredDropSettings = { layers: 8, side: 5, dropInterval: 60, settleSteps: 120, seed: 9 };

/** The fixed number of steps every variant runs. */
export function totalSteps(s: LayeredDropSettings): number {
  return s.layers * s.dropInterval + s.settleSteps;
}

/**
 * Height above a layer's resting place from which it is dropped: ~0.45 s of fall. Low enough that
 * a landing layer mostly stays a layer (figure 9 stacks layers, it does not pile rubble), high
 * enough that every layer still hits the one below with some speed.
 */
const DROP_HEIGHT = 1;
/** Gap between neighbouring cubes in a layer, so a layer starts without overlaps. */
const GAP = 0.08 * CUBE_SIZE;

interface Placement {
  x: number;
  y: number;
  z: number;
  yaw: number;
}

/** Every layer's cube placements, from the seed alone. */
export function layout(s: LayeredDropSettings): Placement[][] {
  const rng = mulberry32(s.seed);
  const pitch = CUBE_SIZE + GAP;
  const layers: Placement[][] = [];
  for (let k = 0; k < s.layers; k++) {
    // Cubes sit in columns over the layer below, with a little seeded jitter in place and turn,
    // so landings are not perfectly symmetric (a perfectly aligned stack never shifts at all).
    const rest = (k + 0.5) * CUBE_SIZE;
    const layer: Placement[] = [];
    for (let i = 0; i < s.side; i++) {
      for (let j = 0; j < s.side; j++) {
        layer.push({
          x: (i - (s.side - 1) / 2) * pitch + jitter(rng, 0.04),
          y: rest + DROP_HEIGHT + jitter(rng, 0.02),
          z: (j - (s.side - 1) / 2) * pitch + jitter(rng, 0.04),
          yaw: jitter(rng, 0.05),
        });
      }
    }
    layers.push(layer);
  }
  return layers;
}

/** One run of one variant, stepped from outside so the page can draw and stay responsive. */
export class LayeredDrop {
  readonly world: CANNON.World = createWorld();
  readonly cubes: CANNON.Body[] = [];
  readonly stepMs: Float64Array;
  readonly steps: number;
  /** Time spent in the mutable types' landed check, which is not part of world.step. */
  bookkeepingMs = 0;
  done = 0;
  private readonly mutable = new MutableTypes(this.world);
  private readonly layers: Placement[][];

  constructor(
    readonly settings: LayeredDropSettings,
    readonly variant: Variant,
  ) {
    setSleeping(this.world, variant === 'sleeping');
    this.mutable.enabled = variant === 'mutable';
    this.layers = layout(settings);
    this.steps = totalSteps(settings);
    this.stepMs = new Float64Array(this.steps);
  }

  get finished(): boolean {
    return this.done >= this.steps;
  }

  /** Runs one fixed step; returns false once all steps are done. */
  step(): boolean {
    if (this.finished) return false;
    const s = this.settings;
    if (this.done % s.dropInterval === 0) {
      const layer = this.layers[this.done / s.dropInterval];
      if (layer) for (const p of layer) this.cubes.push(addCube(this.world, p.x, p.y, p.z, p.yaw));
    }
    const t0 = performance.now();
    this.world.step(DT);
    const t1 = performance.now();
    this.mutable.afterStep();
    this.bookkeepingMs += performance.now() - t1;
    this.stepMs[this.done] = t1 - t0;
    this.done++;
    return true;
  }

  result(): VariantResult {
    const sorted = Float64Array.from(this.stepMs.subarray(0, this.done)).sort();
    const n = sorted.length;
    let total = 0;
    for (const ms of sorted) total += ms;
    const mid = n >> 1;
    const median = n === 0 ? NaN : n % 2 === 1 ? sorted[mid]! : (sorted[mid - 1]! + sorted[mid]!) / 2;
    return {
      variant: this.variant,
      steps: n,
      cubes: this.cubes.length,
      totalMs: total,
      averageMs: total / n,
      medianMs: median,
      bookkeepingMs: this.bookkeepingMs / n,
      staticAtEnd: this.cubes.filter(isStatic).length,
      sleepingAtEnd: this.cubes.filter(isSleeping).length,
    };
  }
}

export interface VariantResult {
  variant: Variant;
  steps: number;
  cubes: number;
  totalMs: number;
  averageMs: number;
  medianMs: number;
  /** Mean per step of work outside world.step that the technique needs (mutable types only). */
  bookkeepingMs: number;
  staticAtEnd: number;
  sleepingAtEnd: number;
}

/** Called between chunks of steps: draw the run in progress, update the progress text. */
export type Progress = (run: LayeredDrop) => void;

/** Wall-clock budget per chunk of steps before yielding to the browser (to draw, take input). */
const CHUNK_MS = 30;

const nextTask = (): Promise<void> => new Promise((resolve) => setTimeout(resolve, 0));

async function runToEnd(run: LayeredDrop, progress: Progress): Promise<void> {
  while (!run.finished) {
    const until = performance.now() + CHUNK_MS;
    while (performance.now() < until && run.step());
    progress(run);
    await nextTask();
  }
}

/**
 * Runs the three variants in turn and returns their results. A short untimed warm-up run comes
 * first: otherwise the first variant (the control) would also pay for V8 compiling Cannon's hot
 * paths, which has nothing to do with the technique being measured.
 */
export async function runExperiment(settings: LayeredDropSettings, progress: Progress): Promise<VariantResult[]> {
  const warmUp = new LayeredDrop({ ...settings, layers: Math.min(2, settings.layers), settleSteps: 0 }, 'control');
  await runToEnd(warmUp, () => undefined);
  const results: VariantResult[] = [];
  for (const { id } of VARIANTS) {
    const run = new LayeredDrop(settings, id);
    await runToEnd(run, progress);
    results.push(run.result());
  }
  return results;
}
