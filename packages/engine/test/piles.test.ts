import { describe, expect, it } from 'vitest';
import { buildScene, buildWorld } from '@maxgrid/scenes';
import type { WorldOptions } from '../src/index.js';

/**
 * Mean distance each body travels in the tenth second of the report's seed box with elasticity 0:
 * by then the circles have fallen and lie in a pile on the floor, so this is how much the pile moves.
 */
function pileMotion(options: WorldOptions): number {
  const world = buildWorld(buildScene('seed-box', { n: 1000, elasticity: 0 }), options);
  for (let s = 0; s < 540; s++) world.step(1 / 60);
  const v = world.views();
  const n = v.slotCount;
  const x = new Float64Array(n);
  const y = new Float64Array(n);
  let moved = 0;
  for (let s = 0; s < 60; s++) {
    x.set(v.x.subarray(0, n));
    y.set(v.y.subarray(0, n));
    world.step(1 / 60);
    for (let k = 0; k < n; k++) moved += Math.hypot(v.x[k] - x[k], v.y[k] - y[k]);
  }
  return moved / n;
}

describe('piles under gravity', () => {
  it('partial position correction with a slop lets a pile rest, where full separation keeps it boiling', () => {
    // Gravity adds g·dt = 5 px/s a step. Full separation pushes bodies through their neighbours,
    // so a settled pile's bodies travel about 200 px in a second (measured 204); removing a fifth
    // of the overlap beyond 0.05 px keeps contacts from step to step, and the pile barely moves (4.4).
    const full = pileMotion({});
    const soft = pileMotion({ positionCorrection: 0.2, contactSlop: 0.05 });
    expect(soft).toBeLessThan(full / 10);
    expect(soft).toBeLessThan(10);
  });
});
