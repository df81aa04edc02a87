import { describe, expect, it } from 'vitest';
import { Ajv } from 'ajv';
import type { RunContext } from '../src/experiments/common.js';
import { loadEnginesNode } from '../src/node/engines.js';
import { blowUpStiffness, integrators, integratorsCsv, integratorsHeadline, integratorsTables, runIntegrators } from '../src/experiments/integrators.js';

describe('integrators experiment', () => {
  it('explicit Euler blows up where semi-implicit Euler and rk4 hold, rk4 drifts least, soft constraints never blow up', async () => {
    const ctx: RunContext = { engines: await loadEnginesNode(['maxgrid:maxgrid']), environment: { runtime: 'vitest' } };
    const result = await runIntegrators({ ...integrators.options('quick', { seconds: 2 }), stiffnesses: [300, 1e6] }, ctx);
    expect(result.rows).toHaveLength(2 * 4 * 2);
    for (const system of ['spring pair', 'jelly'] as const) {
      const row = (method: string, k: number) => result.rows.find((r) => r.system === system && r.method === method && r.stiffness === k)!;
      // omega h = 0.10 per sub-step at k = 300: explicit Euler gains energy 1 % a sub-step.
      expect(blowUpStiffness(result, system, 'explicit-euler')).toBe(300);
      expect(row('semi-implicit-euler', 300).blewUp).toBe(false);
      expect(row('rk4', 300).blewUp).toBe(false);
      expect(row('rk4', 300).drift!).toBeLessThan(row('semi-implicit-euler', 300).drift! / 100);
      // omega h = 5.9 at k = 10^6: past every explicit method's stability limit.
      expect(row('semi-implicit-euler', 1e6).blewUp).toBe(true);
      expect(row('rk4', 1e6).blewUp).toBe(true);
      expect(blowUpStiffness(result, system, 'soft-constraint')).toBeNull();
      // The soft constraint is implicit: it loses energy rather than gaining it.
      expect(row('soft-constraint', 1e6).final!).toBeLessThan(1);
    }
    const validate = new Ajv({ strict: false }).compile(integrators.schema);
    expect(validate(JSON.parse(JSON.stringify(result))), JSON.stringify(validate.errors)).toBe(true);
    expect(integratorsCsv(result).trim().split('\n')).toHaveLength(17);
    expect(integratorsTables(result)[1].rows.map((r) => r[r.length - 1])).toEqual(['300', '1,000,000', '1,000,000', 'never']);
    expect(integratorsHeadline(result)[0]).toMatch(/explicit-euler from k = 300/);
    // 10^6 N/m between 1 kg bodies is 225 Hz, past the 60 Hz that soft constraints are held to at 60 Hz.
    expect(integratorsHeadline(result)[2]).toMatch(/at most at a quarter of the sub-step rate \(60 Hz at 60 Hz with 4 sub-steps\): from k = 1,000,000 \(225 Hz\)/);
    const gentle = await runIntegrators({ ...integrators.options('quick', { seconds: 0.5 }), stiffnesses: [300] }, ctx);
    expect(integratorsHeadline(gentle)[2]).toBe('');
  });

  it('takes --seconds and --dt only', () => {
    expect(() => integrators.options('quick', { ns: [10] })).toThrow(/--n does not apply to experiment 'integrators'/);
  });
});
