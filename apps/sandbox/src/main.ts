import { BodyTypeCode, World, type BroadPhaseName } from '@maxgrid/engine';
import { refusals } from './broadphase-budget.js';
import { Controls, usableCores } from './controls.js';
import { download, toCsv, toJson } from './data-export.js';
import { FrameLog, type FrameSample } from './frame-log.js';
import { attachPointer } from './interaction.js';
import { MonitorPanel } from './monitor/panel.js';
import { QueryTool } from './query-tool.js';
import { Canvas2DRenderer } from './render/canvas2d.js';
import { Overlay, type OverlayOptions } from './render/overlay.js';
import type { Renderer, SceneShapes } from './render/renderer.js';
import { WebGLRenderer } from './render/webgl.js';
import { spawnRadius } from './scene-specs.js';
import {
  copySettings,
  defaultSettings,
  offeredThreads,
  parseSettings,
  refusedTools,
  serializeSettings,
  type RendererName,
  type Settings,
  type ToolName,
} from './settings.js';
import { DT, STEP_BUDGET_MS, Simulation } from './simulation.js';
import { Pace } from './pace.js';
import { decodeSave, encodeSave, saveName } from './save-file.js';
import { TimelineBar } from './timeline.js';
import { ViewTransform } from './view.js';

function byId<T extends HTMLElement>(id: string): T {
  const el = document.getElementById(id);
  if (!el) throw new Error(`sandbox page is missing #${id}`);
  return el as T;
}

const stage = byId<HTMLDivElement>('stage');
const canvas2d = byId<HTMLCanvasElement>('canvas-2d');
const canvasGl = byId<HTMLCanvasElement>('canvas-webgl');
const overlay = new Overlay(byId<HTMLCanvasElement>('overlay'));
const notice = byId<HTMLParagraphElement>('notice');
const paceLine = byId<HTMLParagraphElement>('pace');
const pace = new Pace();
const pauseButton = byId<HTMLButtonElement>('pause');
const overfill = byId<HTMLParagraphElement>('overfill');

const sim = new Simulation();
const view = new ViewTransform();
const monitor = new MonitorPanel(sim.recorder);
const query = new QueryTool(byId('query-readout'));
/** Frames of the current world: cleared on rebuild, so its steps add up to the world's own. */
const frameLog = new FrameLog();
const renderers: Partial<Record<RendererName, Renderer>> = { canvas: new Canvas2DRenderer(canvas2d) };
let renderer: Renderer = renderers.canvas as Renderer;

let settings: Settings = parseSettings(location.search);
settings.threads = offeredThreads(settings.threads, usableCores());
// A scene change waits for the next frame, so dragging a slider rebuilds once per frame at most.
let pendingScene: Settings | null = null;
// Likewise a seek: dragging the scrubber over many steps restores and steps once per frame.
let pendingSeek: number | null = null;
let forceStats = true;

const controls = new Controls(settings, {
  scene(next) {
    pendingScene = next;
  },
  live(next) {
    applyLive(next);
  },
});

function say(message: string): void {
  notice.textContent = message;
}

/**
 * Warns when the circles' area exceeds the box's: the quantity slider allows far more circles
 * than fit (50,000 default circles cover 4.3 times the box), and such a world does not settle but
 * is pushed apart for as long as it runs. Summed from the bodies, so clicks that add circles count.
 */
function showOverfill(): void {
  let ratio = 0;
  if (sim.bounded && !sim.shapes) {
    const v = sim.world.views();
    let area = 0;
    for (let s = 0; s < v.slotCount; s++) if (v.type[s] === BodyTypeCode.dynamic) area += Math.PI * v.radius[s] * v.radius[s];
    ratio = area / (sim.box.width * sim.box.height);
  }
  overfill.hidden = !(ratio > 1);
  overfill.textContent = ratio > 1 ? `Circles cover ${ratio.toFixed(1)}x the box's area: they will overlap and be pushed apart.` : '';
}

/** The button names what a click will do, so a paused page does not look like a running one. */
function showPaused(): void {
  pauseButton.textContent = sim.paused ? 'Resume' : 'Pause';
  pauseButton.setAttribute('aria-pressed', String(sim.paused));
}

/** Broad-phases the current world would make too slow, with why (broadphase-budget.ts). */
let refused: Partial<Record<BroadPhaseName, string>> = {};

/** Keeps the page responsive: a broad-phase over the pair budget in the world now shown gives way to auto. */
function withinBudget(s: Settings): Settings {
  refused = refusals(sim.world.views());
  const why = refused[s.broadphase];
  if (why !== undefined) {
    say(`${why}; using auto.`);
    sim.setBroadphase('auto');
    return { ...s, broadphase: 'auto' };
  }
  if (s.scene === 'mixed' && s.broadphase === 'maxgrid') say('Max Grid sizes every cell by the largest circle, so here it tests many pairs; try hgrid or auto.');
  return s;
}

/** Tools the current world has no use for, with why (refusedTools). */
let unusable: Partial<Record<ToolName, string>> = {};

/** Offers only the tools the world on screen can use: a tool it refuses gives way to Drag. */
function withinTools(s: Settings): Settings {
  unusable = refusedTools(sim.acceptsJoints);
  const why = unusable[s.tool];
  if (why === undefined) return s;
  say(`${why}; using Drag.`);
  return { ...s, tool: 'drag' };
}

/**
 * Builds the world for `next`. A scene may refuse its parameters (more circles than fit the funnel,
 * a minimum radius above the maximum): then the page says why and keeps, or falls back to, a
 * scene that builds, so the controls and the URL always describe the world on screen.
 */
function rebuild(next: Settings): void {
  say('');
  timeline.say('');
  let wanted = copySettings(next);
  try {
    sim.rebuild(wanted);
  } catch (error) {
    const fallback = sim.world ? settings : { ...defaultSettings(wanted.scene), ...pickView(wanted) };
    const kept = sim.world ? 'kept the last scene that fits' : "using the scene's defaults";
    say(`${error instanceof Error ? error.message : String(error)}; ${kept}.`);
    wanted = fallback;
    sim.rebuild(wanted);
  }
  settings = withinTools(withinBudget(wanted));
  shown();
}

/** After the world was replaced (a rebuild, a load): the page's own state starts over with it. */
function shown(): void {
  pendingSeek = null;
  frameLog.clear();
  pace.reset();
  paceLine.textContent = '';
  sim.setThreads(settings.threads, threadsFailed);
  query.clear();
  query.setTool(settings.tool);
  controls.show(settings, refused, unusable);
  saveUrl();
  showOverfill();
  forceStats = true;
}

/**
 * Shows the world of a save as it was: its scene's settings (view and tools included), paused or
 * running. A file that is no save, or a snapshot the engine refuses, changes nothing: the line
 * under the timeline says why, in the engine's words.
 */
function loadSave(name: string, bytes: Uint8Array): void {
  let next: Settings;
  let paused: boolean;
  try {
    const save = decodeSave(bytes);
    next = parseSettings(save.header.settings);
    next.threads = offeredThreads(next.threads, usableCores());
    const world = World.restore(save.snapshot);
    if (world.stats.steps !== save.header.step) throw new RangeError(`the header says step ${save.header.step}, the snapshot is of step ${world.stats.steps}`);
    sim.load(next, world, save.snapshot, save.header.mark);
    paused = save.header.paused;
  } catch (error) {
    timeline.say(`Could not load ${name}: ${error instanceof Error ? error.message : String(error)}. Nothing changed.`, true);
    return;
  }
  say('');
  pendingScene = null;
  settings = withinTools(withinBudget(next));
  settings.renderer = selectRenderer(settings.renderer);
  shown();
  sim.paused = paused;
  showPaused();
  refreshStats();
  timeline.say(`Loaded ${name}: ${settings.scene} at step ${sim.step.toLocaleString('en-US')}.`);
}

function saveWorld(): void {
  const { snapshot, mark } = sim.save();
  const bytes = encodeSave({ sandboxSave: 1, settings: serializeSettings(settings), step: sim.step, paused: sim.paused, mark }, snapshot);
  download(saveName(settings.scene, sim.step), 'application/octet-stream', bytes);
}

function seek(step: number): void {
  sim.seek(step);
  // The snapshot's broad-phase may be another: every one gives the same bits, so the page's stays.
  sim.setBroadphase(settings.broadphase);
  // The integrator is the step's own: going back before a switch switches back, and the form says so.
  if (sim.world.integrator !== settings.integrator) {
    settings.integrator = sim.world.integrator;
    controls.show(settings, refused, unusable);
    saveUrl();
  }
  // world.restore stopped the workers.
  sim.setThreads(settings.threads, threadsFailed);
  showPaused();
  refreshStats();
}

/** The choices that are not the scene: kept when a URL's scene falls back to its defaults. */
function pickView(s: Settings): Partial<Settings> {
  const { broadphase, integrator, renderer, grid, aabb, contacts, sleeping, piles, continuous, events, hits, layers, tool, threads, substeps, spawn } = s;
  return { broadphase, integrator, renderer, grid, aabb, contacts, sleeping, piles, continuous, events, hits, layers, tool, threads, substeps, spawn };
}

function threadsFailed(message: string): void {
  say(`Worker threads did not start (${message}); stepping on one thread.`);
}

function applyLive(next: Settings): void {
  say('');
  settings = copySettings({ ...next, params: settings.params });
  sim.setBroadphase(settings.broadphase);
  settings = withinBudget(settings);
  sim.setIntegrator(settings.integrator);
  sim.setThreads(settings.threads, threadsFailed);
  settings.renderer = selectRenderer(settings.renderer);
  if (settings.tool !== query.tool) {
    sim.endDrag();
    query.setTool(settings.tool);
    query.update(sim.world);
  }
  controls.show(settings, refused, unusable);
  saveUrl();
}

/** Switches the visible canvas; WebGL is created on first use and falls back to canvas 2D. */
function selectRenderer(name: RendererName): RendererName {
  if (name === 'webgl' && !renderers.webgl) {
    try {
      renderers.webgl = new WebGLRenderer(canvasGl);
    } catch (error) {
      controls.disableRenderer('webgl', String(error));
      say(`WebGL is not available here (${String(error)}); drawing with canvas 2D.`);
      name = 'canvas';
    }
  }
  renderer = renderers[name] as Renderer;
  canvas2d.hidden = name !== 'canvas';
  canvasGl.hidden = name !== 'webgl';
  view.width = 0; // Forces the new canvas to be sized on the next frame.
  return name;
}

function saveUrl(): void {
  history.replaceState(null, '', serializeSettings(settings) + location.hash);
}

function resize(): void {
  const box = sim.box;
  const dpr = Math.min(window.devicePixelRatio || 1, 2);
  if (!view.fit(stage.clientWidth, stage.clientHeight, dpr, box.width, box.height, box.x, box.y)) return;
  // A region that follows a body changes the offsets every step, not the size: setting a canvas's
  // size, even to the same value, clears it and reallocates its backing store.
  for (const c of [renderer.canvas, overlay.canvas]) {
    if (c.width !== view.width) c.width = view.width;
    if (c.height !== view.height) c.height = view.height;
  }
}

// Buttons and clicks refresh the numbers at once, so what is on screen matches what was done.
function refreshStats(): void {
  showOverfill();
  query.update(sim.world);
  monitor.update(performance.now(), sim, true);
}

pauseButton.addEventListener('click', () => {
  sim.paused = !sim.paused;
  showPaused();
  refreshStats();
});
byId('step').addEventListener('click', () => {
  sim.stepOnce();
  refreshStats();
});
byId('reset').addEventListener('click', () => {
  rebuild(controls.settings);
  refreshStats();
});
const timeline = new TimelineBar(sim, {
  seek(step) {
    pendingSeek = step;
  },
  save: saveWorld,
  load: loadSave,
});
byId('download').addEventListener('click', () => {
  const format = byId<HTMLSelectElement>('format').value;
  // Only some scenes have a body count.
  const count = settings.params.n === undefined ? '' : `-n${settings.params.n}`;
  const base = `maxgrid-${settings.scene}${count}-seed${settings.seed}`;
  const world = sim.world;
  if (format === 'json') download(`${base}.json`, 'application/json', toJson(sim.recorder, settings, DT, world.broadphase, world.integrator));
  else download(`${base}.csv`, 'text/csv', toCsv(sim.recorder));
});
attachPointer(overlay.canvas, sim, view, query, () => spawnRadius(settings.scene, settings.params), () => settings.spawn, refreshStats, say);

// Read by the renderers and the overlay every frame: kept up to date in place, never rebuilt.
const shapes: SceneShapes = { segments: sim.segments, staticCircles: 0, sleepers: 0, joints: null };
const overlayOptions: OverlayOptions = { grid: false, aabb: false, contacts: false, held: -1, grab: null, segments: sim.segments, touches: sim.touches, hits: sim.hits, query, bounds: null };

rebuild(settings);
settings.renderer = selectRenderer(settings.renderer);
controls.show(settings, refused, unusable);
saveUrl();

declare global {
  interface Window {
    /** Per-frame timings, read by the lab's sandbox-render experiment (see frame-log.ts). */
    __sandboxFrames?: { read(): FrameSample; clear(): void; webglDevice(): string | null };
    /** For the end-to-end tests: a body's pose by handle, the engine's route, the region drawn, the view's mapping to CSS pixels, and the joints. */
    __sandboxProbe?: {
      pose(handle: number): { x: number; y: number; angle: number; type: string };
      jointCount(): number;
      /** The k-th live joint's handle and world anchors, in slot order, or null past the last. */
      joint(k: number): { handle: number; ax: number; ay: number; bx: number; by: number } | null;
      route(): string;
      region(): { x: number; y: number; width: number; height: number };
      toCss(x: number, y: number): { x: number; y: number };
      /** world.stateHash() and the world's step count, read at the same moment. */
      state(): { hash: string; step: number; time: number; paused: boolean };
      /** The scrubber's history: the steps it reaches, its snapshots and their bytes. */
      history(): { oldest: number; head: number; count: number; bytes: number; spacing: number };
    };
  }
}
window.__sandboxProbe = {
  pose: (handle) => {
    const b = sim.world.getBody(handle);
    return { x: b.x, y: b.y, angle: b.angle, type: b.type };
  },
  jointCount: () => sim.world.jointCount,
  joint: (k) => {
    const j = sim.world.jointViews();
    return k < j.count ? { handle: j.handle[k], ax: j.anchorAX[k], ay: j.anchorAY[k], bx: j.anchorBX[k], by: j.anchorBY[k] } : null;
  },
  route: () => sim.world.route.route,
  region: () => ({ ...sim.box }),
  toCss: (x, y) => ({ x: (x * view.scale + view.offsetX) / view.dpr, y: (y * view.scale + view.offsetY) / view.dpr }),
  state: () => ({ hash: sim.world.stateHash(), step: sim.step, time: sim.time, paused: sim.paused }),
  history: () => {
    const h = sim.history;
    return { oldest: h.oldest, head: h.head, count: h.count, bytes: h.bytes, spacing: h.spacing };
  },
};
window.__sandboxFrames = {
  read: () => ({
    ...frameLog.frames(),
    droppedSteps: sim.droppedSteps,
    simulatedSeconds: sim.time,
    bodies: sim.world.bodyCount,
    renderer: settings.renderer,
    threads: sim.world.workerCount,
  }),
  clear: () => frameLog.clear(),
  webglDevice: () => (renderers.webgl instanceof WebGLRenderer ? renderers.webgl.device : null),
};

let last = performance.now();
function frame(now: number): void {
  requestAnimationFrame(frame);
  // A hidden tab or a debugger pause can make one frame seconds long; the simulation caps it too.
  const frameSeconds = (now - last) / 1000;
  const elapsed = Math.min(Math.max(0, frameSeconds), 0.25);
  last = now;
  if (frameSeconds > 0) monitor.fps.push(1 / frameSeconds);
  if (pendingScene) {
    const next = pendingScene;
    pendingScene = null;
    rebuild(next);
  }
  if (pendingSeek !== null) {
    const step = pendingSeek;
    pendingSeek = null;
    seek(step);
  }
  const stepStart = performance.now();
  const steps = sim.advance(elapsed);
  const drawStart = performance.now();
  if (sim.paused) pace.reset();
  else pace.note(Math.max(0, frameSeconds), steps, DT, drawStart - stepStart);
  const paceText = pace.message(STEP_BUDGET_MS);
  if (paceLine.textContent !== paceText) paceLine.textContent = paceText;
  resize();
  shapes.segments = overlayOptions.segments = sim.segments;
  shapes.staticCircles = sim.staticCircles;
  shapes.sleepers = sim.world.stats.sleepingBodies;
  shapes.joints = sim.world.jointCount > 0 ? sim.world.jointViews() : null;
  renderer.draw(sim.world.views(), sim.colors, view, sim.box, shapes);
  overlayOptions.grid = settings.grid;
  overlayOptions.aabb = settings.aabb;
  overlayOptions.contacts = settings.contacts;
  overlayOptions.bounds = sim.bounded ? sim.box : null;
  overlayOptions.held = sim.dragging;
  overlayOptions.grab = sim.grabPoint();
  query.update(sim.world);
  overlay.draw(sim.world, view, overlayOptions);
  frameLog.record(now, drawStart - stepStart, performance.now() - drawStart, steps);
  monitor.update(now, sim, forceStats);
  timeline.update();
  forceStats = false;
}
requestAnimationFrame(frame);
