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
  closest: { x: number; y: number },
): void {
  const ex = bx - ax;
  const ey = by - ay;
  const lengthSq = ex * ex + ey * ey;
  let t = lengthSq > 0 ? ((px - ax) * ex + (py - ay) * ey) / lengthSq : 0;
  if (t < 0) t = 0;
  else if (t > 1) t = 1;
  closest.x = ax + t * ex;
  closest.y = ay + t * ey;
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
  normal: { x: number; y: number },
): void {
  if (dist > 0) {
    normal.x = dx / dist;
    normal.y = dy / dist;
    return;
  }
  const ex = bx - ax;
  const ey = by - ay;
  const length = Math.sqrt(ex * ex + ey * ey);
  normal.x = length > 0 ? -ey / length : 1;
  normal.y = length > 0 ? ex / length : 0;
}
