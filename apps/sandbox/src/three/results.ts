import { VARIANTS, type VariantResult } from './experiment.js';

/**
 * The layered-drop result table: the three variants side by side (one column each), so the
 * report's comparison reads across a row. Every value cell carries data-variant, data-metric and
 * data-value (the unrounded number), so tests and scripts read numbers, not formatted text.
 */

interface Row {
  metric: string;
  label: string;
  value: (r: VariantResult, control: VariantResult | undefined) => number;
  digits: number;
}

const ROWS: readonly Row[] = [
  { metric: 'average-ms', label: 'Average physics step time (ms)', value: (r) => r.averageMs, digits: 3 },
  { metric: 'median-ms', label: 'Median physics step time (ms)', value: (r) => r.medianMs, digits: 3 },
  {
    metric: 'average-vs-control',
    label: 'Average relative to the control experiment',
    value: (r, c) => (c ? r.averageMs / c.averageMs : NaN),
    digits: 2,
  },
  { metric: 'steps', label: 'Steps (fixed dt 1/60 s)', value: (r) => r.steps, digits: 0 },
  { metric: 'cubes', label: 'Cubes', value: (r) => r.cubes, digits: 0 },
  { metric: 'static-at-end', label: 'Static objects at the end', value: (r) => r.staticAtEnd, digits: 0 },
  { metric: 'sleeping-at-end', label: 'Sleeping objects at the end', value: (r) => r.sleepingAtEnd, digits: 0 },
  {
    metric: 'bookkeeping-ms',
    label: 'Landed check, outside world.step (ms per step)',
    value: (r) => r.bookkeepingMs,
    digits: 3,
  },
];

export function renderResults(table: HTMLTableElement, results: readonly VariantResult[]): void {
  const control = results.find((r) => r.variant === 'control');
  const head = document.createElement('thead');
  const headRow = head.insertRow();
  headRow.appendChild(cell('th', 'Measure'));
  for (const r of results) {
    const th = cell('th', VARIANTS.find((v) => v.id === r.variant)?.label ?? r.variant);
    th.scope = 'col';
    th.dataset['variant'] = r.variant;
    headRow.appendChild(th);
  }
  const body = document.createElement('tbody');
  for (const row of ROWS) {
    const tr = body.insertRow();
    const th = cell('th', row.label);
    th.scope = 'row';
    tr.appendChild(th);
    for (const r of results) {
      const value = row.value(r, control);
      const td = cell('td', Number.isFinite(value) ? value.toFixed(row.digits) : '–');
      td.dataset['variant'] = r.variant;
      td.dataset['metric'] = row.metric;
      td.dataset['value'] = String(value);
      tr.appendChild(td);
    }
  }
  table.replaceChildren(head, body);
}

function cell(tag: 'th' | 'td', text: string): HTMLTableCellElement {
  const el = document.createElement(tag);
  el.textContent = text;
  return el;
}
