import type { JointOptions } from '@maxgrid/engine';
import { resolveParams, type ParamSpecs } from './params.js';
import { funnelAndFloor, liftAboveFunnel, type SceneBody, type ShapeScene } from './shape-scene.js';

/** The parameters jellies takes, with their defaults and ranges (resolveParams checks them). */
export const jelliesParams = {
  count: { default: 20, min: 1, max: 10000, integer: true, description: 'jellies' },
  side: { default: 6, min: 2, max: 100, integer: true, description: 'particles along each side of a jelly' },
  hertz: { default: 15, min: 0.1, max: 1000, description: 'spring frequency of the lattice' },
  dampingRatio: { default: 0.5, min: 0, max: 100, description: 'damping ratio of the springs' },
  funnel: { default: 1, min: 0, max: 1, integer: true, description: '1: they fall into a funnel of segments' },
  stiffness: { default: 0, min: 0, max: 1e9, description: 'above 0: force-driven springs of this stiffness (integrated by the world\'s integrator) instead of soft-constraint distance joints' },
  stretch: { default: 1, min: 0.5, max: 2, description: 'the jellies start stretched along x by this factor (their springs at rest at 1)' },
  gravity: { default: 10, min: 0, max: 100, description: 'gravity, m/s^2' },
  floor: { default: 1, min: 0, max: 1, integer: true, description: '1: a floor with walls below the funnel' },
} satisfies ParamSpecs;

/**
 * Lattice jellies (soft bodies from the engine's own parts): each a side x side grid of small
 * circles joined by springs along the rows and columns and across each cell's two diagonals
 * (shear), so that it keeps its shape but wobbles: distance joints with `hertz` (the solver's soft
 * constraints), or with `stiffness` force-driven springs, which the world's integrator integrates; they fall into a funnel of segments,
 * colliding with it and with each other through the ordinary broad-phase. Meters, gravity 10,
 * y down, the funnel's outlet at y = 0.
 */
export function jellies(given?: Partial<Record<keyof typeof jelliesParams, number>>): ShapeScene {
  const p = resolveParams('jellies', jelliesParams, given);
  const spacing = 0.3;
  const radius = 0.14;
  const size = (p.side - 1) * spacing;
  const columns = Math.max(1, Math.round(Math.sqrt(p.count)));
  const bodies: SceneBody[] = [];
  const joints: JointOptions[] = [];
  // Rest lengths from the unstretched lattice, so that a stretched jelly starts with its springs drawn out.
  const spring = (a: number, b: number, rest: number): JointOptions =>
    p.stiffness > 0
      ? { kind: 'spring', bodyA: a, bodyB: b, length: rest, stiffness: p.stiffness, damping: 0 }
      : { kind: 'distance', bodyA: a, bodyB: b, length: rest, hertz: p.hertz, dampingRatio: p.dampingRatio };
  const diagonal = spacing * Math.SQRT2;
  for (let k = 0; k < p.count; k++) {
    const ox = (k % columns - (columns - 1) / 2) * (size + 1);
    const oy = -6 - Math.floor(k / columns) * (size + 1) - size;
    const first = bodies.length;
    for (let i = 0; i < p.side; i++) {
      for (let j = 0; j < p.side; j++) {
        bodies.push({ x: ox + j * spacing * p.stretch, y: oy + i * spacing, shapes: [{ kind: 'circle', radius, density: 1, friction: 0.4 }] });
        const at = first + i * p.side + j;
        if (j > 0) joints.push(spring(at - 1, at, spacing));
        if (i > 0) joints.push(spring(at - p.side, at, spacing));
        if (i > 0 && j > 0) {
          joints.push(spring(at - p.side - 1, at, diagonal));
          joints.push(spring(at - p.side, at - 1, diagonal));
        }
      }
    }
  }
  const width = columns * (size + 1) + 4;
  const segments = funnelAndFloor(width, 3, p.funnel === 1, p.floor === 1);
  const lift = p.funnel === 1 ? liftAboveFunnel(bodies, width, 3, radius, 0.5) : 0;
  for (const body of bodies) body.y -= lift;
  const rows = Math.ceil(p.count / columns);
  return {
    name: 'jellies',
    kind: 'shapes',
    params: Object.freeze({ ...p }),
    bounds: null,
    gravity: { x: 0, y: p.gravity },
    world: { friction: 0.4, restitution: 0, lengthUnit: 1, solver: 'soft' },
    bodies,
    segments,
    joints,
    view: { minX: -width, minY: -8 - rows * (size + 1) - lift, maxX: width, maxY: 9 },
  };
}
