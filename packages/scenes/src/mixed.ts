import { Prng } from './prng.js';
import { resolveParams, type ParamSpecs } from './params.js';
import { allocateScene, type Scene } from './scene.js';

/** The parameters mixed takes, with their defaults and ranges (resolveParams checks them). */
export const mixedParams = {
  n: { default: 10_000, min: 0, max: 4_000_000, integer: true, description: 'number of circles' },
  seed: { default: 1, min: 0, max: 2 ** 32 - 1, integer: true, description: 'PRNG seed' },
  minRadius: { default: 4, min: 0.01, max: 1e4, description: 'small circles have radius in [minRadius, 2 minRadius]' },
  ratio: { default: 100, min: 1, max: 1e4, description: 'large radius over minRadius' },
  largeFraction: { default: 0.001, min: 0, max: 0.5, description: 'share of circles that are large' },
  fill: { default: 0.25, min: 0.001, max: 0.5, description: "circles' total area over the box area" },
  maxSpeed: { default: 100, min: 0, max: 1e6, description: 'speeds are uniform in [0, maxSpeed]' },
} satisfies ParamSpecs;

/** The most fine-lattice places listed for small circles (2^24: about 1.7 s to list, measured). */
const MAX_FINE_CELLS = 2 ** 24;

/**
 * The report's worst case for Max Grid (3.2): many small circles and a few much larger ones. Max
 * Grid sizes every cell by the largest circle, so the small ones crowd into few cells and the
 * neighbourhood search tends to O(n^2); this scene is what the hierarchical grid is measured on.
 * No gravity, restitution 1, square box sized so circles fill `fill` of it.
 *
 * Large circles sit on a coarse lattice; small ones take the cells of a fine lattice that are
 * clear of every large circle, in a seeded shuffled order, so nothing overlaps at the start.
 */
export function mixed(given?: Partial<Record<keyof typeof mixedParams, number>>): Scene {
  const p = resolveParams('mixed', mixedParams, given);
  const rng = new Prng(p.seed);
  const large = Math.round(p.n * p.largeFraction);
  const small = p.n - large;
  const bigR = p.minRadius * p.ratio;
  const radius = new Float64Array(p.n);
  let area = 0;
  for (let k = 0; k < p.n; k++) {
    radius[k] = k < large ? bigR : rng.range(p.minRadius, 2 * p.minRadius);
    area += Math.PI * radius[k] * radius[k];
  }
  const perRowLarge = Math.max(1, Math.ceil(Math.sqrt(large)));
  const side = Math.max(Math.sqrt(area / p.fill), perRowLarge * 2.2 * bigR, 4 * p.minRadius);
  const scene = allocateScene('mixed', p, p.n, {
    bounds: { width: side, height: side },
    gravity: { x: 0, y: 0 },
    restitution: 1,
  });
  scene.radius.set(radius);

  const coarse = side / perRowLarge;
  for (let k = 0; k < large; k++) {
    scene.x[k] = ((k % perRowLarge) + 0.5) * coarse;
    scene.y[k] = (Math.floor(k / perRowLarge) + 0.5) * coarse;
  }

  const fine = 4 * p.minRadius;
  const perRow = Math.max(1, Math.floor(side / fine));
  // Every clear fine cell is listed and shuffled: past this many the list alone takes seconds and
  // gigabytes (200,000 circles at ratio 200 with 5 % large ones crashed Node building 169 million).
  if (perRow * perRow > MAX_FINE_CELLS) {
    throw new RangeError(
      `mixed: a box ${Math.round(side)} wide has ${perRow * perRow} places for small circles, more than ${MAX_FINE_CELLS} to list; lower n, ratio or largeFraction, or raise fill`,
    );
  }
  const free: number[] = [];
  const clearance = bigR + 2 * p.minRadius;
  for (let cell = 0; cell < perRow * perRow; cell++) {
    const cx = ((cell % perRow) + 0.5) * fine;
    const cy = (Math.floor(cell / perRow) + 0.5) * fine;
    // Only the large circles of the 3 x 3 coarse cells around can reach: the next ones lie at
    // least 1.5 coarse = 3.3 bigR away, beyond the clearance (at most 3 bigR). Testing all of them
    // for every fine cell took 20 s at ratio 200 with 5 % large circles (10,000 circles).
    const column = Math.floor(cx / coarse);
    const row = Math.floor(cy / coarse);
    let clear = true;
    for (let r = Math.max(row - 1, 0); r <= row + 1 && clear; r++) {
      for (let c = Math.max(column - 1, 0); c <= Math.min(column + 1, perRowLarge - 1) && clear; c++) {
        const k = r * perRowLarge + c;
        if (k >= large) continue;
        const dx = cx - scene.x[k];
        const dy = cy - scene.y[k];
        clear = dx * dx + dy * dy > clearance * clearance;
      }
    }
    if (clear) free.push(cell);
  }
  if (free.length < small) {
    throw new RangeError(`mixed: only ${free.length} free places for ${small} small circles; lower fill or ratio`);
  }
  for (let k = free.length - 1; k > 0; k--) {
    const j = Math.floor(rng.next() * (k + 1));
    const t = free[k];
    free[k] = free[j];
    free[j] = t;
  }
  for (let k = large; k < p.n; k++) {
    const cell = free[k - large];
    scene.x[k] = ((cell % perRow) + 0.5) * fine;
    scene.y[k] = (Math.floor(cell / perRow) + 0.5) * fine;
  }
  for (let k = 0; k < p.n; k++) {
    const speed = rng.range(0, p.maxSpeed);
    const [dx, dy] = rng.direction();
    scene.vx[k] = speed * dx;
    scene.vy[k] = speed * dy;
  }
  return scene;
}
