import { describe, expect, it } from 'vitest';
import { DEBUG_COLORS, World } from '../src/index.js';

/** Line k's two ends. */
function ends(buffers: { vertices: Float32Array }, k: number): [number, number, number, number] {
  const v = buffers.vertices;
  return [v[4 * k], v[4 * k + 1], v[4 * k + 2], v[4 * k + 3]];
}

function colorOf(buffers: { colors: Float32Array }, k: number): number[] {
  return Array.from(buffers.colors.subarray(8 * k, 8 * k + 4));
}

describe('debugRender: the world as coloured lines for any renderer', () => {
  it("draws each shape's outline on the shape, coloured by its body, with joints, statics and contacts", () => {
    const world = new World({ gravity: { x: 0, y: 10 }, friction: 0.5, restitution: 0, bounds: { width: 20, height: 20 } });
    world.createBox({ x: 10, y: 15, width: 12, height: 1, type: 'static' });
    const box = world.createBox({ x: 8, y: 10, width: 2, height: 1, angle: 0.3 });
    const ball = world.createCircle({ x: 12, y: 10, radius: 0.5, angle: 1 });
    world.createCapsule({ x: 10, y: 6, length: 2, radius: 0.25 });
    world.createSegment({ x1: 1, y1: 18, x2: 19, y2: 18, thickness: 0.2 });
    const joint = world.createJoint({ kind: 'distance', bodyA: box, bodyB: ball });
    for (let s = 0; s < 90; s++) world.step(1 / 60);

    // One buffer object, reused by every call: read it before the next.
    const shapesOnly = world.debugRender({ statics: false, joints: false, contacts: false });
    const shapeLines = shapesOnly.lineCount;
    // Two boxes (4 edges each), the circle (16 around and its turn), the capsule (2 sides, 2 x 8 around).
    expect(shapeLines).toBe(4 + 4 + 17 + 18);
    // The ground's edges in the static colour, on its outline.
    for (let k = 0; k < 4; k++) {
      expect(colorOf(shapesOnly, k)).toEqual(DEBUG_COLORS.static.map(Math.fround));
      const [x1, y1] = ends(shapesOnly, k);
      expect(Math.abs(Math.abs(x1 - 10) - 6)).toBeLessThan(1e-4);
      expect(Math.abs(Math.abs(y1 - 15) - 0.5)).toBeLessThan(1e-4);
    }
    // The box's corners are its shape's vertices, turned and placed.
    const b = world.getBody(box);
    const corners = world.getShape(b.shapes[0]).vertices.map((p) => [b.x + Math.cos(b.angle) * p.x - Math.sin(b.angle) * p.y, b.y + Math.sin(b.angle) * p.x + Math.cos(b.angle) * p.y]);
    for (let k = 4; k < 8; k++) {
      const [x1, y1] = ends(shapesOnly, k);
      expect(Math.min(...corners.map(([cx, cy]) => Math.hypot(cx - x1, cy - y1)))).toBeLessThan(1e-4);
    }
    // The circle's outline lies at its radius; its last line points along its turn.
    const c = world.getBody(ball);
    for (let k = 8; k < 8 + 16; k++) {
      const [x1, y1, x2, y2] = ends(shapesOnly, k);
      expect(Math.hypot(x1 - c.x, y1 - c.y)).toBeCloseTo(0.5, 5);
      expect(Math.hypot(x2 - c.x, y2 - c.y)).toBeCloseTo(0.5, 5);
    }
    const [, , tx, ty] = ends(shapesOnly, 8 + 16);
    expect(Math.atan2(ty - c.y, tx - c.x)).toBeCloseTo(Math.atan2(Math.sin(c.angle), Math.cos(c.angle)), 4);
    // Then the segment (core and two sides), the box's four walls, the joint and the contact normals.
    const contacts = world.contactPoints().count;
    const all = world.debugRender();
    expect(all).toBe(shapesOnly);
    expect(contacts).toBeGreaterThan(0);
    expect(all.lineCount).toBe(shapeLines + 3 + 4 + 1 + contacts);
    const j = world.getJoint(joint);
    expect(ends(all, shapeLines + 7).map((v) => Math.round(v * 1e3) / 1e3)).toEqual([j.anchorA.x, j.anchorA.y, j.anchorB.x, j.anchorB.y].map((v) => Math.round(Math.fround(v) * 1e3) / 1e3));
    expect(colorOf(all, shapeLines + 7)).toEqual(DEBUG_COLORS.joint.map(Math.fround));
    expect(colorOf(all, all.lineCount - 1)).toEqual(DEBUG_COLORS.contact.map(Math.fround));
    expect(world.debugRender({ shapes: false, statics: false, joints: false, contacts: false }).lineCount).toBe(0);
  });

  it("draws a world of the report's circles, and refuses bad options by name", () => {
    const world = new World({ bounds: { width: 100, height: 100 } });
    for (let k = 0; k < 5; k++) world.createCircle({ x: 10 + 10 * k, y: 50, radius: 2, vx: 5 });
    world.step(1 / 60);
    expect(world.route.route).toBe('circles');
    const out = world.debugRender({ statics: false, contacts: false });
    expect(out.lineCount).toBe(5 * 17);
    expect(colorOf(out, 0)).toEqual(DEBUG_COLORS.dynamic.map(Math.fround));
    expect(() => world.debugRender({ shapes: 'yes' as never })).toThrow(/shapes must be true or false/);
    expect(() => world.debugRender({ outlines: true } as never)).toThrow(/outlines/);
  });
});
