/**
 * A point written by the functions below, x then y: a typed array rather than an { x, y } object,
 * whose fields V8 can come to store as boxed numbers, one allocation per write (the segment
 * contacts and the continuous sweep allocated 130 KB a step each that way).
 */
export type PointOut = Float64Array;

/**
 * Closest point on segment (ax, ay)-(bx, by) to point (px, py), written to `closest`: its
 * parameter along the segment clamped to [0, 1]. A zero-length segment is its first point.
 */
export function closestOnSegment(
  px: number,
  py: number,
  ax: number,
  ay: number,
  bx: number,
  by: number,
  closest: PointOut,
): void {
  const ex = bx - ax;
  const ey = by - ay;
  const lengthSq = ex * ex + ey * ey;
  let t = lengthSq > 0 ? ((px - ax) * ex + (py - ay) * ey) / lengthSq : 0;
  if (t < 0) t = 0;
  else if (t > 1) t = 1;
  closest[0] = ax + t * ex;
  closest[1] = ay + t * ey;
}

/**
 * The unit normal, written to `normal`, pushing a circle whose centre lies at (dx, dy) from its
 * closest point on segment (ax, ay)-(bx, by), at distance `dist`: along (dx, dy), or for a centre
 * exactly on the segment along the segment's left normal (+x for a zero-length one).
 */
export function segmentNormal(
  dx: number,
  dy: number,
  dist: number,
  ax: number,
  ay: number,
  bx: number,
  by: number,
  normal: PointOut,
): void {
  if (dist > 0) {
    normal[0] = dx / dist;
    normal[1] = dy / dist;
    return;
  }
  const ex = bx - ax;
  const ey = by - ay;
  const length = Math.sqrt(ex * ex + ey * ey);
  normal[0] = length > 0 ? -ey / length : 1;
  normal[1] = length > 0 ? ex / length : 0;
}
