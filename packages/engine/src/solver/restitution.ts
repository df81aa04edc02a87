/**
 * A pair's restitution is the larger of the two, as in Box2D (`b2MixRestitution`): two equal
 * values e give e, and a bouncy ball stays bouncy against anything. The box walls take part as a
 * body whose restitution is the world's `restitution` option.
 */
export function mixRestitution(a: number, b: number): number {
  return a > b ? a : b;
}
