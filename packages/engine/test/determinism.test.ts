import { describe, expect, it } from 'vitest';
import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import fc from 'fast-check';
import { World } from '../src/index.js';
import { buildScene, buildWorld } from '@maxgrid/scenes';
import { BROADPHASE_NAMES, buildSpec, sceneArbitrary } from './helpers.js';

describe('canonical order: every broad-phase gives bit-identical states', () => {
  it('on random scenes (non-square boxes, radius ratios up to 1:50)', () => {
    fc.assert(
      fc.property(sceneArbitrary, fc.constantFrom('explicit-euler', 'semi-implicit-euler'), (spec, integrator) => {
        const hashes = BROADPHASE_NAMES.map((broadphase) => {
          const world = buildSpec(spec, { broadphase, integrator });
          let contacts = 0;
          for (let s = 0; s < 40; s++) {
            world.step(1 / 60);
            contacts += world.stats.contacts;
          }
          return `${world.stateHash()} ${contacts}`;
        });
        expect(new Set(hashes).size).toBe(1);
      }),
      { numRuns: 60, seed: 20261122 },
    );
  });

  it('when the broad-phase is switched in the middle of a run', () => {
    const reference = buildWorld(buildScene('seed-box', { n: 600, seed: 3 }), { broadphase: 'naive' });
    const switching = buildWorld(buildScene('seed-box', { n: 600, seed: 3 }), { broadphase: 'maxgrid' });
    for (let s = 0; s < 120; s++) {
      switching.setBroadphase(BROADPHASE_NAMES[s % BROADPHASE_NAMES.length]);
      reference.step(1 / 60);
      switching.step(1 / 60);
    }
    expect(switching.stateHash()).toBe(reference.stateHash());
  });
});

describe('determinism', () => {
  it('the same inputs give the same bits, run after run', () => {
    const run = () => {
      const world = buildWorld(buildScene('uniform', { n: 1500, seed: 11 }));
      for (let s = 0; s < 200; s++) world.step(1 / 60);
      return world.stateHash();
    };
    expect(run()).toBe(run());
  });

  it('a different seed gives a different state (the hash is not constant)', () => {
    const hashOf = (seed: number) => buildWorld(buildScene('uniform', { n: 200, seed })).stateHash();
    expect(hashOf(1)).not.toBe(hashOf(2));
  });

  // Pinned so that any change to the physics, its order of operations or the scene builders shows
  // up here. If a change is meant to alter results, update the hash in the same commit and say why.
  it('golden state hash of a fixed seeded scene', () => {
    const world = buildWorld(buildScene('seed-box', { n: 800, seed: 42 }), { integrator: 'explicit-euler' });
    for (let s = 0; s < 600; s++) world.step(1 / 60);
    expect(world.stateHash()).toBe(GOLDEN_SEED_BOX_800);
  });
});

const GOLDEN_SEED_BOX_800 = '1981b004408be274';

describe('the engine uses only correctly rounded arithmetic (docs/engine.md, Guarantees)', () => {
  it('no Math function whose rounding each JavaScript engine chooses appears in the source', () => {
    // +, -, *, /, Math.sqrt and the rounding and min/max functions are exact or correctly rounded
    // by the language; these are not, so they could give other bits in another runtime.
    const inexact = /Math\.(hypot|exp|expm1|log|log1p|log2|log10|pow|sin|cos|tan|asin|acos|atan|atan2|sinh|cosh|tanh|asinh|acosh|atanh|cbrt)\(/;
    const src = fileURLToPath(new URL('../src', import.meta.url));
    const files = readdirSync(src, { recursive: true, encoding: 'utf8' }).filter((f) => f.endsWith('.ts') && !f.startsWith('generated'));
    expect(files.length).toBeGreaterThan(40);
    const found = files.flatMap((file) =>
      readFileSync(join(src, file), 'utf8')
        .split('\n')
        .filter((line) => inexact.test(line) && !/^\s*(\*|\/\/)/.test(line))
        .map((line) => `${file}: ${line.trim()}`),
    );
    expect(found).toEqual([]);
  });
});

export { World };
