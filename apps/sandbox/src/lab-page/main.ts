import box2dSimdWasm from 'box2d-wasm/dist/es/Box2D.simd.wasm?url';
import box2dWasm from 'box2d-wasm/dist/es/Box2D.wasm?url';
import {
  ENGINE_IDS,
  EXPERIMENTS,
  engineTable,
  htmlTable,
  loadEngines,
  renderSvg,
  tablesFor,
  type Engine,
  type Environment,
} from '../../../../packages/lab/src/browser.js';
import { BROWSER_QUICK, browserEnvironment, determinism, fromPlainScene, pageWorlds, type DeterminismResult, type PageWorlds, type PlainScene } from './runs.js';

/** What the page exposes to tests and to anyone who wants the numbers (also printed as JSON). */
export interface LabPageResults {
  environment: Environment;
  determinism: DeterminismResult | null;
  experiments: Record<string, unknown>;
  /** Wall-clock seconds each experiment took in this tab. */
  seconds: Record<string, number>;
  errors: string[];
  done: boolean;
}

declare global {
  interface Window {
    __labResults?: LabPageResults;
    /** Steps a scene built elsewhere (in Node) with every broad-phase: isolates the engine. */
    __labDeterminismOf?: (scene: PlainScene) => Promise<DeterminismResult>;
    /** Worlds stepped on request: the lab's Node-vs-Chromium parity target drives these. */
    __labWorlds?: PageWorlds;
  }
}

const $ = (id: string) => document.getElementById(id)!;

function show(results: LabPageResults): void {
  window.__labResults = results;
  $('lab-json').textContent = JSON.stringify(results, null, 1);
}

function status(text: string): void {
  $('status').textContent = text;
}

const yieldToHost = () => new Promise<void>((resolve) => setTimeout(resolve, 0));

function renderDeterminism(result: DeterminismResult): void {
  const rows = Object.entries(result.hashes).map(
    ([bp, hash]) => `<tr><td>${bp}</td><td><code>${hash}</code></td><td>${result.ms[bp].toFixed(0)}</td></tr>`,
  );
  const same = new Set(Object.values(result.hashes)).size === 1;
  const digest = Object.entries(result.sceneDigest)
    .map(([k, v]) => `${k} <code>${v}</code>`)
    .join(', ');
  $('determinism').innerHTML = `<h2>Determinism</h2>
<p>Scene <code>uniform</code> ${JSON.stringify(result.params)}, built with <code>buildWorld</code>, ${result.steps} steps at dt ${result.dt === 1 / 60 ? '1/60 s' : `${result.dt} s`}:
${same ? 'every broad-phase gives the same state hash' : '<strong>broad-phases disagree</strong>'}. The lab's browser test computes the same in Node and compares.</p>
<p class="muted">Scene columns as built here: ${digest}.</p>
<table><thead><tr><th>broad-phase</th><th>stateHash()</th><th>ms for all steps</th></tr></thead><tbody>${rows.join('')}</tbody></table>`;
}

function renderExperiment(name: string, result: unknown): void {
  const experiment = EXPERIMENTS[name];
  const section = document.createElement('section');
  section.id = `experiment-${name}`;
  const charts = experiment.charts(result).map((c) => `<figure>${renderSvg(c)}</figure>`);
  const tables = tablesFor(name, result).map(htmlTable);
  section.innerHTML = `<h2>${experiment.description}</h2>${charts.join('')}${tables.join('')}`;
  $('experiments').append(section);
}

async function runAll(): Promise<void> {
  const button = $('run') as HTMLButtonElement;
  button.disabled = true;
  $('experiments').replaceChildren();
  const environment = browserEnvironment();
  const results: LabPageResults = { environment, determinism: null, experiments: {}, seconds: {}, errors: [], done: false };
  $('environment').innerHTML = `<p class="muted">${Object.entries(environment)
    .map(([k, v]) => `${k}: ${String(v)}`)
    .join(' · ')}</p>`;
  show(results);
  const only = new URLSearchParams(location.search).get('experiments');
  // Node-only experiments (the C baseline, the targets that drive this page) are not in BROWSER_QUICK.
  const asked = only === null ? Object.keys(BROWSER_QUICK) : only.split(',').map((name) => name.trim());
  const chosen = asked.filter((name) => name in BROWSER_QUICK);
  const refused = asked.filter((name) => !(name in BROWSER_QUICK));
  if (refused.length > 0) {
    const text = `experiments= names ${refused.map((name) => `'${name}'`).join(', ')}, which this page does not run (unknown, or Node-only); it runs ${Object.keys(BROWSER_QUICK).join(', ')}`;
    results.errors.push(text);
    $('experiments').insertAdjacentHTML('beforeend', `<p class="error"></p>`);
    $('experiments').lastElementChild!.textContent = text;
  }
  try {
    status('Determinism: stepping the golden scene with every broad-phase…');
    await yieldToHost();
    const t0 = performance.now();
    results.determinism = await determinism(undefined, yieldToHost);
    results.seconds.determinism = (performance.now() - t0) / 1000;
    renderDeterminism(results.determinism);
    show(results);

    status('Loading engines (box2d-wasm and Rapier compile WebAssembly)…');
    // Only the engines the chosen experiments measure: all 13 took the wait and filled the table for sap-sleep's two.
    const needed = ENGINE_IDS.filter((id) => chosen.some((name) => EXPERIMENTS[name].defaultEngines.includes(id)));
    const engines: Engine[] = await loadEngines(needed, {
      // Vite serves the .wasm files under hashed URLs; Emscripten asks for them by file name.
      box2dLocateFile: (file) => (file.endsWith('.simd.wasm') ? box2dSimdWasm : box2dWasm),
    });
    $('environment').insertAdjacentHTML('beforeend', htmlTable(engineTable(engines.map((e) => e.info))));
    for (const name of chosen) {
      const sizes = BROWSER_QUICK[name];
      const started = performance.now();
      const experiment = EXPERIMENTS[name];
      const ids = experiment.defaultEngines;
      const options = { ...experiment.options('quick', {}), ...sizes };
      const result = await experiment.run(options, {
        engines: engines.filter((e) => ids.includes(e.info.id)),
        environment,
        profile: 'quick',
        yieldToHost,
        progress: (done: number, total: number, label: string) => status(`${name}: ${done}/${total} ${label}`),
      });
      results.experiments[name] = result;
      results.seconds[name] = (performance.now() - started) / 1000;
      renderExperiment(name, result);
      show(results);
      await yieldToHost();
    }
    status('Done.');
  } catch (error) {
    const text = error instanceof Error ? `${error.message}\n${error.stack ?? ''}` : String(error);
    results.errors.push(text);
    $('experiments').insertAdjacentHTML('beforeend', `<p class="error"></p>`);
    $('experiments').lastElementChild!.textContent = text;
    status('Failed; see the error below.');
  } finally {
    results.done = true;
    show(results);
    button.disabled = false;
  }
}

window.__labDeterminismOf = (scene) => determinism(fromPlainScene(scene));
window.__labWorlds = pageWorlds();
$('run').addEventListener('click', () => void runAll());
if (new URLSearchParams(location.search).get('auto') === '1') void runAll();
