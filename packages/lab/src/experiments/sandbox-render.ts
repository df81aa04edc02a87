import type { Table } from '../report/tables.js';
import { fmt } from '../report/tables.js';
import { csvLine, makeMeta, metaSchema, quantile, spread, spreadSchema, type Meta, type Profile, type RunContext, type SandboxRun, type Spread } from './common.js';

/**
 * Issue 5, T7: the sandbox page itself, live in headless Chromium, with `n` circles of the
 * `uniform` scene, timed frame by frame: frames per second, how far the simulation keeps up with
 * real time, and the CPU time each frame spends stepping and drawing. What the GPU does shows only
 * as frame intervals (the browser paces animation frames to what it can present), so the WebGL
 * device is recorded with every run: where it is a software rasteriser (SwiftShader on a machine
 * without a GPU), the frame rate measures the CPU drawing pixels, not the target.
 */
export interface SandboxRenderOptions {
  n: number;
  scene: 'uniform';
  /** Each configuration the page is loaded with. */
  configs: { renderer: 'webgl' | 'canvas'; threads: number }[];
  /** Seconds the page runs before timing: the world's first steps and the GPU's warm-up. */
  warmupSeconds: number;
  seconds: number;
}

/** Interactive: at least this many frames per second (median interval)... */
export const INTERACTIVE_FPS = 30;
/** ...with the simulation at real time: the sandbox's fixed 60 Hz steps, none dropped. */
export const STEPS_PER_SECOND = 60;

export function sandboxRenderDefaults(profile: Profile): SandboxRenderOptions {
  const configs: SandboxRenderOptions['configs'] = [
    { renderer: 'webgl', threads: 1 },
    { renderer: 'webgl', threads: 2 },
    { renderer: 'canvas', threads: 1 },
  ];
  return profile === 'full'
    ? { n: 100_000, scene: 'uniform', configs, warmupSeconds: 5, seconds: 30 }
    : { n: 100_000, scene: 'uniform', configs, warmupSeconds: 3, seconds: 6 };
}

export interface SandboxRenderRun {
  renderer: 'webgl' | 'canvas';
  threads: number;
  /** The WebGL device, or null on canvas 2D. */
  device: string | null;
  /** Whether that device is a software rasteriser; null on canvas 2D. */
  software: boolean | null;
  frames: number;
  seconds: number;
  fps: number;
  frameMs: Spread;
  /** The 95th percentile frame interval: the slow frames a user notices. */
  p95FrameMs: number;
  stepsPerSecond: number;
  droppedSteps: number;
  /** Stepping time per fixed step (a frame's stepping time over its steps); null if none ran. */
  msPerStep: number | null;
  drawMs: Spread;
  interactive: boolean;
  notice: string;
}

export interface SandboxRenderResult {
  meta: Meta;
  status: 'ok' | 'skipped';
  reason?: string;
  runtime?: string;
  settings?: Record<string, string>;
  devicePixelRatio?: number;
  runs: SandboxRenderRun[];
}

export const SANDBOX_ENGINE_ID = 'maxgrid:sandbox-page';

const SANDBOX_WORLD =
  "built by the sandbox page from its URL, with the page's defaults: semi-implicit Euler, continuous collision on, no sleeping, fixed 1/60 s steps, at most 4 a frame";

const SOFTWARE = /swiftshader|llvmpipe|softpipe|software/i;

export function summarise(config: SandboxRenderOptions['configs'][number], run: SandboxRun): SandboxRenderRun {
  const f = run.frames;
  if (f.start.length < 3) throw new Error(`the sandbox drew ${f.start.length} frames in the timed stretch; cannot time it`);
  if (f.renderer !== config.renderer) throw new Error(`asked for renderer ${config.renderer}, the page drew with ${f.renderer} (${run.notice})`);
  if (f.threads !== config.threads) throw new Error(`asked for ${config.threads} threads, the page stepped on ${f.threads} (${run.notice})`);
  const intervals = f.start.slice(1).map((t, i) => t - f.start[i]);
  const seconds = (f.start[f.start.length - 1] - f.start[0]) / 1000;
  // Steps of the first frame belong to time before the stretch began.
  let steps = 0;
  let stepMs = 0;
  for (let i = 1; i < f.steps.length; i++) {
    steps += f.steps[i];
    stepMs += f.stepMs[i];
  }
  const frameMs = spread(intervals);
  const stepsPerSecond = steps / seconds;
  const fps = 1000 / frameMs.median;
  return {
    renderer: config.renderer,
    threads: config.threads,
    device: run.webglDevice,
    software: run.webglDevice === null ? null : SOFTWARE.test(run.webglDevice),
    frames: intervals.length,
    seconds,
    fps,
    frameMs,
    p95FrameMs: quantile([...intervals].sort((a, b) => a - b), 0.95),
    stepsPerSecond,
    droppedSteps: run.droppedSteps,
    msPerStep: steps > 0 ? stepMs / steps : null,
    drawMs: spread(f.drawMs.slice(1)),
    interactive: fps >= INTERACTIVE_FPS && run.droppedSteps === 0 && stepsPerSecond >= 0.98 * STEPS_PER_SECOND,
    notice: run.notice,
  };
}

export async function runSandboxRender(o: SandboxRenderOptions, ctx: RunContext): Promise<SandboxRenderResult> {
  const meta = makeMeta('sandbox-render', ctx, o);
  // The page builds its own world: the lab adapter's settings (discrete collision and so on) do not
  // apply, so it is an engine of its own in the report's settings table.
  meta.engines = meta.engines.map((e) => ({ ...e, id: SANDBOX_ENGINE_ID, settings: { world: SANDBOX_WORLD } }));
  if (!ctx.host) return { meta, status: 'skipped', reason: 'needs Node to drive a headless Chromium', runs: [] };
  ctx.progress?.(0, o.configs.length, 'starting Vite and Chromium');
  const host = await ctx.host.sandbox();
  if (typeof host === 'string') return { meta, status: 'skipped', reason: host, runs: [] };
  try {
    const runs: SandboxRenderRun[] = [];
    let devicePixelRatio = 1;
    for (const [i, config] of o.configs.entries()) {
      ctx.progress?.(i, o.configs.length, `${config.renderer}, ${config.threads} thread(s), N=${o.n}`);
      const query = new URLSearchParams({ scene: o.scene, n: String(o.n), seed: '1', broadphase: 'maxgrid', renderer: config.renderer, threads: String(config.threads) });
      const run = await host.measure(query.toString(), o.warmupSeconds, o.seconds);
      devicePixelRatio = run.devicePixelRatio;
      runs.push(summarise(config, run));
    }
    return { meta, status: 'ok', runtime: host.runtime, settings: host.settings, devicePixelRatio, runs };
  } finally {
    await host.close();
  }
}

export function sandboxRenderCsv(r: SandboxRenderResult): string {
  const head = 'renderer,threads,device,software,frames,seconds,fps,frame_ms_median,frame_ms_p95,steps_per_second,dropped_steps,ms_per_step,draw_ms_median,interactive';
  const lines = r.runs.map((x) =>
    csvLine([x.renderer, x.threads, x.device ?? '', x.software === null ? '' : String(x.software), x.frames, x.seconds, x.fps, x.frameMs.median, x.p95FrameMs, x.stepsPerSecond, x.droppedSteps, x.msPerStep ?? '', x.drawMs.median, String(x.interactive)]),
  );
  return [head, ...lines].join('\n') + '\n';
}

function deviceText(x: SandboxRenderRun): string {
  if (x.device === null) return 'canvas 2D';
  return x.software ? `${x.device} (software)` : x.device;
}

export function sandboxRenderTables(r: SandboxRenderResult): Table[] {
  const n = Number((r.meta.options as { n: number }).n).toLocaleString('en-US');
  return [
    {
      title: `T7 the sandbox page, uniform N = ${n}, live in headless Chromium (target: interactive, ≥ ${INTERACTIVE_FPS} fps with the simulation at real time, WebGL on a GPU)`,
      headers: ['renderer', 'threads', 'device', 'fps (median)', 'frame ms median [p25–p75], p95', 'steps / s (real time 60)', 'dropped steps', 'ms / step', 'draw ms (CPU)', 'interactive'],
      rows:
        r.status === 'skipped'
          ? [[`skipped: ${r.reason ?? ''}`, '', '', '', '', '', '', '', '', '']]
          : r.runs.map((x) => [
              x.renderer,
              String(x.threads),
              deviceText(x),
              fmt(x.fps),
              `${fmt(x.frameMs.median)} [${fmt(x.frameMs.p25)}–${fmt(x.frameMs.p75)}], ${fmt(x.p95FrameMs)}`,
              fmt(x.stepsPerSecond),
              String(x.droppedSteps),
              fmt(x.msPerStep),
              fmt(x.drawMs.median),
              x.interactive ? 'yes' : 'no',
            ]),
      note: r.settings
        ? `${r.runtime}; flags \`${r.settings.flags}\`; environment \`${r.settings.env ?? ''}\`; ${r.settings.page}; viewport ${r.settings.viewport}, device pixel ratio ${r.devicePixelRatio}. Each configuration ran ${fmt((r.meta.options as { warmupSeconds: number }).warmupSeconds)} s before ${fmt((r.meta.options as { seconds: number }).seconds)} s timed. Draw ms is the CPU side of a frame's drawing; the GPU's work shows in the frame intervals.`
        : undefined,
    },
  ];
}

export function sandboxRenderHeadline(r: SandboxRenderResult): string[] {
  if (r.status === 'skipped') return [`Skipped: ${r.reason ?? ''}.`];
  // One paragraph per configuration: markdown joins lines without a blank line between them.
  return r.runs.flatMap((x) => {
    const where = x.device === null ? 'canvas 2D' : x.software ? `WebGL on ${x.device}, a software rasteriser, so this is not a GPU measurement` : `WebGL on ${x.device}`;
    return [`${x.renderer}, ${x.threads} thread(s) (${where}): ${fmt(x.fps)} fps, ${fmt(x.stepsPerSecond)} steps/s, ${x.droppedSteps} dropped: ${x.interactive ? 'interactive' : 'not interactive'} (≥ ${INTERACTIVE_FPS} fps at real time).`, ''];
  });
}

const runSchema = {
  type: 'object',
  required: ['renderer', 'threads', 'device', 'software', 'frames', 'seconds', 'fps', 'frameMs', 'p95FrameMs', 'stepsPerSecond', 'droppedSteps', 'msPerStep', 'drawMs', 'interactive', 'notice'],
  properties: {
    renderer: { enum: ['webgl', 'canvas'] },
    threads: { type: 'integer', minimum: 1 },
    device: { type: ['string', 'null'] },
    software: { type: ['boolean', 'null'] },
    frames: { type: 'integer', minimum: 2 },
    seconds: { type: 'number', exclusiveMinimum: 0 },
    fps: { type: 'number', exclusiveMinimum: 0 },
    frameMs: spreadSchema,
    p95FrameMs: { type: 'number', minimum: 0 },
    stepsPerSecond: { type: 'number', minimum: 0 },
    droppedSteps: { type: 'integer', minimum: 0 },
    msPerStep: { type: ['number', 'null'] },
    drawMs: spreadSchema,
    interactive: { type: 'boolean' },
    notice: { type: 'string' },
  },
  additionalProperties: false,
} as const;

export const sandboxRenderSchema = {
  type: 'object',
  required: ['meta', 'status', 'runs'],
  properties: {
    meta: metaSchema,
    status: { enum: ['ok', 'skipped'] },
    reason: { type: 'string' },
    runtime: { type: 'string' },
    settings: { type: 'object', additionalProperties: { type: 'string' } },
    devicePixelRatio: { type: 'number', exclusiveMinimum: 0 },
    runs: { type: 'array', items: runSchema },
  },
  additionalProperties: false,
} as const;
