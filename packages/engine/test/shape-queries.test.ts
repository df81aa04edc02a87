import { describe, expect, it } from 'vitest';
import { World } from '../src/index.js';
import { farQueriesAsBrute } from './helpers.js';

describe('queries with shapes', () => {
  const world = new World();
  const box = world.createBox({ x: 0, y: 0, width: 2, height: 1, angle: Math.PI / 4 });
  const capsule = world.createCapsule({ x: 5, y: 0, length: 2, radius: 0.5 });
  const triangle = world.createPolygon({ x: 10, y: 0, vertices: [{ x: -1, y: -1 }, { x: 1, y: -1 }, { x: 0, y: 1 }] });
  const table = world.createBody({ x: 20, y: 0 });
  world.addShape(table, { kind: 'box', width: 0.2, height: 2, offsetX: -1 });
  world.addShape(table, { kind: 'box', width: 0.2, height: 2, offsetX: 1 });

  it('points: inside the turned box and the capsule cap, not just inside a bounding circle', () => {
    expect(world.queryPoint(0.6, 0.6)).toEqual([box]);
    expect(world.queryPoint(0.9, -0.2)).toEqual([]);
    expect(world.queryPoint(6.4, 0)).toEqual([capsule]);
    expect(world.queryPoint(6.6, 0)).toEqual([]);
    expect(world.queryPoint(10, 0.9)).toEqual([triangle]);
    expect(world.queryPoint(10.6, 0.9)).toEqual([]);
    // Between the table's legs lies nothing.
    expect(world.queryPoint(20, 0)).toEqual([]);
    expect(world.queryPoint(21, 0.5)).toEqual([table]);
  });

  it('boxes: overlap with the shape itself', () => {
    expect(world.queryAABB(-0.2, 0.9, 0.2, 1.2)).toEqual([box]);
    expect(world.queryAABB(0.8, 0.8, 1.2, 1.2)).toEqual([]);
    expect(world.queryAABB(19.7, -0.5, 20.3, 0.5)).toEqual([]);
    expect(world.queryAABB(-100, -100, 100, 100)).toEqual([box, capsule, triangle, table]);
  });

  it('boxes far larger than the shapes (up to 1e300 across) hold every one of them, and one beside them none', () => {
    for (const e of [1e17, 1e18, 1e50, 1e100, 1e154, 1e300]) {
      expect(world.queryAABB(-e, -e, e, e), String(e)).toEqual([box, capsule, triangle, table]);
      expect(world.queryAABB(30, -e, e, e), String(e)).toEqual([]);
      // The table's right leg reaches x = 21.1; this box starts just inside it.
      expect(world.queryAABB(21.05, -e, e, e), String(e)).toEqual([table]);
    }
  });

  it('rays: the first shape entered, its entry point and outward normal', () => {
    const hit = world.rayCast(-10, 0, 30, 0)!;
    expect(hit.handle).toBe(box);
    // The turned box's top edge (local y = 0.5) crosses y = 0 a quarter of the way from its left
    // corner (-1.06, -0.35) to its right one (0.35, 1.06): at x = -1 / sqrt 2.
    expect(hit.x).toBeCloseTo(-Math.SQRT1_2, 12);
    expect(hit.normalX).toBeCloseTo(-Math.SQRT1_2, 12);
    expect(hit.normalY).toBeCloseTo(Math.SQRT1_2, 12);
    const all = world.rayCastAll(-10, 0, 30, 0);
    expect(all.map((h) => h.handle)).toEqual([box, capsule, triangle, table]);
    expect(all[1].x).toBeCloseTo(3.5, 12);
    expect(all[1].normalX).toBeCloseTo(-1, 12);
    expect(all[3].x).toBeCloseTo(18.9, 12);
    const down = world.rayCast(10, 5, 10, -5)!;
    expect(down.handle).toBe(triangle);
    expect(down.y).toBeCloseTo(1, 12);
    expect(Math.hypot(down.normalX, down.normalY)).toBeCloseTo(1, 12);
    // From inside a shape the ray ignores it.
    expect(world.rayCast(5, 0, 5, 10)).toBeNull();
  });

  it('rays: a unit outward normal on round shapes of any size, where the entry point rounds onto the core', () => {
    // A radius of 1e-20 beside a cast 2 long: the entry point rounds to the centre, or onto the
    // capsule's core, and a normal taken from it has length 0.
    for (const radius of [1e-40, 1e-20, 1e-8, 1, 1e6]) {
      const w = new World({ friction: 0.5 });
      const circle = w.createCircle({ x: 5, y: 0, radius, friction: 0.5 });
      const capsule = w.createCapsule({ x: 5, y: 10 * radius + 10, length: 4, radius });
      const casts = [
        // straight down onto the circle, and the capsule's side, then its end from the right
        { from: [5, -1 - radius], to: [5, 1 + radius], handle: circle, normal: [0, -1] },
        { from: [6, 9 * radius + 9], to: [6, 11 * radius + 11], handle: capsule, normal: [0, -1] },
        { from: [10 + 3 * radius, 10 * radius + 10], to: [0, 10 * radius + 10], handle: capsule, normal: [1, 0] },
      ];
      for (const { from, to, handle, normal } of casts) {
        const hit = w.rayCast(from[0], from[1], to[0], to[1])!;
        expect(hit?.handle, `radius ${radius}`).toBe(handle);
        expect(hit.normalX, `radius ${radius}`).toBeCloseTo(normal[0], 12);
        expect(hit.normalY, `radius ${radius}`).toBeCloseTo(normal[1], 12);
      }
    }
  });
});

describe('query masks and far rays on shapes', () => {
  it("a mask names shapes, not bodies: a compound answers for the shapes in the mask's layers alone", () => {
    const world = new World();
    const body = world.createBody({ x: 0, y: 0 });
    world.addShape(body, { kind: 'box', width: 2, height: 2, category: 2 });
    world.addShape(body, { kind: 'circle', radius: 1, offsetX: 5, category: 4 });
    expect(world.queryPoint(0, 0, { mask: 4 })).toEqual([]);
    expect(world.queryPoint(0, 0, { mask: 2 })).toEqual([body]);
    expect(world.queryPoint(5, 0, { mask: 4 })).toEqual([body]);
    expect(world.queryAABB(-0.5, -0.5, 0.5, 0.5, { mask: 4 })).toEqual([]);
    expect(world.queryAABB(-0.5, -0.5, 0.5, 0.5, { mask: 6 })).toEqual([body]);
    // Across both: the layer-4 circle's face at x = 4, not the box's at x = -1.
    const hit = world.rayCast(-10, 0, 10, 0, { mask: 4 })!;
    expect(hit.x).toBeCloseTo(4, 12);
    expect(hit.normalX).toBeCloseTo(-1, 12);
    expect(world.rayCast(-10, 0, 10, 0, { mask: 2 })!.x).toBeCloseTo(-1, 12);
    expect(world.rayCastAll(-10, 0, 10, 0, { mask: 4 }).map((h) => h.x)).toEqual([hit.x]);
  });

  it('a ray from 1e15 away enters a shape on its surface, not where the fraction rounds to', () => {
    const world = new World();
    const circle = world.createCircle({ x: 0, y: 0, radius: 1, friction: 0.5 });
    world.createBox({ x: 10, y: 10, width: 2, height: 2, angle: 0.3 });
    world.createCapsule({ x: 20, y: 0, length: 2, radius: 0.5, angle: 1 });
    const onCircle = world.rayCast(-1e15, 0.3, 1e15, 0.3)!;
    expect(onCircle.handle).toBe(circle);
    expect(Math.hypot(onCircle.x, onCircle.y)).toBeCloseTo(1, 12);
    expect(onCircle.y).toBeCloseTo(0.3, 12);
    // The box: its entry lies on one of its faces.
    const onBox = world.rayCast(-1e15, 10.2, 15, 10.2)!;
    const c = Math.cos(0.3);
    const sn = Math.sin(0.3);
    const lx = c * (onBox.x - 10) + sn * (onBox.y - 10);
    const ly = -sn * (onBox.x - 10) + c * (onBox.y - 10);
    expect(Math.max(Math.abs(lx), Math.abs(ly))).toBeCloseTo(1, 12);
    // The capsule's round end or side: at its radius from the core.
    const onCapsule = world.rayCast(20.1, -1e15, 20.1, 1e15)!;
    const ax = Math.cos(1);
    const ay = Math.sin(1);
    const u = Math.max(-1, Math.min(1, (onCapsule.x - 20) * ax + onCapsule.y * ay));
    expect(Math.hypot(onCapsule.x - 20 - u * ax, onCapsule.y - u * ay)).toBeCloseTo(0.5, 12);
  });

  it('a ray from up to 1e300 away decides hit or miss on a turned polygon, rounded polygon or capsule as from near', () => {
    // A horizontal line is exact however far its ends: it meets the shape where a short ray on
    // that line does. The differences of start and vertices rounded at the start's size, and a
    // ray passing 0.25 outside a turned box from 1e16 away hit it.
    const world = new World();
    const shapes = [
      world.createBox({ x: 0, y: 0, width: 1, height: 1, angle: 0.3 }),
      world.createBox({ x: 0, y: 4, width: 1, height: 1, radius: 0.1, angle: 0.7 }),
      world.createCapsule({ x: 0, y: 8, length: 1, radius: 0.2, angle: 1.1 }),
      world.createPolygon({ x: 0, y: 12, angle: 2, vertices: [{ x: -0.5, y: -0.3 }, { x: 0.6, y: 0 }, { x: -0.2, y: 0.5 }] }),
    ];
    for (const far of [1e3, 1e12, 1e15, 1e16, 1e20, 1e100, 1e300])
      for (let y = -1; y <= 13; y += 0.05) {
        const near = world.rayCast(-100, y, 100, y);
        // (A ray from -far to 100 ends at 100 only while 100 is more than the rounding of far.)
        const rays = far <= 1e16 ? [[-far, far], [far, -far], [-far, 100]] : [[-far, far], [far, -far]];
        for (const [x1, x2] of rays) {
          const hit = world.rayCast(x1, y, x2, y);
          const label = `${x1} -> ${x2} at y ${y}`;
          expect(hit?.handle ?? null, label).toBe(x1 < x2 && near !== null ? near.handle : hit === null ? null : hit.handle);
          expect(hit === null, label).toBe(near === null);
          if (hit !== null) expect(shapes).toContain(hit.handle);
        }
      }
    // A ray along a row of bodies from far away meets the first (its walk through the grid started
    // 16,384 past it from 1e20 away), and rayCastAll meets them all.
    const row = new World();
    const circles = Array.from({ length: 50 }, (_, i) => row.createCircle({ x: -1000 + 20 * i, y: 0, radius: 0.5 }));
    for (const far of [1e12, 1e16, 1e20, 1e50, 1e300]) {
      expect(row.rayCast(-far, 0, far, 0)?.handle, `${far}`).toBe(circles[0]);
      expect(row.rayCast(far, 0, -far, 0)?.handle, `${far}`).toBe(circles[49]);
      expect(row.rayCastAll(-far, 0, far, 0).length, `${far}`).toBe(50);
    }
  });
});

describe('shape queries with a few bodies far from the crowd', () => {
  it('find what testing every body finds, for points, boxes and rays in, across and beyond the grid', () => {
    // The grid's extent left bodies out (binned into its edge cells) in a good share of the worlds.
    expect(farQueriesAsBrute(true, 60, 6)).toBeGreaterThan(20);
  });
});
