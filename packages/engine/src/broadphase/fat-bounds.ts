/**
 * Broad-phases compare rounded coordinates, the narrow-phase compares a rounded distance, and the
 * two must never disagree on a pair that just touches, or broad-phases would find different
 * contact sets and break bit-identical results. Every broad-phase therefore pads each circle by a
 * hair: a relative 2^-20 of its radius, plus 2^-40 of its coordinate for far-from-origin worlds.
 * Either is far above float64 round-off and far below anything visible as a false positive.
 */
export const RADIUS_PAD = 2 ** -20;
export const COORD_PAD = 2 ** -40;

export function paddedRadius(radius: number, centre: number): number {
  return radius * (1 + RADIUS_PAD) + Math.abs(centre) * COORD_PAD;
}
