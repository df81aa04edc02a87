import { join } from 'node:path';
import type { EngineInfo } from '../engines/adapter.js';
import { warmUpMs, type Profile } from '../experiments/common.js';
import { EXPERIMENTS } from '../experiments/registry.js';
import { htmlReport, type ReportSection } from '../report/html.js';
import { machineLine, sectionMarkdown } from '../report/markdown.js';
import { engineTable, markdownTable } from '../report/tables.js';
import { nodeEnvironment } from './machine.js';
import { writeCharts, writeText } from './output.js';
import { runExperiment } from './run.js';

const ORDER = ['step-time', 'energy', 'false-positives', 'scale', 'sap-sleep', 'cliffs', 'threads-load', 'piles', 'shape-step-time', 'stability', 'shape-energy', 'shape-false-positives', 'joints', 'integrators', 'c-maxgrid', 'targets', 'sandbox-render'] as const;

/**
 * The warm-up every timing experiment gives each engine (experiments/common.ts warmUp), and the
 * measurement that asked for it.
 */
export const HOW_ENGINES_ARE_TIMED =
  `**How engines are timed.** Before an engine is timed on a case (shape-step-time, joints, c-maxgrid, and step-time at each scene's first N), it steps throwaway twins of that case, each from the scene's start through the timed run's own steps, for ${warmUpMs('quick') / 1000} s (quick) or ${warmUpMs('full') / 1000} s (full). JavaScript engines (maxgrid, planck, Matter.js, p2) start in V8's interpreter and WebAssembly ones (Rapier, Box2D) in its baseline compiler, and V8 optimises only code that has run often; a large scene's loops run long enough for that within a step, a small scene's do not. Timed cold, a small scene's first hundreds of steps run several times slower than the rest: on polygon-box at 250 bodies, fresh worlds timed over their steps 30 to 90 one after another in one process took maxgrid 0.54, 0.25, 0.19, then about 0.07 ms a step, and Rapier 0.22, 0.15, 0.12, then about 0.10 ms; the three-body car 0.22 then 0.025 ms (box2d-wasm 0.009 then 0.004-0.005). Without the warm-up the lab ranked engines by how fast they start, and had Rapier and Box2D overtake Max Grid on polygon-box from N = 250. The timed simulation itself still starts from the scene's start, so figures read after a run keep their simulated time.`;

export interface ResultsRequest {
  profile: Profile;
  /** docs/ folder: results.md goes here, charts and data under results/. */
  docsDir: string;
  command: string;
}

/**
 * One row per engine id in the report's settings table: an id met again must carry the same
 * settings, or the table would describe one experiment's engine with another's settings.
 */
export function mergeEngines(into: Map<string, EngineInfo>, engines: EngineInfo[], experiment: string): void {
  for (const e of engines) {
    const seen = into.get(e.id);
    if (seen && JSON.stringify(seen) !== JSON.stringify(e)) {
      throw new Error(`engine id ${e.id} of experiment ${experiment} has settings that differ from an earlier experiment's: give it an id of its own`);
    }
    into.set(e.id, e);
  }
}

/** Runs every experiment with one profile and writes docs/results.md, its charts and data. */
export async function runResults(req: ResultsRequest): Promise<string[]> {
  const dir = join(req.docsDir, 'results');
  const written: string[] = [];
  const results: Record<string, unknown> = {};
  const sections: ReportSection[] = [];
  const engines = new Map<string, EngineInfo>();
  const md: string[] = [];
  for (const name of ORDER) {
    const experiment = EXPERIMENTS[name];
    const { result } = await runExperiment({ experiment, profile: req.profile, overrides: {}, command: req.command });
    results[name] = result;
    mergeEngines(engines, (result.meta as unknown as { engines: EngineInfo[] }).engines, name);
    written.push(writeText(dir, `${name}.json`, JSON.stringify(result) + '\n'), writeText(dir, `${name}.csv`, experiment.csv(result)));
    const charts = writeCharts(dir, experiment.charts(result));
    written.push(...charts.flatMap((c) => [join(dir, `${c.id}.svg`), join(dir, `${c.id}.png`)]));
    const tables = EXPERIMENTS[name].tables(result);
    sections.push({ experiment: name, tables, svgs: charts.map((c) => c.svg) });
    md.push(`## ${experiment.description}`, '', ...sectionMarkdown(experiment, result, charts.map((c) => ({ id: c.id, path: `results/${c.id}.png` }))));
  }
  const environment = nodeEnvironment();
  const engineList = [...engines.values()];
  written.push(
    writeText(
      dir,
      'report.html',
      htmlReport({ title: 'maxgrid lab results', command: req.command, environment, engines: engineList, sections, results }),
    ),
  );
  const head = [
    '# maxgrid lab results',
    '',
    `Produced by one run of \`${req.command}\` (profile **${req.profile}**) on ${new Date().toISOString().slice(0, 10)}; run it again to regenerate this file, the charts and the data in [results/](results/) (JSON, CSV, SVG, PNG, and a self-contained [HTML report](results/report.html)).`,
    '',
    `${machineLine(environment)}. Measured in Node, except the browser-parity target (T6), which steps the same world in headless Chromium through the lab page (\`/lab.html\` in the sandbox, which also runs the quick experiments in a browser), and T7 (\`sandbox-render\`), which times the sandbox page itself in headless Chromium: this machine has no GPU, so its WebGL is SwiftShader; [gpu/sandbox-render.md](gpu/sandbox-render.md) is the same command on a GPU machine.`,
    '',
    'The machine is shared and has two cores, so absolute times are noisy: read the ratios, measured in the same run with engines interleaved per N, rather than single times.',
    '',
    HOW_ENGINES_ARE_TIMED,
    '',
    req.profile === 'quick' ? 'This is the **quick** profile (few N, short runs); `--full` runs the report\'s 10..4200 by 10, 10 s, 10 runs.' : '',
    '',
    markdownTable(engineTable(engineList)),
    '',
  ];
  written.push(writeText(req.docsDir, 'results.md', [...head, ...md].join('\n')));
  return written;
}
