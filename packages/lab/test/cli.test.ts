import { describe, expect, it } from 'vitest';
import { execFile } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, readdirSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { Ajv } from 'ajv';
import { scale } from '../src/experiments/registry.js';

// The CLI runs as users run it: Node with tsx, from the repository root, against the built
// workspace packages (npm test builds them first).
const ROOT = fileURLToPath(new URL('../../..', import.meta.url));
const CLI = 'packages/lab/src/cli.ts';

function lab(...args: string[]): Promise<{ code: number; stdout: string; stderr: string }> {
  return new Promise((resolve) => {
    execFile(process.execPath, ['--import', 'tsx', CLI, ...args], { cwd: ROOT, timeout: 90_000 }, (error, stdout, stderr) => {
      const code = error ? (typeof error.code === 'number' ? error.code : 1) : 0;
      resolve({ code, stdout, stderr });
    });
  });
}

const BAD: [string, string[], RegExp][] = [
  ['unknown experiment', ['nope'], /nope.*(invalid|Allowed choices)/s],
  ['unknown engine', ['step-time', '--engines', 'maxgrid:maxgrid,havok'], /--engines.*'havok'/],
  ['N of zero', ['step-time', '--n', '100,0'], /--n must be a positive integer, got '0'/],
  ['non-numeric N', ['scale', '--n', 'lots'], /--n must be a positive integer, got 'lots'/],
  ['negative runs', ['step-time', '--runs', '-2'], /--runs must be a positive integer, got '-2'/],
  ['non-numeric seconds', ['step-time', '--seconds', 'ten'], /--seconds must be a positive number, got 'ten'/],
  ['unknown scene', ['step-time', '--scene', 'moon'], /--scene: unknown value 'moon'/],
  ['scene without N', ['step-time', '--scene', 'bouncing-ball'], /bouncing-ball.*sweep it over N/],
  ['option the experiment does not take', ['energy', '--runs', '3'], /--runs does not apply to experiment 'energy'/],
  ['inverted N range', ['step-time', '--n-start', '100', '--n-end', '10'], /--n-end 10 is below --n-start 100/],
  ['unknown option', ['scale', '--turbo'], /unknown option '--turbo'/],
  ['an engine twice', ['step-time', '--engines', 'maxgrid:maxgrid,maxgrid:maxgrid'], /--engines lists 'maxgrid:maxgrid' twice/],
  ['an N twice', ['scale', '--n', '100,100'], /--n lists '100' twice/],
  ['engines where they are fixed', ['threads', '--engines', 'rapier'], /--engines does not apply to experiment 'threads': it measures maxgrid:maxgrid only/],
  ['more circles than the sandbox page takes', ['sandbox-render', '--n', '300000'], /--n for experiment 'sandbox-render' is at most 200000.*got 300000/],
  ['an empty --out', ['energy', '--out', ''], /--out must name a folder, got ''/],
  ['an --out that is a file', ['energy', '--out', 'package.json'], /--out package.json: EEXIST/],
  ['a range step alone', ['step-time', '--n-step', '5'], /a range needs both --n-start and --n-end \(got only --n-step 5\)/],
  ['results with an option', ['results', '--n', '10'], /results takes only --quick or --full and --out \(got --n\)/],
];

describe('lab CLI', () => {
  it('rejects bad options with a message naming the option and value, and a non-zero exit', async () => {
    const results = await Promise.all(BAD.map(([, args]) => lab(...args)));
    BAD.forEach(([what, args], i) => {
      const { code, stderr } = results[i];
      expect(code, `${what}: ${args.join(' ')}`).not.toBe(0);
      expect(stderr, what).toMatch(BAD[i][2]);
    });
  });

  it('writes JSON, CSV, markdown, SVG and PNG charts and an HTML report into --out', async () => {
    const out = mkdtempSync(join(tmpdir(), 'lab-cli-'));
    try {
      const { code, stderr } = await lab('scale', '--n', '100,400', '--out', out);
      expect(code, stderr).toBe(0);
      const files = readdirSync(out).sort();
      expect(files).toEqual(
        ['scale-bytes-per-body.png', 'scale-bytes-per-body.svg', 'scale-ns-per-body.png', 'scale-ns-per-body.svg', 'scale.csv', 'scale.html', 'scale.json', 'scale.md'].sort(),
      );
      const result = JSON.parse(readFileSync(join(out, 'scale.json'), 'utf8'));
      const validate = new Ajv({ strict: false }).compile(scale.schema);
      expect(validate(result), JSON.stringify(validate.errors)).toBe(true);
      expect(result.meta.command).toBe(`npm run lab -- scale --n 100,400 --out ${out}`);
      expect(result.meta.profile).toBe('custom');
      expect(readFileSync(join(out, 'scale-ns-per-body.png')).subarray(1, 4).toString()).toBe('PNG');
      expect(readFileSync(join(out, 'scale.csv'), 'utf8').split('\n')[0]).toMatch(/^n,engine,order,age_s,median_ms/);
      expect(existsSync(join(out, 'scale.html'))).toBe(true);
      const md = readFileSync(join(out, 'scale.md'), 'utf8');
      expect(md).toContain(`Produced by \`npm run lab -- scale --n 100,400 --out ${out}\``);
      expect(md).toMatch(/\n\| N \| engine \|/);
    } finally {
      rmSync(out, { recursive: true, force: true });
    }
  });
});
