import { BodyTypeCode, type BodyViews, type BroadPhaseName } from '@maxgrid/engine';

/**
 * Pairs a broad-phase may examine per step before the page refuses it: about 60 ms of stepping
 * at the 11-13 ns a pair the sweeps and naive cost on a 2-core machine (the whole step, the
 * narrow-phase included), so a refused broad-phase would have cost the page most of its frames.
 */
export const PAIR_BUDGET = 5_000_000;

/**
 * What each broad-phase whose work can grow quadratically would examine per step in this world:
 * naive every pair of moving bodies; the sweeps the pairs of moving bodies whose intervals
 * overlap on x (`sap-xy` sweeps the axis with fewer). Static bodies meet moving ones through the
 * engine's static tree and count for none. The grids are linear by construction and not listed.
 */
export function pairEstimates(views: BodyViews): Partial<Record<BroadPhaseName, number>> {
  const { x, y, radius, type, slotCount } = views;
  let moving = 0;
  for (let i = 0; i < slotCount; i++) if (type[i] !== BodyTypeCode.free && type[i] !== BodyTypeCode.static) moving++;
  const overlapsOn = (centre: Float64Array): number => {
    const low = new Float64Array(moving);
    let k = 0;
    for (let i = 0; i < slotCount; i++) if (type[i] !== BodyTypeCode.free && type[i] !== BodyTypeCode.static) low[k++] = centre[i] - radius[i];
    low.sort();
    // Body i meets every body whose interval starts after its own start and within its end.
    let pairs = 0;
    for (let i = 0; i < slotCount; i++) {
      if (type[i] === BodyTypeCode.free || type[i] === BodyTypeCode.static) continue;
      pairs += upperBound(low, centre[i] + radius[i]) - upperBound(low, centre[i] - radius[i]);
    }
    return pairs;
  };
  const onX = overlapsOn(x);
  const onY = overlapsOn(y);
  return { naive: (moving * (moving - 1)) / 2, sap: onX, 'sap-persistent': onX, 'sap-xy': Math.min(onX, onY) };
}

/** Why each broad-phase over the budget is refused here, by name; those missing are offered. */
export function refusals(views: BodyViews): Partial<Record<BroadPhaseName, string>> {
  const out: Partial<Record<BroadPhaseName, string>> = {};
  for (const [name, pairs] of Object.entries(pairEstimates(views)) as [BroadPhaseName, number][]) {
    if (pairs <= PAIR_BUDGET) continue;
    const what = name === 'naive' ? 'every pair of moving bodies' : name === 'sap-xy' ? 'the pairs overlapping on its better axis' : 'the pairs overlapping on x';
    out[name] = `${name} would examine ${millions(pairs)} pairs a step here (${what}), over the page's budget of ${millions(PAIR_BUDGET)}`;
  }
  return out;
}

function millions(n: number): string {
  return n >= 1e6 ? `${(n / 1e6).toFixed(1)} million` : Math.round(n).toLocaleString('en-US');
}

/** Index of the first sorted value above `value`. */
function upperBound(sorted: Float64Array, value: number): number {
  let lo = 0;
  let hi = sorted.length;
  while (lo < hi) {
    const mid = (lo + hi) >>> 1;
    if (sorted[mid] <= value) lo = mid + 1;
    else hi = mid;
  }
  return lo;
}
