import { mkdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { Resvg } from '@resvg/resvg-js';
import type { ChartSpec } from '../report/charts.js';
import { renderSvg } from '../report/render.js';

export function svgToPng(svg: string, width = 1350): Buffer {
  const resvg = new Resvg(svg, {
    fitTo: { mode: 'width', value: width },
    background: '#ffffff',
    font: { loadSystemFonts: true, defaultFontFamily: 'DejaVu Sans', sansSerifFamily: 'DejaVu Sans' },
  });
  return resvg.render().asPng();
}

/** Writes `<id>.svg` and `<id>.png` for each chart into `dir`; returns the SVG strings. */
export function writeCharts(dir: string, charts: ChartSpec[]): { id: string; svg: string }[] {
  mkdirSync(dir, { recursive: true });
  return charts.map((chart) => {
    const svg = renderSvg(chart);
    writeFileSync(join(dir, `${chart.id}.svg`), svg);
    writeFileSync(join(dir, `${chart.id}.png`), svgToPng(svg));
    return { id: chart.id, svg };
  });
}

export function writeText(dir: string, name: string, text: string): string {
  mkdirSync(dir, { recursive: true });
  const path = join(dir, name);
  writeFileSync(path, text);
  return path;
}
