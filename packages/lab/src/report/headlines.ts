import type { EnergyResult } from '../experiments/energy.js';
import type { FalsePositiveResult } from '../experiments/false-positives.js';
import type { ScaleResult } from '../experiments/scale.js';
import { stepTimeRatio, type StepTimeResult } from '../experiments/step-time.js';
import { BASELINE, fmt, ratioText } from './tables.js';

// The sentences that open each experiment's section of docs/results.md: medians and ratios.

export function energyHeadline(r: EnergyResult): string[] {
  return [
    `Bouncing ball after ${String(r.meta.options.ballSeconds)} simulated s, E/E0: ${r.ball.map((s) => `${s.engine} ${fmt(s.final, 4)}`).join(', ')}.`,
    '',
    `Elastic uniform scene (N = ${String(r.meta.options.n)}) after ${String(r.meta.options.seconds)} s, KE/KE0: ${r.uniform.map((s) => `${s.engine} ${fmt(s.final, 4)}`).join(', ')}.`,
  ];
}

export function falsePositiveHeadline(r: FalsePositiveResult): string[] {
  const nMax = Math.max(...r.rows.filter((x) => x.sweep === 'n').map((x) => x.n));
  const at = (rows: typeof r.rows) => rows.map((x) => `${x.engine} ${fmt(x.testsPerContact)}`).join(', ');
  const out = [`Pairs examined per true contact at N = ${nMax}: ${at(r.rows.filter((x) => x.sweep === 'n' && x.n === nMax))}.`, ''];
  for (const sweep of ['mixed', 'log'] as const) {
    const rows = r.rows.filter((x) => x.sweep === sweep);
    if (rows.length === 0) continue;
    const qMax = Math.max(...rows.map((x) => x.ratio));
    out.push(`Radius spread 1:${qMax}, ${sweep === 'mixed' ? 'scene mixed' : 'uniform with log-uniform radii'}: ${at(rows.filter((x) => x.ratio === qMax))}.`, '');
  }
  return out;
}

export function scaleHeadline(r: ScaleResult): string[] {
  const out: string[] = [];
  const fresh = r.rows.filter((x) => x.ageSeconds === 0);
  const ordered = fresh.filter((x) => x.order === 'rows');
  const shuffled = fresh.filter((x) => x.order === 'shuffled');
  for (const rows of [ordered, shuffled]) {
    if (rows.length === 0) continue;
    const first = rows[0];
    const last = rows[rows.length - 1];
    const how = first.order === 'rows' ? 'created row by row' : 'created in a random order';
    out.push(
      `${last.engine}, ${how}: ${fmt(last.nsPerBody)} ns per body per step at N = ${last.n.toLocaleString('en-US')} against ${fmt(first.nsPerBody)} at N = ${first.n.toLocaleString('en-US')} (ratio ${ratioText(last.nsPerBody / first.nsPerBody)}); ${fmt(last.bytesPerBody)} bytes per body.`,
    );
  }
  const last = ordered[ordered.length - 1];
  const twin = last && shuffled.find((x) => x.n === last.n && x.engine === last.engine);
  if (twin) {
    out.push(`At N = ${last.n.toLocaleString('en-US')}, shuffled / row by row = ${ratioText(twin.ms.median / last.ms.median)} per step.`);
  }
  const oldest = Math.max(...r.rows.map((x) => x.ageSeconds));
  if (last && oldest > 0) {
    const parts: string[] = [];
    for (const start of [last, twin]) {
      const aged = start && r.rows.find((x) => x.n === start.n && x.engine === start.engine && x.order === start.order && x.ageSeconds === oldest);
      if (aged) parts.push(`${aged.order === 'rows' ? 'row by row' : 'shuffled'} ${ratioText(aged.ms.median / start.ms.median)}`);
    }
    if (parts.length > 0) out.push(`At N = ${last.n.toLocaleString('en-US')}, after ${oldest} s of motion / fresh: ${parts.join(', ')} per step.`);
  }
  return out;
}

export function stepTimeHeadline(r: StepTimeResult): string[] {
  const out: string[] = [];
  for (const scene of [...new Set(r.rows.map((x) => x.scene))]) {
    const rows = r.rows.filter((x) => x.scene === scene);
    const engines = [...new Set(rows.map((x) => x.engine))];
    const ns = [...new Set(rows.map((x) => x.n))].sort((a, b) => b - a);
    const base = ns.find((n) => rows.some((x) => x.n === n && x.engine === BASELINE));
    if (base === undefined) continue;
    const baseMs = rows.find((x) => x.n === base && x.engine === BASELINE)!.ms.median;
    const ratios = engines
      .filter((e) => e !== BASELINE)
      .map((e) => ({ e, q: stepTimeRatio(r, scene, base, e, BASELINE) }))
      .filter((x) => Number.isFinite(x.q))
      .sort((a, b) => b.q - a.q);
    const compared = ratios.length > 0 ? `; ${ratios.map((x) => `${x.e} / ${BASELINE} = ${ratioText(x.q)}`).join(', ')}` : '';
    out.push(`Scene ${scene}, N = ${base}: ${BASELINE} median ${fmt(baseMs)} ms per step${compared}.`, '');
  }
  const skipped = r.skipped.map((s) => `${s.engine} on ${s.scene} from N = ${s.fromN}`);
  if (skipped.length) out.push(`Dropped for larger N after exceeding ${String(r.meta.options.cutoffMs)} ms per step: ${skipped.join('; ')}.`, '');
  return out;
}
