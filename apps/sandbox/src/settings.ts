import { BROADPHASE_NAMES, INTEGRATOR_NAMES, type BroadPhaseName, type IntegratorName } from '@maxgrid/engine';
import { seedBoxParams } from '@maxgrid/scenes';
import { SCENE_CHOICES, clampNumber, defaultParams, defaultSeed, sceneDefinition, sceneSpecs, type SceneChoice } from './scene-specs.js';

export { SCENE_CHOICES, clampNumber, isJointScene, isShapeScene, sceneDefinition, sceneSpecs, type NumberSpec, type SceneChoice } from './scene-specs.js';

/**
 * Everything the URL reproduces. The scene, its seed and its parameters always rebuild the same
 * bodies; the world options (sleeping, pile solver, continuous collision, events, hits, layers) are construction
 * options, so they rebuild too; the rest choose how the world is stepped, drawn and probed.
 */
export interface Settings {
  scene: SceneChoice;
  seed: number;
  /** The scene's parameters other than the seed, under the scene's own names (n, gravity, ...). */
  params: Record<string, number>;
  broadphase: BroadPhaseName;
  integrator: IntegratorName;
  renderer: RendererName;
  grid: boolean;
  aabb: boolean;
  sleeping: boolean;
  /** Solver iterations with partial position correction (see buildSandboxWorld), so that piles rest and keep their height. */
  piles: boolean;
  continuous: boolean;
  events: boolean;
  /** Hit events: the world records collisions approaching faster than a threshold. */
  hits: boolean;
  layers: boolean;
  tool: ToolName;
  /** Threads stepping the world (world.startWorkers); 1 runs it on the page's own thread. */
  threads: number;
  /** Sub-steps of the soft step (worlds with shapes); rebuilds. */
  substeps: number;
  /** What a click on empty space adds. */
  spawn: SpawnKind;
  /** Overlay: contact points and their normals. */
  contacts: boolean;
}

export const SPAWN_KINDS = ['circle', 'box', 'polygon', 'capsule'] as const;
export type SpawnKind = (typeof SPAWN_KINDS)[number];

/** Sub-step counts offered for the soft step; Box2D v3's default is 4. */
export const SUBSTEP_CHOICES = [1, 2, 4, 8, 16] as const;
export const DEFAULT_SUBSTEPS = 4;

/** Thread counts offered; the page offers those up to the machine's core count. */
export const THREAD_CHOICES = [1, 2, 4, 8] as const;

/** The thread counts offered where `cores` cores are usable (1 where the page has no SharedArrayBuffer). */
export function threadChoices(cores: number): number[] {
  return THREAD_CHOICES.filter((count) => count === 1 || count <= cores);
}

/** The largest count offered that is not above `asked`: a URL's threads=8 runs 2 threads on 2 cores. */
export function offeredThreads(asked: number, cores: number): number {
  return threadChoices(cores).reduce((best, count) => (count <= asked ? count : best), 1);
}

export const RENDERER_NAMES = ['canvas', 'webgl'] as const;
export type RendererName = (typeof RENDERER_NAMES)[number];

export const TOOL_NAMES = ['drag', 'ray', 'point', 'box', 'pin', 'cut'] as const;
export type ToolName = (typeof TOOL_NAMES)[number];

/**
 * The tools a world has no use for, each with why: Pin makes a joint and Cut removes one, so a
 * world that refuses joints (made with solver 'elastic', as uniform-polygons is) is offered neither.
 */
export function refusedTools(acceptsJoints: boolean): Partial<Record<ToolName, string>> {
  if (acceptsJoints) return {};
  const why = "this scene's world has no joints and takes none (its solver is the elastic pass)";
  return { pin: `Pin makes a joint: ${why}`, cut: `Cut removes a joint: ${why}` };
}

/** World options that rebuild the scene, by URL key; `continuous` is on by default, as in the engine. */
export const WORLD_TOGGLES = ['sleeping', 'piles', 'continuous', 'events', 'hits', 'layers'] as const;
export type WorldToggle = (typeof WORLD_TOGGLES)[number];

export const SEED_MAX = seedBoxParams.seed.max;

export function defaultSettings(scene: SceneChoice = 'seed-box'): Settings {
  return {
    scene,
    seed: defaultSeed(scene),
    params: defaultParams(scene),
    broadphase: 'auto',
    integrator: 'semi-implicit-euler',
    renderer: 'canvas',
    grid: false,
    aabb: false,
    sleeping: false,
    piles: false,
    continuous: true,
    events: false,
    hits: false,
    layers: false,
    threads: 1,
    tool: 'drag',
    substeps: DEFAULT_SUBSTEPS,
    spawn: 'circle',
    contacts: false,
  };
}

export function clampSeed(value: number): number {
  return Number.isFinite(value) ? Math.min(SEED_MAX, Math.max(0, Math.trunc(value))) : seedBoxParams.seed.default;
}

function oneOf<T extends string>(names: readonly T[], value: string | null, fallback: T): T {
  return value !== null && (names as readonly string[]).includes(value) ? (value as T) : fallback;
}

function flag(q: URLSearchParams, key: string, fallback: boolean): boolean {
  const raw = q.get(key);
  return raw === '1' ? true : raw === '0' ? false : fallback;
}

/** Reads settings from a query string. Anything missing or malformed falls back to its default. */
export function parseSettings(search: string): Settings {
  const q = new URLSearchParams(search);
  const s = defaultSettings(oneOf(SCENE_CHOICES, q.get('scene'), 'seed-box'));
  for (const spec of sceneSpecs(s.scene)) {
    const raw = q.get(spec.key);
    if (raw !== null && raw.trim() !== '') s.params[spec.key] = clampNumber(spec, Number(raw));
  }
  const seed = q.get('seed');
  if (seed !== null && seed.trim() !== '') s.seed = clampSeed(Number(seed));
  // A broad-phase too slow for the world is refused once it is built (broadphase-budget.ts), where the page can say so.
  s.broadphase = oneOf(BROADPHASE_NAMES, q.get('broadphase'), s.broadphase);
  s.integrator = oneOf(INTEGRATOR_NAMES, q.get('integrator'), s.integrator);
  s.renderer = oneOf(RENDERER_NAMES, q.get('renderer'), s.renderer);
  s.tool = oneOf(TOOL_NAMES, q.get('tool'), s.tool);
  const threads = Number(q.get('threads'));
  s.threads = (THREAD_CHOICES as readonly number[]).includes(threads) ? threads : 1;
  s.grid = flag(q, 'grid', false);
  s.aabb = flag(q, 'aabb', false);
  s.contacts = flag(q, 'contacts', false);
  const substeps = Number(q.get('substeps'));
  s.substeps = (SUBSTEP_CHOICES as readonly number[]).includes(substeps) ? substeps : DEFAULT_SUBSTEPS;
  s.spawn = oneOf(SPAWN_KINDS, q.get('spawn'), s.spawn);
  for (const key of WORLD_TOGGLES) s[key] = flag(q, key, s[key]);
  return s;
}

export function serializeSettings(s: Settings): string {
  const q = new URLSearchParams();
  // The default scene stays implicit, so links made before there was a choice still read the same.
  if (s.scene !== 'seed-box') q.set('scene', s.scene);
  for (const spec of sceneSpecs(s.scene)) q.set(spec.key, String(s.params[spec.key]));
  q.set('seed', String(s.seed));
  q.set('broadphase', s.broadphase);
  q.set('integrator', s.integrator);
  q.set('renderer', s.renderer);
  if (s.grid) q.set('grid', '1');
  if (s.aabb) q.set('aabb', '1');
  if (s.contacts) q.set('contacts', '1');
  if (s.substeps !== DEFAULT_SUBSTEPS) q.set('substeps', String(s.substeps));
  if (s.spawn !== 'circle') q.set('spawn', s.spawn);
  const defaults = defaultSettings();
  for (const key of WORLD_TOGGLES) if (s[key] !== defaults[key]) q.set(key, s[key] ? '1' : '0');
  if (s.tool !== 'drag') q.set('tool', s.tool);
  if (s.threads !== 1) q.set('threads', String(s.threads));
  return '?' + q.toString();
}

/** The scene's full parameter set for these settings: its sliders plus the seed, where it takes one. */
export function sceneParams(s: Settings): Record<string, number> {
  return sceneDefinition(s.scene).params.seed ? { ...s.params, seed: s.seed } : { ...s.params };
}

/** A copy that shares nothing with the original, so controls and page never alias params. */
export function copySettings(s: Settings): Settings {
  return { ...s, params: { ...s.params } };
}
