import { describe, expect, it } from 'vitest';
import { execFileSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, rmSync, symlinkSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';

const ENGINE = fileURLToPath(new URL('..', import.meta.url));
const TSC = fileURLToPath(new URL('../../../node_modules/typescript/bin/tsc', import.meta.url));

/** An app of someone else's, using the public API with every optional field given as undefined, as exactOptionalPropertyTypes users write it. */
const APP = `
import { World, type BoxOptions, type JointOptions, type WorldOptions } from '@maxgrid/engine';
const options: WorldOptions = { gravity: { x: 0, y: 10 }, bounds: undefined, friction: undefined, broadphase: undefined };
const world = new World(options);
const box: BoxOptions = { x: 0, y: 0, width: 1, height: 1, vx: undefined, angle: undefined, type: undefined };
const a = world.createBox(box);
const b = world.createCircle({ x: 2, y: 0, radius: 0.5, vx: undefined, mass: undefined });
world.createSegment({ x1: -5, y1: 3, x2: 5, y2: 3, thickness: undefined });
const joint: JointOptions = { kind: 'revolute', bodyA: a, bodyB: b, anchorA: undefined, lowerAngle: undefined };
world.createJoint(joint);
world.createJoint({ kind: 'spring', bodyA: a, bodyB: b, stiffness: 10, damping: undefined });
world.step(1 / 60);
const hits: number[] = world.queryAABB(-1, -1, 1, 1, { mask: undefined });
const first = world.jointHandles()[0];
if (first !== undefined) console.log(world.getJoint(first).force.y, hits.length, world.views().x[0], world.backend.route);
void world.startWorkers(2, { minBodies: undefined, adaptive: undefined, workerUrl: undefined });
void world.startWorkers(2, { workerUrl: new URL('https://example.com/worker.js') });
`;

function compile(compilerOptions: Record<string, unknown>): string {
  const dir = mkdtempSync(join(tmpdir(), 'maxgrid-consumer-'));
  try {
    mkdirSync(join(dir, 'node_modules', '@maxgrid'), { recursive: true });
    symlinkSync(ENGINE, join(dir, 'node_modules', '@maxgrid', 'engine'), 'dir');
    writeFileSync(join(dir, 'app.ts'), APP);
    writeFileSync(join(dir, 'tsconfig.json'), JSON.stringify({ compilerOptions: { noEmit: true, ...compilerOptions }, files: ['app.ts'] }));
    try {
      execFileSync(process.execPath, [TSC, '-p', dir], { encoding: 'utf8' });
      return '';
    } catch (error) {
      return String((error as { stdout?: string }).stdout ?? error);
    }
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}

describe("the engine's types in a consumer project", () => {
  it("compile under tsc's defaults (its default target and lib, checking the engine's declarations)", () => {
    expect(compile({ module: 'esnext', moduleResolution: 'bundler' })).toBe('');
  }, 60_000);

  it('compile under the strictest options, exactOptionalPropertyTypes included, with optional fields given as undefined', () => {
    expect(compile({ module: 'nodenext', strict: true, exactOptionalPropertyTypes: true, noUncheckedIndexedAccess: true, noImplicitOverride: true, noPropertyAccessFromIndexSignature: true })).toBe('');
  }, 60_000);
});
