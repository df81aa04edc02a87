import { SCENES, SHAPE_SCENES, seedBoxParams, type ParamSpec } from '@maxgrid/scenes';

/** The circle scenes the page offers; bouncing-ball is one circle, a lab accuracy test rather than a view. */
export const CIRCLE_SCENE_CHOICES = ['seed-box', 'funnel', 'mixed', 'uniform'] as const;
/** The scenes of bodies held together by joints (pins, springs, wheels), after the other shapes. */
export const JOINT_SCENE_CHOICES = ['chain', 'bridge', 'joint-grid', 'ragdolls', 'car', 'jellies', 'blobs'] as const;
/** The scenes of shapes (boxes, polygons, capsules that turn), after the circles. */
export const SHAPE_SCENE_CHOICES = ['polygon-box', 'pyramid', 'uniform-polygons', 'many-pyramids', 'tumbler', 'vertical-stack', 'card-house', 'ramp', ...JOINT_SCENE_CHOICES] as const;
export const SCENE_CHOICES = [...CIRCLE_SCENE_CHOICES, ...SHAPE_SCENE_CHOICES] as const;
export type SceneChoice = (typeof SCENE_CHOICES)[number];
export type ShapeSceneChoice = (typeof SHAPE_SCENE_CHOICES)[number];

export function isShapeScene(scene: SceneChoice): scene is ShapeSceneChoice {
  return (SHAPE_SCENE_CHOICES as readonly string[]).includes(scene);
}

export function isJointScene(scene: SceneChoice): boolean {
  return (JOINT_SCENE_CHOICES as readonly string[]).includes(scene);
}

/** A scene's description and parameter specs, circle or shape. */
export function sceneDefinition(scene: SceneChoice): { description: string; params: Record<string, ParamSpec> } {
  const definition = isShapeScene(scene) ? SHAPE_SCENES[scene] : SCENES[scene];
  return { description: definition.description, params: definition.params as Record<string, ParamSpec> };
}

/** The scene's default seed; scenes without one (Box2D's benchmarks) are seed 1 and ignore it. */
export function defaultSeed(scene: SceneChoice): number {
  return sceneDefinition(scene).params.seed?.default ?? 1;
}

export interface NumberSpec {
  key: string;
  label: string;
  /** The URL accepts any value in [min, max] (a whole one where `integer`) and keeps it as it is. */
  min: number;
  max: number;
  /** The slider's resolution: it stops at multiples of it. */
  step: number;
  integer: boolean;
  default: number;
  /** What the parameter means, from the scene's own spec; shown as the slider's tooltip. */
  description: string;
  format(value: number): string;
  /**
   * The range input: its min, max and step, and the value each position stands for. Quantity's
   * positions are logarithmic; elsewhere the position is the value, at a multiple of `step`.
   */
  slider: { min: number; max: number; step: number; toValue(position: number): number; toPosition(value: number): number };
}

const fixed = (digits: number, unit = '') => (v: number) => v.toFixed(digits) + unit;
const percent = (v: number) => `${Math.round(v * 100)}%`;
const count = (v: number) => v.toLocaleString('en-US');

function twoSignificant(v: number): number {
  if (v < 100) return Math.round(v);
  const unit = 10 ** (Math.floor(Math.log10(v)) - 1);
  return Math.round(v / unit) * unit;
}

// Quantities span several decades, so a linear slider would make every small count unreachable;
// positions map logarithmically, rounded to two significant digits.
function logSlider(max: number): NumberSpec['slider'] {
  const positions = 600;
  const decades = Math.log10(max);
  return {
    min: 0,
    max: positions,
    step: 1,
    toValue: (p) => (p <= 0 ? 0 : Math.min(max, twoSignificant(10 ** ((decades * (p - 1)) / (positions - 1))))),
    toPosition: (v) => (v <= 0 ? 0 : 1 + Math.round(((positions - 1) * Math.log10(v)) / decades)),
  };
}

/** Digits after the point in `step` as written (0.0005: 4): k step rounded to them is free of binary noise. */
function decimals(step: number): number {
  const written = String(step);
  const point = written.indexOf('.');
  return point < 0 ? 0 : written.length - point - 1;
}

/**
 * A slider whose stops are the multiples of `step` (a range input stops at its min + k step, so
 * its min is the multiple at or below `min`, and its max the one at or above `max`), each value
 * clamped into [min, max]: a density from 0.001 in steps of 1 stops at 0.001, 1, 2, ... 1000
 * rather than at 1.001, 2.001, ..., and every stop is a value the URL keeps as it is.
 */
function gridSlider(min: number, max: number, step: number): NumberSpec['slider'] {
  const digits = decimals(step);
  const multiple = (k: number) => Number((k * step).toFixed(digits));
  let low = Math.floor(min / step);
  if (multiple(low + 1) <= min) low++;
  let high = Math.ceil(max / step);
  if (multiple(high - 1) >= max) high--;
  return {
    min: multiple(low),
    max: multiple(high),
    step,
    // The input's own arithmetic may leave binary noise (0.30000000000000004) that would show in the URL.
    toValue: (position) => Math.min(max, Math.max(min, Number(position.toFixed(digits)))),
    toPosition: (value) => value,
  };
}

/** The page's widest quantity: the WebGL renderer still draws this many at interactive rates. */
export const QUANTITY_MAX = 200_000;

/** A spec of real values on a slider that stops at multiples of its step. */
function linear(spec: Omit<NumberSpec, 'integer' | 'slider'>): NumberSpec {
  return { ...spec, integer: false, slider: gridSlider(spec.min, spec.max, spec.step) };
}

const seedBox = seedBoxParams;
// The report's sliders, kept as they were for the seed-box scene (labels, ranges, formats).
const SEED_BOX_SPECS: readonly NumberSpec[] = [
  linear({ key: 'gravity', label: 'Gravity', min: -2000, max: 2000, step: 10, default: seedBox.gravity.default, description: seedBox.gravity.description, format: fixed(0, ' px/s²') }),
  linear({ key: 'elasticity', label: 'Elasticity', min: 0, max: 1, step: 0.01, default: seedBox.elasticity.default, description: seedBox.elasticity.description, format: fixed(2) }),
  { key: 'n', label: 'Quantity', min: 0, max: QUANTITY_MAX, step: 1, integer: true, default: seedBox.n.default, description: seedBox.n.description, format: count, slider: logSlider(QUANTITY_MAX) },
  // Size is capped well below the scene's own limit so the largest circle always fits the box.
  linear({ key: 'size', label: 'Size', min: 0.5, max: 40, step: 0.5, default: seedBox.size.default, description: seedBox.size.description, format: fixed(1, ' px') }),
  linear({ key: 'sizeNoise', label: 'Size noise', min: 0, max: 0.99, step: 0.01, default: seedBox.sizeNoise.default, description: seedBox.sizeNoise.description, format: percent }),
  linear({ key: 'velocity', label: 'Velocity', min: 0, max: 2000, step: 10, default: seedBox.velocity.default, description: seedBox.velocity.description, format: fixed(0, ' px/s') }),
  linear({ key: 'velocityNoise', label: 'Velocity noise', min: 0, max: 1, step: 0.01, default: seedBox.velocityNoise.default, description: seedBox.velocityNoise.description, format: percent }),
];

/**
 * How the page shows another scene's parameter. Range and default come from the scene's spec;
 * `max` narrows it where the spec allows values no page can run or show (a million circles, radii
 * of 10,000 px), and the step is the slider's resolution.
 */
interface Presentation {
  label: string;
  step: number;
  format(value: number): string;
  min?: number;
  max?: number;
  log?: boolean;
  /** The page's starting value, where the scene's default is a benchmark's size that steps too slowly to watch. */
  default?: number;
}

const PRESENTATION: Record<string, Presentation> = {
  n: { label: 'Quantity', step: 1, format: count, log: true },
  gravity: { label: 'Gravity', step: 10, min: -2000, max: 2000, format: fixed(0, ' px/s²') },
  elasticity: { label: 'Elasticity', step: 0.01, format: fixed(2) },
  size: { label: 'Size', step: 0.5, format: fixed(1, ' px') },
  minRadius: { label: 'Min radius', step: 0.5, min: 0.5, max: 20, format: fixed(1, ' px') },
  maxRadius: { label: 'Max radius', step: 0.5, min: 0.5, max: 40, format: fixed(1, ' px') },
  ratio: { label: 'Size ratio', step: 1, max: 200, format: fixed(0, '×') },
  largeFraction: { label: 'Large share', step: 0.0005, max: 0.05, format: (v) => `${(v * 100).toFixed(2)}%` },
  fill: { label: 'Fill', step: 0.01, min: 0.01, format: percent },
  maxSpeed: { label: 'Max speed', step: 10, max: 2000, format: fixed(0, ' px/s') },
  logRadius: { label: 'Log radii', step: 1, format: (v) => (v ? 'on' : 'off') },
  shuffle: { label: 'Random order', step: 1, format: (v) => (v ? 'on' : 'off') },
  friction: { label: 'Friction', step: 0.05, max: 2, format: fixed(2) },
  base: { label: 'Base', step: 1, max: 150, format: count },
  rows: { label: 'Rows', step: 1, max: 40, format: count },
  columns: { label: 'Columns', step: 1, max: 40, format: count },
  count: { label: 'Boxes', step: 1, max: 100, format: count },
  massRatio: { label: 'Top mass ratio', step: 1, max: 1000, format: fixed(0, '×') },
  levels: { label: 'Storeys', step: 1, max: 10, format: count },
  angle: { label: 'Slope', step: 1, format: fixed(0, '°') },
  length: { label: 'Length', step: 1, max: 200, format: fixed(0, ' m') },
  grid: { label: 'Boxes per side', step: 1, max: 120, format: count },
  speed: { label: 'Drum speed', step: 1, min: -360, max: 360, format: fixed(0, '°/s') },
  spin: { label: 'Spin', step: 0.1, max: 30, format: fixed(1, ' rad/s') },
  maxSpin: { label: 'Max spin', step: 0.1, max: 30, format: fixed(1, ' rad/s') },
};

/** Scenes in metres (Box2D's benchmarks and stacks) rather than the report's pixels. */
const METRIC_SCENES: readonly SceneChoice[] = ['pyramid', 'many-pyramids', 'tumbler', 'vertical-stack', 'card-house', 'ramp', ...JOINT_SCENE_CHOICES];

const onOff = (v: number) => (v ? 'on' : 'off');

/**
 * Parameters whose name means something else in another scene (joint-grid's `size` is a count,
 * the car's `speed` is in radians per second, not the tumbler's degrees), or that only one scene
 * has. The maxima keep each scene to what a page steps at interactive rates: the scenes allow
 * 10,000 links or a 1,000-circle-square grid, which take seconds a step.
 */
const SCENE_PRESENTATION: Partial<Record<SceneChoice, Record<string, Presentation>>> = {
  // The seed box with shapes: the seed box's sliders, and its box's size. The smallest box holds
  // the largest body (2 x 40 x 1.99 = 159 px across), so every setting of the sliders builds.
  'polygon-box': {
    width: { label: 'Box width', step: 10, min: 200, max: 4000, format: fixed(0, ' px') },
    height: { label: 'Box height', step: 10, min: 200, max: 4000, format: fixed(0, ' px') },
    size: { label: 'Size', step: 0.5, min: 0.5, max: 40, format: fixed(1, ' px') },
    sizeNoise: { label: 'Size noise', step: 0.01, format: percent },
    velocity: { label: 'Velocity', step: 10, max: 2000, format: fixed(0, ' px/s') },
    velocityNoise: { label: 'Velocity noise', step: 0.01, format: percent },
  },
  chain: {
    links: { label: 'Links', step: 1, max: 500, format: count },
    linkLength: { label: 'Link length', step: 0.05, max: 5, format: fixed(2, ' m') },
    horizontal: { label: 'Start horizontal', step: 1, format: onOff },
    density: { label: 'Density', step: 1, max: 1000, format: fixed(0, ' kg/m²') },
    rope: { label: 'Rope of beads', step: 1, format: onOff },
  },
  bridge: {
    planks: { label: 'Planks', step: 1, max: 200, format: count },
    load: { label: 'Boxes dropped', step: 1, max: 200, format: count },
    jointFriction: { label: 'Pin friction', step: 1, max: 1000, format: fixed(0, ' N·m') },
  },
  'joint-grid': {
    // Box2D's 100 x 100 took 140 ms a step in headless Chromium on a two-core machine: a slide show.
    size: { label: 'Circles per side', step: 1, max: 150, default: 40, format: count },
  },
  ragdolls: {
    count: { label: 'Ragdolls', step: 1, max: 400, format: count },
    columns: { label: 'Columns', step: 1, max: 40, format: count },
  },
  car: {
    speed: { label: 'Motor speed', step: 0.5, min: -50, max: 50, format: fixed(1, ' rad/s') },
    torque: { label: 'Motor torque', step: 1, max: 200, format: fixed(0, ' N·m') },
    hertz: { label: 'Suspension', step: 0.5, max: 20, format: fixed(1, ' Hz') },
    bumps: { label: 'Bumps', step: 1, max: 500, format: count },
  },
  jellies: {
    count: { label: 'Jellies', step: 1, max: 200, format: count },
    side: { label: 'Particles per side', step: 1, max: 20, format: count },
    hertz: { label: 'Spring', step: 0.5, max: 60, format: fixed(1, ' Hz') },
    dampingRatio: { label: 'Spring damping', step: 0.05, max: 5, format: fixed(2) },
    funnel: { label: 'Funnel', step: 1, format: onOff },
    stiffness: { label: 'Force springs', step: 10, max: 10_000, format: fixed(0, ' N/m') },
    stretch: { label: 'Start stretched', step: 0.05, format: fixed(2, '×') },
    floor: { label: 'Floor', step: 1, format: onOff },
  },
  blobs: {
    count: { label: 'Blobs', step: 1, max: 200, format: count },
    segments: { label: 'Particles per ring', step: 1, format: (v: number) => String(4 * 2 ** v) },
    radius: { label: 'Radius', step: 0.1, max: 5, format: fixed(1, ' m') },
    pressure: { label: 'Gas pressure', step: 1, max: 1000, format: fixed(0, ' N/m') },
    hertz: { label: 'Ring springs', step: 0.5, max: 60, format: fixed(1, ' Hz') },
    funnel: { label: 'Funnel', step: 1, format: onOff },
  },
};

/** Their parameters shown in metres. */
const METRIC_PRESENTATION: Record<string, Presentation> = {
  gravity: { label: 'Gravity', step: 0.5, max: 100, format: fixed(1, ' m/s²') },
  size: { label: 'Size', step: 0.05, max: 10, format: fixed(2, ' m') },
};

function fromSceneSpec(scene: SceneChoice, key: string, spec: ParamSpec): NumberSpec {
  const metric = METRIC_SCENES.includes(scene);
  const look = SCENE_PRESENTATION[scene]?.[key] ?? (metric ? METRIC_PRESENTATION[key] : undefined) ?? PRESENTATION[key] ?? { label: key, step: spec.integer ? 1 : 0.01, format: fixed(2) };
  const min = Math.max(spec.min, look.min ?? spec.min);
  const max = Math.min(spec.max, look.max ?? spec.max, key === 'n' ? QUANTITY_MAX : Infinity);
  return {
    key,
    label: look.label,
    min,
    max,
    step: look.step,
    integer: spec.integer === true,
    default: Math.min(max, Math.max(min, look.default ?? spec.default)),
    description: spec.description,
    format: look.format,
    slider: look.log ? logSlider(max) : gridSlider(min, max, look.step),
  };
}

const cache = new Map<SceneChoice, readonly NumberSpec[]>();

/** The sliders of a scene: every parameter but the seed, which has its own box. */
export function sceneSpecs(scene: SceneChoice): readonly NumberSpec[] {
  if (scene === 'seed-box') return SEED_BOX_SPECS;
  let specs = cache.get(scene);
  if (!specs) {
    const params: Record<string, ParamSpec> = sceneDefinition(scene).params;
    specs = Object.entries(params)
      .filter(([key]) => key !== 'seed')
      .map(([key, spec]) => fromSceneSpec(scene, key, spec));
    cache.set(scene, specs);
  }
  return specs;
}

export function defaultParams(scene: SceneChoice): Record<string, number> {
  const out: Record<string, number> = {};
  for (const spec of sceneSpecs(scene)) out[spec.key] = spec.default;
  return out;
}

/**
 * A value for the spec: clamped into its range, and rounded where it takes whole numbers; NaN
 * falls back to the default. A value already valid comes back as it is, whether or not a slider
 * stops there, so that a URL or a save rebuilds the world it was made from.
 */
export function clampNumber(spec: NumberSpec, value: number): number {
  if (!Number.isFinite(value)) return spec.default;
  const clamped = Math.min(spec.max, Math.max(spec.min, value));
  return spec.integer ? Math.round(clamped) : clamped;
}

/** The body (by handle) an open scene's region follows across as it moves, or -1: the car, which drives away. */
export function followedBody(scene: ShapeSceneChoice): number {
  return scene === 'car' ? 0 : -1;
}

/** Radius (half the size) of a body added by a click: the scene's typical size. */
export function spawnRadius(scene: SceneChoice, p: Record<string, number>): number {
  if (scene === 'mixed') return 1.5 * p.minRadius;
  if (scene === 'uniform' || scene === 'uniform-polygons') return (p.minRadius + p.maxRadius) / 2;
  if (scene === 'tumbler') return 0.125;
  if (scene === 'card-house') return 0.1;
  if (scene === 'pyramid' || scene === 'many-pyramids' || scene === 'vertical-stack' || scene === 'ramp') return 0.5;
  if (scene === 'chain') return p.linkLength / 4;
  if (scene === 'bridge' || scene === 'joint-grid' || scene === 'car') return 0.4;
  if (scene === 'ragdolls' || scene === 'jellies' || scene === 'blobs') return 0.25;
  return p.size;
}
