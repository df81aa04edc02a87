import type { EngineInfo } from '../engines/adapter.js';
import type { Environment } from '../experiments/common.js';
import { engineTable, escapeHtml, htmlTable, type Table } from './tables.js';
import { EXPERIMENTS } from '../experiments/registry.js';

/** The tables an experiment's result is reported with, in the markdown and the HTML alike. */
export function tablesFor(experiment: string, result: unknown): Table[] {
  const entry = EXPERIMENTS[experiment];
  if (!entry) throw new RangeError(`no tables for experiment '${experiment}'`);
  return entry.tables(result);
}

export interface ReportSection {
  experiment: string;
  tables: Table[];
  /** Inline SVG strings from `renderSvg`. */
  svgs: string[];
}

export interface ReportInput {
  title: string;
  command: string;
  environment: Environment;
  engines: EngineInfo[];
  sections: ReportSection[];
  /** Every result, embedded so the page carries its own data. */
  results: Record<string, unknown>;
}

/** One HTML file with no external references: styles, SVG charts and the JSON data inline. */
export function htmlReport(input: ReportInput): string {
  const env = Object.entries(input.environment)
    .map(([k, v]) => `<li><b>${escapeHtml(k)}</b>: ${escapeHtml(String(v))}</li>`)
    .join('');
  const sections = input.sections
    .map(
      (s) => `<section><h2>${escapeHtml(s.experiment)}</h2>
${s.svgs.map((svg) => `<figure>${svg}</figure>`).join('\n')}
${s.tables.map(htmlTable).join('\n')}
</section>`,
    )
    .join('\n');
  // JSON inside a script element must not contain "</script"; escaping "<" keeps it inert.
  const data = JSON.stringify(input.results).replace(/</g, '\\u003c');
  return `<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>${escapeHtml(input.title)}</title>
<style>
body { font: 14px/1.45 system-ui, sans-serif; margin: 2rem auto; max-width: 1200px; color: #222; }
table { border-collapse: collapse; margin: 0.5rem 0 1.5rem; font-size: 13px; }
th, td { border: 1px solid #ccc; padding: 3px 8px; text-align: right; vertical-align: top; }
th:first-child, td:first-child { text-align: left; }
figure { margin: 1rem 0; }
code { background: #f3f3f3; padding: 1px 4px; }
</style></head>
<body>
<h1>${escapeHtml(input.title)}</h1>
<p>Regenerate with <code>${escapeHtml(input.command)}</code></p>
<ul>${env}</ul>
${htmlTable(engineTable(input.engines))}
${sections}
<script type="application/json" id="lab-data">${data}</script>
</body></html>
`;
}
