import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { World } from '../src/index.js';

/** The distance between segments p1-p2 and q1-q2 (0 where they cross), written out here apart from the engine's. */
function segmentDistance(p1x: number, p1y: number, p2x: number, p2y: number, q1x: number, q1y: number, q2x: number, q2y: number): number {
  const cross = (ax: number, ay: number, bx: number, by: number, cx: number, cy: number): number => (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
  const d1 = cross(q1x, q1y, q2x, q2y, p1x, p1y);
  const d2 = cross(q1x, q1y, q2x, q2y, p2x, p2y);
  const d3 = cross(p1x, p1y, p2x, p2y, q1x, q1y);
  const d4 = cross(p1x, p1y, p2x, p2y, q2x, q2y);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return 0;
  const toSegment = (px: number, py: number, ax: number, ay: number, bx: number, by: number): number => {
    const ex = bx - ax;
    const ey = by - ay;
    const l2 = ex * ex + ey * ey;
    const t = l2 > 0 ? Math.min(1, Math.max(0, ((px - ax) * ex + (py - ay) * ey) / l2)) : 0;
    return Math.hypot(px - ax - t * ex, py - ay - t * ey);
  };
  return Math.min(toSegment(p1x, p1y, q1x, q1y, q2x, q2y), toSegment(p2x, p2y, q1x, q1y, q2x, q2y), toSegment(q1x, q1y, p1x, p1y, p2x, p2y), toSegment(q2x, q2y, p1x, p1y, p2x, p2y));
}

describe('queries find static segments as the capsules they collide as', () => {
  // A floor 0.5 thick (a capsule of radius 0.5 about y = 10), a ramp of thickness 0, and a box
  // and a circle above the floor, in a world with shapes.
  const world = new World();
  const floor = world.createSegment({ x1: 0, y1: 10, x2: 20, y2: 10, thickness: 0.5 });
  const ramp = world.createSegment({ x1: 30, y1: 10, x2: 40, y2: 0 });
  const box = world.createBox({ x: 5, y: 5, width: 2, height: 2 });
  const ball = world.createCircle({ x: 12, y: 5, radius: 1 });

  it('a ray down onto the floor enters its top face at y = 9.5 with the normal up (-y), and one from below its bottom face', () => {
    const down = world.rayCast(15, 0, 15, 20)!;
    expect(down.handle).toBe(floor);
    expect(down.fraction).toBeCloseTo(9.5 / 20, 14);
    expect(down.x).toBe(15);
    expect(down.y).toBeCloseTo(9.5, 12);
    expect(down.normalX).toBeCloseTo(0, 15);
    expect(down.normalY).toBe(-1);
    const up = world.rayCast(15, 20, 15, 0)!;
    expect(up.handle).toBe(floor);
    expect(up.y).toBeCloseTo(10.5, 12);
    expect(up.normalX).toBeCloseTo(0, 15);
    expect(up.normalY).toBe(1);
    expect(world.hasBody(down.handle)).toBe(false);
  });

  it("the floor's rounded end: a ray along its line enters the end cap at x = -0.5, the normal back along the ray", () => {
    const hit = world.rayCast(-10, 10, 5, 10)!;
    expect(hit.handle).toBe(floor);
    expect(hit.x).toBeCloseTo(-0.5, 12);
    expect(hit.normalX).toBeCloseTo(-1, 12);
    expect(hit.normalY).toBeCloseTo(0, 12);
  });

  it('a segment of thickness 0 is hit where a ray crosses it, the normal facing the ray, and missed past its end', () => {
    // The ramp from (30, 10) to (40, 0) crosses y = 5 at x = 35.
    const hit = world.rayCast(25, 5, 45, 5)!;
    expect(hit.handle).toBe(ramp);
    expect(hit.x).toBeCloseTo(35, 12);
    expect(hit.y).toBeCloseTo(5, 12);
    expect(hit.normalX).toBeCloseTo(-Math.SQRT1_2, 12);
    expect(hit.normalY).toBeCloseTo(-Math.SQRT1_2, 12);
    const back = world.rayCast(45, 5, 25, 5)!;
    expect(back.normalX).toBeCloseTo(Math.SQRT1_2, 12);
    expect(back.normalY).toBeCloseTo(Math.SQRT1_2, 12);
    expect(world.rayCast(25, -1, 45, -1)).toBeNull();
  });

  it('the nearer of a body and a segment is hit first, and rayCastAll lists both, nearest first', () => {
    // Straight down through the box (top face at y = 4) onto the floor (y = 9.5).
    const first = world.rayCast(5, 0, 5, 20)!;
    expect(first.handle).toBe(box);
    expect(first.y).toBeCloseTo(4, 12);
    expect(world.rayCastAll(5, 0, 5, 20).map((h) => h.handle)).toEqual([box, floor]);
    expect(world.rayCastAll(5, 20, 5, 0).map((h) => h.handle)).toEqual([floor, box]);
    // From under the floor, the floor hides the box.
    expect(world.rayCast(5, 20, 5, 0)!.handle).toBe(floor);
    // Across the circle and the ramp.
    expect(world.rayCastAll(0, 5, 50, 5).map((h) => h.handle)).toEqual([box, ball, ramp]);
  });

  it('a ray starting inside the thick floor ignores it, as a ray starting inside a shape does', () => {
    expect(world.rayCast(15, 10.2, 15, 20)).toBeNull();
    expect(world.rayCast(5, 10.2, 5, 0)!.handle).toBe(box);
  });

  it('points and boxes: within the thickness, boundary included, and not in the bounding box alone', () => {
    expect(world.queryPoint(15, 10.5)).toEqual([floor]);
    expect(world.queryPoint(15, 10.51)).toEqual([]);
    expect(world.queryPoint(-0.3, 10.3)).toEqual([floor]);
    // In the floor's bounding box, past its rounded end.
    expect(world.queryPoint(-0.45, 10.45)).toEqual([]);
    // A segment of thickness 0 holds no area: a box across it finds it, a point beside it does not.
    expect(world.queryAABB(34.9, 4.9, 35.1, 5.1)).toEqual([ramp]);
    expect(world.queryPoint(35, 4.9)).toEqual([]);
    expect(world.queryAABB(4.5, 5.5, 5.5, 9.5)).toEqual([box, floor]);
    expect(world.queryAABB(4.5, 5.5, 5.5, 9.49)).toEqual([box]);
    // Inside the ramp's bounding box, below its line.
    expect(world.queryAABB(31, 1, 33, 3)).toEqual([]);
    expect(world.queryAABB(31, 1, 33, 8)).toEqual([ramp]);
    expect(world.queryAABB(-100, -100, 100, 100)).toEqual([box, ball, floor, ramp]);
  });

  it("a segment answers to the query's mask by its category, and a destroyed one, or one added since, is known at once", () => {
    const w = new World();
    const low = w.createSegment({ x1: -5, y1: 0, x2: 5, y2: 0, category: 0b10 });
    expect(w.rayCast(0, -5, 0, 5, { mask: 0b01 })).toBeNull();
    expect(w.rayCast(0, -5, 0, 5, { mask: 0b10 })!.handle).toBe(low);
    expect(w.queryPoint(0, 0, { mask: 0b01 })).toEqual([]);
    expect(w.queryAABB(-1, -1, 1, 1, { mask: 0b11 })).toEqual([low]);
    const high = w.createSegment({ x1: -5, y1: -2, x2: 5, y2: -2 });
    expect(w.rayCast(0, -5, 0, 5)!.handle).toBe(high);
    w.destroySegment(high);
    expect(w.rayCast(0, -5, 0, 5)!.handle).toBe(low);
    w.destroySegment(low);
    expect(w.rayCast(0, -5, 0, 5)).toBeNull();
    expect(w.queryAABB(-10, -10, 10, 10)).toEqual([]);
  });

  it('a world of circles alone finds its segments too, and a restored snapshot finds the same', () => {
    const w = new World({ bounds: { width: 100, height: 100 } });
    const s = w.createSegment({ x1: 10, y1: 50, x2: 90, y2: 50, thickness: 1 });
    const c = w.createCircle({ x: 50, y: 20, radius: 2 });
    expect(w.rayCastAll(50, 0, 50, 100).map((h) => h.handle)).toEqual([c, s]);
    expect(w.rayCast(50, 30, 50, 100)!.y).toBeCloseTo(49, 12);
    const restored = World.restore(w.snapshot());
    expect(restored.rayCastAll(50, 0, 50, 100)).toEqual(w.rayCastAll(50, 0, 50, 100));
    expect(restored.queryPoint(50, 50.5)).toEqual([s]);
  });

  it('a terrain of thousands of segments, made in either order: a box over it all lists every one, ascending', () => {
    for (const order of ['left to right', 'right to left']) {
      const w = new World();
      const n = 3000;
      const made: number[] = [];
      for (let k = 0; k < n; k++) {
        const x = order === 'left to right' ? k : n - 1 - k;
        made.push(w.createSegment({ x1: x, y1: Math.sin(x / 10), x2: x + 1, y2: Math.sin((x + 1) / 10) }));
      }
      const sorted = made.slice().sort((a, b) => a - b);
      expect(w.queryAABB(-1, -2, n + 1, 2), order).toEqual(sorted);
      // Along y = 0 the ray crosses the links whose ends lie either side of it (none ends on it but the first).
      const crossing = made.filter((h) => {
        const g = w.getSegment(h);
        return Math.min(g.y1, g.y2) <= 0 && Math.max(g.y1, g.y2) >= 0;
      });
      expect(
        w
          .rayCastAll(-1, 0, n + 1, 0)
          .map((hit) => hit.handle)
          .sort((a, b) => a - b),
        order,
      ).toEqual(crossing.sort((a, b) => a - b));
    }
  });

  it('a ray aimed exactly at a join of two segments of no thickness hits it, from any direction', () => {
    const w = new World();
    const points = Array.from({ length: 201 }, (_, k) => ({ x: k * 0.7, y: Math.sin(k * 1.3) + 0.01 * k }));
    for (let k = 0; k < 200; k++) w.createSegment({ x1: points[k].x, y1: points[k].y, x2: points[k + 1].x, y2: points[k + 1].y });
    let seed = 7;
    const random = (): number => ((seed = (seed * 16807) % 2147483647) - 1) / 2147483646;
    for (let n = 0; n < 2000; n++) {
      const v = points[1 + Math.floor(random() * 199)];
      const angle = (random() - 0.5) * 2.8;
      const x1 = v.x + 5 * Math.sin(angle);
      const y1 = v.y - 5 * Math.cos(angle);
      // Through the vertex and on, twice as far.
      expect(w.rayCast(x1, y1, 2 * v.x - x1, 2 * v.y - y1), `ray ${n} at (${v.x}, ${v.y})`).not.toBeNull();
    }
  });

  it('on random segments and rays, a ray hits exactly the segments it passes within their thickness of, each once, nearest first', () => {
    fc.assert(
      fc.property(
        fc.array(fc.tuple(fc.integer({ min: 0, max: 100 }), fc.integer({ min: 0, max: 100 }), fc.integer({ min: 0, max: 100 }), fc.integer({ min: 0, max: 100 }), fc.integer({ min: 0, max: 3 })), { minLength: 1, maxLength: 40 }),
        fc.tuple(fc.integer({ min: -20, max: 120 }), fc.integer({ min: -20, max: 120 }), fc.integer({ min: -20, max: 120 }), fc.integer({ min: -20, max: 120 })),
        (specs, [x1, y1, x2, y2]) => {
          fc.pre(x1 !== x2 || y1 !== y2);
          const w = new World();
          const handles = specs.map(([ax, ay, bx, by, t]) => w.createSegment({ x1: ax + 0.25, y1: ay + 0.125, x2: bx + 0.5, y2: by + 0.375, thickness: t / 2 }));
          const hits = w.rayCastAll(x1, y1, x2, y2);
          // Margins keep the rounding of the two distance computations out of the comparison.
          for (let k = 0; k < specs.length; k++) {
            const [ax, ay, bx, by, t] = specs[k];
            const apart = segmentDistance(x1, y1, x2, y2, ax + 0.25, ay + 0.125, bx + 0.5, by + 0.375) - t / 2;
            const startInside = segmentDistance(x1, y1, x1, y1, ax + 0.25, ay + 0.125, bx + 0.5, by + 0.375) - t / 2;
            const hit = hits.some((h) => h.handle === handles[k]);
            if (apart > 1e-9) expect(hit).toBe(false);
            if (apart < -1e-9 && startInside > 1e-9) expect(hit).toBe(true);
            if (startInside < -1e-9) expect(hit).toBe(false);
          }
          expect(new Set(hits.map((h) => h.handle)).size).toBe(hits.length);
          for (let k = 1; k < hits.length; k++) expect(hits[k].fraction).toBeGreaterThanOrEqual(hits[k - 1].fraction);
          const first = w.rayCast(x1, y1, x2, y2);
          expect(first === null ? null : first.handle).toBe(hits.length === 0 ? null : hits[0].handle);
        },
      ),
      { numRuns: 300, seed: 19 },
    );
  });
});
