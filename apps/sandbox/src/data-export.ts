import { COLUMNS, type Recorder } from './monitor/recorder.js';
import type { Settings } from './settings.js';

/** One row per recorded step, with a header line: what the report downloaded (5.13). */
export function toCsv(recorder: Recorder): string {
  const rows: string[] = [COLUMNS.join(',')];
  const n = recorder.length;
  for (let i = 0; i < n; i++) {
    let row = '';
    for (let c = 0; c < COLUMNS.length; c++) {
      if (c > 0) row += ',';
      row += String(recorder.series[COLUMNS[c]].at(i));
    }
    rows.push(row);
  }
  return rows.join('\n') + '\n';
}

/** The same series as columns, with the settings and step size that produced them. */
export function toJson(recorder: Recorder, settings: Settings, dt: number, broadphase: string, integrator: string): string {
  const series: Record<string, number[]> = {};
  for (const c of COLUMNS) {
    const ring = recorder.series[c];
    const out = new Array<number>(ring.length);
    for (let i = 0; i < ring.length; i++) out[i] = ring.at(i);
    series[c] = out;
  }
  // Settings flattened as the URL has them (n, seed, gravity, ... at the top), one level deep.
  const { params, ...rest } = settings;
  return JSON.stringify({
    scene: settings.scene,
    settings: { ...rest, ...params },
    dt,
    broadphase,
    integrator,
    potentialZero: 'floor of the box (height above it, as the report measures h)',
    steps: recorder.length,
    columns: COLUMNS,
    series,
  });
}

export function download(filename: string, mime: string, data: BlobPart): void {
  const url = URL.createObjectURL(new Blob([data], { type: mime }));
  const a = document.createElement('a');
  a.href = url;
  a.download = filename;
  document.body.append(a);
  a.click();
  a.remove();
  // Revoke later: the download reads the blob asynchronously.
  setTimeout(() => URL.revokeObjectURL(url), 10_000);
}
