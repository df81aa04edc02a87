import { describe, expect, it } from 'vitest';
import { Prng } from '@maxgrid/scenes';
import { SCENE_CHOICES, clampNumber, defaultSettings, parseSettings, sceneSpecs, serializeSettings, type NumberSpec } from '../../src/settings.js';

/** Settings through the URL and back, as a reload, a shared link or a save (its header holds the URL) reads them. */
const reload = (s: ReturnType<typeof defaultSettings>) => parseSettings(serializeSettings(s));

/**
 * Up to `most` positions of the slider, both ends included, as a range input steps: from its min
 * by its step, in binary arithmetic (noise included).
 */
function positions(spec: NumberSpec, most = 2000): number[] {
  const { min, max, step } = spec.slider;
  const count = Math.round((max - min) / step);
  const every = Math.max(1, Math.ceil(count / most));
  const out: number[] = [];
  for (let k = 0; k < count; k += every) out.push(min + k * step);
  out.push(max);
  return out;
}

describe('URL settings', () => {
  it.each(SCENE_CHOICES)("%s: its defaults come back from the URL as they were", (scene) => {
    const s = defaultSettings(scene);
    expect(reload(s)).toEqual(s);
  });

  it.each(SCENE_CHOICES)('%s: any valid value of every parameter comes back from the URL exactly', (scene) => {
    const rng = new Prng(11);
    const changed: string[] = [];
    for (const spec of sceneSpecs(scene)) {
      const values = [spec.min, spec.max, spec.default];
      for (let k = 0; k < 50; k++) {
        const v = rng.range(spec.min, spec.max);
        values.push(spec.integer ? Math.round(v) : v, spec.integer ? Math.round(v) : Number(v.toFixed(3)));
      }
      for (const value of values) {
        const s = defaultSettings(scene);
        s.params[spec.key] = value;
        const back = reload(s).params[spec.key];
        if (back !== value) changed.push(`${spec.key} ${value} -> ${back}`);
      }
    }
    expect(changed).toEqual([]);
  });

  it.each(SCENE_CHOICES)('%s: every slider stop is a value in range that the URL keeps, and the stop it shows', (scene) => {
    const wrong: string[] = [];
    for (const spec of sceneSpecs(scene)) {
      // The slider reaches both ends of the range.
      expect(spec.slider.toValue(spec.slider.min), spec.key).toBe(spec.min);
      expect(spec.slider.toValue(spec.slider.max), spec.key).toBe(spec.max);
      for (const p of positions(spec)) {
        const value = spec.slider.toValue(p);
        if (!(value >= spec.min && value <= spec.max) || clampNumber(spec, value) !== value) wrong.push(`${spec.key}: stop ${p} is ${value}`);
        const s = defaultSettings(scene);
        s.params[spec.key] = value;
        if (reload(s).params[spec.key] !== value) wrong.push(`${spec.key}: stop ${p}, ${value}, reloads as ${reload(s).params[spec.key]}`);
        // The log slider has stops that round to one value; the first of them shows it.
        if (spec.slider.toValue(spec.slider.toPosition(value)) !== value) wrong.push(`${spec.key}: ${value} shows as stop ${spec.slider.toPosition(value)}`);
      }
    }
    expect(wrong).toEqual([]);
  });

  it('linear sliders stop at multiples of their step, and at the ends of a range that starts or ends between them', () => {
    const density = sceneSpecs('chain').find((s) => s.key === 'density')!;
    expect([0, 1, 2, 20].map((p) => density.slider.toValue(p))).toEqual([0.001, 1, 2, 20]);
    expect(density.slider.min).toBe(0);
    const fill = sceneSpecs('uniform').find((s) => s.key === 'fill')!;
    expect(fill.slider.toValue(0.1 + 0.2)).toBe(0.3);
    const hertz = sceneSpecs('jellies').find((s) => s.key === 'hertz')!;
    expect([hertz.slider.min, 15].map((p) => hertz.slider.toValue(p))).toEqual([0.1, 15]);
  });

  it('values out of range are clamped, whole-number parameters rounded, and what is no number falls back to the default', () => {
    const s = parseSettings('?scene=chain&links=1e9&density=-3&linkLength=abc&horizontal=0.7');
    const specs = Object.fromEntries(sceneSpecs('chain').map((spec) => [spec.key, spec]));
    expect(s.params.links).toBe(specs.links.max);
    expect(s.params.density).toBe(specs.density.min);
    expect(s.params.linkLength).toBe(specs.linkLength.default);
    expect(s.params.horizontal).toBe(1);
    expect(reload(s)).toEqual(s);
  });
});
