import { describe, expect, it } from 'vitest';
import { BoxWall, World } from '../src/index.js';

const SLOP = 0.005;

/** Steps a world for `seconds` at 60 Hz. */
function run(world: World, seconds: number): void {
  for (let s = 0; s < Math.round(seconds * 60); s++) world.step(1 / 60);
}

describe('bodyContacts: each contact of a body as the last step left it', () => {
  it('a box resting on a static box: one contact, the normal down into the ground, its two corners on the top face', () => {
    const world = new World({ gravity: { x: 0, y: 10 }, friction: 0.6, restitution: 0 });
    const ground = world.createBox({ x: 0, y: 1, width: 20, height: 2, type: 'static' });
    const box = world.createBox({ x: 1, y: -0.6, width: 1, height: 1 });
    run(world, 2);
    const [contact, ...rest] = world.bodyContacts(box);
    expect(rest).toEqual([]);
    expect(contact.other).toBe(ground);
    expect(contact.wall).toBe(-1);
    expect(contact.shape).toBe(world.getBody(box).shapes[0]);
    expect(contact.otherShape).toBe(world.getBody(ground).shapes[0]);
    // y grows downwards: the ground lies at +y from the box.
    expect(contact.normalX).toBeCloseTo(0, 9);
    expect(contact.normalY).toBeCloseTo(1, 9);
    expect(contact.pointCount).toBe(2);
    const xs = contact.points.map((p) => p.x).sort((a, b) => a - b);
    expect(xs[0]).toBeCloseTo(0.5, 2);
    expect(xs[1]).toBeCloseTo(1.5, 2);
    for (const p of contact.points) {
      expect(Math.abs(p.y)).toBeLessThan(SLOP);
      expect(Math.abs(p.separation)).toBeLessThan(SLOP);
    }
    // The ground sees the same contact from its side.
    const [under] = world.bodyContacts(ground);
    expect(under.other).toBe(box);
    expect(under.shape).toBe(contact.otherShape);
    expect(under.normalY).toBeCloseTo(-1, 9);
    expect(under.points.map((p) => p.x).sort((a, b) => a - b)).toEqual(xs.map((x) => expect.closeTo(x, 6)));
    for (const p of under.points) expect(Math.abs(p.separation)).toBeLessThan(SLOP);
  });

  it('on a ramp of angle θ the normal is the ramp’s own, (sin θ, cos θ) into it, as the box rests there below its friction angle', () => {
    for (const angle of [0.1, 0.3, 0.5]) {
      const world = new World({ gravity: { x: 0, y: 10 }, friction: 0.8, restitution: 0 });
      const c = Math.cos(angle);
      const s = Math.sin(angle);
      // A ramp rising to the left (y down): its top face's outward normal is (-sin, -cos).
      world.createBox({ x: 0, y: 0, width: 40, height: 2, angle: -angle, type: 'static' });
      const box = world.createBox({ x: -1.5 * s, y: -1.5 * c, width: 1, height: 1, angle: -angle });
      run(world, 1);
      const contacts = world.bodyContacts(box);
      expect(contacts.length, String(angle)).toBe(1);
      expect(contacts[0].normalX).toBeCloseTo(s, 6);
      expect(contacts[0].normalY).toBeCloseTo(c, 6);
    }
  });

  it("a static segment: the segment's handle, no shape on its side", () => {
    const world = new World({ gravity: { x: 0, y: 10 }, friction: 0.6, restitution: 0 });
    const floor = world.createSegment({ x1: -10, y1: 0, x2: 10, y2: 0 });
    const ball = world.createCircle({ x: 0, y: -1, radius: 0.5, friction: 0.6, restitution: 0 });
    run(world, 2);
    const [contact] = world.bodyContacts(ball);
    expect(contact.other).toBe(floor);
    expect(world.hasBody(contact.other)).toBe(false);
    expect(contact.otherShape).toBe(-1);
    expect(contact.wall).toBe(-1);
    expect(contact.normalY).toBeCloseTo(1, 9);
    expect(contact.pointCount).toBe(1);
    expect(contact.points[0].x).toBeCloseTo(0, 6);
    expect(Math.abs(contact.points[0].separation)).toBeLessThan(SLOP);
  });

  it("the world's box: a box on its floor touches the bottom wall (other -1), one against the left wall touches that", () => {
    const world = new World({ bounds: { width: 10, height: 10 }, gravity: { x: -10, y: 10 }, friction: 0.6, restitution: 0 });
    const box = world.createBox({ x: 5, y: 5, width: 1, height: 1 });
    run(world, 3);
    const contacts = world.bodyContacts(box).sort((a, b) => a.wall - b.wall);
    expect(contacts.map((c) => [c.other, c.wall])).toEqual([
      [-1, BoxWall.minX],
      [-1, BoxWall.maxY],
    ]);
    expect(contacts[0].normalX).toBeCloseTo(-1, 9);
    expect(contacts[0].normalY).toBeCloseTo(0, 9);
    expect(contacts[1].normalX).toBeCloseTo(0, 9);
    expect(contacts[1].normalY).toBeCloseTo(1, 9);
  });

  it('lists only the points within the margin: a capsule standing on its end touches with its foot alone', () => {
    const world = new World({ gravity: { x: 0, y: 10 }, friction: 0.6, restitution: 0 });
    const ground = world.createBox({ x: 0, y: 1, width: 20, height: 2, type: 'static' });
    const capsule = world.createCapsule({ x: 0, y: -0.7, length: 1, radius: 0.2, angle: Math.PI / 2, fixedRotation: true });
    run(world, 1);
    const [contact, ...rest] = world.bodyContacts(capsule);
    expect(rest).toEqual([]);
    expect(contact.other).toBe(ground);
    expect(contact.pointCount).toBe(1);
    expect(contact.points.length).toBe(1);
    expect(Math.abs(contact.points[0].separation)).toBeLessThan(SLOP);
    expect(contact.points[0].x).toBeCloseTo(0, 6);
  });

  it('a table on two legs: one contact per leg, each naming its leg', () => {
    const world = new World({ gravity: { x: 0, y: 10 }, friction: 0.6, restitution: 0 });
    world.createBox({ x: 0, y: 1, width: 20, height: 2, type: 'static' });
    const table = world.createBody({ x: 0, y: -1 });
    const left = world.addShape(table, { kind: 'box', width: 0.2, height: 1, offsetX: -1 });
    const right = world.addShape(table, { kind: 'box', width: 0.2, height: 1, offsetX: 1 });
    world.addShape(table, { kind: 'box', width: 2.2, height: 0.2, offsetY: -0.6 });
    run(world, 2);
    expect(world.bodyContacts(table).map((c) => c.shape).sort()).toEqual([left, right].sort());
  });

  it('a box asleep on the ground keeps its contact', () => {
    const world = new World({ gravity: { x: 0, y: 10 }, friction: 0.6, restitution: 0, sleeping: true });
    const ground = world.createBox({ x: 0, y: 1, width: 20, height: 2, type: 'static' });
    const box = world.createBox({ x: 0, y: -0.5, width: 1, height: 1 });
    run(world, 4);
    expect(world.getBody(box).awake).toBe(false);
    expect(world.bodyContacts(box).map((c) => c.other)).toEqual([ground]);
  });

  it('frictionless circles: each touching pair, the normal along the centres, one point midway, the overlap as a negative separation', () => {
    const world = new World({ bounds: { width: 100, height: 100 } });
    const a = world.createCircle({ x: 50, y: 50, radius: 2, vx: 1 });
    const b = world.createCircle({ x: 52, y: 51.5, radius: 1 });
    const far = world.createCircle({ x: 10, y: 10, radius: 1 });
    world.step(0);
    const [ab] = world.bodyContacts(a);
    expect(ab.other).toBe(b);
    expect([ab.shape, ab.otherShape, ab.wall]).toEqual([-1, -1, -1]);
    const { x: ax, y: ay } = world.getBody(a);
    const { x: bx, y: by } = world.getBody(b);
    const d = Math.hypot(bx - ax, by - ay);
    expect(ab.normalX).toBeCloseTo((bx - ax) / d, 12);
    expect(ab.normalY).toBeCloseTo((by - ay) / d, 12);
    expect(ab.points[0].separation).toBeCloseTo(d - 3, 12);
    expect(ab.points[0].x).toBeCloseTo(ax + ab.normalX * (2 + (d - 3) / 2), 12);
    const [ba] = world.bodyContacts(b);
    expect(ba.other).toBe(a);
    expect(ba.normalX).toBeCloseTo(-ab.normalX, 12);
    expect(ba.points[0].x).toBeCloseTo(ab.points[0].x, 12);
    expect(world.bodyContacts(far)).toEqual([]);
    // On the left wall and a thick segment, circles' own contacts: the wall at x = 0, the segment's capsule.
    const onWall = world.createCircle({ x: 1, y: 80, radius: 1 });
    const segment = world.createSegment({ x1: 60, y1: 90, x2: 90, y2: 90, thickness: 0.5 });
    const onSegment = world.createCircle({ x: 70, y: 88, radius: 1.5 });
    expect(world.bodyContacts(onWall).map((c) => [c.other, c.wall, c.normalX, c.normalY, c.points[0].x, c.points[0].separation])).toEqual([[-1, BoxWall.minX, -1, 0, 0, 0]]);
    const [s] = world.bodyContacts(onSegment);
    expect([s.other, s.wall, s.normalX, s.normalY, s.points[0].y, s.points[0].separation]).toEqual([segment, -1, 0, 1, 89.5, 0]);
    world.setPosition(onSegment, 70, 87.9);
    expect(world.bodyContacts(onSegment)).toEqual([]);
  });

  it('contacts follow the world as it is: a destroyed body leaves them at once, and one made in its slot has its own, on either route', () => {
    for (const shapes of [false, true]) {
      const world = new World({ bounds: { width: 100, height: 100 } });
      const make = (x: number, y: number): number => (shapes ? world.createBox({ x, y, width: 2, height: 2 }) : world.createCircle({ x, y, radius: 1 }));
      const a = make(50, 50);
      const b = make(51.5, 50);
      world.step(0);
      expect(world.bodyContacts(a).map((c) => c.other)).toEqual([b]);
      const slotB = world.slotOfHandle(b);
      world.destroyBody(b);
      expect(world.bodyContacts(a)).toEqual([]);
      // A body in b's slot, away from a: no contact; one that overlaps a: a contact at once.
      const c = make(80, 80);
      expect(world.slotOfHandle(c)).toBe(slotB);
      expect(world.bodyContacts(c)).toEqual([]);
      expect(world.bodyContacts(a)).toEqual([]);
      const d = make(48.5, 50);
      expect(world.bodyContacts(a).map((x) => x.other)).toEqual([d]);
      expect(world.bodyContacts(d)[0].normalX).toBeCloseTo(1, 12);
    }
  });

  it('circles: a gap within contactSlop touches in every direction, as does a centre on a segment', () => {
    const world = new World({ bounds: { width: 100, height: 100 }, contactSlop: 0.01 });
    const a = world.createCircle({ x: 10, y: 10, radius: 2 });
    const alongX = world.createCircle({ x: 13.005, y: 10, radius: 1 });
    const alongY = world.createCircle({ x: 10, y: 13.005, radius: 1 });
    const apart = world.createCircle({ x: 6.98, y: 10, radius: 1 });
    expect(world.bodyContacts(a).map((c) => c.other)).toEqual([alongX, alongY]);
    expect(world.bodyContacts(apart)).toEqual([]);
    const floor = world.createSegment({ x1: 40, y1: 50, x2: 60, y2: 50, thickness: 0.5 });
    const above = world.createCircle({ x: 50, y: 48.495, radius: 1 });
    const through = world.createCircle({ x: 45, y: 50, radius: 1 });
    expect(world.bodyContacts(above).map((c) => [c.other, c.normalY])).toEqual([[floor, 1]]);
    // A centre on the segment's line: the left normal pushes it, so the contact points the other way.
    const [onLine] = world.bodyContacts(through);
    expect(onLine.other).toBe(floor);
    expect(onLine.normalX).toBeCloseTo(0, 12);
    expect(onLine.normalY).toBe(-1);
    expect(onLine.points[0].separation).toBe(-1.5);
  });

  it('reuses the objects of `out`, and refuses what is not a live body handle or a writable array', () => {
    const world = new World({ gravity: { x: 0, y: 10 }, friction: 0.6, restitution: 0 });
    const ground = world.createBox({ x: 0, y: 1, width: 20, height: 2, type: 'static' });
    const box = world.createBox({ x: 0, y: -0.5, width: 1, height: 1 });
    const segment = world.createSegment({ x1: 30, y1: 0, x2: 40, y2: 0 });
    run(world, 1);
    const out = world.bodyContacts(box);
    const first = out[0];
    world.step(1 / 60);
    expect(world.bodyContacts(box, out)).toBe(out);
    expect(out[0]).toBe(first);
    expect(out[0].other).toBe(ground);
    expect(() => world.bodyContacts(segment)).toThrow(RangeError);
    expect(() => world.bodyContacts(Number.NaN)).toThrow(/handle/);
    expect(() => world.bodyContacts(box, Object.freeze([]) as never)).toThrow(TypeError);
    expect(() => world.bodyContacts(box, [{ points: 3 }] as never)).toThrow(/out\[0\]\.points/);
    expect(() => world.bodyContacts(box, [{ points: [3] }] as never)).toThrow(/out\[0\]\.points\[0\]/);
    const twice = { points: [] };
    expect(() => world.bodyContacts(box, [twice, twice] as never)).toThrow(/out\[1\] is the same object as out\[0\]/);
    const shared: never[] = [];
    expect(() => world.bodyContacts(box, [{ points: shared }, { points: shared }] as never)).toThrow(/out\[1\]\.points is out\[0\]\.points/);
    const gone = world.createBox({ x: 5, y: -0.5, width: 1, height: 1 });
    world.destroyBody(gone);
    expect(() => world.bodyContacts(gone)).toThrow(RangeError);
  });

  it('a restored snapshot lists the same contacts', () => {
    const world = new World({ gravity: { x: 0, y: 10 }, friction: 0.6, restitution: 0 });
    world.createBox({ x: 0, y: 1, width: 20, height: 2, type: 'static' });
    const box = world.createBox({ x: 0, y: -0.5, width: 1, height: 1, angle: 0.2 });
    run(world, 0.5);
    const restored = World.restore(world.snapshot());
    expect(restored.bodyContacts(box)).toEqual(world.bodyContacts(box));
    const other = new World();
    other.createBox({ x: 0, y: 0, width: 1, height: 1 });
    other.step(0);
    other.restore(world.snapshot());
    expect(other.bodyContacts(box)).toEqual(world.bodyContacts(box));
  });
});
