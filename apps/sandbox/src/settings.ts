import { BROADPHASE_NAMES, INTEGRATOR_NAMES, type BroadPhaseName, type IntegratorName } from '@maxgrid/engine';
import { seedBoxParams } from '@maxgrid/scenes';

/**
 * Everything the URL reproduces. The scene fields are exactly the seed-box scene's parameters, so
 * a (settings) value always rebuilds the same bodies; the rest choose how the world is stepped
 * and drawn.
 */
export interface Settings {
  n: number;
  seed: number;
  gravity: number;
  elasticity: number;
  size: number;
  sizeNoise: number;
  velocity: number;
  velocityNoise: number;
  broadphase: BroadPhaseName;
  integrator: IntegratorName;
  renderer: RendererName;
  grid: boolean;
  aabb: boolean;
}

export type SceneKey = 'n' | 'seed' | 'gravity' | 'elasticity' | 'size' | 'sizeNoise' | 'velocity' | 'velocityNoise';

export const RENDERER_NAMES = ['canvas', 'webgl'] as const;
export type RendererName = (typeof RENDERER_NAMES)[number];

export interface NumberSpec {
  key: SceneKey;
  label: string;
  /** The URL accepts [min, max]; the slider may cover the same range through `slider`. */
  min: number;
  max: number;
  step: number;
  default: number;
  format(value: number): string;
  /** For sliders whose position is not the value (Quantity is logarithmic). */
  slider?: { min: number; max: number; toValue(position: number): number; toPosition(value: number): number };
}

const fixed = (digits: number, unit = '') => (v: number) => v.toFixed(digits) + unit;
const percent = (v: number) => `${Math.round(v * 100)}%`;

// Quantity spans 0..200,000, so a linear slider would make every count under a few thousand
// unreachable; positions map logarithmically, rounded to two significant digits.
const QUANTITY_MAX = 200_000;
const QUANTITY_POSITIONS = 600;
const QUANTITY_DECADES = Math.log10(QUANTITY_MAX);

function twoSignificant(v: number): number {
  if (v < 100) return Math.round(v);
  const unit = 10 ** (Math.floor(Math.log10(v)) - 1);
  return Math.round(v / unit) * unit;
}

export const NUMBER_SPECS: readonly NumberSpec[] = [
  { key: 'gravity', label: 'Gravity', min: -2000, max: 2000, step: 10, default: seedBoxParams.gravity.default, format: fixed(0, ' px/s²') },
  { key: 'elasticity', label: 'Elasticity', min: 0, max: 1, step: 0.01, default: seedBoxParams.elasticity.default, format: fixed(2) },
  {
    key: 'n',
    label: 'Quantity',
    min: 0,
    max: QUANTITY_MAX,
    step: 1,
    default: seedBoxParams.n.default,
    format: (v) => v.toLocaleString('en-US'),
    slider: {
      min: 0,
      max: QUANTITY_POSITIONS,
      toValue: (p) => (p <= 0 ? 0 : Math.min(QUANTITY_MAX, twoSignificant(10 ** ((QUANTITY_DECADES * (p - 1)) / (QUANTITY_POSITIONS - 1))))),
      toPosition: (v) => (v <= 0 ? 0 : 1 + Math.round(((QUANTITY_POSITIONS - 1) * Math.log10(v)) / QUANTITY_DECADES)),
    },
  },
  // Size is capped well below the scene's own limit so the largest circle always fits the box.
  { key: 'size', label: 'Size', min: 0.5, max: 40, step: 0.5, default: seedBoxParams.size.default, format: fixed(1, ' px') },
  { key: 'sizeNoise', label: 'Size noise', min: 0, max: 0.99, step: 0.01, default: seedBoxParams.sizeNoise.default, format: percent },
  { key: 'velocity', label: 'Velocity', min: 0, max: 2000, step: 10, default: seedBoxParams.velocity.default, format: fixed(0, ' px/s') },
  { key: 'velocityNoise', label: 'Velocity noise', min: 0, max: 1, step: 0.01, default: seedBoxParams.velocityNoise.default, format: percent },
];

export const SEED_MAX = seedBoxParams.seed.max;

/** Naive is O(n²) per step: above this many bodies one step would freeze the page for seconds. */
export const NAIVE_LIMIT = 5000;

export function defaultSettings(): Settings {
  const s = { seed: seedBoxParams.seed.default } as Settings;
  for (const spec of NUMBER_SPECS) s[spec.key] = spec.default;
  s.broadphase = 'maxgrid';
  s.integrator = 'semi-implicit-euler';
  s.renderer = 'canvas';
  s.grid = false;
  s.aabb = false;
  return s;
}

/** Clamps into the spec's range and snaps to its step; NaN falls back to the default. */
export function clampNumber(spec: NumberSpec, value: number): number {
  if (!Number.isFinite(value)) return spec.default;
  const clamped = Math.min(spec.max, Math.max(spec.min, value));
  if (spec.key === 'n') return Math.round(clamped);
  const snapped = spec.min + Math.round((clamped - spec.min) / spec.step) * spec.step;
  // Round away binary noise such as 0.30000000000000004, which would show up in the URL.
  return Math.min(spec.max, Number(snapped.toFixed(6)));
}

export function clampSeed(value: number): number {
  return Number.isFinite(value) ? Math.min(SEED_MAX, Math.max(0, Math.trunc(value))) : seedBoxParams.seed.default;
}

/** A broad-phase that can run this many bodies without stalling the page. */
export function usableBroadphase(name: BroadPhaseName, n: number): BroadPhaseName {
  return name === 'naive' && n > NAIVE_LIMIT ? 'maxgrid' : name;
}

function oneOf<T extends string>(names: readonly T[], value: string | null, fallback: T): T {
  return value !== null && (names as readonly string[]).includes(value) ? (value as T) : fallback;
}

/** Reads settings from a query string. Anything missing or malformed falls back to its default. */
export function parseSettings(search: string): Settings {
  const q = new URLSearchParams(search);
  const s = defaultSettings();
  for (const spec of NUMBER_SPECS) {
    const raw = q.get(spec.key);
    if (raw !== null && raw.trim() !== '') s[spec.key] = clampNumber(spec, Number(raw));
  }
  const seed = q.get('seed');
  if (seed !== null && seed.trim() !== '') s.seed = clampSeed(Number(seed));
  // Too many bodies for naive is resolved when the world is built, where the page can say so.
  s.broadphase = oneOf(BROADPHASE_NAMES, q.get('broadphase'), s.broadphase);
  s.integrator = oneOf(INTEGRATOR_NAMES, q.get('integrator'), s.integrator);
  s.renderer = oneOf(RENDERER_NAMES, q.get('renderer'), s.renderer);
  s.grid = q.get('grid') === '1';
  s.aabb = q.get('aabb') === '1';
  return s;
}

export function serializeSettings(s: Settings): string {
  const q = new URLSearchParams();
  for (const spec of NUMBER_SPECS) q.set(spec.key, String(s[spec.key]));
  q.set('seed', String(s.seed));
  q.set('broadphase', s.broadphase);
  q.set('integrator', s.integrator);
  q.set('renderer', s.renderer);
  if (s.grid) q.set('grid', '1');
  if (s.aabb) q.set('aabb', '1');
  return '?' + q.toString();
}

/** The seed-box parameters for these settings (box size left at the report's 1600 x 900). */
export function sceneParams(s: Settings): Record<string, number> {
  return {
    n: s.n,
    seed: s.seed,
    gravity: s.gravity,
    elasticity: s.elasticity,
    size: s.size,
    sizeNoise: s.sizeNoise,
    velocity: s.velocity,
    velocityNoise: s.velocityNoise,
  };
}
