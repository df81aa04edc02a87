import { BROADPHASE_NAMES, INTEGRATOR_NAMES } from '@maxgrid/engine';
import {
  NAIVE_LIMIT,
  NUMBER_SPECS,
  SEED_MAX,
  clampNumber,
  clampSeed,
  type NumberSpec,
  type RendererName,
  type Settings,
} from './settings.js';

export interface ControlEvents {
  /** A scene parameter changed: rebuild. */
  scene(settings: Settings): void;
  /** Broad-phase, integrator, renderer or an overlay changed: no rebuild. */
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
 * `show` writes a Settings value into them and every change reads them back into a new one.
 */
export class Controls {
  private readonly sliders: Slider[] = [];
  private readonly seed = byId<HTMLInputElement>('seed');
  private readonly broadphase = byId<HTMLSelectElement>('broadphase');
  private readonly integrator = byId<HTMLSelectElement>('integrator');
  readonly renderer = byId<HTMLSelectElement>('renderer');
  private readonly grid = byId<HTMLInputElement>('grid');
  private readonly aabb = byId<HTMLInputElement>('aabb');
  private current: Settings;

  constructor(initial: Settings, private readonly events: ControlEvents) {
    this.current = { ...initial };
    // Enter in the seed box would submit the form and reload the page with raw slider positions.
    byId<HTMLFormElement>('settings').addEventListener('submit', (e) => e.preventDefault());
    const fieldset = byId<HTMLFieldSetElement>('scene-controls');
    const seedField = this.seed.closest('.field');
    for (const spec of NUMBER_SPECS) {
      const slider = this.makeSlider(spec);
      fieldset.insertBefore(slider.input.parentElement as HTMLElement, seedField);
      this.sliders.push(slider);
    }
    this.seed.max = String(SEED_MAX);
    for (const name of BROADPHASE_NAMES) this.broadphase.append(new Option(name, name));
    for (const name of INTEGRATOR_NAMES) this.integrator.append(new Option(name, name));

    // Typing a seed rebuilds as it goes; the box is tidied (clamped) only when editing ends, so a
    // half-typed or empty value is never written back under the cursor.
    this.seed.addEventListener('input', () => {
      const value = Number(this.seed.value);
      if (this.seed.value.trim() === '' || !Number.isFinite(value)) return;
      const seed = clampSeed(value);
      if (seed === this.current.seed) return;
      this.current.seed = seed;
      this.events.scene({ ...this.current });
    });
    this.seed.addEventListener('change', () => {
      this.seed.value = String(this.current.seed);
    });
    const live = () => {
      this.current.broadphase = this.broadphase.value as Settings['broadphase'];
      this.current.integrator = this.integrator.value as Settings['integrator'];
      this.current.renderer = this.renderer.value as RendererName;
      this.current.grid = this.grid.checked;
      this.current.aabb = this.aabb.checked;
      this.events.live({ ...this.current });
    };
    for (const el of [this.broadphase, this.integrator, this.renderer, this.grid, this.aabb]) el.addEventListener('change', live);
    this.show(initial);
  }

  get settings(): Settings {
    return { ...this.current };
  }

  show(s: Settings): void {
    this.current = { ...s };
    for (const { spec, input, output } of this.sliders) {
      const value = s[spec.key];
      input.value = String(spec.slider ? spec.slider.toPosition(value) : value);
      input.setAttribute('aria-valuetext', spec.format(value));
      output.value = spec.format(value);
    }
    this.seed.value = String(s.seed);
    this.broadphase.value = s.broadphase;
    this.integrator.value = s.integrator;
    this.renderer.value = s.renderer;
    this.grid.checked = s.grid;
    this.aabb.checked = s.aabb;
    // Naive tests every pair: offered only while a step stays well under a second.
    const naive = this.broadphase.querySelector<HTMLOptionElement>('option[value="naive"]');
    if (naive) {
      naive.disabled = s.n > NAIVE_LIMIT;
      naive.title = naive.disabled ? `O(n²): only up to ${NAIVE_LIMIT.toLocaleString('en-US')} bodies` : '';
    }
  }

  disableRenderer(name: RendererName, why: string): void {
    const option = this.renderer.querySelector<HTMLOptionElement>(`option[value="${name}"]`);
    if (option) {
      option.disabled = true;
      option.title = why;
    }
  }

  private makeSlider(spec: NumberSpec): Slider {
    const id = `slider-${spec.key}`;
    const field = document.createElement('div');
    field.className = 'field';
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
    input.min = String(spec.slider ? spec.slider.min : spec.min);
    input.max = String(spec.slider ? spec.slider.max : spec.max);
    input.step = String(spec.slider ? 1 : spec.step);
    field.append(label, input);
    // 'input' fires while dragging: the label follows at once, the rebuild is coalesced by the page.
    input.addEventListener('input', () => {
      const raw = Number(input.value);
      const value = clampNumber(spec, spec.slider ? spec.slider.toValue(raw) : raw);
      if (value === this.current[spec.key]) return;
      this.current[spec.key] = value;
      output.value = spec.format(value);
      input.setAttribute('aria-valuetext', spec.format(value));
      this.events.scene({ ...this.current });
    });
    return { spec, input, output };
  }
}
