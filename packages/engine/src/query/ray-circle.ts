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
  // Squares of lengths past ~1.3e154 overflow (a cast from -2e154 missed a circle at the origin):
  // such casts take rayCircleFar, which squares no length. Others never reach it: same bits.
  if (!(discriminant < Infinity) || !(c < Infinity) || !(a < Infinity) || !(b > -Infinity)) return rayCircleFar(fx, fy, dx, dy, r);
  if (discriminant < 0) return -1;
  const t = c / (-b + Math.sqrt(discriminant));
  return t <= 1 ? t : -1;
}

/**
 * rayCircle in terms of the unit direction: the offset h of the line from the centre (f x u), and
 * the distance along it to the closest approach (-f . u), none of which overflows for finite
 * inputs; then the entry point lies half a chord, sqrt((r - h)(r + h)), before the closest approach.
 */
function rayCircleFar(fx: number, fy: number, dx: number, dy: number, r: number): number {
  if (norm(fx, fy) <= r) return -1;
  const length = norm(dx, dy);
  if (length === 0 || !Number.isFinite(length)) return -1;
  const ux = dx / length;
  const uy = dy / length;
  const ahead = -(fx * ux + fy * uy);
  if (ahead <= 0) return -1;
  const h = Math.abs(fx * uy - fy * ux);
  if (h > r) return -1;
  const t = (ahead - Math.sqrt((r - h) * (r + h))) / length;
  return t <= 1 ? t : -1;
}

/**
 * Where a ray from (x1, y1) along (dx, dy) enters the circle at (cx, cy), radius r, relative to the
 * centre, into `at`: the closest approach of the line, minus half a chord along it. Unlike
 * start + t d, it does not round at the start's distance: cast from 1e15 radii away, start + t d
 * put the hit 0.12 radii off and gave a normal of length 0.90; this stays on the circle.
 */
export function rayCircleEntry(x1: number, y1: number, dx: number, dy: number, cx: number, cy: number, r: number, at: { x: number; y: number }): void {
  const length = norm(dx, dy);
  const ux = dx / length;
  const uy = dy / length;
  const h = (x1 - cx) * uy - (y1 - cy) * ux;
  const offset = Math.abs(h) < r ? Math.sqrt((r - h) * (r + h)) : 0;
  at.x = h * uy - offset * ux;
  at.y = -h * ux - offset * uy;
}

/**
 * sqrt(x^2 + y^2) without overflow, from multiplication, addition and Math.sqrt alone, which are
 * correctly rounded everywhere (Math.hypot's rounding is left to each JavaScript engine, which
 * would break determinism across runtimes). Huge and tiny inputs are scaled by a power of two,
 * which is exact, chosen by fixed thresholds rather than Math.log2 (not exact either).
 */
export function norm(x: number, y: number): number {
  const largest = Math.max(Math.abs(x), Math.abs(y));
  const scale = largest > 2 ** 500 ? 2 ** -600 : largest < 2 ** -500 ? 2 ** 600 : 1;
  const sx = x * scale;
  const sy = y * scale;
  return Math.sqrt(sx * sx + sy * sy) / scale;
}
