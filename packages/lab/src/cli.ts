import { Argument, Command, InvalidArgumentError, Option } from 'commander';
import { mkdirSync } from 'node:fs';
import { resolve } from 'node:path';
import { SCENE_NAMES } from '@maxgrid/scenes';
import { ENGINE_IDS } from './engines/registry.js';
import { SHAPE_ENGINE_IDS } from './shape-engines/registry.js';

/** Circle engines, then the shape engines not among them: experiments on shape scenes take the latter. */
const ALL_ENGINE_IDS = [...ENGINE_IDS, ...SHAPE_ENGINE_IDS.filter((id) => !ENGINE_IDS.includes(id))];
import { nRange } from './experiments/common.js';
import { EXPERIMENTS, EXPERIMENT_NAMES, OVERRIDE_FLAGS as FLAGS, type Overrides } from './experiments/registry.js';

// Every parser names the option and the value it rejects; commander prefixes "error: option ...".
function positiveInteger(flag: string) {
  return (value: string): number => {
    const n = Number(value);
    if (value.trim() === '' || !Number.isSafeInteger(n) || n <= 0) throw new InvalidArgumentError(`${flag} must be a positive integer, got '${value}'.`);
    return n;
  };
}

function positiveNumber(flag: string) {
  return (value: string): number => {
    const x = Number(value);
    if (value.trim() === '' || !Number.isFinite(x) || x <= 0) throw new InvalidArgumentError(`${flag} must be a positive number, got '${value}'.`);
    return x;
  };
}

function list<T>(flag: string, item: (value: string) => T) {
  return (value: string): T[] => {
    const parts = value.split(',').map((s) => s.trim());
    if (parts.some((p) => p === '')) throw new InvalidArgumentError(`${flag} must be a comma-separated list without empty items, got '${value}'.`);
    const items = parts.map(item);
    // A repeated item would be measured twice and its rows merged: 1 run would be reported as 2.
    const twice = items.find((x, k) => items.indexOf(x) !== k);
    if (twice !== undefined) throw new InvalidArgumentError(`${flag} lists '${String(twice)}' twice, in '${value}'.`);
    return items;
  };
}

function folder(value: string): string {
  if (value.trim() === '') throw new InvalidArgumentError(`--out must name a folder, got '${value}'.`);
  return value;
}

function oneOf(flag: string, allowed: readonly string[]) {
  return (value: string): string => {
    if (!allowed.includes(value)) throw new InvalidArgumentError(`${flag}: unknown value '${value}'; choose from ${allowed.join(', ')}.`);
    return value;
  };
}

interface CliOptions {
  engines?: string[];
  n?: number[];
  nStart?: number;
  nEnd?: number;
  nStep?: number;
  runs?: number;
  seconds?: number;
  scene?: string[];
  dt?: number;
  out?: string;
  quick?: boolean;
  full?: boolean;
}

function nsFrom(o: CliOptions): number[] | undefined {
  const range = [o.nStart, o.nEnd, o.nStep];
  if (range.every((v) => v === undefined)) return o.n;
  const given = [['--n-start', o.nStart], ['--n-end', o.nEnd], ['--n-step', o.nStep]].filter(([, v]) => v !== undefined).map(([flag, v]) => `${flag} ${v}`).join(', ');
  if (o.n) throw new InvalidArgumentError(`give --n or --n-start/--n-end/--n-step, not both (got --n ${o.n.join(',')} and ${given}).`);
  if (o.nStart === undefined || o.nEnd === undefined) throw new InvalidArgumentError(`a range needs both --n-start and --n-end (got only ${given}).`);
  if (o.nEnd < o.nStart) throw new InvalidArgumentError(`--n-end ${o.nEnd} is below --n-start ${o.nStart}.`);
  return nRange(o.nStart, o.nEnd, o.nStep ?? o.nStart);
}

const program = new Command()
  .name('npm run lab --')
  .description("maxgrid's lab: the report's experiments against Box2D, planck, Rapier, Matter.js and p2")
  .addArgument(new Argument('<experiment>', 'what to run').choices(EXPERIMENT_NAMES))
  .option('--engines <ids>', `comma-separated engines: ${ALL_ENGINE_IDS.join(', ')} (shape experiments: ${SHAPE_ENGINE_IDS.join(', ')})`, list('--engines', oneOf('--engines', ALL_ENGINE_IDS)))
  .option('--n <list>', 'comma-separated body counts, e.g. 1000,4000', list('--n', positiveInteger('--n')))
  .option('--n-start <n>', 'first N of a range (the report: 10)', positiveInteger('--n-start'))
  .option('--n-end <n>', 'last N of a range (the report: 4200)', positiveInteger('--n-end'))
  .option('--n-step <n>', 'N increment (the report: 10; default --n-start)', positiveInteger('--n-step'))
  .option('--runs <n>', 'runs per N (the report: 10); threads: timed steps; c-maxgrid, sap-sleep: rounds', positiveInteger('--runs'))
  .option('--seconds <s>', 'simulated seconds per run (the report: 10); sandbox-render: seconds of page time timed', positiveNumber('--seconds'))
  .option('--scene <names>', `comma-separated scenes: ${SCENE_NAMES.join(', ')}`, list('--scene', oneOf('--scene', SCENE_NAMES)))
  .option('--dt <s>', 'time step in seconds (default 1/60)', positiveNumber('--dt'))
  .option('--out <dir>', 'output folder (default out/lab/<experiment>; for results, docs)', folder)
  .addOption(new Option('--quick', 'the quick profile (default)').conflicts('full'))
  .addOption(new Option('--full', "each experiment's full profile (step-time: the report's 10..4200 by 10, 10 s, 10 runs; hours)"))
  .showHelpAfterError('(run with --help for usage)')
  .action(async (name: string, o: CliOptions) => {
    const profile = o.full ? 'full' : 'quick';
    const overrides: Overrides = { ns: nsFrom(o), runs: o.runs, seconds: o.seconds, scenes: o.scene, dt: o.dt };
    const command = `npm run lab -- ${process.argv.slice(2).join(' ')}`;
    if (name === 'results') {
      const extra = (Object.keys(overrides) as (keyof Overrides)[]).filter((key) => overrides[key] !== undefined).map((key) => FLAGS[key]);
      if (o.engines) extra.push('--engines');
      if (extra.length > 0) {
        throw new InvalidArgumentError(`results takes only --quick or --full and --out (got ${extra.join(', ')}): it runs every experiment with its profile.`);
      }
      const { runResults } = await import('./node/results.js');
      const written = await runResults({ profile, docsDir: resolve(o.out ?? 'docs'), command });
      console.log(written.join('\n'));
      return;
    }
    const experiment = EXPERIMENTS[name];
    // Validate before loading engines, ECharts and resvg, so a bad option fails at once.
    experiment.options(profile, overrides);
    if (o.engines && experiment.fixedEngines) {
      throw new InvalidArgumentError(`option --engines does not apply to experiment '${name}': it measures ${experiment.defaultEngines.join(', ')} only.`);
    }
    const outDir = resolve(o.out ?? `out/lab/${name}`);
    // Before the measurement, which can take hours: a folder that cannot be made would lose it.
    try {
      mkdirSync(outDir, { recursive: true });
    } catch (error) {
      throw new InvalidArgumentError(`--out ${o.out ?? outDir}: ${error instanceof Error ? error.message : String(error)}.`);
    }
    const { runExperiment, writeExperiment } = await import('./node/run.js');
    const output = await runExperiment({ experiment, profile, overrides, engineIds: o.engines, command });
    const files = writeExperiment(outDir, experiment, output, command);
    console.log(files.join('\n'));
  });

program.parseAsync(process.argv).catch((error: unknown) => {
  const message = error instanceof Error ? error.message : String(error);
  console.error(`error: ${message}`);
  process.exitCode = error instanceof InvalidArgumentError || error instanceof RangeError || error instanceof TypeError ? 2 : 1;
});
