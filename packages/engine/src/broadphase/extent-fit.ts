/** A box around body centres; grids are laid over one. */
export interface Extent {
  minX: number;
  minY: number;
  maxX: number;
  maxY: number;
}

const HISTOGRAM_BINS = 256;
/** The share of bodies either end of an axis may leave out of a fitted extent: 1/OUTLIER_SHARE. */
const OUTLIER_SHARE = 256;

/**
 * Fits a grid's extent to where its bodies are. A grid holds a bounded number of cells (4n + 64)
 * over its extent and grows its cells until they fit, so an extent much wider than the crowd (a few
 * bodies far away, a crowd in a corner of a huge box) makes every cell hold everyone and the scan
 * quadratic. Grids bin a body outside their extent into the nearest edge cell (see cellIndex in
 * cell-grid.ts), where touching bodies still meet: clamping never moves two bodies further apart in
 * cells along either axis. So the extent only decides speed, and may leave bodies out.
 *
 * Bodies are slots[from, from + count), or from..from + count - 1 themselves when `slots` is null.
 */
export class ExtentFitter {
  private readonly histogramX = new Int32Array(HISTOGRAM_BINS);
  /** keptRange's results, x then y: a returned pair would be an array allocated per call. */
  private readonly kept = new Int32Array(4);
  private readonly histogramY = new Int32Array(HISTOGRAM_BINS);

  /** The box around the bodies' centres, into `out`. */
  measure(x: Float64Array, y: Float64Array, slots: Int32Array | null, from: number, count: number, out: Extent): void {
    let minX = Infinity;
    let minY = Infinity;
    let maxX = -Infinity;
    let maxY = -Infinity;
    for (let k = from; k < from + count; k++) {
      const i = slots === null ? k : slots[k];
      const px = x[i];
      const py = y[i];
      if (px < minX) minX = px;
      if (px > maxX) maxX = px;
      if (py < minY) minY = py;
      if (py > maxY) maxY = py;
    }
    out.minX = minX;
    out.minY = minY;
    out.maxX = maxX;
    out.maxY = maxY;
  }

  /**
   * Narrows `out`, which must hold every body, while a grid of `cellSize` over it would need more
   * than `budget` cells: to the range along each axis that holds all but 1/256 of the bodies at
   * either end, found by histograms. A few far bodies put the crowd in one column of the first
   * histogram, which the next round spreads out; three rounds narrow a million-to-one extent.
   */
  fit(x: Float64Array, y: Float64Array, slots: Int32Array | null, from: number, count: number, cellSize: number, budget: number, out: Extent): void {
    const outliers = Math.floor(count / OUTLIER_SHARE);
    for (let round = 0; round < 3; round++) {
      const { minX, minY, maxX, maxY } = out;
      if (count < 2 || cellsOver(minX, minY, maxX, maxY, cellSize) <= budget) return;
      this.histograms(x, y, slots, from, count, out);
      const kept = this.kept;
      keptRange(this.histogramX, outliers, kept, 0);
      keptRange(this.histogramY, outliers, kept, 2);
      const x0 = kept[0];
      const x1 = kept[1];
      const y0 = kept[2];
      const y1 = kept[3];
      const wx = (maxX - minX) / HISTOGRAM_BINS;
      const wy = (maxY - minY) / HISTOGRAM_BINS;
      const nextMinX = x0 === 0 ? minX : minX + x0 * wx;
      const nextMaxX = x1 === HISTOGRAM_BINS - 1 ? maxX : minX + (x1 + 1) * wx;
      const nextMinY = y0 === 0 ? minY : minY + y0 * wy;
      const nextMaxY = y1 === HISTOGRAM_BINS - 1 ? maxY : minY + (y1 + 1) * wy;
      if (nextMinX === minX && nextMaxX === maxX && nextMinY === minY && nextMaxY === maxY) return;
      out.minX = nextMinX;
      out.maxX = nextMaxX;
      out.minY = nextMinY;
      out.maxY = nextMaxY;
    }
  }

  /** The bodies counted into HISTOGRAM_BINS columns of `box` per axis (outside ones clamped to the ends). */
  private histograms(x: Float64Array, y: Float64Array, slots: Int32Array | null, from: number, count: number, box: Extent): void {
    const { histogramX, histogramY } = this;
    const { minX, minY, maxX, maxY } = box;
    histogramX.fill(0);
    histogramY.fill(0);
    const sx = maxX > minX ? HISTOGRAM_BINS / (maxX - minX) : 0;
    const sy = maxY > minY ? HISTOGRAM_BINS / (maxY - minY) : 0;
    for (let k = from; k < from + count; k++) {
      const i = slots === null ? k : slots[k];
      const bx = (x[i] - minX) * sx;
      const by = (y[i] - minY) * sy;
      histogramX[bx > 0 ? (bx < HISTOGRAM_BINS - 1 ? bx | 0 : HISTOGRAM_BINS - 1) : 0]++;
      histogramY[by > 0 ? (by < HISTOGRAM_BINS - 1 ? by | 0 : HISTOGRAM_BINS - 1) : 0]++;
    }
  }
}

/** Cells a grid of `cellSize` over the extent would have. */
export function cellsOver(minX: number, minY: number, maxX: number, maxY: number, cellSize: number): number {
  return (Math.floor((maxX - minX) / cellSize) + 1) * (Math.floor((maxY - minY) / cellSize) + 1);
}

/** The first and last histogram columns once `outliers` bodies are left out from each end, into out[at], out[at + 1]. */
function keptRange(histogram: Int32Array, outliers: number, out: Int32Array, at: number): void {
  let low = 0;
  for (let seen = 0; low < histogram.length - 1; low++) {
    seen += histogram[low];
    if (seen > outliers) break;
  }
  let high = histogram.length - 1;
  for (let seen = 0; high > low; high--) {
    seen += histogram[high];
    if (seen > outliers) break;
  }
  out[at] = low;
  out[at + 1] = high;
}
