import type { WorldShape } from './world-shape.js';
import type { Manifold } from './manifold.js';
import { collidePolygons } from './polygon-polygon.js';

/**
 * A polygon (A) and a capsule (B): a capsule is a rounded two-point polygon, whose edges are the
 * two sides of its segment, so the polygon test applies as it is (Box2D v3 does the same with
 * b2MakeCapsule). Its end caps are covered by the rounding radius and the vertex-vertex case.
 */
export function collidePolygonCapsule(a: WorldShape, b: WorldShape, m: Manifold): void {
  collidePolygons(a, b, m);
}
