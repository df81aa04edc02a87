import { describe, expect, it } from 'vitest';
import { World } from '../src/index.js';

/** Runs `call`, expects `kind` with a message matching `message`, and checks the world did not change. */
function refuses(world: World, call: () => unknown, kind: typeof TypeError | typeof RangeError, message: RegExp): void {
  // The snapshot's bytes too: they hold every field of the world, scratch and lazily made columns included.
  const bytes = world.snapshot();
  const before = { hash: world.stateHash(), bodies: world.bodyCount, shapes: world.shapeCount };
  let thrown: unknown;
  try {
    call();
  } catch (error) {
    thrown = error;
  }
  expect(thrown).toBeInstanceOf(kind);
  expect((thrown as Error).message).toMatch(message);
  expect({ hash: world.stateHash(), bodies: world.bodyCount, shapes: world.shapeCount }).toEqual(before);
  expect(Buffer.from(world.snapshot()).equals(Buffer.from(bytes))).toBe(true);
}

const square = [{ x: 0, y: 0 }, { x: 1, y: 0 }, { x: 1, y: 1 }, { x: 0, y: 1 }];

describe('bad shapes are refused by name, and the world is left as it was', () => {
  const world = new World();
  world.createBox({ x: 0, y: 0, width: 1, height: 1 });

  it('polygons: not convex, too many vertices, duplicates, collinear points, no area', () => {
    refuses(world, () => world.createPolygon({ x: 0, y: 0, vertices: [{ x: 0, y: 0 }, { x: 2, y: 0 }, { x: 1, y: 0.5 }, { x: 2, y: 2 }, { x: 0, y: 2 }] }), RangeError, /convex.*vertices\[2\] \(1, 0.5\)/);
    refuses(world, () => world.createPolygon({ x: 0, y: 0, vertices: Array.from({ length: 9 }, (_, k) => ({ x: Math.cos(k), y: Math.sin(k) })) }), RangeError, /3 to 8 points, got 9/);
    refuses(world, () => world.createPolygon({ x: 0, y: 0, vertices: [{ x: 0, y: 0 }, { x: 1, y: 0 }, { x: 1, y: 0 }, { x: 0, y: 1 }] }), RangeError, /distinct, .*: vertices\[2\] \(1, 0\) lies 0 from vertices\[1\]/);
    // Distinct but within a millionth of the polygon's size: the message says so, with the distance.
    refuses(world, () => world.createPolygon({ x: 0, y: 0, vertices: [{ x: 0, y: 0 }, { x: 1e-7, y: 0 }, { x: 1e-7, y: 1 }, { x: 0, y: 1 }] }), RangeError, /farther apart than 0\.000001 of the polygon's size \(1\): vertices\[1\] \(1e-7, 0\) lies 1e-7 from vertices\[0\]/);
    refuses(world, () => world.createPolygon({ x: 0, y: 0, vertices: [{ x: 0, y: 0 }, { x: 1, y: 0 }, { x: 2, y: 0 }, { x: 1, y: 1 }] }), RangeError, /collinear, .*: vertices\[1\] \(1, 0\) lies 0 from it/);
    refuses(world, () => world.createPolygon({ x: 0, y: 0, vertices: [{ x: 0, y: 0 }, { x: 1, y: 1 }, { x: 2, y: 2 }] }), RangeError, /no area/);
    refuses(world, () => world.createPolygon({ x: 0, y: 0, vertices: [{ x: 0, y: 0 }, { x: 1, y: NaN }, { x: 0, y: 1 }] }), TypeError, /vertices\[1\]\.y must be a finite number, got NaN/);
    refuses(world, () => world.createPolygon({ x: 0, y: 0, vertices: 'square' as never }), TypeError, /vertices must be an array/);
    // A self-intersecting star has every turn the same way round and is still refused.
    const star = [0, 2, 4, 1, 3].map((k) => ({ x: Math.cos((k * 2 * Math.PI) / 5), y: Math.sin((k * 2 * Math.PI) / 5) }));
    refuses(world, () => world.createPolygon({ x: 0, y: 0, vertices: star }), RangeError, /convex/);
  });

  it('clockwise polygons are accepted and turned counter-clockwise', () => {
    const h = world.createPolygon({ x: 5, y: 5, vertices: [...square].reverse() });
    expect(world.getBody(h).mass).toBeCloseTo(1, 12);
    world.destroyBody(h);
  });

  it('sizes, angles and materials', () => {
    refuses(world, () => world.createBox({ x: 0, y: 0, width: 0, height: 1 }), RangeError, /width must be > 0, got 0/);
    refuses(world, () => world.createBox({ x: 0, y: 0, width: 1, height: 1, radius: 0.5 }), RangeError, /radius must be less than half/);
    refuses(world, () => world.createBox({ x: 0, y: 0, width: 1, height: 1, angle: NaN }), TypeError, /angle must be a finite number, got NaN/);
    refuses(world, () => world.createCapsule({ x: 0, y: 0, length: -1, radius: 1 }), RangeError, /length must be > 0, got -1/);
    refuses(world, () => world.createBox({ x: 0, y: 0, width: 1, height: 1, friction: -0.1 }), RangeError, /friction must be >= 0/);
    refuses(world, () => world.createBox({ x: 0, y: 0, width: 1, height: 1, mass: 2, density: 3 }), TypeError, /mass or density, not both/);
    refuses(world, () => world.createBox({ x: 0, y: 0, width: 1, height: 1, colour: 'red' } as never), TypeError, /unknown option 'colour'/);
    refuses(world, () => world.createBox({ x: 0, y: 0, width: 1, height: 1, type: 'static', vx: 3 }), RangeError, /vx of a static body must be 0/);
  });

  it('a static circle takes no velocity either, on the circle engine and on the shape route, as every other creator', () => {
    const circles = new World({ gravity: { x: 0, y: 0 } });
    circles.createCircle({ x: 5, y: 5, radius: 1 });
    for (const w of [circles, world]) {
      refuses(w, () => w.createCircle({ x: 0, y: 0, radius: 1, type: 'static', vx: 3 }), RangeError, /vx of a static body must be 0, got 3; make it kinematic/);
      refuses(w, () => w.createCircle({ x: 0, y: 0, radius: 1, type: 'static', vy: -1e-300 }), RangeError, /vy of a static body must be 0/);
      refuses(w, () => w.createCircle({ x: 0, y: 0, radius: 1, type: 'static', vx: NaN }), TypeError, /vx must be a finite number, got NaN/);
      refuses(w, () => w.createBody({ x: 0, y: 0, type: 'static', vy: 2 }), RangeError, /vy of a static body must be 0/);
      const h = w.createCircle({ x: 0, y: 0, radius: 1, type: 'static', vx: 0, vy: -0 });
      expect(w.getBody(h)).toMatchObject({ vx: 0, vy: 0, type: 'static' });
      w.destroyBody(h);
      const k = w.createCircle({ x: 0, y: 0, radius: 1, type: 'kinematic', vx: 3 });
      expect(w.getBody(k).vx).toBe(3);
      w.destroyBody(k);
    }
  });

  it('a mass given at either bound is accepted for any size, though its density times the area rounds past it', () => {
    const w = new World();
    for (const mass of [1e100, 1e-100]) {
      for (const size of [1e-5, 0.1, 0.3, 0.7, 1, 3, 7, 1e5]) {
        const made = [
          w.createBox({ x: 0, y: 0, width: size, height: size, mass }),
          w.createCapsule({ x: 0, y: 0, length: size, radius: size / 3, mass }),
          w.createPolygon({ x: 0, y: 0, vertices: [{ x: 0, y: 0 }, { x: size, y: 0 }, { x: 0, y: size }], mass }),
          w.createCircle({ x: 0, y: 0, radius: size, mass }),
        ];
        for (const h of made) expect(w.getBody(h).mass / mass, `size ${size}`).toBeCloseTo(1, 12);
      }
    }
  });

  it('a dynamic body whose shapes have no mass', () => {
    refuses(world, () => world.createBox({ x: 0, y: 0, width: 1, height: 1, density: 0 }), RangeError, /needs mass/);
    const h = world.createBody({ x: 3, y: 0 });
    refuses(world, () => world.addShape(h, { kind: 'circle', radius: 1, density: 0 }), RangeError, new RegExp(`body ${h} needs mass`));
    const s = world.addShape(h, { kind: 'circle', radius: 1 });
    world.addShape(h, { kind: 'box', width: 1, height: 1, density: 0, sensor: true });
    refuses(world, () => world.destroyShape(s), RangeError, /needs mass: its shapes would give it mass 0/);
    // Nor may removing a shape leave a mass the shapes could not have been given.
    const light = world.createBox({ x: 6, y: 0, width: 1, height: 1 });
    world.addShape(light, { kind: 'circle', radius: 0.5, density: 1e-300 });
    refuses(world, () => world.destroyShape(world.getBody(light).shapes[0]), RangeError, new RegExp(`body ${light}'s shapes would give it mass 7.85\\d*e-301, outside \\[1e-100, 1e\\+100\\]`));
    world.destroyBody(light);
    // Static and kinematic bodies need no mass.
    const k = world.createBox({ x: 0, y: 9, width: 1, height: 1, density: 0, type: 'kinematic' });
    refuses(world, () => world.setType(k, 'dynamic'), RangeError, /needs mass/);
    world.destroyBody(k);
    world.destroyBody(h);
  });

  it('shapes on destroyed bodies, stale and foreign handles', () => {
    const h = world.createBody({ x: 3, y: 0 });
    const s = world.addShape(h, { kind: 'circle', radius: 1 });
    world.destroyBody(h);
    refuses(world, () => world.addShape(h, { kind: 'circle', radius: 1 }), RangeError, /stale/);
    refuses(world, () => world.getShape(s), RangeError, /shape handle .* is stale/);
    refuses(world, () => world.destroyShape(s), RangeError, /stale/);
    refuses(world, () => world.getShape(0), RangeError, /is a body or segment handle, not a shape handle/);
    refuses(world, () => world.getBody(s), RangeError, /is a shape handle, not a body handle/);
    refuses(world, () => world.addShape(world.handles()[0], { kind: 'triangle' } as never), RangeError, /kind must be one of/);
  });

  it('a refused torque or angular impulse on a circle of the circle route makes no rotation columns', () => {
    const circles = new World();
    const h = circles.createCircle({ x: 0, y: 0, radius: 1 });
    refuses(circles, () => circles.applyTorque(h, 1e300), RangeError, /angular acceleration exceed 1e\+100 \(pending torque 1e\+300, inertia 1.5707963267948966\)/);
    refuses(circles, () => circles.applyAngularImpulse(h, 1e300), RangeError, /angular velocity 6.36\d*e\+299 exceed/);
    refuses(circles, () => circles.createBox({ x: 0, y: 0, width: 3, height: 3, density: 1e-300 }), RangeError, /mass 9e-300, outside/);
    expect(circles.views().c.length).toBe(0);
    // Accepted, the same calls spin it as I w = impulse says.
    circles.applyAngularImpulse(h, Math.PI / 2);
    expect(circles.getBody(h).angularVelocity).toBeCloseTo(1, 12);
  });

  it('transforms and spins that would break the state', () => {
    const h = world.handles()[0];
    refuses(world, () => world.setTransform(h, 0, 0, Infinity), TypeError, /angle must be a finite number/);
    refuses(world, () => world.setAngularVelocity(h, NaN), TypeError, /angularVelocity must be a finite number/);
    refuses(world, () => world.applyTorque(h, 1e308), RangeError, /exceed 1e\+100/);
    refuses(world, () => world.applyAngularImpulse(h, 1e308), RangeError, /exceed 1e\+100/);
    refuses(world, () => world.setAngularVelocity(h, 1e101), RangeError, /angularVelocity must be within ±1e\+100/);
    const wall = world.createBox({ x: 0, y: 20, width: 1, height: 1, type: 'static' });
    refuses(world, () => world.setAngularVelocity(wall, 1), RangeError, /static/);
    refuses(world, () => world.applyTorque(wall, 1), RangeError, /only dynamic bodies take a torque/);
  });

  it('shapes must fit the box of a boxed world', () => {
    const boxed = new World({ bounds: { width: 10, height: 10 } });
    refuses(boxed, () => boxed.createBox({ x: 1, y: 5, width: 3, height: 1 }), RangeError, /outside the box/);
    const h = boxed.createBox({ x: 5, y: 5, width: 3, height: 1 });
    refuses(boxed, () => boxed.setTransform(h, 9, 5, 0), RangeError, /outside the box/);
    refuses(boxed, () => boxed.addShape(h, { kind: 'circle', radius: 1, offsetX: 5 }), RangeError, /outside the box/);
  });

  it('a body without shapes is held by its origin in a boxed world', () => {
    const boxed = new World({ bounds: { width: 10, height: 10 }, gravity: { x: 0, y: 10 } });
    refuses(boxed, () => boxed.createBody({ x: -1, y: 5 }), RangeError, /without shapes at \(-1, 5\) is outside the box/);
    refuses(boxed, () => boxed.createBody({ x: 5, y: 10.5 }), RangeError, /at \(5, 10.5\) is outside the box/);
    const point = boxed.createBody({ x: 5, y: 5, vx: -3 });
    refuses(boxed, () => boxed.setTransform(point, 5, 11, 0), RangeError, /at \(5, 11\) is outside the box/);
    refuses(boxed, () => boxed.setPosition(point, 10.25, 5), RangeError, /at \(10.25, 5\) is outside the box/);
    // Falling and drifting left, it stops in the corner instead of leaving the box for good.
    for (let i = 0; i < 180; i++) boxed.step(1 / 60);
    const b = boxed.getBody(point);
    expect([b.x, b.y, b.vx, b.vy]).toEqual([0, 10, 0, 0]);
    // So a shape can be given to it there.
    boxed.addShape(point, { kind: 'box', width: 1, height: 1, offsetX: 0.5, offsetY: -0.5 });
    expect(boxed.bodyCount).toBe(1);
    // Nor can its last shape be taken away where that leaves its origin outside the box.
    const offset = boxed.createPolygon({ x: -1, y: 5, vertices: [{ x: 2, y: 0 }, { x: 3, y: 0 }, { x: 2, y: 1 }] });
    const last = boxed.getBody(offset).shapes[0];
    refuses(boxed, () => boxed.destroyShape(last), RangeError, /the last of body \d+, would leave a body without shapes with its origin at \(-1, 5\), outside the box/);
    boxed.setTransform(offset, 1, 5, 0);
    boxed.destroyShape(last);
    expect(boxed.getBody(offset).shapes).toEqual([]);
  });

  it('a force or torque already applied is checked again when the mass or inertia it acts on changes', () => {
    // Applied while the body does not turn (fixed, or without shapes), the torque is fine; the
    // change that would let it spin the body past every bound is refused instead.
    for (const solver of ['elastic', 'soft'] as const) {
      const world = new World({ solver, gravity: { x: 0, y: 0 } });
      const fixed = world.createBox({ x: 0, y: 0, width: 1, height: 1, fixedRotation: true });
      world.applyTorque(fixed, 1e308);
      refuses(world, () => world.setFixedRotation(fixed, false), RangeError, /freeing its rotation would give body \d+ inertia 0.1666\d*, under which the torque 1e\+308 .* beyond 1e\+100/);
      const bare = world.createBody({ x: 5, y: 0 });
      world.applyTorque(bare, 1e308);
      refuses(world, () => world.addShape(bare, { kind: 'box', width: 1, height: 1 }), RangeError, /adding this shape would give body \d+ inertia .* torque 1e\+308/);
      const light = world.createBody({ x: 10, y: 0 });
      world.applyForce(light, 1e100, 0);
      refuses(world, () => world.addShape(light, { kind: 'box', width: 1e-45, height: 1e-45 }), RangeError, /mass 1e-90, under which the force \(1e\+100, 0\)/);
      // Removing the heavy part of an L leaves the light one under the same force.
      const l = world.createBox({ x: 20, y: 0, width: 1, height: 1, density: 1e6 });
      world.addShape(l, { kind: 'box', width: 1e-3, height: 1e-3, offsetX: 1 });
      world.applyForce(l, 1e100, 0);
      refuses(world, () => world.destroyShape(world.getBody(l).shapes[0]), RangeError, /destroying this shape would give body \d+ mass 9.99+\d*e-7, under which the force \(1e\+100, 0\)/);
      // After the step the loads are spent, and the same changes go through.
      world.step(1 / 60);
      world.setFixedRotation(fixed, false);
      world.addShape(bare, { kind: 'box', width: 1, height: 1 });
      for (const h of world.handles()) {
        const b = world.getBody(h);
        for (const v of [b.x, b.y, b.angle, b.vx, b.vy, b.angularVelocity]) expect(Number.isFinite(v)).toBe(true);
      }
      // A load within bounds under the new inertia is kept: the torque turns the freed box at tau / I.
      world.applyTorque(fixed, 1);
      world.setFixedRotation(fixed, true);
      world.setFixedRotation(fixed, false);
      world.step(1 / 60);
      if (solver === 'elastic') expect(world.getBody(fixed).angularVelocity).toBeCloseTo(6 / 60, 12);
    }
    // The circle route: a tiny circle's inertia is tiny.
    const circles = new World();
    const dot = circles.createCircle({ x: 0, y: 0, radius: 1e-50, mass: 1e-100, fixedRotation: true });
    circles.applyTorque(dot, 1e300);
    refuses(circles, () => circles.setFixedRotation(dot, false), RangeError, /freeing its rotation .* torque 1e\+300/);
  });

  it('a circle of the circle route too large to be a shape keeps the world off the shape route', () => {
    const circles = new World();
    const huge = circles.createCircle({ x: 0, y: 0, radius: 1e100, mass: 1 });
    const message = /body \d+, a circle of radius 1e\+100, would become a shape reaching beyond 1e\+50/;
    refuses(circles, () => circles.createBody({ x: 0, y: 0 }), RangeError, message);
    refuses(circles, () => circles.createBox({ x: 0, y: 0, width: 1, height: 1 }), RangeError, message);
    refuses(circles, () => circles.addShape(huge, { kind: 'circle', radius: 1 }), RangeError, message);
    refuses(circles, () => circles.createCircle({ x: 0, y: 0, radius: 1, friction: 0.5 }), RangeError, message);
    refuses(circles, () => circles.setIntegrator('rk4'), RangeError, message);
    expect(circles.getBody(huge).inertia).toBe(5e199);
    circles.destroyBody(huge);
    circles.createBox({ x: 0, y: 0, width: 1, height: 1 });
    expect(circles.bodyCount).toBe(1);
  });

  it('a box or polygon too small beside its offset for its vertices to keep their places (a unit box 1e17 out)', () => {
    const world = new World();
    const body = world.createBody({ x: 0, y: 0 });
    world.addShape(body, { kind: 'circle', radius: 1 });
    refuses(world, () => world.addShape(body, { kind: 'box', width: 1, height: 1, offsetX: 1e17 }), RangeError, /box shape with width 1, height 1 at offsetX 100000000000000000 rounds to an outline/);
    refuses(world, () => world.addShape(body, { kind: 'polygon', vertices: square, offsetY: -1e16 }), RangeError, /polygon shape with its vertices at offsetY -10000000000000000/);
    refuses(world, () => world.addShape(body, { kind: 'box', width: 1e-6, height: 1e-6, offsetX: 1e11, offsetAngle: 1 }), RangeError, /rounds to an outline/);
    // Far, and large enough to keep its shape: accepted.
    expect(world.addShape(body, { kind: 'box', width: 1, height: 1, offsetX: 1e12 })).toBeGreaterThanOrEqual(0);
  });

  it('options are read once each, nested ones included, and the value read is the value used', () => {
    const reads = new Map<string, number>();
    /** `value` with each key a getter that counts its reads, under `path`; plain objects and arrays within likewise. */
    const counted = <T,>(path: string, value: T): T => {
      if (typeof value !== 'object' || value === null) return value;
      const out: Record<string, unknown> = Array.isArray(value) ? ([] as unknown as Record<string, unknown>) : {};
      for (const [key, item] of Object.entries(value)) {
        const inner = counted(`${path}.${key}`, item);
        Object.defineProperty(out, key, {
          enumerable: true,
          get: () => {
            reads.set(`${path}.${key}`, (reads.get(`${path}.${key}`) ?? 0) + 1);
            return inner;
          },
        });
      }
      return out as T;
    };
    const world = new World(counted('World', { gravity: { x: 0, y: 10 }, friction: 0.5, restitution: 0.2, restitutionThreshold: 1, sleepSpeed: 0.1 }));
    const a = world.createCircle(counted('createCircle', { x: 0, y: 0, radius: 1, restitution: 0.5, type: 'dynamic' as const, mass: 2, vx: 1, friction: 0.3 }));
    const b = world.createBox(counted('createBox', { x: 3, y: 0, width: 1, height: 2, mass: 4, angle: 0.5 }));
    world.createPolygon(counted('createPolygon', { x: 6, y: 0, vertices: [{ x: 0, y: 0 }, { x: 1, y: 0 }, { x: 0, y: 1 }], radius: 0.1 }));
    world.addShape(b, counted('addShape', { kind: 'capsule' as const, length: 1, radius: 0.2, offsetX: 1, density: 2 }));
    world.createJoint(counted('revolute', { kind: 'revolute' as const, bodyA: a, bodyB: b, anchorA: { x: 1, y: 0 }, anchorB: { x: -1, y: 0 }, lowerAngle: -1, upperAngle: 1 }));
    world.createJoint(counted('distance', { kind: 'distance' as const, bodyA: a, bodyB: b, length: 3 }));
    expect([...reads].filter(([, n]) => n !== 1)).toEqual([]);
    expect(reads.size).toBeGreaterThan(40);
    // A getter that answers differently at each read gives the world what was checked.
    let n = 0;
    const body = world.createBox({
      x: 0,
      y: 20,
      width: 1,
      height: 1,
      get mass() {
        return n++ === 0 ? 3 : Number.NaN;
      },
    });
    expect(world.getBody(body).mass).toBe(3);
  });

  it('options whose getters create or destroy bodies are refused: the handles checked may no longer be those bodies', () => {
    const world = new World();
    const a = world.createBox({ x: 0, y: 0, width: 1, height: 1 });
    const b = world.createBox({ x: 3, y: 0, width: 1, height: 1 });
    expect(() =>
      world.createJoint({
        kind: 'distance',
        bodyA: a,
        get bodyB() {
          world.destroyBody(a);
          return b;
        },
      }),
    ).toThrow(/joint options: reading them created or destroyed bodies/);
    expect(world.jointCount).toBe(0);
    // a's slot, reused, takes no joint
    const c = world.createCircle({ x: 100, y: 0, radius: 1 });
    expect(world.jointsOf(c)).toEqual([]);
    const d = world.createBody({ x: 0, y: 10 });
    expect(() =>
      world.addShape(d, {
        kind: 'box',
        height: 1,
        get width() {
          world.destroyBody(d);
          return 1;
        },
      }),
    ).toThrow(TypeError);
    expect(world.shapeCount).toBe(2);
  });

  it('handle lookups refuse what is not a finite number, and answer false or -1 for numbers that name nothing', () => {
    const world = new World();
    const h = world.createBox({ x: 0, y: 0, width: 1, height: 1 });
    for (const bad of ['0', NaN, Infinity, {}, null, undefined, true]) {
      expect(() => world.hasBody(bad as unknown as number), String(bad)).toThrow(/handle must be a finite number/);
      expect(() => world.hasJoint(bad as unknown as number), String(bad)).toThrow(TypeError);
      expect(() => world.slotOfHandle(bad as unknown as number), String(bad)).toThrow(TypeError);
      expect(() => world.handleAtSlot(bad as unknown as number), String(bad)).toThrow(/slot must be a finite number/);
      expect(() => world.shapeHandleAtSlot(bad as unknown as number), String(bad)).toThrow(TypeError);
    }
    expect(world.hasBody(h)).toBe(true);
    expect(world.hasBody(h + 0.5)).toBe(false);
    expect(world.hasBody(-1)).toBe(false);
    expect(world.hasJoint(0)).toBe(false);
    expect(world.slotOfHandle(1e9)).toBe(-1);
    expect(world.handleAtSlot(7)).toBe(-1);
  });

  it('a polygon whose outline crosses itself is refused for what it is', () => {
    const world = new World();
    refuses(world, () => world.createPolygon({ x: 0, y: 0, vertices: [{ x: 0, y: 0 }, { x: 1, y: 1 }, { x: 1, y: 0 }, { x: 0, y: 1 }] }), RangeError, /crosses itself/);
  });
});
