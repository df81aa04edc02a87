import type { EChartsCoreOption } from 'echarts';

/** One chart: an ECharts option plus the file stem and title it is published under. */
export interface ChartSpec {
  id: string;
  title: string;
  option: EChartsCoreOption;
  width?: number;
  height?: number;
}

export interface Series {
  name: string;
  points: [number, number][];
}

export interface LineChartInput {
  id: string;
  title: string;
  xName: string;
  yName: string;
  series: Series[];
  xLog?: boolean;
  yLog?: boolean;
  /** Shaded band per series (e.g. p25..p75), drawn as thin dashed lines. */
  bands?: { name: string; low: [number, number][]; high: [number, number][] }[];
}

// Distinct colours for up to 16 engines (maxgrid per broad-phase plus five peers), so no two
// series in one chart share a colour.
const PALETTE = [
  '#e6194b', '#f58231', '#bfa300', '#9a6324', '#3cb44b', '#008080', '#4363d8', '#911eb4',
  '#f032e6', '#42d4f4', '#800000', '#000075', '#808000', '#a9a9a9', '#469990', '#dcbeff',
];

export function lineChart(input: LineChartInput): ChartSpec {
  const series: object[] = input.series.map((s, i) => ({
    name: s.name,
    type: 'line',
    data: s.points,
    showSymbol: s.points.length <= 40,
    symbolSize: 5,
    lineStyle: { width: 2 },
    color: PALETTE[i % PALETTE.length],
  }));
  for (const band of input.bands ?? []) {
    const i = input.series.findIndex((s) => s.name === band.name);
    for (const data of [band.low, band.high]) {
      series.push({
        name: band.name,
        type: 'line',
        data,
        showSymbol: false,
        lineStyle: { width: 1, type: 'dashed', opacity: 0.6 },
        color: PALETTE[i % PALETTE.length],
        silent: true,
      });
    }
  }
  return {
    id: input.id,
    title: input.title,
    option: {
      backgroundColor: '#ffffff',
      animation: false,
      title: { text: input.title, left: 'center', textStyle: { fontSize: 15 } },
      legend: { top: 34, data: input.series.map((s) => s.name) },
      grid: { left: 80, right: 30, top: 90, bottom: 60 },
      xAxis: { type: input.xLog ? 'log' : 'value', name: input.xName, nameLocation: 'middle', nameGap: 32, scale: !input.xLog },
      yAxis: { type: input.yLog ? 'log' : 'value', name: input.yName, nameLocation: 'middle', nameGap: 60, scale: !input.yLog },
      series,
    },
  };
}

export interface BarChartInput {
  id: string;
  title: string;
  categories: string[];
  yName: string;
  series: { name: string; values: number[] }[];
  yLog?: boolean;
}

export function barChart(input: BarChartInput): ChartSpec {
  return {
    id: input.id,
    title: input.title,
    option: {
      backgroundColor: '#ffffff',
      animation: false,
      title: { text: input.title, left: 'center', textStyle: { fontSize: 15 } },
      legend: { top: 34 },
      grid: { left: 80, right: 30, top: 90, bottom: 60 },
      xAxis: { type: 'category', data: input.categories },
      yAxis: { type: input.yLog ? 'log' : 'value', name: input.yName, nameLocation: 'middle', nameGap: 60 },
      series: input.series.map((s, i) => ({ name: s.name, type: 'bar', data: s.values, color: PALETTE[i % PALETTE.length] })),
    },
  };
}
