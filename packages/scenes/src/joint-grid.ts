import type { JointOptions } from '@maxgrid/engine';
import { resolveParams, type ParamSpecs } from './params.js';
import type { SceneBody, ShapeScene } from './shape-scene.js';

/** The parameters jointGrid takes, with their defaults and ranges (resolveParams checks them). */
export const jointGridParams = {
  size: { default: 100, min: 2, max: 1000, integer: true, description: 'circles along each side of the grid' },
} satisfies ParamSpecs;

/** The seven static circles the grid hangs from: the middle of the top row. */
function isFixed(row: number, column: number, middle: number): boolean {
  return row === 0 && column >= middle - 3 && column <= middle + 3;
}

/**
 * Box2D v3's joint_grid benchmark: a size x size grid of circles (radius 0.4, one apart) each
 * pinned by revolute joints to its neighbour above and to its left, hanging from the seven
 * static circles in the middle of the top row. Meters, gravity 10, y down.
 */
export function jointGrid(given?: Partial<Record<keyof typeof jointGridParams, number>>): ShapeScene {
  const p = resolveParams('joint-grid', jointGridParams, given);
  const n = p.size;
  const bodies: SceneBody[] = [];
  const joints: JointOptions[] = [];
  const middle = Math.floor(n / 2);
  for (let column = 0; column < n; column++) {
    for (let row = 0; row < n; row++) {
      const fixed = isFixed(row, column, middle);
      const index = bodies.length;
      bodies.push({ x: column, y: row, type: fixed ? 'static' : 'dynamic', shapes: [{ kind: 'circle', radius: 0.4, density: 1, friction: 0.6 }] });
      if (row > 0) joints.push({ kind: 'revolute', bodyA: index - 1, bodyB: index, anchorA: { x: 0, y: 0.5 }, anchorB: { x: 0, y: -0.5 } });
      // Two fixed circles need no joint (and a joint needs something to move).
      if (column > 0 && !(fixed && isFixed(row, column - 1, middle))) joints.push({ kind: 'revolute', bodyA: index - n, bodyB: index, anchorA: { x: 0.5, y: 0 }, anchorB: { x: -0.5, y: 0 } });
    }
  }
  return {
    name: 'joint-grid',
    kind: 'shapes',
    params: Object.freeze({ ...p }),
    bounds: null,
    gravity: { x: 0, y: 10 },
    world: { friction: 0.6, restitution: 0, lengthUnit: 1, solver: 'soft' },
    bodies,
    segments: [],
    joints,
    view: { minX: -n, minY: -1, maxX: 2 * n, maxY: 2 * n },
  };
}
