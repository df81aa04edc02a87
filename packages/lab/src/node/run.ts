import { join } from 'node:path';
import type { Engine } from '../engines/adapter.js';
import type { Profile } from '../experiments/common.js';
import type { AnyExperiment, Overrides } from '../experiments/registry.js';
import { htmlReport, tablesFor } from '../report/html.js';
import { machineLine, sectionMarkdown } from '../report/markdown.js';
import { loadEnginesNode, loadShapeEnginesNode } from './engines.js';
import { nodeEnvironment } from './machine.js';
import { writeCharts, writeText } from './output.js';
import { progressBar } from './progress.js';
import { nodeHost } from './host.js';

export interface RunRequest {
  experiment: AnyExperiment;
  profile: Profile;
  overrides: Overrides;
  engineIds?: string[];
  /** The command line that reproduces the run, written into every output. */
  command: string;
}

export interface RunOutput {
  result: { meta: { command?: string } } & Record<string, unknown>;
  engines: Engine[];
  svgs: { id: string; svg: string }[];
}

/** Runs one experiment in Node with a progress bar; options are validated before engines load. */
export async function runExperiment(req: RunRequest): Promise<Omit<RunOutput, 'svgs'>> {
  const options = req.experiment.options(req.profile, req.overrides);
  const ids = req.engineIds ?? req.experiment.defaultEngines;
  const engines = req.experiment.shapes ? [] : await loadEnginesNode(ids);
  const shapeEngines = req.experiment.shapes ? await loadShapeEnginesNode(ids) : undefined;
  const custom = Object.values(req.overrides).some((v) => v !== undefined) || req.engineIds !== undefined;
  const bar = progressBar(req.experiment.name);
  try {
    const result = await req.experiment.run(options, {
      engines,
      shapeEngines,
      environment: nodeEnvironment(),
      profile: custom ? 'custom' : req.profile,
      progress: bar.progress,
      host: nodeHost(),
    });
    result.meta.command = req.command;
    return { result, engines };
  } finally {
    bar.stop();
  }
}

/** The experiment's section as docs/results.md has it, with the command and machine it came from. */
export function experimentMarkdown(experiment: AnyExperiment, result: Omit<RunOutput, 'svgs'>['result'], command: string, chartIds: string[]): string {
  const meta = result.meta as unknown as { generatedAt: string; environment: Record<string, string | number> };
  return [
    `# maxgrid lab: ${experiment.name}`,
    '',
    `${experiment.description}. Produced by \`${command}\` on ${meta.generatedAt.slice(0, 10)}.`,
    '',
    `${machineLine(meta.environment)}.`,
    '',
    ...sectionMarkdown(experiment, result, chartIds.map((id) => ({ id, path: `${id}.png` }))),
  ].join('\n');
}

/** JSON, CSV, markdown, SVG and PNG charts and a self-contained HTML report, all into `dir`. */
export function writeExperiment(dir: string, experiment: AnyExperiment, output: Omit<RunOutput, 'svgs'>, command: string): string[] {
  const name = experiment.name;
  const files = [
    writeText(dir, `${name}.json`, JSON.stringify(output.result, null, 1) + '\n'),
    writeText(dir, `${name}.csv`, experiment.csv(output.result)),
  ];
  const charts = writeCharts(dir, experiment.charts(output.result));
  files.push(...charts.flatMap((c) => [join(dir, `${c.id}.svg`), join(dir, `${c.id}.png`)]));
  files.push(writeText(dir, `${name}.md`, experimentMarkdown(experiment, output.result, command, charts.map((c) => c.id))));
  const meta = output.result.meta as unknown as { environment: Record<string, string | number> };
  files.push(
    writeText(
      dir,
      `${name}.html`,
      htmlReport({
        title: `maxgrid lab: ${name}`,
        command,
        environment: { runtime: String(meta.environment.runtime), ...meta.environment },
        engines: output.engines.map((e) => e.info),
        sections: [{ experiment: name, tables: tablesFor(name, output.result), svgs: charts.map((c) => c.svg) }],
        results: { [name]: output.result },
      }),
    ),
  );
  return files;
}
