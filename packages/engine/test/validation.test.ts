import { describe, expect, it } from 'vitest';
import { World } from '../src/index.js';

function populated(): { world: World; handle: number } {
  const world = new World({ bounds: { width: 200, height: 100 }, gravity: { x: 0, y: 10 } });
  const handle = world.createCircle({ x: 50, y: 50, vx: 3, vy: 4, radius: 5 });
  world.createCircle({ x: 100, y: 50, radius: 8, type: 'static' });
  world.step(1 / 60);
  return { world, handle };
}

function snapshot(world: World) {
  return {
    hash: world.stateHash(),
    count: world.bodyCount,
    handles: world.handles(),
    broadphase: world.broadphase,
    integrator: world.integrator,
    gravity: world.gravity,
    circles: world.handles().map((h) => world.getCircle(h)),
    route: world.route,
    shapeCount: world.shapeCount,
    radii: Array.from(world.views().radius.subarray(0, world.bodyCount)),
  };
}

/** Expects `action` to throw `kind` with a message naming `field` and `value`, changing nothing. */
function rejects(action: (world: World, handle: number) => unknown, kind: typeof TypeError | typeof RangeError, field: string, value: string) {
  const { world, handle } = populated();
  const before = snapshot(world);
  let error: unknown;
  try {
    action(world, handle);
  } catch (e) {
    error = e;
  }
  expect(error).toBeInstanceOf(kind);
  const message = (error as Error).message;
  expect(message).toContain(field);
  expect(message).toContain(value);
  expect(snapshot(world)).toEqual(before);
}

describe('bad input is rejected with a named error and leaves the world unchanged', () => {
  it.each([
    ['x', NaN, 'NaN'],
    ['y', Infinity, 'Infinity'],
    ['vx', -Infinity, '-Infinity'],
    ['vy', NaN, 'NaN'],
    ['radius', NaN, 'NaN'],
    ['mass', Infinity, 'Infinity'],
    ['restitution', NaN, 'NaN'],
  ])('createCircle with %s = %s', (field, value, shown) => {
    rejects((w) => w.createCircle({ x: 20, y: 20, radius: 3, [field]: value }), TypeError, field, shown);
  });

  it.each([
    ['radius', 0],
    ['radius', -2],
    ['mass', -1],
    ['mass', 0],
    ['restitution', -0.5],
    ['density', -1],
  ])('createCircle with %s = %s', (field, value) => {
    rejects((w) => w.createCircle({ x: 20, y: 20, radius: 3, [field]: value }), RangeError, field, String(value));
  });

  it('createCircle with a non-number', () => {
    rejects((w) => w.createCircle({ x: '20' as unknown as number, y: 20, radius: 3 }), TypeError, 'x', '"20"');
  });

  it('createCircle with an unknown type', () => {
    rejects((w) => w.createCircle({ x: 20, y: 20, radius: 3, type: 'ghost' as never }), RangeError, 'type', 'ghost');
  });

  it('createCircle with a misspelt option', () => {
    rejects((w) => w.createCircle({ x: 20, y: 20, radius: 3, radus: 4 } as never), TypeError, 'radus', 'radus');
  });

  it.each([
    [199, 50, 5],
    [50, -1, 5],
    [4, 50, 5],
    [100, 50, 60],
  ])('createCircle outside the box at (%s, %s) radius %s', (x, y, radius) => {
    rejects((w) => w.createCircle({ x, y, radius }), RangeError, 'outside the box', `(${x}, ${y})`);
  });

  it.each([
    [-1 / 60, RangeError, '-0.01666'],
    [NaN, TypeError, 'NaN'],
    [Infinity, TypeError, 'Infinity'],
  ] as const)('step(%s)', (dt, kind, shown) => {
    rejects((w) => w.step(dt), kind, 'dt', shown);
  });

  it('unknown broad-phase name', () => {
    rejects((w) => w.setBroadphase('grid' as never), RangeError, 'broadphase', 'grid');
  });

  it('unknown integrator name', () => {
    rejects((w) => w.setIntegrator('verlet' as never), RangeError, 'integrator', 'verlet');
  });

  it('unknown type in setType', () => {
    rejects((w, h) => w.setType(h, 'frozen' as never), RangeError, 'type', 'frozen');
  });

  it('non-finite velocity and position', () => {
    rejects((w, h) => w.setVelocity(h, NaN, 0), TypeError, 'vx', 'NaN');
    rejects((w, h) => w.setPosition(h, 10, Infinity), TypeError, 'y', 'Infinity');
    rejects((w, h) => w.setPosition(h, 1, 50), RangeError, 'outside the box', '(1, 50)');
    rejects((w) => w.setGravity(0, NaN), TypeError, 'gravity.y', 'NaN');
  });

  it.each([
    ['category', -(2 ** 31) - 1],
    ['category', 2 ** 32],
    ['mask', 1.5],
    ['linearDamping', -0.1],
  ])('createCircle with %s = %s', (field, value) => {
    rejects((w) => w.createCircle({ x: 20, y: 20, radius: 3, [field]: value }), RangeError, field, String(value));
  });

  it('forces, impulses, filters and queries with bad values', () => {
    rejects((w, h) => w.applyForce(h, NaN, 0), TypeError, 'fx', 'NaN');
    rejects((w, h) => w.applyImpulse(h, 0, Infinity), TypeError, 'iy', 'Infinity');
    rejects((w, h) => w.applyTorque(h, NaN), TypeError, 'torque', 'NaN');
    rejects((w, h) => w.applyAngularImpulse(h, '1' as never), TypeError, 'impulse', '"1"');
    rejects((w, h) => w.setCollisionFilter(h, 1, -(2 ** 31) - 1), RangeError, 'mask', '-2147483649');
    rejects((w, h) => w.setGravityScale(h, NaN), TypeError, 'gravityScale', 'NaN');
    rejects((w, h) => w.setLinearDamping(h, -1), RangeError, 'linearDamping', '-1');
    rejects((w) => w.queryAABB(10, 0, 5, 10), RangeError, 'min <= max', '(10, 0)');
    rejects((w) => w.queryPoint(NaN, 0), TypeError, 'x', 'NaN');
    rejects((w) => w.rayCast(0, 0, 1, Infinity), TypeError, 'y2', 'Infinity');
    rejects((w) => w.queryPoint(0, 0, { mask: 0.5 }), RangeError, 'mask', '0.5');
  });

  it('takes a negative 32-bit layer set as its bits, as ~ and | give it', () => {
    const PLAYER = 2;
    const world = new World({ gravity: { x: 0, y: 0 } });
    const player = world.createCircle({ x: 0, y: 0, radius: 1, category: PLAYER, mask: ~PLAYER });
    expect(world.getCircle(player)).toMatchObject({ category: 2, mask: 0xfffffffd });
    const bullet = world.createCircle({ x: 10, y: 0, radius: 1, category: 1 << 31, mask: ~PLAYER, vx: -600 });
    expect(world.getCircle(bullet).category).toBe(0x80000000);
    world.setCollisionFilter(bullet, 1 << 31, ~PLAYER | 0);
    expect(world.getCircle(bullet).mask).toBe(0xfffffffd);
    // The bullet's mask leaves out the player's layer: it passes through.
    world.step(1 / 60);
    expect(world.getCircle(bullet).vx).toBe(-600);
    expect(world.queryPoint(0, 0, { mask: ~PLAYER })).toEqual([bullet]);
  });

  it('friction, rolling resistance and contact damping beyond 1e100, whose products would overflow', () => {
    rejects((w) => w.createCircle({ x: 20, y: 20, radius: 3, friction: 1e155 }), RangeError, 'friction', '1e+155');
    rejects((w) => w.createBox({ x: 20, y: 20, width: 3, height: 3, rollingResistance: 1e200 }), RangeError, 'rollingResistance', '1e+200');
    rejects((w) => w.createSegment({ x1: 0, y1: 90, x2: 100, y2: 90, friction: 1e101 }), RangeError, 'friction', '1e+101');
    expect(() => new World({ friction: 1e155 })).toThrow(/friction must be at most 1e\+100.*1e\+155/);
    expect(() => new World({ contactDampingRatio: 1e308 })).toThrow(/contactDampingRatio must be at most 1e\+100.*1e\+308/);
  });

  it('a shape refused by addShape leaves a circle world on the circle route, its body as it was', () => {
    // Outside the box, and too heavy: both are checked before the world takes the shape route.
    rejects((w, h) => w.addShape(h, { kind: 'circle', radius: 1, offsetX: 160 }), RangeError, 'outside the box', 'spanning (209.');
    rejects((w, h) => w.addShape(h, { kind: 'box', width: 10, height: 10, density: 1e99 }), RangeError, 'mass', '1e+101');
  });

  it('shapes reaching beyond 1e50 from their body, whose inertia would overflow; a circle that size on the circle route', () => {
    const world = new World();
    world.createBox({ x: 0, y: 0, width: 1e50, height: 1e50, mass: 1 });
    const state = (w: World) => ({ hash: w.stateHash(), bodies: w.bodyCount, shapes: w.shapeCount, route: w.route });
    const before = state(world);
    expect(() => world.createBox({ x: 0, y: 0, width: 1e78, height: 1e78, mass: 1 })).toThrow(/width 1e\+78, height 1e\+78 reaches .* beyond 1e\+50/);
    expect(() => world.createCapsule({ x: 0, y: 0, length: 1e80, radius: 1 })).toThrow(/length 1e\+80/);
    expect(() => world.createCircle({ x: 0, y: 0, radius: 1e80, density: 1e-160, friction: 0.5 })).toThrow(/radius 1e\+80/);
    const body = world.createBody({ x: 0, y: 0 });
    const between = state(world);
    expect(() => world.addShape(body, { kind: 'circle', radius: 1, offsetX: 2e50 })).toThrow(/offsetX 2e\+50/);
    expect(state(world)).toEqual(between);
    world.destroyBody(body);
    expect(state(world)).toEqual(before);
    for (const h of world.handles()) expect(Number.isFinite(world.getBody(h).inertia)).toBe(true);
    // Without friction a circle stays on the circle route, where its disc's inertia is m r^2 / 2.
    const circles = new World();
    const big = circles.createCircle({ x: 0, y: 0, radius: 1e80, density: 1e-160 });
    expect(circles.route.route).toBe('circles');
    expect(circles.getBody(big).mass).toBeCloseTo(Math.PI, 12);
  });

  it('forces and impulses on a static body', () => {
    const { world } = populated();
    const wall = world.handles()[1];
    expect(() => world.applyForce(wall, 1, 0)).toThrow(/static: only dynamic bodies take a force, got \(1, 0\)/);
    expect(() => world.applyImpulse(wall, 0, 2)).toThrow(/static: only dynamic bodies take an impulse/);
  });

  it.each([
    [{ sleeping: 'yes' }, TypeError, 'sleeping', '"yes"'],
    [{ sleepSpeed: -1 }, RangeError, 'sleepSpeed', '-1'],
    [{ hitEventThreshold: NaN }, TypeError, 'hitEventThreshold', 'NaN'],
    [{ contactEvents: 1 }, TypeError, 'contactEvents', '1'],
  ])('World option %o', (options, kind, field, shown) => {
    expect(() => new World(options as never)).toThrow(kind);
    expect(() => new World(options as never)).toThrow(field);
    expect(() => new World(options as never)).toThrow(shown);
  });

  it.each([
    [{ mass: 5e-324 }, 'mass', '5e-324'],
    [{ mass: 1e-310 }, 'mass', '1e-310'],
    [{ mass: 1e-101 }, 'mass', '1e-101'],
    [{ mass: 1e101 }, 'mass', '1e+101'],
    [{ density: 5e-324 }, 'density', '5e-324'],
  ])('createCircle with a mass outside [1e-100, 1e100], whose steps could overflow: %o', (options, field, shown) => {
    rejects((w) => w.createCircle({ x: 20, y: 20, radius: 3, ...options }), RangeError, field, shown);
  });

  it('the tiniest mass the check passes (1e-100) still collides without NaN', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    world.createCircle({ x: 0, y: 0, radius: 5, vx: 10, mass: 1e-100 });
    world.createCircle({ x: 9, y: 0, radius: 5 });
    world.step(1 / 60);
    expect(Number.isFinite(world.kineticEnergy())).toBe(true);
  });

  it.each([
    ['10', TypeError, '"10"'],
    [Number.NaN, TypeError, 'NaN'],
    [-1, RangeError, '-1'],
    [2.5, RangeError, '2.5'],
    [2 ** 24 + 1, RangeError, String(2 ** 24 + 1)],
    [2 ** 40, RangeError, String(2 ** 40)],
  ])('reserve(%s)', (count, kind, shown) => {
    rejects((w) => w.reserve(count as number), kind, 'reserve count', shown);
  });

  it('a handle that is not a finite number is a TypeError, a string shown as a string', () => {
    rejects((w) => w.destroyBody('0' as never), TypeError, 'handle', '"0"');
    rejects((w) => w.destroySegment('0' as never), TypeError, 'segment handle', '"0"');
    rejects((w) => w.getCircle(Number.NaN), TypeError, 'handle', 'NaN');
    rejects((w) => w.setVelocity(Number.POSITIVE_INFINITY, 1, 1), TypeError, 'handle', 'Infinity');
    rejects((w) => w.getSegment(undefined as never), TypeError, 'segment handle', 'undefined');
  });

  it('options must be plain objects: a Map or inherited options are refused, not read in part', () => {
    expect(() => new World(new Map([['broadPhase', 'naive']]) as never)).toThrow(/World options must be a plain object, got a Map/);
    expect(() => new World(Object.create({ broadPhase: 'naive', gravity: { x: 0, y: 1 } }) as never)).toThrow(/World options must be a plain object/);
    rejects((w) => w.createCircle(Object.create({ x: 1, y: 1, radius: 1 }) as never), TypeError, 'circle options', 'plain object');
    expect(new World(Object.assign(Object.create(null), { gravity: { x: 0, y: 1 } })).bodyCount).toBe(0);
    expect(() => new World(null as never)).toThrow(/World options must be an object, got null/);
    expect(new World(undefined).bodyCount).toBe(0);
  });

  it('awake must be a boolean, a string shown as a string', () => {
    rejects((w, h) => w.setAwake(h, 'true' as never), TypeError, 'awake', '"true"');
  });

  it('an impulse or a force that would make a velocity or an acceleration exceed 1e100', () => {
    const world = new World({ bounds: { width: 100, height: 100 } });
    const light = world.createCircle({ x: 50, y: 50, radius: 1, mass: 0.5 });
    const other = world.createCircle({ x: 20, y: 50, radius: 1 });
    world.applyForce(light, 1e99, 0);
    const before = world.getCircle(light);
    const hash = world.stateHash();
    // 1e99 pending plus 1e100, over a mass of 0.5, is 2.2e100.
    expect(() => world.applyForce(light, 1e100, 0)).toThrow(/force \(1e\+100, 0\) on body 0 would make its acceleration exceed 1e\+100/);
    expect(() => world.applyImpulse(light, 0, -1e100)).toThrow(/impulse \(0, -1e\+100\) on body 0 would make its velocity \(0, -2e\+100\) exceed 1e\+100/);
    expect(world.getCircle(light)).toEqual(before);
    expect(world.stateHash()).toBe(hash);
    world.step(1 / 60);
    for (const h of [light, other]) {
      const c = world.getCircle(h);
      expect([c.x, c.y, c.vx, c.vy].every(Number.isFinite)).toBe(true);
    }
  });

  it('a velocity for a static body', () => {
    const { world } = populated();
    const wall = world.handles()[1];
    expect(() => world.setVelocity(wall, 1, 0)).toThrow(/static/);
  });

  it.each([12345, -1, 1.5, 2 ** 24 + 0])('unknown handle %s', (handle) => {
    rejects((w) => w.getCircle(handle), RangeError, 'handle', String(handle));
    rejects((w) => w.destroyBody(handle), RangeError, 'handle', String(handle));
    rejects((w) => w.setVelocity(handle, 1, 1), RangeError, 'handle', String(handle));
  });

  it('stale handle', () => {
    const { world, handle } = populated();
    world.destroyBody(handle);
    const before = snapshot(world);
    expect(() => world.getCircle(handle)).toThrow(RangeError);
    expect(() => world.getCircle(handle)).toThrow(/stale/);
    expect(() => world.destroyBody(handle)).toThrow(/stale/);
    expect(() => world.setType(handle, 'static')).toThrow(/stale/);
    expect(snapshot(world)).toEqual(before);
  });
});

describe('bad World options', () => {
  it.each([
    [{ gravity: { x: NaN, y: 0 } }, TypeError, 'gravity.x', 'NaN'],
    [{ gravity: { x: 0, y: Infinity } }, TypeError, 'gravity.y', 'Infinity'],
    [{ bounds: { width: 0, height: 10 } }, RangeError, 'bounds.width', '0'],
    [{ bounds: { width: 10, height: -5 } }, RangeError, 'bounds.height', '-5'],
    [{ bounds: { width: 10, height: NaN } }, TypeError, 'bounds.height', 'NaN'],
    [{ restitution: -0.1 }, RangeError, 'restitution', '-0.1'],
    [{ integrator: 'verlet' }, RangeError, 'integrator', 'verlet'],
    [{ broadphase: 'bvh' }, RangeError, 'broadphase', 'bvh'],
    [{ gravty: { x: 0, y: 1 } }, TypeError, 'gravty', 'gravty'],
    [{ positionCorrection: 0 }, RangeError, 'positionCorrection', '0'],
    [{ positionCorrection: 1.5 }, RangeError, 'positionCorrection', '1.5'],
    [{ positionCorrection: NaN }, TypeError, 'positionCorrection', 'NaN'],
    [{ contactSlop: -0.01 }, RangeError, 'contactSlop', '-0.01'],
    [{ contactSlop: '0.1' }, TypeError, 'contactSlop', '"0.1"'],
    [{ solverIterations: 0 }, RangeError, 'solverIterations', '0'],
    [{ solverIterations: 2.5 }, RangeError, 'solverIterations', '2.5'],
    [{ solverIterations: 65 }, RangeError, 'solverIterations', '65'],
  ])('%o', (options, kind, field, shown) => {
    expect(() => new World(options as never)).toThrow(kind);
    expect(() => new World(options as never)).toThrow(field);
    expect(() => new World(options as never)).toThrow(shown);
  });

  it('sensible defaults', () => {
    const world = new World();
    expect(world.broadphase).toBe('auto');
    expect(world.integrator).toBe('semi-implicit-euler');
    expect(world.gravity).toEqual({ x: 0, y: 0 });
    expect(world.restitution).toBe(1);
    expect(world.box).toBeNull();
    const h = world.createCircle({ x: 0, y: 0, radius: 2 });
    expect(world.getCircle(h)).toEqual({
      x: 0,
      y: 0,
      vx: 0,
      vy: 0,
      radius: 2,
      mass: Math.PI * 4,
      type: 'dynamic',
      restitution: 1,
      category: 1,
      mask: 0xffffffff,
      gravityScale: 1,
      linearDamping: 0,
      awake: true,
    });
  });
});
