import type { EngineInfo } from '../engines/adapter.js';
import type { EnergyResult } from '../experiments/energy.js';
import type { FalsePositiveResult, FalsePositiveSweep } from '../experiments/false-positives.js';
import type { ScaleResult } from '../experiments/scale.js';
import { stepTimeRatio, type StepTimeResult } from '../experiments/step-time.js';
import { BOX2D_WASM_CORE } from '../engines/versions.js';

export interface Table {
  title: string;
  headers: string[];
  rows: string[][];
  note?: string;
}

/** Three significant digits, without exponent noise for ordinary magnitudes. */
export function fmt(x: number | null | undefined, digits = 3): string {
  if (x === null || x === undefined || !Number.isFinite(x)) return '–';
  if (x === 0) return '0';
  const a = Math.abs(x);
  if (a >= 1000) return Math.round(x).toLocaleString('en-US');
  return Number(x.toPrecision(digits)).toString();
}

export function ratioText(x: number): string {
  return Number.isFinite(x) ? `${fmt(x)}×` : '–';
}

export const BASELINE = 'maxgrid:maxgrid';

/**
 * How tables, headlines and charts name an engine: by its id, but box2d-wasm by the Box2D it
 * compiles, 2.4.1, where the shape experiments speak of Box2D v3's benchmarks. Data files keep ids.
 */
export function engineLabel(id: string): string {
  return id === 'box2d-wasm' ? `Box2D ${BOX2D_WASM_CORE} (WASM)` : id;
}

export function engineTable(engines: EngineInfo[]): Table {
  return {
    title: 'Engines and settings',
    headers: ['engine', 'package@version', 'precision', 'length scale', 'settings'],
    rows: engines.map((e) => [
      e.id,
      `${e.package}@${e.version}`,
      e.precision,
      e.lengthScale === 0 ? "1 m = the scene's lengthUnit" : e.lengthScale === 1 ? 'scene px' : `1 px = ${e.lengthScale} m`,
      Object.entries(e.settings)
        .map(([k, v]) => `${k}=${String(v)}`)
        .join('; '),
    ]),
  };
}

/**
 * A table note's sentence on the warm-up (experiments/common.ts warmUp): `when`, each engine
 * warmed up for `warmUpMs`; empty for results from before it, whose options lack it.
 */
export function warmUpNote(when: string, warmUpMs: unknown): string {
  if (typeof warmUpMs !== 'number') return '';
  return ` ${when}, each engine warmed up for ${fmt(warmUpMs / 1000)} s on throwaway twins of the case (the same steps from its start), so that small scenes are timed at their steady speed, not while V8 still compiles them.`;
}

/** How step-time timed each engine, from its options. */
function stepTimeProtocol(result: StepTimeResult): string {
  const o = result.meta.options;
  return `Per run, each engine's own world of the run's seeded scene: ${String(o.warmupSteps)} untimed steps, then the mean of ${String(result.rows[0]?.stepsPerRun ?? '')} timed ones; engines in turn, the order rotated per run.${warmUpNote('Before its first run of a scene', o.warmUpMs)}`;
}

export function stepTimeTables(result: StepTimeResult): Table[] {
  const tables: Table[] = [];
  const scenes = [...new Set(result.rows.map((r) => r.scene))];
  for (const scene of scenes) {
    const rows = result.rows.filter((r) => r.scene === scene);
    const engines = [...new Set(rows.map((r) => r.engine))];
    const ns = [...new Set(rows.map((r) => r.n))].sort((a, b) => a - b);
    const hasBaseline = engines.includes(BASELINE);
    tables.push({
      title: `Step time, scene ${scene}: median ms per step [p25–p75] over runs`,
      headers: ['N', ...engines],
      rows: ns.map((n) => [
        String(n),
        ...engines.map((e) => {
          const r = rows.find((x) => x.n === n && x.engine === e);
          return r ? `${fmt(r.ms.median)} [${fmt(r.ms.p25)}–${fmt(r.ms.p75)}]` : 'skipped';
        }),
      ]),
      note: stepTimeProtocol(result),
    });
    if (hasBaseline) {
      tables.push({
        title: `Step time ratio to ${BASELINE}, scene ${scene} (engine median / ${BASELINE} median at the same N)`,
        headers: ['N', ...engines.filter((e) => e !== BASELINE)],
        rows: ns.map((n) => [String(n), ...engines.filter((e) => e !== BASELINE).map((e) => ratioText(stepTimeRatio(result, scene, n, e, BASELINE)))]),
      });
    }
  }
  return tables;
}

export function energyTables(result: EnergyResult): Table[] {
  return [
    {
      title: `Energy: bouncing ball for ${String(result.meta.options.ballSeconds)} s (E/E0), and uniform N=${String(result.meta.options.n)} for ${String(result.meta.options.seconds)} s (KE/KE0)`,
      headers: ['engine', 'ball E(end)/E0', 'ball min', 'ball max', 'uniform KE(end)/KE0', 'uniform min', 'uniform max'],
      rows: result.ball.map((b, i) => {
        const u = result.uniform[i];
        return [b.engine, fmt(b.final, 4), fmt(b.min, 4), fmt(b.max, 4), fmt(u.final, 4), fmt(u.min, 4), fmt(u.max, 4)];
      }),
    },
  ];
}

export function falsePositiveTables(result: FalsePositiveResult): Table[] {
  const engines = [...new Set(result.rows.map((r) => r.engine))];
  const cell = (r: FalsePositiveResult['rows'][number] | undefined) =>
    r ? `${fmt(r.testsPerContact)} (${fmt(r.pairTests)} / ${fmt(r.candidatePairs)} / ${fmt(r.contacts)})` : 'skipped';
  const sweep = (kind: FalsePositiveSweep, title: string, key: 'n' | 'ratio', label: (v: number) => string): Table => {
    const rows = result.rows.filter((r) => r.sweep === kind);
    const keys = [...new Set(rows.map((r) => r[key]))].sort((a, b) => a - b);
    return {
      title,
      headers: [key === 'n' ? 'N' : 'radius ratio', ...engines],
      rows: keys.map((v) => [label(v), ...engines.map((e) => cell(rows.find((r) => r[key] === v && r.engine === e)))]),
      note: 'Each cell: pairs examined per contact (pairs examined / pairs passed to the narrow-phase / contacts, means per step). Pairs examined is `world.stats.pairTests`, the broad-phase\'s own work.',
    };
  };
  const spreadN = String(result.meta.options.spreadN);
  const minR = String(result.meta.options.minRadius);
  return [
    sweep('n', 'False positives vs N (uniform, radii 4–8): pairs examined per contact', 'n', String),
    sweep('mixed', `False positives vs radius spread, scene mixed (N = ${spreadN}; small radii ${minR}–2·${minR}, 0.1% of circles ${minR}·ratio)`, 'ratio', (q) => `1:${q}`),
    sweep('log', `False positives vs radius spread, scene uniform with log-uniform radii ${minR} to ${minR}·ratio (N = ${spreadN})`, 'ratio', (q) => `1:${q}`),
  ];
}

export function scaleTables(result: ScaleResult): Table[] {
  return [
    {
      title: 'Scale (uniform scene): median step, ns per body per step, engine bytes per body; circles created row by row (as they lie) or in a random order, timed fresh and after simulated seconds of motion',
      headers: ['N', 'engine', 'creation order', 'timed after', 'median ms [p25–p75]', 'ns / body / step', 'bytes / body'],
      rows: result.rows.map((r) => [
        r.n.toLocaleString('en-US'),
        r.engine,
        r.order === 'rows' ? 'row by row' : 'shuffled',
        r.ageSeconds > 0 ? `${r.ageSeconds} s` : 'fresh',
        `${fmt(r.ms.median)} [${fmt(r.ms.p25)}–${fmt(r.ms.p75)}]`,
        fmt(r.nsPerBody),
        fmt(r.bytesPerBody),
      ]),
    },
  ];
}

export function markdownTable(t: Table): string {
  const esc = (s: string) => s.replace(/\|/g, '\\|');
  const lines = [`**${t.title}**`, '', `| ${t.headers.map(esc).join(' | ')} |`, `|${t.headers.map(() => ' --- ').join('|')}|`];
  for (const row of t.rows) lines.push(`| ${row.map(esc).join(' | ')} |`);
  if (t.note) lines.push('', t.note);
  return lines.join('\n');
}

export function escapeHtml(s: string): string {
  return s.replace(/[&<>"']/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', "'": '&#39;' })[c]!);
}

export function htmlTable(t: Table): string {
  const head = t.headers.map((h) => `<th>${escapeHtml(h)}</th>`).join('');
  const body = t.rows.map((r) => `<tr>${r.map((c) => `<td>${escapeHtml(c)}</td>`).join('')}</tr>`).join('\n');
  return `<h3>${escapeHtml(t.title)}</h3>\n<table><thead><tr>${head}</tr></thead>\n<tbody>${body}</tbody></table>`;
}
