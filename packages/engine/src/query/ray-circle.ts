/**
 * Where the segment p(t) = (x1, y1) + t (dx, dy), t in [0, 1], first enters a circle, or -1.
 * A segment that starts inside the circle does not hit it, as in Box2D's b2RayCastCircle: a ray
 * cast from inside a body should find what lies beyond it.
 */
export function rayCircle(x1: number, y1: number, dx: number, dy: number, cx: number, cy: number, r: number): number {
  const fx = x1 - cx;
  const fy = y1 - cy;
  const c = fx * fx + fy * fy - r * r;
  if (c <= 0) return -1;
  const a = dx * dx + dy * dy;
  if (a === 0) return -1;
  const b = fx * dx + fy * dy;
  if (b >= 0) return -1;
  // b^2 - a c, written as a r^2 - (f x d)^2 (Lagrange's identity): the textbook form subtracts two
  // nearly equal huge numbers once the start lies ~10^8 radii away: a cast from (-1e9, 50) to
  // (1e9, 50) missed a circle of radius 5 at (50, 50). The near root as c / q, q = -b + sqrt(disc), has no cancellation.
  const cross = fx * dy - fy * dx;
  const discriminant = a * r * r - cross * cross;
  if (discriminant < 0) return -1;
  const t = c / (-b + Math.sqrt(discriminant));
  return t <= 1 ? t : -1;
}
