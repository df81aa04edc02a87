import { BROADPHASE_NAMES, INTEGRATOR_NAMES, type BroadPhaseName } from '@maxgrid/engine';
import {
  SCENE_CHOICES,
  SEED_MAX,
  SPAWN_KINDS,
  SUBSTEP_CHOICES,
  isJointScene,
  isShapeScene,
  sceneDefinition,
  threadChoices,
  WORLD_TOGGLES,
  clampNumber,
  clampSeed,
  copySettings,
  defaultSettings,
  sceneSpecs,
  type NumberSpec,
  type RendererName,
  type SceneChoice,
  type Settings,
  type SpawnKind,
  type ToolName,
} from './settings.js';

export interface ControlEvents {
  /** The scene, a scene parameter or a world option changed: rebuild. */
  scene(settings: Settings): void;
  /** Broad-phase, integrator, renderer, an overlay or the tool changed: no rebuild. */
  live(settings: Settings): void;
}

function byId<T extends HTMLElement>(id: string): T {
  const el = document.getElementById(id);
  if (!el) throw new Error(`sandbox page is missing #${id}`);
  return el as T;
}

interface Slider {
  spec: NumberSpec;
  input: HTMLInputElement;
  output: HTMLOutputElement;
}

/**
 * The form: one labelled <input> or <select> per setting. The controls hold no state of their own;
 * `show` writes a Settings value into them and every change reads them back into a new one. The
 * sliders are the current scene's, made from its parameter specs, and remade when it changes.
 */
export class Controls {
  private sliders: Slider[] = [];
  private slidersFor: SceneChoice | null = null;
  private readonly fieldset = byId<HTMLFieldSetElement>('scene-controls');
  private readonly sceneSelect = byId<HTMLSelectElement>('scene');
  private readonly seed = byId<HTMLInputElement>('seed');
  private readonly broadphase = byId<HTMLSelectElement>('broadphase');
  private readonly integrator = byId<HTMLSelectElement>('integrator');
  private readonly threads = byId<HTMLSelectElement>('threads');
  readonly renderer = byId<HTMLSelectElement>('renderer');
  private readonly tool = byId<HTMLSelectElement>('tool');
  private readonly grid = byId<HTMLInputElement>('grid');
  private readonly aabb = byId<HTMLInputElement>('aabb');
  private readonly contacts = byId<HTMLInputElement>('contacts');
  private readonly spawn = byId<HTMLSelectElement>('spawn');
  private readonly substeps = byId<HTMLSelectElement>('substeps');
  private readonly toggles = WORLD_TOGGLES.map((key) => ({ key, input: byId<HTMLInputElement>(`toggle-${key}`) }));
  private current: Settings;

  constructor(initial: Settings, private readonly events: ControlEvents) {
    this.current = copySettings(initial);
    // Enter in the seed box would submit the form and reload the page with raw slider positions.
    byId<HTMLFormElement>('settings').addEventListener('submit', (e) => e.preventDefault());
    const circles = document.createElement('optgroup');
    circles.label = 'Circles';
    const shapes = document.createElement('optgroup');
    shapes.label = 'Shapes';
    const joints = document.createElement('optgroup');
    joints.label = 'Joints';
    for (const name of SCENE_CHOICES) {
      const option = new Option(name, name);
      option.title = sceneDefinition(name).description;
      (isJointScene(name) ? joints : isShapeScene(name) ? shapes : circles).append(option);
    }
    this.sceneSelect.append(circles, shapes, joints);
    for (const kind of SPAWN_KINDS) this.spawn.append(new Option(kind, kind));
    for (const count of SUBSTEP_CHOICES) this.substeps.append(new Option(String(count), String(count)));
    this.substeps.addEventListener('change', () => {
      this.current.substeps = Number(this.substeps.value);
      this.events.scene(copySettings(this.current));
    });
    this.seed.max = String(SEED_MAX);
    for (const name of BROADPHASE_NAMES) this.broadphase.append(new Option(name, name));
    for (const name of INTEGRATOR_NAMES) this.integrator.append(new Option(name, name));
    // Worker threads need SharedArrayBuffer, which only a cross-origin isolated page has.
    for (const count of threadChoices(usableCores())) this.threads.append(new Option(String(count), String(count)));

    // Another scene starts from its own defaults; the seed, engine and view choices carry over.
    this.sceneSelect.addEventListener('change', () => {
      const scene = this.sceneSelect.value as SceneChoice;
      if (scene === this.current.scene) return;
      this.current = { ...copySettings(this.current), scene, params: defaultSettings(scene).params };
      this.events.scene(copySettings(this.current));
    });
    // Typing a seed rebuilds as it goes; the box is tidied (clamped) only when editing ends, so a
    // half-typed or empty value is never written back under the cursor.
    this.seed.addEventListener('input', () => {
      const value = Number(this.seed.value);
      if (this.seed.value.trim() === '' || !Number.isFinite(value)) return;
      const seed = clampSeed(value);
      if (seed === this.current.seed) return;
      this.current.seed = seed;
      this.events.scene(copySettings(this.current));
    });
    this.seed.addEventListener('change', () => {
      this.seed.value = String(this.current.seed);
    });
    for (const { key, input } of this.toggles) {
      input.addEventListener('change', () => {
        this.current[key] = input.checked;
        this.events.scene(copySettings(this.current));
      });
    }
    const live = () => {
      this.current.broadphase = this.broadphase.value as Settings['broadphase'];
      this.current.integrator = this.integrator.value as Settings['integrator'];
      this.current.threads = Number(this.threads.value);
      this.current.renderer = this.renderer.value as RendererName;
      this.current.tool = this.tool.value as ToolName;
      this.current.grid = this.grid.checked;
      this.current.aabb = this.aabb.checked;
      this.current.contacts = this.contacts.checked;
      this.current.spawn = this.spawn.value as SpawnKind;
      this.events.live(copySettings(this.current));
    };
    for (const el of [this.broadphase, this.integrator, this.threads, this.renderer, this.tool, this.grid, this.aabb, this.contacts, this.spawn]) el.addEventListener('change', live);
    this.show(initial);
  }

  get settings(): Settings {
    return copySettings(this.current);
  }

  /** Shows `s`; broad-phases in `refused` and tools in `unusable` are disabled, their reason as the option's title. */
  show(s: Settings, refused: Partial<Record<BroadPhaseName, string>> = {}, unusable: Partial<Record<ToolName, string>> = {}): void {
    this.current = copySettings(s);
    if (this.slidersFor !== s.scene) this.makeSliders(s.scene);
    for (const { spec, input, output } of this.sliders) {
      const value = s.params[spec.key];
      input.value = String(spec.slider.toPosition(value));
      input.setAttribute('aria-valuetext', spec.format(value));
      output.value = spec.format(value);
    }
    this.sceneSelect.value = s.scene;
    this.seed.value = String(s.seed);
    // Box2D's benchmarks are one fixed layout: no seed to choose.
    this.seed.disabled = !sceneDefinition(s.scene).params.seed;
    this.broadphase.value = s.broadphase;
    this.integrator.value = s.integrator;
    this.threads.value = String(s.threads);
    this.renderer.value = s.renderer;
    this.tool.value = s.tool;
    this.grid.checked = s.grid;
    this.aabb.checked = s.aabb;
    this.contacts.checked = s.contacts;
    this.spawn.value = s.spawn;
    this.substeps.value = String(s.substeps);
    // Sub-steps belong to the soft step of worlds with shapes; the circle route has none.
    this.substeps.disabled = !isShapeScene(s.scene);
    this.substeps.title = this.substeps.disabled ? 'Sub-steps belong to the soft step of scenes with shapes' : "Box2D v3's soft step: sub-steps per step";
    for (const { key, input } of this.toggles) input.checked = s[key];
    for (const option of this.broadphase.options) {
      const why = refused[option.value as BroadPhaseName];
      option.disabled = why !== undefined;
      option.title = why ?? '';
    }
    for (const option of this.tool.options) {
      const why = unusable[option.value as ToolName];
      option.disabled = why !== undefined;
      option.title = why ?? '';
    }
  }

  disableRenderer(name: RendererName, why: string): void {
    const option = this.renderer.querySelector<HTMLOptionElement>(`option[value="${name}"]`);
    if (option) {
      option.disabled = true;
      option.title = why;
    }
  }

  private makeSliders(scene: SceneChoice): void {
    for (const { input } of this.sliders) input.parentElement?.remove();
    this.sliders = [];
    const seedField = this.seed.closest('.field');
    for (const spec of sceneSpecs(scene)) {
      const slider = this.makeSlider(spec);
      this.fieldset.insertBefore(slider.input.parentElement as HTMLElement, seedField);
      this.sliders.push(slider);
    }
    this.slidersFor = scene;
  }

  private makeSlider(spec: NumberSpec): Slider {
    const id = `slider-${spec.key}`;
    const field = document.createElement('div');
    field.className = 'field';
    field.title = spec.description;
    const label = document.createElement('label');
    label.htmlFor = id;
    const name = document.createElement('span');
    name.textContent = spec.label;
    const output = document.createElement('output');
    output.htmlFor.add(id);
    label.append(name, ' ', output);
    const input = document.createElement('input');
    input.type = 'range';
    input.id = id;
    input.name = spec.key;
    input.min = String(spec.slider.min);
    input.max = String(spec.slider.max);
    input.step = String(spec.slider.step);
    field.append(label, input);
    // 'input' fires while dragging: the label follows at once, the rebuild is coalesced by the page.
    input.addEventListener('input', () => {
      const raw = Number(input.value);
      const value = clampNumber(spec, spec.slider.toValue(raw));
      if (value === this.current.params[spec.key]) return;
      this.current.params[spec.key] = value;
      output.value = spec.format(value);
      input.setAttribute('aria-valuetext', spec.format(value));
      this.events.scene(copySettings(this.current));
    });
    return { spec, input, output };
  }
}

/** Cores worker threads can use: Web Workers share memory only on a cross-origin isolated page. */
export function usableCores(): number {
  return globalThis.crossOriginIsolated ? navigator.hardwareConcurrency || 1 : 1;
}
