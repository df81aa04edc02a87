import type { CMaxgridResult } from '../experiments/c-maxgrid.js';
import type { SapSleepResult } from '../experiments/sap-sleep.js';
import type { TargetsResult, Timing } from '../experiments/targets.js';
import { fmt, ratioText, type Table } from './tables.js';

const spreadText = (s: { median: number; p25: number; p75: number }) => `${fmt(s.median)} [${fmt(s.p25)}–${fmt(s.p75)}]`;
const n = (x: number) => x.toLocaleString('en-US');
const ratioOrDash = (x: number | null | undefined) => (x === null || x === undefined ? '–' : ratioText(x));

export function cMaxgridTables(result: CMaxgridResult): Table[] {
  const c = result.compiler;
  return [
    {
      title: `maxgrid (TypeScript, Node) vs the same step in C, scene ${String(result.meta.options.scene)}: median ms per step [p25–p75]`,
      headers: ['N', 'C', 'maxgrid:maxgrid', 'maxgrid / C', 'state hash (C = JS)'],
      rows:
        c.status === 'skipped'
          ? [['–', `skipped: ${c.reason}`, '–', '–', '–']]
          : result.rows.map((r) =>
              r.status === 'ok'
                ? [n(r.n), spreadText(r.cMs!), spreadText(r.jsMs!), ratioText(r.ratio!), `${r.cHash} = ${r.jsHash}`]
                : [n(r.n), 'no timing: hashes differ', 'no timing', '–', `${r.cHash} ≠ ${r.jsHash}`],
            ),
      note: c.status === 'ok' ? `Compiled with \`${c.command}\` (${c.version}); ${String(result.meta.options.rounds)} rounds alternating C and JS${typeof result.meta.options.warmUpMs === 'number' ? `, maxgrid warmed up for ${fmt(result.meta.options.warmUpMs / 1000)} s on throwaway worlds of each N first` : ''}.` : undefined,
    },
  ];
}

export function sapSleepTables(result: SapSleepResult): Table[] {
  const cases = [...new Set(result.rows.map((r) => r.case))];
  const engines = [...new Set(result.rows.map((r) => r.engine))];
  const [a, b] = engines;
  return [
    {
      title: `sap vs sap-persistent (N = ${n(Number(result.meta.options.n))}): median ms per step [p25–p75], pairs examined per step`,
      headers: ['case', 'scene and settings', 'settle steps', 'asleep (start → end)', ...engines.map((e) => `${e} ms`), ...engines.map((e) => `${e} pairs examined`), b ? `${b} / ${a}` : 'ratio'],
      rows: cases.map((c) => {
        const rows = engines.map((e) => result.rows.find((r) => r.case === c && r.engine === e)!);
        const s = rows[0].settings;
        const pct = (x: number) => `${Math.round(x * 100)}%`;
        return [
          c,
          `${rows[0].scene}: ${Object.entries(s)
            .map(([k, v]) => `${k} ${typeof v === 'number' ? fmt(v) : String(v)}`)
            .join(', ')}`,
          String(rows[0].settleSteps),
          `${pct(rows[0].asleepStart)} → ${pct(rows[0].asleepEnd)}`,
          ...rows.map((r) => spreadText(r.ms)),
          ...rows.map((r) => fmt(r.pairTests)),
          rows[1] ? ratioText(rows[1].ms.median / rows[0].ms.median) : '–',
        ];
      }),
    },
  ];
}

function timingRows(timings: Timing[]): string[][] {
  return timings.map((t) => [t.engine, t.scene, n(t.n), spreadText(t.ms), String(t.steps), fmt(t.nsPerBody)]);
}

const TIMING_HEADERS = ['engine', 'scene', 'N', 'median ms [p25–p75]', 'timed steps', 'ns / body / step'];

export function targetsTables(r: TargetsResult): Table[] {
  const o = r.meta.options as Record<string, number>;
  const protocol = `${o.rounds} rounds × ${o.stepsPerRound} steps per engine after ${o.warmupSteps} warm-up steps, engines interleaved per round, dt 1/${Math.round(1 / o.dt)}`;
  const t2 = r.t2;
  const t6 = r.t6;
  const c = t2.comparison;
  return [
    {
      title: `T1 against peers: uniform N = ${n(o.n)} (target: maxgrid ≤ 1/25 of Rapier and of box2d-wasm)`,
      headers: TIMING_HEADERS,
      rows: [
        ...timingRows(r.t1.timings),
        ['rapier / maxgrid:maxgrid', '', '', ratioOrDash(r.t1.rapierOverMaxgrid), '', ''],
        ['box2d-wasm / maxgrid:maxgrid', '', '', ratioOrDash(r.t1.box2dOverMaxgrid), '', ''],
      ],
      note: `Few steps, because the peers take 100+ ms per step at this N: ${protocol}.`,
    },
    {
      title: `T2 against the hardware: maxgrid vs the same step in C at N = ${n(o.n)} (target: ≤ 1.3×)`,
      headers: ['C median ms [p25–p75]', 'maxgrid:maxgrid median ms [p25–p75]', 'maxgrid / C', 'state hashes'],
      rows: [
        t2.status === 'skipped'
          ? [`skipped: ${t2.reason ?? ''}`, '–', '–', '–']
          : t2.status === 'hash-mismatch'
            ? ['no timing: hashes differ', '–', '–', `${c!.cHash} ≠ ${c!.jsHash}`]
            : [spreadText(c!.cMs!), spreadText(c!.jsMs!), ratioOrDash(c!.ratio), `equal (${c!.cHash})`],
      ],
      note: t2.compile ? `C compiled with \`${t2.compile}\`; ${c?.rounds ?? 0} runs each of ${c?.stepsPerRound ?? 0} timed steps, alternating C and JS.` : undefined,
    },
    {
      title: `T3 a million: uniform N = ${n(r.t3.n)} (targets: ≤ 200 bytes per body; ns per body ≤ 1.5× the 64k cost)`,
      headers: ['median ms [p25–p75]', 'timed steps', 'engine bytes / body', 'ns / body / step', `${n(r.t3.smallN)}: median ms [p25–p75]`, 'ns / body', 'ratio 1M / 64k', 'build ms'],
      rows: [[spreadText(r.t3.ms), String(r.t3.steps), fmt(r.t3.bytesPerBody), fmt(r.t3.nsPerBody), spreadText(r.t3.smallMs), fmt(r.t3.nsPerBodyAt64k), ratioText(r.t3.ratio), fmt(r.t3.buildMs)]],
      note:
        `Engine bytes are \`world.memoryBytes()\`, the engine's own typed arrays and WebAssembly memories. Timed after ${o.bigWarmupSteps} untimed steps, once the scene's contacts have stopped climbing. ` +
        `After each step of the big world, ${n(Math.round(r.t3.smallSteps / r.t3.steps))} steps of a ${n(r.t3.smallN)}-body one (${r.t3.smallSteps} in all), so the two per-body costs are taken side by side.`,
    },
    t4Table(r),
    {
      title: `T5 mixed sizes: scene mixed, ratio 1:${o.mixedRatio}, N = ${n(o.n)} (targets: ≤ 2× the uniform per-body cost; ≥ 10× faster than Rapier)`,
      headers: TIMING_HEADERS,
      rows: [
        ...timingRows(r.t5.timings),
        ...Object.entries(r.t5.mixedOverUniform).map(([id, q]) => [`${id}: mixed / uniform per body`, '', '', ratioText(q), '', '']),
        ['rapier / maxgrid:auto on mixed', '', '', ratioOrDash(r.t5.rapierOverAuto), '', ''],
      ],
      note: `Uniform references are T1's timings of the same broad-phase. ${protocol}.`,
    },
    {
      title: `T6 browser parity: maxgrid:maxgrid, uniform N = ${n(o.n)}, Chromium vs Node (target: ≤ 1.3×)`,
      headers: ['runtime', 'Node median ms [p25–p75]', 'Chromium median ms [p25–p75]', 'Chromium / Node', 'same state hash'],
      rows: [
        t6.status === 'skipped'
          ? [`skipped: ${t6.reason ?? ''}`, '–', '–', '–', '–']
          : [t6.runtime!, spreadText(t6.node!), spreadText(t6.browser!), ratioText(t6.ratio!), t6.hashesMatch ? 'yes' : 'NO'],
      ],
      note: t6.settings
        ? `Chromium flags: \`${t6.settings.flags}\`; ${t6.settings.page}; ${o.parityRounds} rounds of ${o.stepsPerRound * 2} steps on each side after ${o.warmupSteps} warm-up steps, alternating which side goes first.`
        : undefined,
    },
    {
      title: 'T7: measured by another command',
      headers: ['target', 'status'],
      rows: r.notMeasured.map((x) => [x.target, x.reason]),
    },
  ];
}

/** One-paragraph summaries for docs/results.md, quoting medians and ratios from the run. */
export function cMaxgridHeadline(r: CMaxgridResult): string[] {
  if (r.compiler.status === 'skipped') return [`Skipped: ${r.compiler.reason}.`];
  return r.rows.map((x) =>
    x.status === 'ok'
      ? `N = ${n(x.n)}: C median ${fmt(x.cMs!.median)} ms, maxgrid:maxgrid ${fmt(x.jsMs!.median)} ms, maxgrid / C = ${ratioText(x.ratio!)} (state hashes equal).`
      : `N = ${n(x.n)}: no timing reported, the C state hash ${x.cHash} differs from the engine's ${x.jsHash}.`,
  );
}

export function sapSleepHeadline(r: SapSleepResult): string[] {
  const cases = [...new Set(r.rows.map((x) => x.case))];
  return cases.map((c) => {
    const [a, b] = r.rows.filter((x) => x.case === c);
    const pct = Math.round(a.asleepStart * 100);
    return `${c} (${a.scene}, ${pct}% asleep): ${a.engine} ${fmt(a.ms.median)} ms, ${b ? `${b.engine} ${fmt(b.ms.median)} ms, ratio ${ratioText(b.ms.median / a.ms.median)}` : ''}.`;
  });
}

export function targetsHeadline(r: TargetsResult): string[] {
  const o = r.meta.options as Record<string, number>;
  const c = r.t2.comparison;
  return [
    `T1 (uniform ${n(o.n)}): rapier / maxgrid = ${ratioOrDash(r.t1.rapierOverMaxgrid)}, box2d-wasm / maxgrid = ${ratioOrDash(r.t1.box2dOverMaxgrid)} (target ≥ 25×).`,
    `T2: ${r.t2.status === 'ok' ? `maxgrid / C = ${ratioOrDash(c?.ratio)} (target ≤ 1.3×)` : r.t2.status === 'skipped' ? `skipped: ${r.t2.reason ?? ''}` : 'no timing: the C and engine state hashes differ'}.`,
    `T3 (${n(r.t3.n)} bodies): ${fmt(r.t3.bytesPerBody)} bytes per body (target ≤ 200), ${fmt(r.t3.nsPerBody)} ns per body per step, ${ratioText(r.t3.ratio)} the 64k cost (target ≤ 1.5×).`,
    `T5 (mixed 1:${o.mixedRatio}, ${n(o.n)}): per-body cost mixed / uniform ${Object.entries(r.t5.mixedOverUniform)
      .map(([id, q]) => `${id} ${ratioText(q)}`)
      .join(', ')} (target ≤ 2×); rapier / maxgrid:auto = ${ratioOrDash(r.t5.rapierOverAuto)} (target ≥ 10×).`,
    `T6: ${r.t6.status === 'ok' ? `Chromium / Node = ${ratioText(r.t6.ratio!)} (target ≤ 1.3×; ${r.t6.runtime}; state hashes ${r.t6.hashesMatch ? 'equal' : 'DIFFER'})` : `skipped: ${r.t6.reason ?? ''}`}.`,
    t4Headline(r),
    'T7: measured by `npm run lab -- sandbox-render` (see its section).',
  ].flatMap((line) => [line, '']);
}

function t4Table(r: TargetsResult) {
  const t4 = r.t4;
  const o = r.meta.options as Record<string, number>;
  return {
    title: `T4 multi-core: uniform N = ${n(t4.n ?? 0)}, 1 thread vs ${t4.threads ?? '–'} threads (target: ≥ 1.6× on 2 cores, same bits; moonshot ≥ 60 steps/s)`,
    headers: [
      '1 thread median ms [p25–p75]',
      'parallel median ms [p25–p75]',
      'speed-up',
      'parallel steps / s',
      'same state hash',
      'host scaling, compute / memory: before → after',
    ],
    rows: [
      t4.status === 'skipped'
        ? [`skipped: ${t4.reason ?? ''}`, '–', '–', '–', '–', '–']
        : [
            spreadText(t4.serialMs!),
            spreadText(t4.parallelMs!),
            ratioText(t4.speedup!),
            fmt(t4.parallelStepsPerSecond!),
            t4.hashesMatch ? 'yes' : 'NO',
            hostScalingText(t4),
          ],
    ],
    note:
      t4.status === 'ok'
        ? `Two worlds from one seeded scene, ${t4.steps} timed steps each after ${o.bigWarmupSteps} untimed ones, alternating step by step; the parallel world uses \`world.startWorkers(${t4.threads})\` (worker_threads). docs/engine.md says what runs on each thread. Host scaling: twice the work on 2 threads against once on 1, by time (2 is perfect), for a compute-bound loop and for streaming 128 MiB per thread, probed just before and just after; on a shared machine the memory figure moves with other tenants.`
        : undefined,
  };
}

function hostScalingText(t4: TargetsResult['t4']): string {
  const { hostScalingBefore: before, hostScalingAfter: after } = t4;
  if (!before || !after) return 'not probed';
  return `${ratioText(before.compute)} / ${ratioText(before.memory)} → ${ratioText(after.compute)} / ${ratioText(after.memory)}`;
}

function t4Headline(r: TargetsResult): string {
  const t4 = r.t4;
  if (t4.status !== 'ok') return `T4: skipped: ${t4.reason ?? ''}.`;
  const host = t4.hostScalingBefore && t4.hostScalingAfter ? `; the host's own 2-thread memory scaling ${ratioText(t4.hostScalingBefore.memory)} before, ${ratioText(t4.hostScalingAfter.memory)} after` : '';
  return `T4 (${n(t4.n!)} bodies, ${t4.threads} threads): ${ratioText(t4.speedup!)} the 1-thread speed (target ≥ 1.6×), ${fmt(t4.parallelStepsPerSecond!)} steps/s (moonshot ≥ 60); state hashes ${t4.hashesMatch ? 'equal' : 'DIFFER'}${host}.`;
}
