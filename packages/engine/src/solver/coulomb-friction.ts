/**
 * Coulomb friction at one contact point, in one pass: the tangent impulse that stops the point's
 * sliding `slip` (its tangential speed) through `inverseMass`, the point's inverse effective mass
 * along the tangent, held within [-limit, limit], where limit is the friction coefficient times the
 * point's normal impulse. The elastic pass's bounce and the continuous sweep's bounce take it
 * after their normal impulses, point by point.
 */
export function coulombImpulse(slip: number, inverseMass: number, limit: number): number {
  const impulse = inverseMass > 0 ? -slip / inverseMass : 0;
  return impulse < -limit ? -limit : impulse > limit ? limit : impulse;
}
