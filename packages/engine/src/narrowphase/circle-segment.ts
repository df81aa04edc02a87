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
