/**
 * Shapes' bounding boxes that turn with their bodies (ShapeStore.box): four doubles a shape, in
 * its body's centre-of-mass frame, the box's centre and half sizes along the body's axes,
 * rounding included.
 *
 * The narrow-phase tests them before a pair function: the bounding circles that the broad-phase
 * and `consume` compare hold a square in 1.57 times its area, and a long thin shape (a wall of the
 * tumbler's drum, 20 x 1) in sixteen times, so many pairs whose circles overlap are ones whose
 * boxes do not. The test is the separating axis test on the boxes' four sides: a dozen
 * multiply-adds, where the pair function first transforms every vertex of both shapes.
 */
export const OrientedBox = { x: 0, y: 1, halfWidth: 2, halfHeight: 3 } as const;
/** Doubles per box. */
export const ORIENTED_BOX = 4;

const { x: BX, y: BY, halfWidth: BW, halfHeight: BH } = OrientedBox;

/**
 * Writes the box [loX, hiX] x [loY, hiY] (in a body's frame) into box[at..at+3]. The half sizes grow by a millionth of the box's size and distance from the
 * centre of mass, so that the box holds every shape despite the rounding of its centre: a pair
 * dropped by boxesApart must be one its pair function finds apart.
 */
export function setBox(box: Float64Array, at: number, loX: number, loY: number, hiX: number, hiY: number): void {
  const x = (loX + hiX) / 2;
  const y = (loY + hiY) / 2;
  const halfWidth = (hiX - loX) / 2;
  const halfHeight = (hiY - loY) / 2;
  const pad = 1e-6 * (Math.abs(x) + Math.abs(y) + halfWidth + halfHeight);
  box[at + BX] = x;
  box[at + BY] = y;
  box[at + BW] = halfWidth + pad;
  box[at + BH] = halfHeight + pad;
}

/**
 * Whether the box at boxI[oi..] on body i and the one at boxJ[oj..] on body j lie farther apart
 * than reach[0] (the pair functions' speculative distance), each turned with its body: (x, y)
 * the bodies' centres of mass, (c, s) their rotations. The four axes are the boxes' sides; two
 * boxes that overlap on all four touch. The allowance for the rounding of the world frame's
 * arithmetic grows with the distance from the origin (the boxes' own is in their size).
 */
export function boxesApart(x: Float64Array, y: Float64Array, c: Float64Array, s: Float64Array, i: number, boxI: Float64Array, oi: number, j: number, boxJ: Float64Array, oj: number, reach: Float64Array): boolean {
  const ci = c[i];
  const si = s[i];
  const cj = c[j];
  const sj = s[j];
  const ax = x[i] + ci * boxI[oi + BX] - si * boxI[oi + BY];
  const ay = y[i] + si * boxI[oi + BX] + ci * boxI[oi + BY];
  const bx = x[j] + cj * boxJ[oj + BX] - sj * boxJ[oj + BY];
  const by = y[j] + sj * boxJ[oj + BX] + cj * boxJ[oj + BY];
  const dx = bx - ax;
  const dy = by - ay;
  const wa = boxI[oi + BW];
  const ha = boxI[oi + BH];
  const wb = boxJ[oj + BW];
  const hb = boxJ[oj + BH];
  // The cosine and sine of the angle between the bodies, as lengths: how far each box's sides
  // reach along the other's axes.
  const rc = Math.abs(ci * cj + si * sj);
  const rs = Math.abs(ci * sj - si * cj);
  const r = reach[0] + 1e-12 * (Math.abs(ax) + Math.abs(ay) + Math.abs(bx) + Math.abs(by));
  return (
    Math.abs(ci * dx + si * dy) > wa + wb * rc + hb * rs + r ||
    Math.abs(ci * dy - si * dx) > ha + wb * rs + hb * rc + r ||
    Math.abs(cj * dx + sj * dy) > wb + wa * rc + ha * rs + r ||
    Math.abs(cj * dy - sj * dx) > hb + wa * rs + ha * rc + r
  );
}
