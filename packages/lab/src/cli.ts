import { Argument, Command, InvalidArgumentError, Option } from 'commander';
import { resolve } from 'node:path';
import { SCENE_NAMES } from '@maxgrid/scenes';
import { ENGINE_IDS } from './engines/registry.js';
import { nRange } from './experiments/common.js';
import { EXPERIMENTS, EXPERIMENT_NAMES, type Overrides } from './experiments/registry.js';

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
    return parts.map(item);
  };
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
  if (o.n) throw new InvalidArgumentError(`give --n or --n-start/--n-end/--n-step, not both (--n ${o.n.join(',')}, --n-start ${String(o.nStart)}).`);
  if (o.nStart === undefined || o.nEnd === undefined) throw new InvalidArgumentError(`--n-start and --n-end go together (got --n-start ${String(o.nStart)}, --n-end ${String(o.nEnd)}).`);
  if (o.nEnd < o.nStart) throw new InvalidArgumentError(`--n-end ${o.nEnd} is below --n-start ${o.nStart}.`);
  return nRange(o.nStart, o.nEnd, o.nStep ?? o.nStart);
}

const program = new Command()
  .name('npm run lab --')
  .description("maxgrid's lab: the report's experiments against Box2D, planck, Rapier, Matter.js and p2")
  .addArgument(new Argument('<experiment>', 'what to run').choices(EXPERIMENT_NAMES))
  .option('--engines <ids>', `comma-separated engines: ${ENGINE_IDS.join(', ')}`, list('--engines', oneOf('--engines', ENGINE_IDS)))
  .option('--n <list>', 'comma-separated body counts, e.g. 1000,4000', list('--n', positiveInteger('--n')))
  .option('--n-start <n>', 'first N of a range (the report: 10)', positiveInteger('--n-start'))
  .option('--n-end <n>', 'last N of a range (the report: 4200)', positiveInteger('--n-end'))
  .option('--n-step <n>', 'N increment (the report: 10; default --n-start)', positiveInteger('--n-step'))
  .option('--runs <n>', 'runs per N (the report: 10)', positiveInteger('--runs'))
  .option('--seconds <s>', 'simulated seconds per run (the report: 10)', positiveNumber('--seconds'))
  .option('--scene <names>', `comma-separated scenes: ${SCENE_NAMES.join(', ')}`, list('--scene', oneOf('--scene', SCENE_NAMES)))
  .option('--dt <s>', 'time step in seconds (default 1/60)', positiveNumber('--dt'))
  .option('--out <dir>', 'output folder (default out/lab/<experiment>; for results, docs)')
  .addOption(new Option('--quick', 'the quick profile (default)').conflicts('full'))
  .addOption(new Option('--full', "the report's full profile: 10..4200 by 10, 10 s, 10 runs (hours)"))
  .showHelpAfterError('(run with --help for usage)')
  .action(async (name: string, o: CliOptions) => {
    const profile = o.full ? 'full' : 'quick';
    const overrides: Overrides = { ns: nsFrom(o), runs: o.runs, seconds: o.seconds, scenes: o.scene, dt: o.dt };
    const command = `npm run lab -- ${process.argv.slice(2).join(' ')}`;
    if (name === 'results') {
      if (Object.values(overrides).some((v) => v !== undefined) || o.engines) {
        throw new InvalidArgumentError('results takes only --quick or --full and --out: it runs every experiment with its profile.');
      }
      const { runResults } = await import('./node/results.js');
      const written = await runResults({ profile, docsDir: resolve(o.out ?? 'docs'), command });
      console.log(written.join('\n'));
      return;
    }
    const experiment = EXPERIMENTS[name];
    // Validate before loading engines, ECharts and resvg, so a bad option fails at once.
    experiment.options(profile, overrides);
    const { runExperiment, writeExperiment } = await import('./node/run.js');
    const output = await runExperiment({ experiment, profile, overrides, engineIds: o.engines, command });
    const files = writeExperiment(resolve(o.out ?? `out/lab/${name}`), experiment, output, command);
    console.log(files.join('\n'));
  });

program.parseAsync(process.argv).catch((error: unknown) => {
  const message = error instanceof Error ? error.message : String(error);
  console.error(`error: ${message}`);
  process.exitCode = error instanceof InvalidArgumentError || error instanceof RangeError || error instanceof TypeError ? 2 : 1;
});
