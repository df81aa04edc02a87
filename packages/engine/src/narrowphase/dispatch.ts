import { ShapeKind } from '../shapes/geometry.js';
import type { WorldShape } from './world-shape.js';
import type { Manifold } from './manifold.js';
import { collideCircles } from './circle-circle.js';
import { collideCapsuleCircle } from './capsule-circle.js';
import { collideCapsules } from './capsule-capsule.js';
import { collidePolygonCircle } from './polygon-circle.js';
import { collidePolygonCapsule } from './polygon-capsule.js';
import { collidePolygons } from './polygon-polygon.js';

/** A pair function: fills `m` for shapes a and b, keeping points closer than `m.margin`. */
export type Collide = (a: WorldShape, b: WorldShape, m: Manifold) => void;

/**
 * The pair functions by [kind of A][kind of B]. Each pair is written once, for one order; the
 * other order runs it with the shapes swapped and the manifold flipped (`SWAPPED`). A new shape
 * pair is one file and one line here.
 */
const PAIRS: Collide[][] = [];
const SWAPPED: boolean[][] = [];
const KINDS = 3;
for (let k = 0; k < KINDS; k++) {
  PAIRS.push(new Array<Collide>(KINDS));
  SWAPPED.push(new Array<boolean>(KINDS).fill(false));
}
function pair(a: number, b: number, collide: Collide): void {
  PAIRS[a][b] = collide;
  PAIRS[b][a] = collide;
  SWAPPED[b][a] = a !== b;
}
pair(ShapeKind.circle, ShapeKind.circle, collideCircles);
pair(ShapeKind.capsule, ShapeKind.circle, collideCapsuleCircle);
pair(ShapeKind.capsule, ShapeKind.capsule, collideCapsules);
pair(ShapeKind.polygon, ShapeKind.circle, collidePolygonCircle);
pair(ShapeKind.polygon, ShapeKind.capsule, collidePolygonCapsule);
pair(ShapeKind.polygon, ShapeKind.polygon, collidePolygons);

/** The manifold of a and b, normal from a to b, for the margin and slop set in `m`. */
export function collide(a: WorldShape, b: WorldShape, m: Manifold): void {
  if (SWAPPED[a.kind][b.kind]) {
    PAIRS[a.kind][b.kind](b, a, m);
    m.flip();
  } else {
    PAIRS[a.kind][b.kind](a, b, m);
  }
}
