import { describe, expect, it } from 'vitest';
import { World } from '../src/index.js';

const DT = 1 / 60;

/** A flat floor at y = 0 of `links` links of 1 m from x = 0. */
function floorPoints(links: number): { x: number; y: number }[] {
  return Array.from({ length: links + 1 }, (_, k) => ({ x: k, y: 0 }));
}

/** Steps `world` and returns the least vx and the largest |vy| of body h after `settle` steps. */
function slide(world: World, h: number, steps: number, settle = 10): { minVx: number; maxVy: number } {
  let minVx = Infinity;
  let maxVy = 0;
  for (let s = 0; s < steps; s++) {
    world.step(DT);
    const b = world.getBody(h);
    if (s < settle) continue;
    minVx = Math.min(minVx, b.vx);
    maxVy = Math.max(maxVy, Math.abs(b.vy));
  }
  return { minVx, maxVy };
}

describe('chains: static segments joined smoothly', () => {
  it('a frictionless box and capsule slide across 30 flush joins without losing speed or bumping', () => {
    for (const kind of ['box', 'capsule'] as const) {
      const world = new World({ gravity: { x: 0, y: 10 }, friction: 0, restitution: 0 });
      world.createChain({ points: floorPoints(30) });
      const h = kind === 'box' ? world.createBox({ x: 1.5, y: -0.5, width: 1, height: 1, vx: 4 }) : world.createCapsule({ x: 1.5, y: -0.3, length: 1, radius: 0.3, vx: 4 });
      const { minVx, maxVy } = slide(world, h, 300);
      // 20 m in 5 s: across 20 joins.
      expect(world.getBody(h).x, kind).toBeGreaterThan(21);
      expect(minVx, kind).toBeGreaterThan(4 * 0.999);
      // Resting under gravity the soft step reports about g h / 2 of vertical speed; a seam's bump is metres a second.
      expect(maxVy, kind).toBeLessThan(0.01);
    }
  });

  it('a disc rolls across the joins at v = ωr, keeping its speed', () => {
    const world = new World({ gravity: { x: 0, y: 10 }, friction: 0.6, restitution: 0 });
    world.createChain({ points: floorPoints(40) });
    const disc = world.createCircle({ x: 1.5, y: -0.5, radius: 0.5, vx: 4, angularVelocity: 8 });
    const { minVx } = slide(world, disc, 300);
    const b = world.getBody(disc);
    expect(minVx).toBeGreaterThan(4 * 0.995);
    // Rolling: the contact's point at rest, within 1 % (the disc rests a slop deep, on a radius that much shorter).
    expect(Math.abs(b.vx - b.angularVelocity * 0.5)).toBeLessThan(0.01 * b.vx);
    expect(b.y).toBeCloseTo(-0.5, 2);
  });

  it('corners stay corners: a box rests balanced on a convex apex, in a V on both faces, and stops at a riser', () => {
    // A gentle crest: the apex at (10, -0.5) is a convex join the box's bottom face rests on.
    const crest = new World({ gravity: { x: 0, y: 10 }, friction: 0.5, restitution: 0 });
    crest.createChain({ points: [{ x: 0, y: 0 }, { x: 10, y: -0.5 }, { x: 20, y: 0 }] });
    const onApex = crest.createBox({ x: 10, y: -1.1, width: 1, height: 1 });
    for (let s = 0; s < 300; s++) crest.step(DT);
    const apex = crest.getBody(onApex);
    expect(apex.x).toBeCloseTo(10, 3);
    expect(apex.y).toBeGreaterThan(-1.0 - 0.01);
    expect(apex.y).toBeLessThan(-1.0 + 0.01);
    // A V: the box turns to lie on both faces, at the bottom, not sunk into either.
    const valley = new World({ gravity: { x: 0, y: 10 }, friction: 0.5, restitution: 0 });
    valley.createChain({ points: [{ x: 0, y: -5 }, { x: 5, y: 0 }, { x: 10, y: -5 }] });
    const inV = valley.createBox({ x: 4, y: -3, width: 1, height: 1 });
    for (let s = 0; s < 400; s++) valley.step(DT);
    const v = valley.getBody(inV);
    expect(v.x).toBeCloseTo(5, 2);
    expect(v.y).toBeCloseTo(-Math.SQRT1_2, 2);
    const contacts = valley.bodyContacts(inV);
    expect(contacts.length).toBe(2);
    for (const c of contacts) for (const p of c.points) expect(p.separation).toBeGreaterThan(-0.01);
    // A riser at x = 5: the box sliding into it stops against it.
    const step = new World({ gravity: { x: 0, y: 10 }, friction: 0, restitution: 0 });
    step.createChain({ points: [{ x: 0, y: 0 }, { x: 5, y: 0 }, { x: 5, y: -2 }, { x: 10, y: -2 }] });
    const box = step.createBox({ x: 3, y: -0.5, width: 1, height: 1, vx: 6 });
    let farthest = -Infinity;
    for (let s = 0; s < 240; s++) {
      step.step(DT);
      farthest = Math.max(farthest, step.getBody(box).x);
    }
    expect(farthest).toBeLessThan(4.5 + 0.01);
    expect(farthest).toBeGreaterThan(4.5 - 0.01);
  });

  it('a loop holds what is inside it: a fast ball bouncing in a closed triangle never leaves', () => {
    const world = new World({ gravity: { x: 0, y: 10 }, friction: 0.3, restitution: 0.8 });
    const corners = [{ x: 0, y: 0 }, { x: 10, y: 0 }, { x: 5, y: -8 }];
    const links = world.createChain({ points: corners, loop: true });
    expect(links.length).toBe(3);
    const ball = world.createCircle({ x: 5, y: -2, radius: 0.5, vx: 30, vy: -20 });
    const inside = (x: number, y: number): boolean => {
      for (let k = 0; k < 3; k++) {
        const a = corners[k];
        const b = corners[(k + 1) % 3];
        // Counter-clockwise on screen (y down): inside lies to the left of each edge, as seen with y down.
        if ((b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x) > 0) return false;
      }
      return true;
    };
    for (let s = 0; s < 600; s++) {
      world.step(DT);
      const b = world.getBody(ball);
      expect(inside(b.x, b.y), `step ${s}: (${b.x}, ${b.y})`).toBe(true);
    }
  });

  it("the links are segments: handles in order, each from its point to the next, found by queries, one destroyed leaves the rest", () => {
    const world = new World({ gravity: { x: 0, y: 10 }, friction: 0.5, restitution: 0 });
    const points = [{ x: 0, y: 0 }, { x: 4, y: 1 }, { x: 8, y: 0 }];
    const links = world.createChain({ points, thickness: 0.1, friction: 0.2, category: 2 });
    expect(links.map((h) => world.getSegment(h))).toEqual([
      { x1: 0, y1: 0, x2: 4, y2: 1, thickness: 0.1, restitution: 0, friction: 0.2, category: 2, mask: 0xffffffff },
      { x1: 4, y1: 1, x2: 8, y2: 0, thickness: 0.1, restitution: 0, friction: 0.2, category: 2, mask: 0xffffffff },
    ]);
    expect(world.rayCast(6, -5, 6, 5)!.handle).toBe(links[1]);
    world.destroySegment(links[0]);
    expect(world.segmentCount).toBe(1);
    const box = world.createBox({ x: 6, y: -1, width: 1, height: 1 });
    for (let s = 0; s < 120; s++) world.step(DT);
    expect(world.bodyContacts(box).map((c) => c.other)).toEqual([links[1]]);
  });

  it('refuses bad points and options with the field named, and makes no link', () => {
    const world = new World();
    const bad: [unknown, RegExp][] = [
      [{ points: [{ x: 0, y: 0 }] }, /at least 2 points/],
      [{ points: [{ x: 0, y: 0 }, { x: 1, y: 0 }], loop: true }, /at least 3 points/],
      [{ points: [{ x: 0, y: 0 }, { x: 1, y: 0 }, { x: 1, y: 0 }] }, /points\[1\] and points\[2\] are the same point/],
      [{ points: [{ x: 0, y: 0 }, { x: Number.NaN, y: 0 }] }, /points\[1\]\.x/],
      [{ points: [{ x: 0, y: 0 }, { x: 1 }] }, /points\[1\]\.y/],
      [{ points: 'square' }, /points must be an array/],
      [{ points: [{ x: 0, y: 0 }, { x: 1, y: 0 }], thickness: -1 }, /thickness/],
      [{ points: [{ x: 0, y: 0 }, { x: 1, y: 0 }], loop: 'yes' }, /loop must be a boolean/],
      [{ points: [{ x: 0, y: 0 }, { x: 1, y: 0 }], smooth: true }, /smooth/],
      [{ points: [{ x: 0, y: 0 }, { x: 1, y: 0 }, { x: 0, y: 0 }], loop: true }, /points\[2\] and points\[0\] are the same point/],
    ];
    for (const [options, message] of bad) {
      expect(() => world.createChain(options as never), JSON.stringify(options)).toThrow(message);
      expect(world.segmentCount).toBe(0);
    }
  });

  it('a restored snapshot slides on to the same bits', () => {
    const world = new World({ gravity: { x: 0, y: 10 }, friction: 0, restitution: 0 });
    world.createChain({ points: floorPoints(20) });
    world.createBox({ x: 1.5, y: -0.5, width: 1, height: 1, vx: 4 });
    for (let s = 0; s < 40; s++) world.step(DT);
    const copy = World.restore(world.snapshot());
    for (let s = 0; s < 120; s++) {
      world.step(DT);
      copy.step(DT);
    }
    expect(copy.stateHash()).toBe(world.stateHash());
    expect(copy.snapshot()).toEqual(world.snapshot());
  });
});
