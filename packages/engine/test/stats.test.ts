import { describe, expect, it } from 'vitest';
import { buildScene, buildWorld } from '@maxgrid/scenes';
import { BROADPHASE_NAMES } from './helpers.js';

describe('world.stats', () => {
  it('reports candidates before the narrow-phase, contacts after it, and stage times', () => {
    const counts = BROADPHASE_NAMES.map((broadphase) => {
      const world = buildWorld(buildScene('seed-box', { n: 400, seed: 8 }), { broadphase });
      world.step(1 / 60);
      const s = world.stats;
      expect(s.steps).toBe(1);
      expect(s.bodies).toBe(400);
      expect(s.candidatePairs).toBeGreaterThanOrEqual(s.contacts);
      for (const key of ['integrateMs', 'boundaryMs', 'broadphaseMs', 'narrowphaseMs', 'solveMs', 'correctMs', 'totalMs'] as const) {
        expect(Number.isFinite(s[key]) && s[key] >= 0).toBe(true);
      }
      return { broadphase, candidates: s.candidatePairs, contacts: s.contacts };
    });
    expect(counts.find((c) => c.broadphase === 'naive')?.candidates).toBe((400 * 399) / 2);
    expect(new Set(counts.map((c) => c.contacts)).size).toBe(1);
    expect(counts[0].contacts).toBeGreaterThan(0);
  });
});
