import * as echarts from 'echarts';
import type { ChartSpec } from './charts.js';

// Kept apart from the chart builders: ECharts takes seconds to import, and the CLI should reject
// a bad option without paying for it.

// Without a DOM, ECharts estimates text widths too narrow for the DejaVu Sans that resvg draws
// the PNGs with, and legend entries overlap. An average advance of 0.62 em matches that font.
let measured = false;
function useFontMetrics(): void {
  if (measured || typeof document !== 'undefined') return;
  measured = true;
  echarts.setPlatformAPI({
    measureText(text: string, font?: string) {
      const size = Number(/(\d+(?:\.\d+)?)px/.exec(font ?? '')?.[1] ?? 12);
      return { width: text.length * size * 0.62 };
    },
  });
}

/** Server-side (DOM-free) SVG rendering; the same call works in Node and in the browser. */
export function renderSvg(chart: ChartSpec): string {
  useFontMetrics();
  const instance = echarts.init(null, null, {
    renderer: 'svg',
    ssr: true,
    width: chart.width ?? 900,
    height: chart.height ?? 500,
  });
  try {
    instance.setOption(chart.option);
    return instance.renderToSVGString();
  } finally {
    instance.dispose();
  }
}
