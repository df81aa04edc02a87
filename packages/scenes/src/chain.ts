import type { JointOptions } from '@maxgrid/engine';
import { resolveParams, type ParamSpecs } from './params.js';
import type { SceneBody, ShapeScene } from './shape-scene.js';

/** The parameters chain takes, with their defaults and ranges (resolveParams checks them). */
export const chainParams = {
  links: { default: 100, min: 1, max: 10000, integer: true, description: 'links in the chain' },
  linkLength: { default: 1, min: 0.05, max: 100, description: 'length of a link (pin to pin), m' },
  horizontal: { default: 0, min: 0, max: 1, integer: true, description: '1: starts straight out to the right and swings down; 0: hangs straight down' },
  density: { default: 20, min: 0.001, max: 1e6, description: 'density of the links' },
  rope: { default: 0, min: 0, max: 1, integer: true, description: '1: a rope, beads on distance joints that keep them at most a link apart and let them close up; 0: capsules on revolute joints' },
} satisfies ParamSpecs;

/**
 * A chain of capsules pinned end to end by revolute joints, the first to a static anchor at the
 * origin (Box2D's chain sample): meters, gravity 10, y down. Each link is a capsule as long as its
 * pin spacing, a quarter of that wide, so neighbours just touch (they do not collide: joined
 * bodies are kept apart from collision). With `rope`, a rope of beads instead: circles half a
 * link wide, each held at most a link from the one before by a distance joint with a range.
 */
export function chain(given?: Partial<Record<keyof typeof chainParams, number>>): ShapeScene {
  const p = resolveParams('chain', chainParams, given);
  const L = p.linkLength;
  const radius = L / 8;
  const down = p.horizontal === 0;
  // A link's capsule runs along its own x axis; hanging down, the body is turned a quarter turn.
  const angle = down ? Math.PI / 2 : 0;
  const bodies: SceneBody[] = [{ x: 0, y: 0, type: 'static', shapes: [{ kind: 'circle', radius }] }];
  const joints: JointOptions[] = [];
  for (let k = 0; k < p.links; k++) {
    if (p.rope === 1) {
      // A bead a link out from the last, held at most a link from it (a rope's distance joint:
      // free within [0, L], so the rope slackens and folds, and never stretches but by the solver's softness).
      const along = (k + 1) * L;
      bodies.push({ x: down ? 0 : along, y: down ? along : 0, shapes: [{ kind: 'circle', radius: L / 4, density: p.density, friction: 0.6 }] });
      joints.push({ kind: 'distance', bodyA: k, bodyB: k + 1, length: L, minLength: 0, maxLength: L });
      continue;
    }
    const along = (k + 0.5) * L;
    bodies.push({ x: down ? 0 : along, y: down ? along : 0, angle, shapes: [{ kind: 'capsule', length: L - 2 * radius, radius, density: p.density, friction: 0.6 }] });
    joints.push({ kind: 'revolute', bodyA: k, bodyB: k + 1, anchorA: k === 0 ? { x: 0, y: 0 } : { x: L / 2, y: 0 }, anchorB: { x: -L / 2, y: 0 } });
  }
  const span = p.links * L;
  return {
    name: 'chain',
    kind: 'shapes',
    params: Object.freeze({ ...p }),
    bounds: null,
    gravity: { x: 0, y: 10 },
    world: { friction: 0.6, restitution: 0, lengthUnit: 1, solver: 'soft' },
    bodies,
    segments: [],
    joints,
    view: { minX: -span - 1, minY: -1, maxX: span + 1, maxY: span + 1 },
  };
}
