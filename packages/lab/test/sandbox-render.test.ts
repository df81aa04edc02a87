import { describe, expect, it } from 'vitest';
import { Ajv } from 'ajv';
import type { FrameSample, RunContext, SandboxHost, SandboxRun } from '../src/experiments/common.js';
import { sandboxRender } from '../src/experiments/registry.js';
import {
  INTERACTIVE_FPS,
  runSandboxRender,
  sandboxRenderCsv,
  sandboxRenderHeadline,
  sandboxRenderTables,
  SANDBOX_ENGINE_ID,
  summarise,
} from '../src/experiments/sandbox-render.js';
import type { Engine, EngineInfo } from '../src/engines/adapter.js';
import { mergeEngines } from '../src/node/results.js';

const NVIDIA = 'ANGLE (NVIDIA, Vulkan 1.4.312 (NVIDIA NVIDIA H100 80GB HBM3 (0x00002330)), NVIDIA)';
const SWIFTSHADER = 'ANGLE (Google, Vulkan 1.3.0 (SwiftShader Device (Subzero) (0x0000C0DE)), SwiftShader driver)';

/** `frames` frames `intervalMs` apart, each running `steps` steps of `msPerStep` and drawing for `drawMs`. */
function sample(frames: number, intervalMs: number, steps: number, msPerStep = 2, drawMs = 1, renderer = 'webgl', threads = 1): FrameSample {
  return {
    start: Array.from({ length: frames }, (_, i) => 1000 + i * intervalMs),
    stepMs: Array.from({ length: frames }, () => steps * msPerStep),
    drawMs: Array.from({ length: frames }, () => drawMs),
    steps: Array.from({ length: frames }, () => steps),
    droppedSteps: 0,
    simulatedSeconds: (frames * steps) / 60,
    bodies: 100_000,
    renderer,
    threads,
  };
}

function run(frames: FrameSample, device: string | null = NVIDIA, droppedSteps = 0): SandboxRun {
  return { frames, droppedSteps, webglDevice: device, notice: '', devicePixelRatio: 1 };
}

const webgl1 = { renderer: 'webgl', threads: 1 } as const;

describe('sandbox-render summary (T7)', () => {
  it('counts frames, steps and time from the frame log: 60 Hz with one step a frame is interactive', () => {
    const x = summarise(webgl1, run(sample(121, 1000 / 60, 1, 3, 1.5)));
    expect(x.frames).toBe(120);
    expect(x.seconds).toBeCloseTo(2, 9);
    expect(x.fps).toBeCloseTo(60, 9);
    expect(x.stepsPerSecond).toBeCloseTo(60, 9);
    expect(x.msPerStep).toBeCloseTo(3, 9);
    expect(x.drawMs.median).toBe(1.5);
    expect(x.software).toBe(false);
    expect(x.interactive).toBe(true);
  });

  it('leaves out the first frame’s steps: they were run for time before the timed stretch', () => {
    const frames = sample(61, 1000 / 60, 1);
    frames.steps[0] = 4;
    expect(summarise(webgl1, run(frames)).stepsPerSecond).toBeCloseTo(60, 9);
  });

  it('is not interactive below the frame rate, when steps drop, or when the simulation falls behind', () => {
    // 20 fps catching up three steps a frame: real time, but too few frames.
    const slow = summarise(webgl1, run(sample(41, 50, 3)));
    expect(slow.stepsPerSecond).toBeCloseTo(60, 9);
    expect(slow.fps).toBeLessThan(INTERACTIVE_FPS);
    expect(slow.interactive).toBe(false);
    expect(summarise(webgl1, run(sample(121, 1000 / 60, 1), NVIDIA, 5)).interactive).toBe(false);
    // 60 fps, but a step only every other frame: half speed.
    const half = sample(121, 1000 / 60, 1);
    half.steps = half.steps.map((s, i) => (i % 2 === 0 ? s : 0));
    const behind = summarise(webgl1, run(half));
    expect(behind.stepsPerSecond).toBeCloseTo(30, 0);
    expect(behind.interactive).toBe(false);
  });

  it('names a software rasteriser as such, and canvas 2D as no WebGL device', () => {
    expect(summarise(webgl1, run(sample(10, 20, 1), SWIFTSHADER)).software).toBe(true);
    const canvas = summarise({ renderer: 'canvas', threads: 1 }, run(sample(10, 20, 1, 2, 1, 'canvas'), null));
    expect(canvas.device).toBeNull();
    expect(canvas.software).toBeNull();
  });

  it('refuses a run the page did not do as asked, naming what it did', () => {
    expect(() => summarise(webgl1, run(sample(10, 20, 1, 2, 1, 'canvas')))).toThrow(/asked for renderer webgl, the page drew with canvas/);
    expect(() => summarise({ renderer: 'webgl', threads: 2 }, run(sample(10, 20, 1)))).toThrow(/asked for 2 threads, the page stepped on 1/);
    expect(() => summarise(webgl1, run(sample(2, 20, 1)))).toThrow(/2 frames/);
  });

  it('runs each configuration through the host and writes results that validate, with tables and CSV', async () => {
    const asked: string[] = [];
    const host: SandboxHost = {
      runtime: 'Chromium (test)',
      settings: { flags: '--test', page: 'test page', viewport: '1280x720 CSS px' },
      async measure(query) {
        asked.push(query);
        const q = new URLSearchParams(query);
        return run(sample(31, 1000 / 60, 1, 2, 1, q.get('renderer')!, Number(q.get('threads'))), q.get('renderer') === 'webgl' ? NVIDIA : null);
      },
      async close() {},
    };
    const ctx: RunContext = {
      engines: [],
      environment: { runtime: 'vitest' },
      host: { cBaseline: async () => 'none', browser: async () => 'none', sandbox: async () => host },
    };
    const options = sandboxRender.options('quick', { ns: [5000], seconds: 1 });
    const result = await runSandboxRender(options, ctx);
    expect(asked).toEqual(options.configs.map((c) => `scene=uniform&n=5000&seed=1&broadphase=maxgrid&renderer=${c.renderer}&threads=${c.threads}`));
    expect(result.status).toBe('ok');
    expect(result.runs.map((x) => x.interactive)).toEqual([true, true, true]);
    result.meta.engines = [{ id: 'maxgrid:maxgrid', package: '@maxgrid/engine', version: '0.1.0', precision: 'f64', lengthScale: 1, settings: { world: 'test' } }];
    const validate = new Ajv({ strict: false }).compile(sandboxRender.schema);
    expect(validate(JSON.parse(JSON.stringify(result))), JSON.stringify(validate.errors)).toBe(true);
    const csv = sandboxRenderCsv(result).trim().split('\n');
    expect(csv).toHaveLength(1 + options.configs.length);
    expect(sandboxRenderTables(result)[0].rows).toHaveLength(options.configs.length);
    expect(sandboxRenderHeadline(result)[1]).toBe('');
    expect(sandboxRenderHeadline(result)[0]).toMatch(/^webgl, 1 thread\(s\) \(WebGL on ANGLE \(NVIDIA.*60 fps, 60 steps\/s, 0 dropped: interactive/);
  });

  it('names the page its own engine, so the settings table does not give maxgrid:maxgrid the page\'s settings', async () => {
    const lab: EngineInfo = { id: 'maxgrid:maxgrid', package: '@maxgrid/engine', version: '0.1.0', precision: 'f64', lengthScale: 1, settings: { continuous: 'false' } };
    const ctx: RunContext = {
      engines: [{ info: lab } as Engine],
      environment: { runtime: 'vitest' },
      host: { cBaseline: async () => 'none', browser: async () => 'none', sandbox: async () => 'no Chromium here' },
    };
    const result = await runSandboxRender(sandboxRender.options('quick', {}), ctx);
    expect(result.meta.engines.map((e) => e.id)).toEqual([SANDBOX_ENGINE_ID]);
    const table = new Map<string, EngineInfo>();
    mergeEngines(table, [lab], 'step-time');
    mergeEngines(table, result.meta.engines, 'sandbox-render');
    expect(table.get('maxgrid:maxgrid')).toEqual(lab);
    expect(() => mergeEngines(table, [{ ...lab, settings: { continuous: 'true' } }], 'other')).toThrow(/engine id maxgrid:maxgrid of experiment other has settings that differ/);
  });

  it('records a skip, with the reason, where no browser can be started', async () => {
    const ctx: RunContext = { engines: [], environment: { runtime: 'vitest' }, host: { cBaseline: async () => 'none', browser: async () => 'none', sandbox: async () => 'no Chromium here' } };
    const result = await runSandboxRender(sandboxRender.options('quick', {}), ctx);
    expect(result).toMatchObject({ status: 'skipped', reason: 'no Chromium here', runs: [] });
    expect(sandboxRenderHeadline(result)).toEqual(['Skipped: no Chromium here.']);
  });

  it('takes --n (one value) and --seconds, and rejects the rest by name', () => {
    expect(sandboxRender.options('quick', { ns: [200_000], seconds: 2 })).toMatchObject({ n: 200_000, seconds: 2 });
    expect(() => sandboxRender.options('quick', { ns: [1000, 2000] })).toThrow(/--n takes one value.*1000,2000/);
    expect(() => sandboxRender.options('quick', { runs: 3 })).toThrow(/--runs does not apply to experiment 'sandbox-render'/);
  });
});
