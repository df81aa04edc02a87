import { csvLine } from './common.js';
import type { TargetsResult } from './targets.js';

/** One line per measured quantity: target, what, engine or runtime, value, unit. */
export function targetsCsv(r: TargetsResult): string {
  const lines = [csvLine(['target', 'quantity', 'subject', 'value', 'unit'])];
  const add = (target: string, quantity: string, subject: string, value: number | string | null | undefined, unit: string) =>
    lines.push(csvLine([target, quantity, subject, value ?? '', unit]));
  for (const t of r.t1.timings) add('T1', `median step ${t.scene} N=${t.n}`, t.engine, t.ms.median, 'ms');
  add('T1', 'rapier / maxgrid:maxgrid', 'ratio', r.t1.rapierOverMaxgrid, 'x');
  add('T1', 'box2d-wasm / maxgrid:maxgrid', 'ratio', r.t1.box2dOverMaxgrid, 'x');
  if (r.t2.comparison?.cMs) {
    add('T2', 'median step C', 'C', r.t2.comparison.cMs.median, 'ms');
    add('T2', 'median step maxgrid', 'maxgrid:maxgrid', r.t2.comparison.jsMs!.median, 'ms');
    add('T2', 'maxgrid / C', 'ratio', r.t2.comparison.ratio, 'x');
  } else add('T2', 'status', r.t2.status, r.t2.reason ?? r.t2.status, '');
  add('T3', `bytes per body N=${r.t3.n}`, 'maxgrid:maxgrid', r.t3.bytesPerBody, 'B');
  add('T3', `ns per body per step N=${r.t3.n}`, 'maxgrid:maxgrid', r.t3.nsPerBody, 'ns');
  add('T3', `ns per body per step N=${r.t3.smallN}, alongside`, 'maxgrid:maxgrid', r.t3.nsPerBodyAt64k, 'ns');
  add('T3', 'ns per body 1M / 64k', 'ratio', r.t3.ratio, 'x');
  if (r.t4.status === 'ok') {
    add('T4', `median step 1 thread N=${r.t4.n}`, 'maxgrid:maxgrid', r.t4.serialMs!.median, 'ms');
    add('T4', `median step ${r.t4.threads} threads N=${r.t4.n}`, 'maxgrid:maxgrid', r.t4.parallelMs!.median, 'ms');
    add('T4', 'speed-up', 'ratio', r.t4.speedup, 'x');
    for (const [when, scaling] of [['before', r.t4.hostScalingBefore], ['after', r.t4.hostScalingAfter]] as const) {
      if (!scaling) continue;
      add('T4', `host 2-thread scaling, compute, ${when}`, 'host', scaling.compute, 'x');
      add('T4', `host 2-thread scaling, memory, ${when}`, 'host', scaling.memory, 'x');
    }
  } else add('T4', 'status', 'skipped', r.t4.reason, '');
  for (const t of r.t5.timings) add('T5', `median step ${t.scene} N=${t.n}`, t.engine, t.ms.median, 'ms');
  for (const [id, q] of Object.entries(r.t5.mixedOverUniform)) add('T5', 'mixed / uniform per body', id, q, 'x');
  add('T5', 'rapier / maxgrid:auto on mixed', 'ratio', r.t5.rapierOverAuto, 'x');
  if (r.t6.status === 'ok') {
    add('T6', 'median step Node', 'Node', r.t6.node!.median, 'ms');
    add('T6', 'median step Chromium', r.t6.runtime!, r.t6.browser!.median, 'ms');
    add('T6', 'Chromium / Node', 'ratio', r.t6.ratio, 'x');
  } else add('T6', 'status', 'skipped', r.t6.reason, '');
  for (const x of r.notMeasured) add(x.target.split(' ')[0], 'status', 'not measured', x.reason, '');
  return lines.join('\n') + '\n';
}
