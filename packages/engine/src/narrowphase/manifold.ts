/**
 * What a pair function finds: up to two contact points sharing one normal, which points from
 * shape A to shape B. Each point lies midway between the two surfaces, with the signed distance
 * between them (`separation`, negative when they overlap) and a feature id naming the pair of
 * features (edges, vertices) that made it, so that a point can inherit last step's impulse when
 * the same features touch again (warm starting). A manifold exists when its shapes are closer than
 * the caller's margin: speculative points up to that distance apart let the solver stop bodies
 * before they meet (a polygon face keeps its second point even beyond the margin, see
 * polygon-polygon.ts).
 *
 * Pair functions write the normal and each point (at pointCount, then counted) into the fields
 * themselves rather than through setters: a pair function is too large for V8 to inline every
 * call it makes, and each number passed to a call it does not inline is boxed, an allocation per
 * pair and step.
 */
export class Manifold {
  /**
   * What the caller asks of the pair function, set before the call rather than passed: points
   * closer than `margin`, and the solver's linear `slop`. A double passed to a call V8 does not
   * inline is boxed; the pair functions are called through the dispatch table, and a caller that
   * computed these numbers in its own frame boxed both at every pair (48 KB a step for 1,000
   * polygons where V8 inlined the narrow-phase's loop into its caller).
   */
  margin = 0;
  slop = 0;
  pointCount = 0;
  normalX = 0;
  normalY = 0;
  readonly x = new Float64Array(2);
  readonly y = new Float64Array(2);
  readonly separation = new Float64Array(2);
  readonly id = new Int32Array(2);

  clear(): void {
    this.pointCount = 0;
  }

  /** Turns a manifold of (B, A) into one of (A, B): the normal reverses, points and ids stay. */
  flip(): void {
    this.normalX = -this.normalX;
    this.normalY = -this.normalY;
  }
}
