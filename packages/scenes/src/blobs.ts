import type { JointOptions } from '@maxgrid/engine';
import { resolveParams, type ParamSpecs } from './params.js';
import { funnelAndFloor, liftAboveFunnel, type SceneBody, type ShapeScene } from './shape-scene.js';

/** The parameters blobs takes, with their defaults and ranges (resolveParams checks them). */
export const blobsParams = {
  count: { default: 12, min: 1, max: 10000, integer: true, description: 'blobs' },
  segments: { default: 2, min: 0, max: 4, integer: true, description: 'particles per ring: 4 x 2^segments (16 by default)' },
  radius: { default: 1, min: 0.1, max: 100, description: "a blob's radius, m" },
  pressure: { default: 40, min: 0, max: 1e6, description: 'gas pressure at the rest area, N/m (0: an empty ring, which folds)' },
  hertz: { default: 20, min: 0, max: 1000, description: 'frequency of the springs between neighbours (0: rigid links)' },
  gravity: { default: 10, min: 0, max: 100, description: 'gravity, m/s^2' },
  funnel: { default: 1, min: 0, max: 1, integer: true, description: '1: they fall into a funnel onto a floor; 0: no funnel or floor, so they fall for ever (unless gravity is 0)' },
} satisfies ParamSpecs;

/**
 * Directions around a circle, 4 x 2^segments of them, evenly spaced: the four axes halved again
 * and again by normalising the sum of neighbours. Square roots and divisions are correctly
 * rounded, so every runtime builds the same points (no Math.sin or Math.cos).
 */
function directions(segments: number): { x: number; y: number }[] {
  let points = [{ x: 1, y: 0 }, { x: 0, y: 1 }, { x: -1, y: 0 }, { x: 0, y: -1 }];
  for (let s = 0; s < segments; s++) {
    const next: { x: number; y: number }[] = [];
    for (let k = 0; k < points.length; k++) {
      const a = points[k];
      const b = points[(k + 1) % points.length];
      const x = a.x + b.x;
      const y = a.y + b.y;
      const length = Math.sqrt(x * x + y * y);
      next.push(a, { x: x / length, y: y / length });
    }
    points = next;
  }
  return points;
}

/**
 * Pressure blobs (soft bodies from the engine's own parts): each a ring of small circles joined
 * to their neighbours by distance springs, around a gas (a pressure joint) that pushes the ring
 * out as its area shrinks, P = p0 A0 / A; they fall into a funnel onto a floor, colliding with it
 * and each other through the ordinary broad-phase. Meters, gravity along +y (down), the funnel's
 * outlet at y = 0.
 */
export function blobs(given?: Partial<Record<keyof typeof blobsParams, number>>): ShapeScene {
  const p = resolveParams('blobs', blobsParams, given);
  const around = directions(p.segments);
  const n = around.length;
  // Particles as wide as their spacing around the ring: neighbours just touch.
  const particle = (Math.PI * p.radius) / n;
  const columns = Math.max(1, Math.round(Math.sqrt(p.count)));
  const bodies: SceneBody[] = [];
  const joints: JointOptions[] = [];
  const pitch = 2 * p.radius + 1;
  for (let k = 0; k < p.count; k++) {
    const cx = (k % columns - (columns - 1) / 2) * pitch;
    const cy = -6 - Math.floor(k / columns) * pitch - p.radius;
    const first = bodies.length;
    for (const d of around) bodies.push({ x: cx + p.radius * d.x, y: cy + p.radius * d.y, shapes: [{ kind: 'circle', radius: particle, density: 1, friction: 0.4 }] });
    for (let i = 0; i < n; i++) {
      const a = first + i;
      const b = first + ((i + 1) % n);
      joints.push(p.hertz > 0 ? { kind: 'distance', bodyA: a, bodyB: b, hertz: p.hertz, dampingRatio: 0.5 } : { kind: 'distance', bodyA: a, bodyB: b });
    }
    joints.push({ kind: 'pressure', bodies: Array.from({ length: n }, (_, i) => first + i), pressure: p.pressure });
  }
  const width = columns * pitch + 4;
  const segments = funnelAndFloor(width, 4 * p.radius, p.funnel === 1, p.funnel === 1);
  const lift = p.funnel === 1 ? liftAboveFunnel(bodies, width, 4 * p.radius, particle, 0.5) : 0;
  for (const body of bodies) body.y -= lift;
  const rows = Math.ceil(p.count / columns);
  return {
    name: 'blobs',
    kind: 'shapes',
    params: Object.freeze({ ...p }),
    bounds: null,
    gravity: { x: 0, y: p.gravity },
    world: { friction: 0.4, restitution: 0, lengthUnit: 1, solver: 'soft' },
    bodies,
    segments,
    joints,
    view: { minX: -width, minY: -8 - rows * pitch - lift, maxX: width, maxY: 9 },
  };
}
