import type * as CANNON from 'cannon-es';
import { CUBE_SIZE, DT, MutableTypes, addCube, createWorld, isSleeping, isStatic, setSleeping } from './physics.js';
import { DEFAULT_SETTINGS, VARIANTS, runExperiment, totalSteps, type LayeredDropSettings } from './experiment.js';
import { renderResults } from './results.js';
import { PerfMonitor } from './monitor.js';
import { CubeView } from './view.js';
import { jitter, mulberry32 } from './rng.js';

/**
 * The 3D page: the report's early exploration with three.js and Cannon (5.3). A stack of cubes
 * falls onto a plane (figure 8), with the sleeping objects and mutable physics object types
 * toggles of 5.3.3, and the layered-drop experiment of figure 9 run from a button.
 */

function byId<T extends HTMLElement>(id: string, type: new () => T): T {
  const el = document.getElementById(id);
  if (!(el instanceof type)) throw new Error(`#${id} is missing or not a ${type.name}`);
  return el;
}

const ui = {
  view: byId('view', HTMLElement),
  perf: byId('perf', HTMLCanvasElement),
  perfReadout: byId('perf-readout', HTMLElement),
  sleeping: byId('sleeping', HTMLInputElement),
  mutable: byId('mutable', HTMLInputElement),
  stackHeight: byId('stack-height', HTMLInputElement),
  seed: byId('seed', HTMLInputElement),
  drop: byId('drop', HTMLButtonElement),
  simStats: byId('sim-stats', HTMLElement),
  layers: byId('layers', HTMLInputElement),
  side: byId('side', HTMLInputElement),
  dropInterval: byId('drop-interval', HTMLInputElement),
  settleSteps: byId('settle-steps', HTMLInputElement),
  experimentSeed: byId('experiment-seed', HTMLInputElement),
  stepsPerVariant: byId('steps-per-variant', HTMLElement),
  run: byId('run-experiment', HTMLButtonElement),
  status: byId('experiment-status', HTMLElement),
  results: byId('layered-drop-results', HTMLTableElement),
};

/** An integer from a number input, clamped to its min/max, falling back when it is empty or not a number. */
function intInput(input: HTMLInputElement, fallback: number): number {
  const v = Math.round(Number(input.value));
  if (input.value.trim() === '' || !Number.isFinite(v)) return fallback;
  const min = input.min === '' ? -Infinity : Number(input.min);
  const max = input.max === '' ? Infinity : Number(input.max);
  return Math.min(max, Math.max(min, v));
}

// Once an edit ends, each box shows the value in use: a clamped or empty entry used to stay on
// screen while another value ran (Stack height 1000 showed 1000 and dropped 40).
for (const input of [ui.stackHeight, ui.seed, ui.layers, ui.side, ui.dropInterval, ui.settleSteps, ui.experimentSeed]) {
  input.addEventListener('change', () => {
    input.value = String(intInput(input, Number(input.defaultValue)));
  });
}

/** The controls that change the live stack or the experiment's settings: held while it runs. */
const heldDuringExperiment = [ui.drop, ui.stackHeight, ui.seed, ui.sleeping, ui.mutable, ui.layers, ui.side, ui.dropInterval, ui.settleSteps, ui.experimentSeed];

// ---- The live stack (figure 8) ----------------------------------------------------------------

/** Stack footprint: FOOTPRINT × FOOTPRINT columns of cubes. */
const FOOTPRINT = 2;
/** Height of the stack's bottom above the plane when dropped. */
const DROP_HEIGHT = 2;
/** At most this many fixed steps per frame: a slow frame then slows the simulation down instead of
 *  spiralling (each catch-up step making the next frame slower still). */
const MAX_STEPS_PER_FRAME = 4;

interface Live {
  world: CANNON.World;
  cubes: CANNON.Body[];
  mutable: MutableTypes;
  steps: number;
}

/** Builds the stack from the seed: each cube slightly off-centre and turned, so the stack collapses. */
function buildLive(height: number, seed: number): Live {
  const world = createWorld();
  const rng = mulberry32(seed);
  const cubes: CANNON.Body[] = [];
  const pitch = CUBE_SIZE * 1.02;
  for (let level = 0; level < height; level++) {
    for (let i = 0; i < FOOTPRINT; i++) {
      for (let j = 0; j < FOOTPRINT; j++) {
        const x = (i - (FOOTPRINT - 1) / 2) * pitch + jitter(rng, 0.12);
        const z = (j - (FOOTPRINT - 1) / 2) * pitch + jitter(rng, 0.12);
        cubes.push(addCube(world, x, DROP_HEIGHT + (level + 0.5) * pitch, z, jitter(rng, 0.3)));
      }
    }
  }
  const live: Live = { world, cubes, mutable: new MutableTypes(world), steps: 0 };
  applyToggles(live);
  return live;
}

function applyToggles(target: Live): void {
  setSleeping(target.world, ui.sleeping.checked);
  if (ui.mutable.checked) target.mutable.enabled = true;
  else if (target.mutable.enabled) target.mutable.disable();
}

const view = new CubeView(ui.view);
const monitor = new PerfMonitor(ui.perf, ui.perfReadout);
let live = buildLive(intInput(ui.stackHeight, Number(ui.stackHeight.defaultValue)), intInput(ui.seed, Number(ui.seed.defaultValue)));
view.aim(DROP_HEIGHT + intInput(ui.stackHeight, Number(ui.stackHeight.defaultValue)));
let accumulator = 0;
let lastTime = -1;
/** True while the layered-drop experiment owns the view and the CPU. */
let experimentRunning = false;

/** Shows the live simulation's progress, in text and in data attributes that tests can read. */
function showStats(): void {
  let sumY = 0;
  let statics = 0;
  let sleeping = 0;
  for (const c of live.cubes) {
    sumY += c.position.y;
    if (isStatic(c)) statics++;
    else if (isSleeping(c)) sleeping++;
  }
  const meanY = live.cubes.length ? sumY / live.cubes.length : 0;
  const s = ui.simStats;
  s.dataset['steps'] = String(live.steps);
  s.dataset['meanHeight'] = meanY.toFixed(4);
  s.dataset['cubes'] = String(live.cubes.length);
  s.dataset['static'] = String(statics);
  s.dataset['sleeping'] = String(sleeping);
  s.textContent =
    `${live.cubes.length} cubes, ${live.steps} steps, mean height ${meanY.toFixed(2)} m; ` +
    `${statics} static objects, ${sleeping} sleeping objects`;
}

/** The animation loop of 5.3.1: requestAnimationFrame, physics at a fixed step, then draw. */
function frame(now: number): void {
  requestAnimationFrame(frame);
  if (experimentRunning) {
    lastTime = -1;
    return;
  }
  // Physics is decoupled from the display's rate: whole fixed steps from an accumulator.
  accumulator += lastTime < 0 ? DT : Math.min((now - lastTime) / 1000, MAX_STEPS_PER_FRAME * DT);
  lastTime = now;
  let physicsMs = 0;
  while (accumulator >= DT) {
    const t0 = performance.now();
    live.world.step(DT);
    physicsMs += performance.now() - t0;
    live.mutable.afterStep();
    live.steps++;
    accumulator -= DT;
  }
  view.render(live.cubes);
  monitor.frame(now, physicsMs);
  showStats();
}

ui.sleeping.addEventListener('change', () => applyToggles(live));
ui.mutable.addEventListener('change', () => applyToggles(live));
ui.drop.addEventListener('click', () => {
  const height = intInput(ui.stackHeight, Number(ui.stackHeight.defaultValue));
  live = buildLive(height, intInput(ui.seed, Number(ui.seed.defaultValue)));
  view.aim(DROP_HEIGHT + height);
  accumulator = 0;
});
window.addEventListener('resize', () => view.resize());
requestAnimationFrame(frame);

// ---- The layered-drop experiment (figure 9) ---------------------------------------------------

function readSettings(): LayeredDropSettings {
  const d = DEFAULT_SETTINGS;
  return {
    layers: intInput(ui.layers, d.layers),
    side: intInput(ui.side, d.side),
    dropInterval: intInput(ui.dropInterval, d.dropInterval),
    settleSteps: intInput(ui.settleSteps, d.settleSteps),
    seed: intInput(ui.experimentSeed, d.seed),
  };
}

function showStepsPerVariant(): void {
  const s = readSettings();
  ui.stepsPerVariant.textContent = `${totalSteps(s)} steps per variant, ${s.layers * s.side * s.side} cubes`;
}
for (const input of [ui.layers, ui.side, ui.dropInterval, ui.settleSteps]) input.addEventListener('input', showStepsPerVariant);
showStepsPerVariant();

ui.run.addEventListener('click', () => {
  if (experimentRunning) return;
  const settings = readSettings();
  experimentRunning = true;
  ui.run.disabled = true;
  for (const control of heldDuringExperiment) control.disabled = true;
  ui.results.dataset['status'] = 'running';
  view.aim(settings.layers * CUBE_SIZE + 2);
  // Draw the run in progress, but keep drawing to about a fifth of the wall time: with software
  // WebGL a frame can cost more than the physics it shows, and the experiment should finish soon.
  let nextRender = 0;
  runExperiment(settings, (run) => {
    const label = VARIANTS.find((v) => v.id === run.variant)?.label ?? run.variant;
    ui.status.textContent = `Running: ${label}, step ${run.done} of ${run.steps}…`;
    const t0 = performance.now();
    if (t0 < nextRender && !run.finished) return;
    view.render(run.cubes);
    const t1 = performance.now();
    nextRender = t1 + 4 * (t1 - t0);
  })
    .then((results) => {
      renderResults(ui.results, results);
      ui.results.dataset['status'] = 'done';
      ui.status.textContent =
        `Done: ${settings.layers} layers of ${settings.side}×${settings.side} cubes, ` +
        `${totalSteps(settings)} steps of 1/60 s per variant, seed ${settings.seed}.`;
    })
    .catch((error: unknown) => {
      ui.results.dataset['status'] = 'error';
      ui.status.textContent = `The experiment failed: ${String(error)}`;
      console.error(error);
    })
    .finally(() => {
      experimentRunning = false;
      ui.run.disabled = false;
      for (const control of heldDuringExperiment) control.disabled = false;
      monitor.restart();
      view.aim(DROP_HEIGHT + intInput(ui.stackHeight, Number(ui.stackHeight.defaultValue)));
    });
});
