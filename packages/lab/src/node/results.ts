import { join } from 'node:path';
import type { EngineInfo } from '../engines/adapter.js';
import type { Profile } from '../experiments/common.js';
import type { EnergyResult } from '../experiments/energy.js';
import type { FalsePositiveResult } from '../experiments/false-positives.js';
import { EXPERIMENTS } from '../experiments/registry.js';
import type { ScaleResult } from '../experiments/scale.js';
import { stepTimeRatio, type StepTimeResult } from '../experiments/step-time.js';
import { htmlReport, tablesFor, type ReportSection } from '../report/html.js';
import { BASELINE, engineTable, fmt, markdownTable, ratioText } from '../report/tables.js';
import { nodeEnvironment } from './machine.js';
import type { CMaxgridResult } from '../experiments/c-maxgrid.js';
import type { SapSleepResult } from '../experiments/sap-sleep.js';
import type { TargetsResult } from '../experiments/targets.js';
import { cMaxgridHeadline, sapSleepHeadline, targetsHeadline } from '../report/tables-targets.js';
import { writeCharts, writeText } from './output.js';
import { runExperiment } from './run.js';

const ORDER = ['step-time', 'energy', 'false-positives', 'scale', 'sap-sleep', 'c-maxgrid', 'targets'] as const;

export interface ResultsRequest {
  profile: Profile;
  /** docs/ folder: results.md goes here, charts and data under results/. */
  docsDir: string;
  command: string;
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
    for (const e of (result.meta as unknown as { engines: EngineInfo[] }).engines) engines.set(e.id, e);
    written.push(writeText(dir, `${name}.json`, JSON.stringify(result) + '\n'), writeText(dir, `${name}.csv`, experiment.csv(result)));
    const charts = writeCharts(dir, experiment.charts(result));
    written.push(...charts.flatMap((c) => [join(dir, `${c.id}.svg`), join(dir, `${c.id}.png`)]));
    const tables = tablesFor(name, result);
    sections.push({ experiment: name, tables, svgs: charts.map((c) => c.svg) });
    md.push(`## ${experiment.description}`, '', ...headline(name, result), '');
    for (const c of charts) md.push(`![${c.id}](results/${c.id}.png)`, '');
    for (const t of tables) md.push(markdownTable(t), '');
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
    `Machine: ${environment.cpu}, ${environment.cores} cores, ${environment.memoryGiB} GiB, ${environment.platform}; ${environment.runtime} (V8 ${environment.v8}). Measured in Node, except the browser-parity target (T6), which steps the same world in headless Chromium through the lab page (\`/lab.html\` in the sandbox, which also runs the quick experiments in a browser).`,
    '',
    'The machine is shared and has two cores, so absolute times are noisy: read the ratios, measured in the same run with engines interleaved per N, rather than single times.',
    req.profile === 'quick' ? 'This is the **quick** profile (few N, short runs); `--full` runs the report\'s 10..4200 by 10, 10 s, 10 runs.' : '',
    '',
    markdownTable(engineTable(engineList)),
    '',
  ];
  written.push(writeText(req.docsDir, 'results.md', [...head, ...md].join('\n')));
  return written;
}

function headline(name: string, result: unknown): string[] {
  switch (name) {
    case 'step-time':
      return stepTimeHeadline(result as StepTimeResult);
    case 'energy': {
      const r = result as EnergyResult;
      return [
        `Bouncing ball after ${String(r.meta.options.ballSeconds)} simulated s, E/E0: ${r.ball.map((s) => `${s.engine} ${fmt(s.final, 4)}`).join(', ')}.`,
        '',
        `Elastic uniform scene (N = ${String(r.meta.options.n)}) after ${String(r.meta.options.seconds)} s, KE/KE0: ${r.uniform.map((s) => `${s.engine} ${fmt(s.final, 4)}`).join(', ')}.`,
      ];
    }
    case 'false-positives': {
      const r = result as FalsePositiveResult;
      const nMax = Math.max(...r.rows.filter((x) => x.sweep === 'n').map((x) => x.n));
      const at = (rows: typeof r.rows) => rows.map((x) => `${x.engine} ${fmt(x.testsPerContact)}`).join(', ');
      const out = [`Pairs examined per true contact at N = ${nMax}: ${at(r.rows.filter((x) => x.sweep === 'n' && x.n === nMax))}.`, ''];
      for (const sweep of ['mixed', 'log'] as const) {
        const rows = r.rows.filter((x) => x.sweep === sweep);
        if (rows.length === 0) continue;
        const qMax = Math.max(...rows.map((x) => x.ratio));
        out.push(`Radius spread 1:${qMax}, ${sweep === 'mixed' ? 'scene mixed' : 'uniform with log-uniform radii'}: ${at(rows.filter((x) => x.ratio === qMax))}.`, '');
      }
      return out;
    }
    case 'sap-sleep':
      return sapSleepHeadline(result as SapSleepResult);
    case 'c-maxgrid':
      return cMaxgridHeadline(result as CMaxgridResult);
    case 'targets':
      return targetsHeadline(result as TargetsResult);
    case 'scale': {
      const r = result as ScaleResult;
      const first = r.rows[0];
      const last = r.rows[r.rows.length - 1];
      return [
        `${last.engine}: ${fmt(last.nsPerBody)} ns per body per step at N = ${last.n.toLocaleString('en-US')} against ${fmt(first.nsPerBody)} at N = ${first.n.toLocaleString('en-US')} (ratio ${ratioText(last.nsPerBody / first.nsPerBody)}); ${fmt(last.bytesPerBody)} bytes per body.`,
      ];
    }
    default:
      return [];
  }
}

function stepTimeHeadline(r: StepTimeResult): string[] {
  const out: string[] = [];
  for (const scene of [...new Set(r.rows.map((x) => x.scene))]) {
    const rows = r.rows.filter((x) => x.scene === scene);
    const engines = [...new Set(rows.map((x) => x.engine))];
    const ns = [...new Set(rows.map((x) => x.n))].sort((a, b) => b - a);
    const base = ns.find((n) => rows.some((x) => x.n === n && x.engine === BASELINE));
    if (base === undefined) continue;
    const baseMs = rows.find((x) => x.n === base && x.engine === BASELINE)!.ms.median;
    const ratios = engines
      .filter((e) => e !== BASELINE)
      .map((e) => ({ e, q: stepTimeRatio(r, scene, base, e, BASELINE) }))
      .filter((x) => Number.isFinite(x.q))
      .sort((a, b) => b.q - a.q);
    out.push(
      `Scene ${scene}, N = ${base}: ${BASELINE} median ${fmt(baseMs)} ms per step; ${ratios.map((x) => `${x.e} / ${BASELINE} = ${ratioText(x.q)}`).join(', ')}.`,
      '',
    );
  }
  const skipped = r.skipped.map((s) => `${s.engine} on ${s.scene} from N = ${s.fromN}`);
  if (skipped.length) out.push(`Dropped for larger N after exceeding ${String(r.meta.options.cutoffMs)} ms per step: ${skipped.join('; ')}.`, '');
  return out;
}
