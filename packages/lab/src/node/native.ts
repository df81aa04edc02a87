import { execFile } from 'node:child_process';
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import type { Scene } from '@maxgrid/scenes';
import type { CBaseline, CRun } from '../experiments/common.js';

/** The C baseline's source: a plain C copy of the engine's maxgrid step (see its header). */
export const C_SOURCE = fileURLToPath(new URL('../../native/maxgrid.c', import.meta.url));

/**
 * -O3 -march=native as issue 5 asks; -ffp-contract=off because GCC would otherwise fuse a*b+c
 * into FMA instructions, which round once where JavaScript rounds twice, and the hashes differ.
 */
export const C_FLAGS = ['-O3', '-march=native', '-ffp-contract=off'];

function exec(file: string, args: string[], maxBuffer = 64 * 2 ** 20): Promise<{ stdout: string; stderr: string }> {
  return new Promise((resolve, reject) => {
    execFile(file, args, { maxBuffer }, (error, stdout, stderr) => {
      if (error) reject(Object.assign(error, { stderr }));
      else resolve({ stdout, stderr });
    });
  });
}

/**
 * Why the C program cannot run `scene`, or null: it implements exactly the all-dynamic boxed
 * step with gravity along y (uniform, seed-box, mixed), nothing else.
 */
export function cUnsupported(scene: Scene): string | null {
  const statics = scene.fixed === null ? 0 : scene.fixed.reduce((a, f) => a + f, 0);
  if (statics > 0) return `scene '${scene.name}' has ${statics} static circles`;
  if (scene.segments.length > 0) return `scene '${scene.name}' has ${scene.segments.length} segments`;
  if (scene.gravity.x !== 0) return `scene '${scene.name}' has gravity along x (${scene.gravity.x})`;
  return null;
}

/**
 * The binary scene file native/maxgrid.c reads, little-endian: int32 n, f64 width, height,
 * gravityY, restitution, then n records of f64 x, y, vx, vy, radius.
 */
export function cSceneBytes(scene: Scene): Uint8Array {
  const reason = cUnsupported(scene);
  if (reason) throw new RangeError(`c-maxgrid cannot run this scene: ${reason}`);
  const bytes = new Uint8Array(4 + 4 * 8 + scene.count * 5 * 8);
  const view = new DataView(bytes.buffer);
  view.setInt32(0, scene.count, true);
  const header = [scene.bounds.width, scene.bounds.height, scene.gravity.y, scene.restitution];
  header.forEach((v, i) => view.setFloat64(4 + i * 8, v, true));
  let at = 4 + 4 * 8;
  for (let k = 0; k < scene.count; k++) {
    for (const v of [scene.x[k], scene.y[k], scene.vx[k], scene.vy[k], scene.radius[k]]) {
      view.setFloat64(at, v, true);
      at += 8;
    }
  }
  return bytes;
}

let cached: Promise<CBaseline | string> | undefined;

/**
 * Compiles native/maxgrid.c once per process into a temp folder (removed at exit), or resolves
 * to "no C compiler: ..." when `$CC` (default gcc) is missing. CC=none forces the skip.
 */
export function cBaseline(): Promise<CBaseline | string> {
  cached ??= compile();
  return cached;
}

async function compile(): Promise<CBaseline | string> {
  const compiler = process.env.CC ?? 'gcc';
  if (compiler === 'none') return 'no C compiler (CC=none)';
  let version: string;
  try {
    version = (await exec(compiler, ['--version'])).stdout.split('\n')[0].trim();
  } catch {
    return `no C compiler ('${compiler}' not found on PATH)`;
  }
  const dir = mkdtempSync(join(tmpdir(), 'maxgrid-c-'));
  process.once('exit', () => rmSync(dir, { recursive: true, force: true }));
  const binary = join(dir, 'maxgrid');
  const args = [...C_FLAGS, '-o', binary, C_SOURCE, '-lm'];
  try {
    await exec(compiler, args);
  } catch (error) {
    throw new Error(`compiling the C baseline failed: ${compiler} ${args.join(' ')}\n${String((error as { stderr?: string }).stderr ?? error)}`);
  }
  let runs = 0;
  return {
    command: `${compiler} ${C_FLAGS.join(' ')} -o maxgrid packages/lab/native/maxgrid.c -lm`,
    compiler: version,
    async run(scene: Scene, steps: number, warmupSteps: number, dt: number): Promise<CRun> {
      const file = join(dir, `scene-${runs++}.bin`);
      writeFileSync(file, cSceneBytes(scene));
      try {
        // String(dt) is the shortest decimal that reads back as the same double, and strtod
        // rounds correctly, so C steps with exactly the engine's dt.
        const { stdout } = await exec(binary, [file, String(steps), String(dt), String(warmupSteps)]);
        const out = JSON.parse(stdout) as { n: number; stepMs: number[]; hash: string };
        if (out.n !== scene.count || out.stepMs.length !== steps) throw new Error(`C baseline printed n=${out.n} and ${out.stepMs.length} steps, expected ${scene.count} and ${steps}`);
        return { stepMs: out.stepMs, hash: out.hash };
      } finally {
        rmSync(file, { force: true });
      }
    },
  };
}
