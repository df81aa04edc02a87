import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { World } from '../src/index.js';
import { solvePointBlock } from '../src/solver/joints/joint-kernel.js';

/**
 * The public API, driven at random with numbers from ordinary to the largest a double holds:
 * every call either succeeds or throws a TypeError or RangeError, and whatever succeeds, no body
 * of the world ever holds a NaN or an infinity, and in a boxed world none ends a step outside
 * the box. Restitution up to its limit makes speeds grow at every bounce: they saturate.
 */

/** Ordinary values and extremes, both signs. */
const wide = fc.oneof(
  fc.double({ min: -100, max: 100, noNaN: true }),
  fc.constantFrom(0, 1e-300, 1e-100, 1e-50, 1e50, 1e99, 1e100, 1e101, 1e200, 1e308, Number.MAX_VALUE, -1e100, -1e308),
);
const positive = fc.oneof(fc.double({ min: 0.01, max: 20, noNaN: true }), fc.constantFrom(1e-100, 1e-101, 1e-50, 1e50, 1e100, 1e101, 1e300));
const restitution = fc.oneof(fc.double({ min: 0, max: 3, noNaN: true }), fc.constantFrom(0, 1, 2, 10, 1000, 1001, 1e300));
const dt = fc.constantFrom(1 / 60, 1e-9, 0.5, 10, 1e3, 1e6, 1e7, 1e307);

type Op =
  | { op: 'circle' | 'box' | 'capsule'; x: number; y: number; vx: number; vy: number; size: number; restitution: number; mass: number | null; spin: number; friction: number }
  | { op: 'velocity' | 'force' | 'impulse' | 'position'; body: number; x: number; y: number }
  | { op: 'spin' | 'torque' | 'angular'; body: number; value: number }
  | { op: 'gravity'; x: number; y: number }
  | { op: 'bare'; x: number; y: number }
  | { op: 'fixed'; body: number; fixed: boolean }
  | { op: 'shape'; body: number; size: number; density: number; offset: number }
  | { op: 'unshape'; body: number }
  | { op: 'step'; dt: number };

const opArbitrary: fc.Arbitrary<Op> = fc.oneof(
  fc.record({
    op: fc.constantFrom('circle' as const, 'box' as const, 'capsule' as const),
    x: fc.oneof(fc.double({ min: 5, max: 95, noNaN: true }), wide),
    y: fc.oneof(fc.double({ min: 5, max: 95, noNaN: true }), wide),
    vx: wide,
    vy: wide,
    size: positive,
    restitution,
    mass: fc.option(positive, { nil: null }),
    spin: wide,
    friction: fc.constantFrom(0, 0.5),
  }),
  fc.record({ op: fc.constantFrom('velocity' as const, 'force' as const, 'impulse' as const, 'position' as const), body: fc.nat(20), x: wide, y: wide }),
  fc.record({ op: fc.constantFrom('spin' as const, 'torque' as const, 'angular' as const), body: fc.nat(20), value: wide }),
  fc.record({ op: fc.constant('gravity' as const), x: wide, y: wide }),
  // Changes of a body's mass and inertia, between loads applied and the step that spends them.
  fc.record({ op: fc.constant('bare' as const), x: fc.double({ min: 5, max: 95, noNaN: true }), y: fc.double({ min: 5, max: 95, noNaN: true }) }),
  fc.record({ op: fc.constant('fixed' as const), body: fc.nat(20), fixed: fc.boolean() }),
  fc.record({ op: fc.constant('shape' as const), body: fc.nat(20), size: positive, density: positive, offset: fc.oneof(fc.constant(0), wide) }),
  fc.record({ op: fc.constant('unshape' as const), body: fc.nat(20) }),
  fc.record({ op: fc.constant('step' as const), dt }),
);

function apply(world: World, o: Op): void {
  const handles = world.handles();
  const pick = (k: number) => handles[k % Math.max(1, handles.length)];
  try {
    switch (o.op) {
      case 'circle':
        world.createCircle({ x: o.x, y: o.y, vx: o.vx, vy: o.vy, radius: o.size, restitution: o.restitution, ...(o.mass === null ? {} : { mass: o.mass }), friction: o.friction });
        break;
      case 'box':
        world.createBox({ x: o.x, y: o.y, vx: o.vx, vy: o.vy, width: o.size, height: o.size / 2 + 0.01, restitution: o.restitution, angularVelocity: o.spin, friction: o.friction, ...(o.mass === null ? {} : { mass: o.mass }) });
        break;
      case 'capsule':
        world.createCapsule({ x: o.x, y: o.y, vx: o.vx, vy: o.vy, length: o.size, radius: o.size / 3, restitution: o.restitution, angularVelocity: o.spin });
        break;
      case 'velocity':
        if (handles.length) world.setVelocity(pick(o.body), o.x, o.y);
        break;
      case 'force':
        if (handles.length) world.applyForce(pick(o.body), o.x, o.y);
        break;
      case 'impulse':
        if (handles.length) world.applyImpulse(pick(o.body), o.x, o.y);
        break;
      case 'position':
        if (handles.length) world.setPosition(pick(o.body), o.x, o.y);
        break;
      case 'spin':
        if (handles.length) world.setAngularVelocity(pick(o.body), o.value);
        break;
      case 'torque':
        if (handles.length) world.applyTorque(pick(o.body), o.value);
        break;
      case 'angular':
        if (handles.length) world.applyAngularImpulse(pick(o.body), o.value);
        break;
      case 'gravity':
        world.setGravity(o.x, o.y);
        break;
      case 'bare':
        world.createBody({ x: o.x, y: o.y });
        break;
      case 'fixed':
        if (handles.length) world.setFixedRotation(pick(o.body), o.fixed);
        break;
      case 'shape':
        if (handles.length) world.addShape(pick(o.body), { kind: 'box', width: o.size, height: o.size, density: o.density, offsetX: o.offset });
        break;
      case 'unshape':
        if (handles.length) {
          const shapes = world.getBody(pick(o.body)).shapes;
          if (shapes.length) world.destroyShape(shapes[0]);
        }
        break;
      case 'step':
        world.step(o.dt);
        break;
    }
  } catch (error) {
    // Refusals are the contract's other half: a TypeError or RangeError, nothing else.
    if (!(error instanceof TypeError || error instanceof RangeError)) throw error;
  }
}

function assertFinite(world: World, box: { width: number; height: number } | null, after: Op): void {
  const v = world.views();
  for (let k = 0; k < v.slotCount; k++) {
    if (v.type[k] === 0) continue;
    const values = [v.x[k], v.y[k], v.vx[k], v.vy[k]];
    if (v.c.length > 0) values.push(v.c[k], v.s[k], v.angularVelocity[k]);
    if (!values.every(Number.isFinite)) throw new Error(`slot ${k} holds ${values.join(', ')} after ${JSON.stringify(after)}`);
    if (box && after.op === 'step' && !(v.x[k] >= 0 && v.x[k] <= box.width && v.y[k] >= 0 && v.y[k] <= box.height)) {
      throw new Error(`slot ${k} at (${v.x[k]}, ${v.y[k]}) is outside the ${box.width} x ${box.height} box after ${JSON.stringify(after)}`);
    }
  }
}

describe('no NaN or infinity from finite input', () => {
  it('random calls with extreme numbers, in a box and in the open, circles and shapes, either solver', () => {
    fc.assert(
      fc.property(
        fc.boolean(),
        fc.constantFrom('auto' as const, 'elastic' as const, 'soft' as const),
        fc.array(opArbitrary, { minLength: 5, maxLength: 60 }),
        (boxed, solver, ops) => {
          const box = boxed ? { width: 100, height: 100 } : null;
          const world = new World({ bounds: box, solver, restitution: 1 });
          for (const o of ops) {
            apply(world, o);
            assertFinite(world, box, o);
          }
          // And onwards: whatever the calls left, stepping keeps it so.
          for (let s = 0; s < 60; s++) {
            world.step(1 / 60);
            assertFinite(world, box, { op: 'step', dt: 1 / 60 });
          }
        },
      ),
      { numRuns: 300, seed: 20261201 },
    );
  });

  it('loads applied, then the mass or inertia they act on changed, on a few bodies', () => {
    // Found by an audit: a torque applied to a body that did not turn (fixed, or without shapes)
    // reached infinity once it could, and a force on a body of mass 1 outlived its mass.
    const few = fc.nat(3);
    const load = fc.constantFrom(1, 1e50, 1e100, 1e200, 1e308);
    const ops: fc.Arbitrary<Op> = fc.oneof(
      fc.record({ op: fc.constant('bare' as const), x: fc.double({ min: 5, max: 95, noNaN: true }), y: fc.double({ min: 5, max: 95, noNaN: true }) }),
      fc.record({ op: fc.constant('fixed' as const), body: few, fixed: fc.boolean() }),
      fc.record({ op: fc.constant('shape' as const), body: few, size: fc.constantFrom(1e-45, 1e-20, 1, 10), density: fc.constantFrom(1e-50, 1, 1e50), offset: fc.constantFrom(0, 1, 1e20) }),
      fc.record({ op: fc.constant('unshape' as const), body: few }),
      fc.record({ op: fc.constant('torque' as const), body: few, value: load }),
      fc.record({ op: fc.constant('force' as const), body: few, x: load, y: fc.constant(0) }),
      fc.record({ op: fc.constant('step' as const), dt: fc.constant(1 / 60) }),
    );
    fc.assert(
      fc.property(fc.constantFrom('elastic' as const, 'soft' as const), fc.array(ops, { minLength: 5, maxLength: 30 }), (solver, list) => {
        const world = new World({ solver, gravity: { x: 0, y: 0 } });
        for (const o of list) {
          apply(world, o);
          assertFinite(world, null, o);
        }
        world.step(1 / 60);
        assertFinite(world, null, { op: 'step', dt: 1 / 60 });
      }),
      { numRuns: 300, seed: 20261204 },
    );
  });

  it("restitution above 1 saturates at the world's top speed rather than running to infinity", () => {
    const cases = [
      { options: {}, shapes: false, cap: 1e100 },
      { options: { maxLinearSpeed: 5000 }, shapes: false, cap: 5000 },
      // With shapes the default is Box2D's, 400 m/s at lengthUnit 1.
      { options: { solver: 'elastic' }, shapes: true, cap: 400 },
      { options: { solver: 'soft' }, shapes: true, cap: 400 },
    ] as const;
    for (const { options, shapes, cap } of cases) {
      const world = new World({ bounds: { width: 100, height: 100 }, restitution: 2, ...options });
      for (let i = 0; i < 50; i++) {
        const o = { x: 10 + (i % 10) * 8, y: 10 + Math.floor(i / 10) * 15, vx: 30 * ((i * 7) % 5) - 60, vy: 40 };
        if (shapes) world.createBox({ ...o, width: 3, height: 3 });
        else world.createCircle({ ...o, radius: 2 });
      }
      let fastest = 0;
      for (let s = 0; s < 2000; s++) {
        world.step(1 / 60);
        const v = world.views();
        for (let k = 0; k < v.slotCount; k++) fastest = Math.max(fastest, Math.hypot(v.vx[k], v.vy[k]));
        assertFinite(world, { width: 100, height: 100 }, { op: 'step', dt: 1 / 60 });
      }
      expect(fastest, JSON.stringify(options)).toBeGreaterThan(cap / 2);
      expect(fastest, JSON.stringify(options)).toBeLessThanOrEqual(cap * (1 + 1e-12));
    }
  });

  it('joints of every kind whose anchors lie as far as allowed, on the smallest, lightest and heaviest bodies, stay finite', () => {
    // Found by an audit: a wheel anchored 1e45 from a unit box, whose effective masses (prepared
    // from the lever arms at the step's start) went stale as the box turned, and a target joint
    // whose 2 x 2 determinant squared past the largest double.
    const kinds = ['distance', 'revolute', 'prismatic', 'weld', 'wheel', 'target'] as const;
    for (const kind of kinds) {
      for (const size of [1e-20, 1, 1e6]) {
        for (const mass of [1e-100, 1, 1e100]) {
          for (const far of [1e15, 1e45, 1e50]) {
            const world = new World({ gravity: { x: 0, y: 10 } });
            const a = world.createBox({ x: 0, y: 0, width: size, height: size, mass, angularVelocity: 1 });
            const b = world.createBox({ x: 2 * size, y: 0, width: size, height: size, mass });
            const anchor = { x: 0.6 * far, y: 0.8 * far };
            if (kind === 'target') world.createJoint({ kind, body: b, target: { x: 0, y: 0 }, anchor });
            else world.createJoint({ kind, bodyA: a, bodyB: b, anchorB: anchor });
            for (let s = 0; s < 20; s++) {
              world.step(1 / 60);
              try {
                assertFinite(world, null, { op: 'step', dt: 1 / 60 });
              } catch (e) {
                throw new Error(`${kind} joint, bodies ${size} wide of mass ${mass}, anchor ${far} out, step ${s + 1}: ${(e as Error).message}`);
              }
            }
          }
        }
      }
    }
  });

  it('a body spun at up to 1e100 rad/s between steps enters the soft step at its angular limit, joints and all', () => {
    // Found by the audit: two boxes 1e-20 wide on a wheel joint, one spun at 1e100, whose spin
    // the joint's first impulses grew past the largest double before the sub-step capped it.
    for (const kind of ['wheel', 'revolute', 'prismatic', 'weld'] as const) {
      for (const spin of [1e3, 1e50, 1e100]) {
        const world = new World();
        const a = world.createBox({ x: 0, y: 0, width: 1e-20, height: 1e-20, mass: 1, angularVelocity: spin });
        const b = world.createBox({ x: 2e-20, y: 0, width: 1e-20, height: 1e-20, mass: 1 });
        world.createJoint({ kind, bodyA: a, bodyB: b });
        for (let s = 0; s < 10; s++) {
          world.step(1 / 60);
          try {
            assertFinite(world, null, { op: 'step', dt: 1 / 60 });
          } catch (e) {
            throw new Error(`${kind} joint, spin ${spin}, step ${s + 1}: ${(e as Error).message}`);
          }
        }
      }
    }
  });

  it('joints between bodies far smaller than the distance they travel in a step stay finite', () => {
    // Found by an audit: bodies 1e-10 wide on a wheel joint, parting at 1000 m/s, 64 sub-steps.
    // Their arms grow 1e9 times within the step, past the effective mass prepared at its start.
    for (const kind of ['wheel', 'prismatic', 'revolute', 'weld', 'distance'] as const) {
      for (const size of [1e-17, 1e-10, 1e-6]) {
        for (const substeps of [4, 64]) {
          for (const bullet of [false, true]) {
            const world = new World({ substeps });
            const a = world.createCircle({ x: 0, y: 0, radius: size, friction: 0.5 });
            const b = world.createBox({ x: 3 * size, y: size, width: size / 4, height: size / 4, vy: 1000, bullet });
            world.createJoint({ kind, bodyA: a, bodyB: b });
            for (const dt of [1 / 60, 1 / 60, 1e6]) {
              world.step(dt);
              try {
                assertFinite(world, null, { op: 'step', dt });
              } catch (e) {
                throw new Error(`${kind}, size ${size}, ${substeps} sub-steps${bullet ? ', bullet' : ''}: ${(e as Error).message}`);
              }
            }
          }
        }
      }
    }
  });

  it('sliding joints whose bodies travel far along the axis within a step stay finite, even at a speed limit of 1e100', () => {
    // A unit box and disc on a wheel joint sliding at 1 m/s along its axis at dt 1e6 (or bodies
    // 1e-10 wide at 60 Hz), in a world whose speed limit is 1e100: the arm across the axis grows a
    // millionfold within the step, and a mass prepared at its start, with the bodies held only
    // within limits that high, lets the solve double past the largest double.
    let cases = 0;
    for (const kind of ['wheel', 'prismatic'] as const) {
      for (const size of [1e-10, 1]) {
        for (const speed of [1, 1e3, 1e10]) {
          for (const along of [true, false]) {
            const world = new World({ maxLinearSpeed: 1e100, gravity: { x: 0, y: 10 } });
            const a = world.createBox({ x: 0, y: 0, width: size, height: size });
            const b = world.createCircle({ x: 0, y: 2 * size, radius: size / 2, friction: 0.5, vx: along ? speed : 0, vy: along ? 0 : speed });
            world.createJoint({ kind, bodyA: a, bodyB: b });
            for (const dt of [1 / 60, 1 / 60, 1e6, 1e6]) {
              world.step(dt);
              try {
                assertFinite(world, null, { op: 'step', dt });
              } catch (e) {
                throw new Error(`${kind}, size ${size}, speed ${speed} ${along ? 'along' : 'across'}: ${(e as Error).message}`);
              }
            }
            cases++;
          }
        }
      }
    }
    expect(cases).toBe(24);
  });

  it('joints at the extremes an audit found: limits between bodies far apart or at 1e100 m/s, far anchors on tiny bodies, stiff springs at dt 1e-100', () => {
    // Each case is accepted input that took a state to NaN: a joint's solve pushes in stages whose
    // spins cancel exactly in theory and by some 1e-16 x impulse x arm in doubles, which the next
    // stage multiplies (limits, blocks); a limit's kept impulse fed by that growth within a step;
    // and an impulse times a far arm overflowing before it met a body's inverse inertia of 0.
    type Case = [string, () => { world: World; dt: number; steps: number }];
    const box = (world: World, x: number, y: number, width: number, more: Record<string, unknown> = {}): number => world.createBox({ x, y, width, height: width / 2, ...more });
    const cases: Case[] = [];
    // The speed limit given, or made from the largest length unit.
    for (const [limit, options] of [['speed limit 1e100', { maxLinearSpeed: 1e100 }], ['length unit 1e100', { lengthUnit: 1e100 }], ['length unit 2.5e98', { lengthUnit: 2.5e98 }]] as const) {
      for (const kind of ['prismatic', 'wheel'] as const) {
        cases.push([`${kind} limits, unit boxes at 1e100 m/s, ${limit}`, () => {
          const world = new World({ ...options, gravity: { x: 0, y: 10 } });
          const a = world.createBox({ x: 0, y: 0, width: 1, height: 1, vx: 1e100 });
          const b = world.createBox({ x: 3, y: 0, width: 1, height: 1, vy: -1e100 });
          world.createJoint({ kind, bodyA: a, bodyB: b, lowerTranslation: -1, upperTranslation: 1 });
          return { world, dt: 1 / 60, steps: 5 };
        }]);
      }
    }
    for (const [bx, by] of [[1e99, 0], [0, 1e99]]) {
      cases.push([`prismatic limits, unit boxes, B at (${bx}, ${by}) off A's turned axis`, () => {
        const world = new World({ gravity: { x: 0, y: 10 } });
        const a = box(world, 0, 0, 1, { angle: 0.1 });
        const b = box(world, bx, by, 1);
        world.createJoint({ kind: 'prismatic', bodyA: a, bodyB: b, lowerTranslation: -1, upperTranslation: 1 });
        return { world, dt: 1 / 60, steps: 30 };
      }]);
    }
    cases.push(['revolute limits, a 1e-20 box pinned 1e20 out', () => {
      const world = new World({ gravity: { x: 0, y: 10 } });
      const a = box(world, 0, 0, 1);
      const b = box(world, 0, 0, 1e-20);
      world.createJoint({ kind: 'revolute', bodyA: a, bodyB: b, anchorB: { x: 1e20, y: 0 }, lowerAngle: -0.5, upperAngle: 0.5 });
      return { world, dt: 1 / 60, steps: 30 };
    }]);
    cases.push(['revolute lower limit, a light 1e6 box pinned 7e49 out, a tiny fixed-rotation box', () => {
      const world = new World();
      const a = box(world, 0, 0, 1e6, { angle: 0.5, density: 1e-100 });
      const b = box(world, 0, 0, 1e-20, { fixedRotation: true });
      world.createJoint({ kind: 'revolute', bodyA: a, bodyB: b, anchorA: { x: 7e49, y: 0 }, lowerAngle: -1 });
      return { world, dt: 1 / 60, steps: 10 };
    }]);
    cases.push(['revolute upper limit and a motor of 1e100 rad/s, a tiny box 1e40 out, 64 sub-steps', () => {
      const world = new World({ substeps: 64 });
      const bare = world.createBody({ x: 0, y: 0 });
      const tiny = box(world, 0, 0, 1e-20);
      const joint = world.createJoint({ kind: 'revolute', bodyA: bare, bodyB: tiny, anchorB: { x: 0, y: 1e40 }, upperAngle: 1 });
      world.setJointMotor(joint, 1e100, 1e10);
      return { world, dt: 1 / 60, steps: 30 };
    }]);
    for (const kind of ['wheel', 'prismatic'] as const) {
      cases.push([`${kind} spring of 1e100 Hz from a static box to a fixed-rotation one 1e99 away, dt 1e-100`, () => {
        const world = new World({ substeps: 1 });
        const ground = world.createBox({ x: 0, y: 0, width: 1, height: 1, type: 'static' });
        const body = world.createBox({ x: 1e99, y: 0, width: 1, height: 1, mass: 1e50, fixedRotation: true });
        world.createJoint({ kind, bodyA: ground, bodyB: body, axis: { x: 1, y: 1 }, hertz: 1e100 });
        return { world, dt: 1e-100, steps: 3 };
      }]);
    }
    cases.push(['distance spring of 1e100 Hz to a kinematic body anchored 1e40 out, dt 1e-100', () => {
      const world = new World({ substeps: 1 });
      const k = world.createBody({ x: 0, y: -1e99, type: 'kinematic' });
      const a = box(world, 0, 0, 1e50);
      world.createJoint({ kind: 'distance', bodyA: a, bodyB: k, anchorB: { x: 0, y: 1e40 }, hertz: 1e100, dampingRatio: 0 });
      world.setTransform(a, 1e30, -1e99, 0);
      return { world, dt: 1e-100, steps: 3 };
    }]);
    cases.push(['weld springs of 1e100 Hz to a kinematic box anchored 1e50 out, dt 1e-100', () => {
      const world = new World({ substeps: 1 });
      const k = box(world, 0, 0, 1e-20, { type: 'kinematic' });
      const d = box(world, 0, 0, 1e-20, { density: 1e100 });
      world.createJoint({ kind: 'weld', bodyA: d, bodyB: k, anchorB: { x: 1e50, y: 0 }, linearHertz: 1e100, angularHertz: 1e100 });
      world.setTransform(k, 0, 1e99, 0);
      return { world, dt: 1e-100, steps: 3 };
    }]);
    // A joint that cannot be met takes more impulse every sub-step, which the step's bound on its
    // kept impulses met only at the next step: 64 sub-steps of a long step outgrew the doubles.
    cases.push(['wheel joint between circles a box was pushed through at 1000 m/s, dt 1000 s in 64 sub-steps', () => {
      const world = new World({ substeps: 64 });
      const a = world.createCircle({ x: 1, y: 1, radius: 2 });
      world.createBox({ x: 1, y: 1, vx: -1000, width: 2, height: 2 });
      const b = world.createCircle({ x: 0, y: 1, radius: 5 });
      world.createJoint({ kind: 'wheel', bodyA: b, bodyB: a });
      return { world, dt: 1000, steps: 3 };
    }]);
    cases.push(['prismatic limits from a heavy circle to a fixed-rotation capsule 1e100 away, a step of 1/60 s then of 1e-100 s', () => {
      const world = new World();
      const a = world.createCapsule({ x: -1e100, y: 0, angle: -0.3, fixedRotation: true, length: 1e10, radius: 5 });
      const b = world.createCircle({ x: 0, y: 0, mass: 1e94, radius: 1 });
      world.createJoint({ kind: 'prismatic', bodyA: b, bodyB: a, lowerTranslation: -1e30, upperTranslation: 1e30 });
      world.step(1 / 60);
      return { world, dt: 1e-100, steps: 2 };
    }]);
    // The angular limit, pi / 4 a step, is 8e99 rad/s at dt 1e-100: the box turned that fast
    // about an arm of 1e99 moved its end at 1e199 m/s, whose products overflowed.
    for (const kind of ['prismatic', 'wheel'] as const) {
      cases.push([`${kind} limits from a box 1e30 tall to a circle of radius 1e10 1e99 away, dt 1e-100`, () => {
        const world = new World({ gravity: { x: 0, y: 10 } });
        const a = world.createBox({ x: 0, y: 0, width: 1, height: 1e30 });
        const b = world.createBody({ x: -1e99, y: 1e99 });
        world.addShape(b, { kind: 'circle', radius: 1e10 });
        world.createJoint({ kind, bodyA: a, bodyB: b, axis: { x: 1, y: 0.8 }, lowerTranslation: -1, upperTranslation: 1 });
        return { world, dt: 1e-100, steps: 5 };
      }]);
    }
    // Bodies that part by many times a joint's arms within a step leave its masses, prepared at
    // the step's start, far too small: each pass overshot, and the spins grew to 1e173 (random
    // scenes an audit reduced).
    cases.push(['wheel joint from a pentagon 1e5 times lighter than the triangle 3 m away, in a box, at 400 m/s, dt 0.5', () => {
      const world = new World({ gravity: { x: -257.7511064296542, y: 0.9955533071030347 }, substeps: 8, bounds: { width: 8.299109959700607, height: 6.034432445376843 } });
      const tri = world.createPolygon({ x: 1.1966880296225235, y: 5.369402324259228, density: 103.5104363204893, vertices: [{ x: 0.23647625704019873, y: 0 }, { x: -0.11823812852009931, y: 0.20479444598867083 }, { x: -0.11823812852009948, y: -0.20479444598867078 }] });
      world.createCapsule({ x: 5.361494086366298, y: 4.260298894008914, density: 0.10372897081770349, length: 0.18208059152895525, radius: 0.19211913862310145 });
      const pent = world.createPolygon({ x: 2.2282483922308574, y: 2.09347747248169, density: 0.001136238648957886, vertices: [{ x: 0.12473026512296062, y: 0 }, { x: 0.038543771635887625, y: 0.11862553142441382 }, { x: -0.10090890419736792, y: 0.07331461035380649 }, { x: -0.10090890419736794, y: -0.07331461035380646 }, { x: 0.0385437716358876, y: -0.11862553142441383 }] });
      world.createJoint({ kind: 'wheel', bodyA: pent, bodyB: tri, axis: { x: 1, y: 0 } });
      return { world, dt: 0.5, steps: 80 };
    }]);
    cases.push(['weld from a falling disc of radius 8.6 to a dense capsule 14 m away, dt 0.5', () => {
      const world = new World({ gravity: { x: -10.614644782163928, y: 2679.8484129084904 }, substeps: 3 });
      world.createBox({ x: 0, y: 50, width: 1000, height: 0.0020777730956649232, angle: 0.22455595689825714, type: 'static' });
      const comp = world.createBody({ x: 7.207106113433838, y: 18.659679174423218 });
      world.addShape(comp, { kind: 'box', width: 0.018125852950698226, height: 0.006041950983566076, density: 733.6586119585365 });
      world.addShape(comp, { kind: 'circle', radius: 0.004531463237674557, offsetX: 0.018125852950698226, density: 7336.586119585365 });
      const disc = world.createCircle({ x: -28.72640287876129, y: -28.93107257783413, vy: 163.7221378015603, radius: 8.604815067638446, density: 0.4051253137215061 });
      const cap = world.createCapsule({ x: -20.523844242095947, y: -18.448599264025688, angle: 4.184595297090709, density: 105.85117806600259, length: 0.034943928249941816, radius: 0.0068379478274889285 });
      world.createJoint({ kind: 'weld', bodyA: disc, bodyB: cap });
      return { world, dt: 0.5, steps: 90 };
    }]);
    // A turn about the anchors cancels all but a sliver of its moment on a body whose anchor
    // lies far out in its radii of gyration; from stale arms, or past the rounding of that
    // sliver, the rest became spin, times the body's inverse inertia, at every pass.
    const farTriangle = (world: World): { a: number; b: number } => {
      world.createSegment({ x1: -100, y1: 40, x2: 100, y2: 54.91781225427985 });
      const a = world.createBox({ x: 15.224012464284897, y: -31.467947781085968, vx: -90.61039591321267, density: 0.04692824269397097, width: 5.2103036811562236, height: 5.2103036811562236, fixedRotation: true });
      const b = world.createPolygon({ x: -7.2236936539411545, y: 7.611932754516602, density: 0.36597856004459495, vertices: [{ x: 0.009452442465962184, y: 0 }, { x: -0.00472622123298109, y: 0.008186055303334076 }, { x: -0.004726221232981096, y: -0.008186055303334074 }] });
      return { a, b };
    };
    const sideways = { gravity: { x: -49.46211126664351, y: 2.2736003653923738 } };
    cases.push(['weld from a fast fixed-rotation box to a 9 mm triangle 42 m away (its anchor there)', () => {
      const world = new World(sideways);
      const { a, b } = farTriangle(world);
      world.createJoint({ kind: 'weld', bodyA: a, bodyB: b });
      return { world, dt: 1 / 60, steps: 160 };
    }]);
    for (const extra of [{ hertz: 5, dampingRatio: 0.5 }, { hertz: 30, dampingRatio: 0, lowerAngle: -0.1, upperAngle: 0.1 }]) {
      cases.push([`revolute ${JSON.stringify(extra)} from a fast box to a 9 mm triangle pinned 36 m out`, () => {
        const world = new World(sideways);
        const { a, b } = farTriangle(world);
        world.createJoint({ kind: 'revolute', bodyA: a, bodyB: b, anchorB: { x: 30, y: -20 }, ...extra });
        return { world, dt: 1 / 60, steps: 200 };
      }]);
    }
    cases.push(['weld from a fixed-rotation box to a 0.1 m square 17 m away, dt 0.5', () => {
      const world = new World({ gravity: { x: -0.22408902389865837, y: 374.3936611589853 } });
      world.createBox({ x: 0, y: 50, width: 1000, height: 0.06836111497904208, angle: -0.051757088396698236, type: 'static' });
      const a = world.createBox({ x: -25.048397049307823, y: -5.959696918725967, vx: -0.17385163783952645, vy: 1.3436166697991416, density: 1.6579984295395014, width: 0.2586023145313202, height: 0.2586023145313202, fixedRotation: true });
      const b = world.createPolygon({ x: -10.243190243840218, y: 3.118634968996048, vx: 3.8666336913323676, vy: 27.20025772033676, density: 0.8709426789069494, vertices: [{ x: 0.1064073018143574, y: 0 }, { x: 0, y: 0.1064073018143574 }, { x: -0.1064073018143574, y: 0 }, { x: 0, y: -0.1064073018143574 }] });
      world.createJoint({ kind: 'weld', bodyA: a, bodyB: b });
      return { world, dt: 0.5, steps: 110 };
    }]);
    cases.push(['weld from a heavy box to a capsule of radius 5 mm 24 m away, under strong gravity', () => {
      const world = new World({ gravity: { x: 1696.735201735466, y: 6886.905098091116 } });
      world.createBox({ x: 0, y: 50, width: 1000, height: 0.8555292270099888, type: 'static' });
      const a = world.createBox({ x: 4.913905307650566, y: -14.329296290874481, density: 203.35838932994534, width: 3.77993622794688, height: 3.77993622794688 });
      const b = world.createCapsule({ x: 25.09827594459057, y: -2.635045439004898, density: 55.714052758744174, length: 0.11417580154612651, radius: 0.005226003196267073 });
      world.createJoint({ kind: 'weld', bodyA: a, bodyB: b });
      return { world, dt: 1 / 60, steps: 60 };
    }]);
    const failures: string[] = [];
    for (const [label, make] of cases) {
      const { world, dt, steps } = make();
      try {
        for (let s = 0; s < steps; s++) {
          world.step(dt);
          assertFinite(world, null, { op: 'step', dt });
        }
      } catch (e) {
        failures.push(`${label}: ${(e as Error).message}`);
      }
    }
    expect(failures).toEqual([]);
    // Beyond the largest length unit, refused by name.
    expect(() => new World({ lengthUnit: 1e101 })).toThrow(/lengthUnit must be within \[1e-100, 1e\+100\].*got 1e\+101/);
  });

  it('a weld to a compound whose only shape lies 8e48 out, beside a box of mass 1e100, under the strongest gravity, stays finite', () => {
    // The contacts with the heavy box spin the light triangle at 4e115 rad/s within a sub-step,
    // and the weld's point block, its arm 8e48 on a body of inverse inertia 8e49, cancels its
    // determinant to rounding and overflows its products in plain arithmetic: NaN in step 1 (or a
    // WebAssembly RuntimeError from the bullet's sweep).
    for (const bullet of [false, true]) {
      const world = new World({ gravity: { x: 0, y: -1e100 } });
      const far = world.createBody({ x: 4.317941863245435e-11, y: -4.184170418324387e-11 });
      world.addShape(far, { kind: 'circle', radius: 2.955711058696059e-13, offsetY: 8.250149618834257e48 });
      world.createBox({ x: -3.4068756211340295e-11, y: 4.779623681993694e-11, width: 1.5749527373103433e-11, height: 1.5749527373103433e-21, radius: 7.87476211159898e-22, mass: 1e100 });
      world.createBox({ x: -2.0518031841080043e-11, y: 9.005331008726474e-12, width: 3.269208764504487e-11, height: 1.6346043822522436e-11, radius: 8.009561473035993e-12, bullet });
      const triangle = world.createPolygon({
        x: 2.753038369399871e-11,
        y: 2.6237214520848365e-12,
        vertices: [
          { x: 1.5968586230633747e-10, y: 1.2982890795470924e-12 },
          { x: -1.0400130337689856e-10, y: 6.06012494395973e-11 },
          { x: -5.04879160983461e-11, y: -7.575831170027027e-11 },
        ],
      });
      world.createJoint({ kind: 'weld', bodyA: triangle, bodyB: far });
      for (const dt of [1e6, 1e6, 1 / 60]) {
        world.step(dt);
        assertFinite(world, null, { op: 'step', dt });
      }
    }
  });

  it("a point block of far arms is solved from its determinant's positive terms, as its eigen-decomposition gives", () => {
    // K = m I + iB |rB|^2 u u^T with u the arm turned a quarter, unit: K^-1 c = (c.u) u / (m + iB |rB|^2) + (c - (c.u) u) / m.
    // Speeds c with a part along the arm as well, whose answer dominates (a speed nearly across the
    // arm leaves that part to rounding in either computation).
    const cases = [
      { m: 3.6435620864491504e24, iB: 8.341270726441998e49, rBx: 1.5895615633113394e48, rBy: -8.095570564796173e48, cx: 1e164, cy: 1e164 },
      { m: 1, iB: 1, rBx: 1e6, rBy: 3e6, cx: 1, cy: -2 },
      { m: 1e-20, iB: 1e40, rBx: -1e45, rBy: 2e44, cx: 1e30, cy: 3e29 },
      { m: 2, iB: 0.5, rBx: 0.3, rBy: -0.4, cx: 1e-3, cy: 5 },
    ];
    for (const { m, iB, rBx, rBy, cx, cy } of cases) {
      const length = Math.hypot(rBx, rBy);
      const ux = -rBy / length;
      const uy = rBx / length;
      const along = cx * ux + cy * uy;
      const stiff = along / (m + iB * length * length);
      const ex = stiff * ux + (cx - along * ux) / m;
      const ey = stiff * uy + (cy - along * uy) / m;
      const b = solvePointBlock(m, 0, 0, 0, iB, rBx, rBy, cx, cy);
      const size = Math.hypot(ex, ey);
      expect(Math.hypot(b[0] - ex, b[1] - ey)).toBeLessThan(1e-9 * size);
    }
  });

  it('a gravity scale times gravity beyond 1e100 is refused by name wherever either is set, the world unchanged', () => {
    // Found by an audit: each within its bound, 1e100 times 1e100 made NaN at dt 1e6.
    const world = new World({ gravity: { x: 0, y: -1e100 } });
    const body = world.createBox({ x: 0, y: 0, width: 1, height: 1 });
    const hash = world.stateHash();
    expect(() => world.createBox({ x: 3, y: 0, width: 1, height: 1, gravityScale: 1e100 })).toThrow(/gravityScale 1e\+100 times gravity/);
    expect(() => world.createCircle({ x: 3, y: 0, radius: 1, gravityScale: -2 })).toThrow(RangeError);
    expect(() => world.createBody({ x: 3, y: 0, gravityScale: 2 })).toThrow(RangeError);
    expect(() => world.setGravityScale(body, 1.5)).toThrow(/gravityScale 1\.5 times gravity/);
    world.setGravityScale(body, 0.5);
    world.setGravity(0, -1e99);
    expect(() => world.setGravityScale(body, 11)).toThrow(RangeError);
    world.setGravityScale(body, 5);
    expect(() => world.setGravity(0, 1e100)).toThrow(/gravity \(0, 1e\+100\) times a body's gravityScale 5/);
    expect(world.getBody(body).gravityScale).toBe(5);
    world.setGravityScale(body, 1);
    world.setGravity(0, -1e100);
    expect(world.bodyCount).toBe(1);
    expect(world.stateHash()).toBe(hash);
    // At the bound, stepping at the longest step stays finite.
    world.setGravityScale(body, -1);
    for (const dt of [1e6, 1e6, 1 / 60]) {
      world.step(dt);
      assertFinite(world, null, { op: 'step', dt });
    }
  });

  it.each([0, 1e-300, 1e-310, 5e-324])('shapeless bodies all at or next to one point (%s; radius 0, no margin) step and answer queries on every broad-phase', (at) => {
    // Found by audits: cells of size 0 made the grid NaN columns wide, and its kernel divided by
    // zero; so did cells a few ulps of 1e-300 wide (padded for coordinates that small), whose inverse
    // overflows, at every later step too.
    for (const broadphase of ['maxgrid', 'hgrid', 'auto', 'naive'] as const) {
      for (const bounds of [null, { width: 10, height: 10 }]) {
        const world = new World({ solver: 'elastic', broadphase, bounds });
        for (let k = 0; k < 3; k++) world.createBody({ x: at, y: k === 1 ? at : 0, bullet: k === 2 });
        for (let s = 0; s < 3; s++) {
          world.step(1 / 60);
          assertFinite(world, bounds, { op: 'step', dt: 1 / 60 });
        }
        expect(world.queryPoint(0, 0)).toBeInstanceOf(Array);
        world.queryAABB(-1, -1, 1, 1);
        world.rayCast(-1, -1, 1, 1);
      }
    }
  });

  it('a tiny dense polygon whose inertia rounds to a subnormal steps finite on the ground', () => {
    // Found by an audit: its inertia came out 1e-323, and 1 / that is infinite.
    const world = new World({ gravity: { x: 0, y: 10 } });
    const tiny = world.createPolygon({ x: 0, y: 0, density: 1e100, vertices: [{ x: 2e-100, y: 0 }, { x: -1e-100, y: 1.7320508075688774e-100 }, { x: 0, y: -1.7320508075688768e-97 }] });
    world.createBox({ x: 0, y: 0.5, width: 2, height: 1, type: 'static' });
    expect(world.getBody(tiny).inertia).toBeLessThan(1e-300);
    for (let s = 0; s < 30; s++) {
      world.step(1 / 60);
      assertFinite(world, null, { op: 'step', dt: 1 / 60 });
    }
  });

  it('a step shorter than 1e-100 s (but 0) is refused by name, the world unchanged; springs stay finite at 1e-100', () => {
    // Found by an audit: a spring's bias rate is 1 / its sub-step, infinite below 1 / DBL_MAX, and a
    // step that rounded a sub-step to 0 made damped springs and target joints 0 / 0.
    for (const substeps of [1, 64]) {
      const world = new World({ substeps });
      const ground = world.createBox({ x: 0, y: 5, width: 20, height: 1, type: 'static' });
      const a = world.createBox({ x: 0, y: 0, width: 1, height: 1 });
      const b = world.createBox({ x: 2, y: 0, width: 1, height: 1 });
      const c = world.createBox({ x: 4, y: 0, width: 1, height: 1 });
      world.createJoint({ kind: 'distance', bodyA: a, bodyB: b, hertz: 5 });
      world.createJoint({ kind: 'distance', bodyA: a, bodyB: c, hertz: 5, dampingRatio: 0.5 });
      world.createJoint({ kind: 'revolute', bodyA: ground, bodyB: a, anchorA: { x: 0, y: -5 }, hertz: 5, lowerAngle: -1, upperAngle: 1 });
      world.createJoint({ kind: 'wheel', bodyA: b, bodyB: c });
      world.createJoint({ kind: 'weld', bodyA: ground, bodyB: c, linearHertz: 3, angularHertz: 2 });
      world.createJoint({ kind: 'target', body: b, target: { x: 3, y: 1 } });
      const before = world.snapshot();
      for (const dt of [1e-101, 1e-307, 1e-310, 5e-324]) {
        expect(() => world.step(dt)).toThrow(new RangeError(`dt must be 0 or at least 1e-100 s (so that a step cannot overflow), got ${dt}`));
      }
      expect(Buffer.from(world.snapshot()).equals(Buffer.from(before))).toBe(true);
      for (const dt of [0, 1e-100, 1e-60, 1e-20]) {
        for (let s = 0; s < 3; s++) {
          world.step(dt);
          assertFinite(world, null, { op: 'step', dt });
        }
      }
    }
  });

  it('a joint anchor farther from its body than a shape may reach (1e50) is refused by name, the world unchanged', () => {
    const world = new World();
    const a = world.createBox({ x: 0, y: 0, width: 1, height: 1 });
    const b = world.createBox({ x: 2, y: 0, width: 1, height: 1 });
    const before = world.snapshot();
    const far = { x: 0, y: 2e50 };
    expect(() => world.createJoint({ kind: 'revolute', bodyA: a, bodyB: b, anchorA: far })).toThrow(/anchorA \(0, 2e\+50\) lies 2e\+50 from its body's origin, beyond 1e\+50/);
    expect(() => world.createJoint({ kind: 'wheel', bodyA: a, bodyB: b, anchorB: far })).toThrow(RangeError);
    expect(() => world.createJoint({ kind: 'target', body: b, target: { x: 0, y: 0 }, anchor: far })).toThrow(/^anchor \(0, 2e\+50\)/);
    expect(Buffer.from(world.snapshot()).equals(Buffer.from(before))).toBe(true);
    // A weld's anchor left out is the other's point in its body: far off where the bodies are far apart.
    const distant = world.createBox({ x: 1e60, y: 0, width: 1, height: 1 });
    const withDistant = world.snapshot();
    expect(() => world.createJoint({ kind: 'weld', bodyA: a, bodyB: distant })).toThrow(/anchorB \(anchorA's point in body B\) \(-1e\+60, 0\)/);
    expect(Buffer.from(world.snapshot()).equals(Buffer.from(withDistant))).toBe(true);
    expect(world.jointCount).toBe(0);
  });

  it('a velocity set above the speed limit between steps is capped before the solve, where a long lever arm would grow it', () => {
    for (const dt of [1 / 60, 1, 1e6]) {
      // Found by the random calls above: a small circle inside a vast one that moves at 1e100.
      const world = new World({ restitution: 0 });
      world.createCircle({ x: 5, y: 5, radius: 0.10816306050644718, mass: 0.051303625256859234 });
      world.createCircle({ x: 24.900679227530844, y: 36.49328857177978, vx: -1e100, radius: 1e50, mass: 16.42229057277295, friction: 0.5 });
      for (let s = 0; s < 5; s++) {
        world.step(dt);
        try {
          assertFinite(world, null, { op: 'step', dt });
        } catch (e) {
          throw new Error(`dt ${dt}, step ${s + 1}: ${(e as Error).message}`);
        }
      }
    }
  });

  it('a spring too stiff for the step, on the lightest body allowed, beside a rigid joint, stays finite under every integrator', () => {
    for (const integrator of ['semi-implicit-euler', 'explicit-euler', 'rk4'] as const) {
      for (const kind of ['weld', 'revolute', 'prismatic', 'wheel', 'distance'] as const) {
        for (const dt of [1 / 60, 1e5]) {
          const world = new World({ integrator, gravity: { x: 0, y: 10 } });
          const a = world.createBox({ x: 0, y: 0, width: 1, height: 1, density: 1e-99 });
          const b = world.createBox({ x: 2, y: 0, width: 1, height: 1 });
          world.createJoint({ kind: 'spring', bodyA: a, bodyB: b, stiffness: 1e100, length: 0 });
          world.createJoint({ kind, bodyA: a, bodyB: b });
          for (let s = 0; s < 20; s++) {
            world.step(dt);
            try {
              assertFinite(world, null, { op: 'step', dt });
            } catch (e) {
              throw new Error(`${integrator}, spring and ${kind} joint, dt ${dt}, step ${s + 1}: ${(e as Error).message}`);
            }
          }
        }
      }
    }
  });

  it('a small body deep inside a vast spinning one, heavy or light, stays finite: its contact arm is bounded in radii of gyration', () => {
    // Found by an audit: a 1 x 0.001 box of mass 1e100 1e47 deep in a spinning box 1e49 wide. The
    // contact's midpoint lies half the depth from the small body's centre, and the rounding of
    // the spin its impulses give there grew from point to point to NaN within one pass.
    // Both solvers: a default world of shapes without gravity or friction takes the elastic pass.
    const meetings = (solver: 'soft' | 'elastic'): number => {
      let cases = 0;
      for (const size of [1e20, 1e35, 1e49]) {
        for (const massBig of [1, 1e50, 1e100]) {
          for (const massSmall of [1e-100, 1, 1e100]) {
            for (const kind of ['box', 'capsule'] as const) {
              for (const depth of [0.02, 0.1, 0.3]) {
                const world = new World({ solver });
                const big = world.createBox({ x: 0.06 * size, y: (depth - 0.5) * size, width: size, height: size, mass: massBig, angularVelocity: 1 });
                kind === 'box' ? world.createBox({ x: 0, y: 0, width: 1, height: 0.001, mass: massSmall }) : world.createCapsule({ x: 0, y: 0, length: 1, radius: 0.001, mass: massSmall });
                for (const dt of [1, 1 / 60, 1 / 60, 1 / 60]) {
                  world.step(dt);
                  try {
                    assertFinite(world, null, { op: 'step', dt });
                  } catch (e) {
                    throw new Error(`${solver}: ${kind} of mass ${massSmall} at depth ${depth} in a box ${size} wide of mass ${massBig}: ${(e as Error).message}`);
                  }
                }
                if (world.stats.contacts > 0) cases++;
                expect(world.getBody(big).angle).not.toBe(0);
              }
            }
          }
        }
      }
      return cases;
    };
    // The worlds above meet: the guard is exercised, not stepped around.
    expect(meetings('soft')).toBeGreaterThan(100);
    expect(meetings('elastic')).toBeGreaterThan(20);
  });

  it('a capsule offset so far from its body origin that its core rounds to a point has the mass of the disc it collides as, finite', () => {
    for (const offset of [1e15, 1e16, 1e17, 1e20, 6.4e19]) {
      const world = new World({ solver: 'soft' });
      const body = world.createBody({ x: 0, y: 0 });
      world.addShape(body, { kind: 'capsule', length: 2, radius: 1, offsetX: offset });
      const b = world.getBody(body);
      expect(Number.isFinite(b.inertia) && Number.isFinite(b.centerX), `offset ${offset}`).toBe(true);
      // Its core's ends 1 from the middle: apart at 1e15, one point from 1e16 on (a disc, pi r^2).
      expect(b.mass, `offset ${offset}`).toBeCloseTo(offset < 1e16 ? Math.PI + 4 : Math.PI, 9);
      world.step(1 / 60);
      assertFinite(world, null, { op: 'step', dt: 1 / 60 });
    }
  });

  it('shapes of any size across segments up to 2e100 long, anywhere, stay finite and the step never throws', () => {
    // A segment's closest point to a shape multiplies squared lengths together (its parameter's
    // numerator and denominator), past the largest double for lengths beyond about 1e77.
    const extent = fc.constantFrom(1e-3, 1, 1e12, 1e50, 1e60, 1e80, 1e99, 1e100);
    const place = fc.constantFrom(0, 1, -1, 1e50, -1e99, 1e100);
    fc.assert(
      fc.property(
        fc.record({ x1: place, y1: place, x2: place, y2: place, half: extent }),
        fc.constantFrom('circle' as const, 'capsule' as const, 'box' as const),
        fc.record({ size: extent, angle: fc.constantFrom(0, 0.001, 1), bullet: fc.boolean(), vy: fc.constantFrom(0, 10, 1e6) }),
        fc.constantFrom('soft' as const, 'elastic' as const),
        fc.constantFrom(1 / 60, 0),
        (segment, kind, body, solver, dt) => {
          const world = new World({ solver, friction: 0.5, gravity: { x: 0, y: 10 } });
          // Either the segment given, or one of length 2 * half through the origin.
          const { x1, y1, x2, y2 } = segment.x1 === segment.x2 && segment.y1 === segment.y2 ? { x1: -segment.half, y1: 1, x2: segment.half, y2: 0 } : segment;
          world.createSegment({ x1, y1, x2, y2 });
          const size = Math.min(body.size, 1e49);
          const common = { x: 0, y: 0, angle: body.angle, vy: body.vy, bullet: body.bullet };
          if (kind === 'circle') world.createCircle({ ...common, radius: size, friction: 0.5 });
          else if (kind === 'capsule') world.createCapsule({ ...common, length: Math.min(2 * size, 1e50), radius: 2 });
          else world.createBox({ ...common, width: size, height: size });
          for (let s = 0; s < 3; s++) {
            world.step(dt);
            assertFinite(world, null, { op: 'step', dt });
          }
          const contacts = world.contactPoints();
          for (let k = 0; k < contacts.count; k++) {
            expect([contacts.x[k], contacts.y[k], contacts.separation[k]].every(Number.isFinite), `contact ${k}`).toBe(true);
          }
        },
      ),
      { numRuns: 400, seed: 23 },
    );
  });

  it("a joint's reported force and torque (its kept impulses over the sub-step) stay finite at dt 1e-100, and the world restores", () => {
    const world = new World();
    const a = world.createCircle({ x: 1e100, y: 0, angularVelocity: 100, radius: 1 });
    const b = world.createCircle({ x: 0, y: 0, radius: 1e30 });
    const joint = world.createJoint({ kind: 'prismatic', bodyA: a, bodyB: b, lowerTranslation: -0.3, upperTranslation: 1e30 });
    world.step(1e-100);
    const reported = world.getJoint(joint);
    expect([reported.force.x, reported.force.y, reported.torque].every(Number.isFinite)).toBe(true);
    const restored = World.restore(world.snapshot());
    expect(restored.getJoint(joint).torque).toBe(reported.torque);
    restored.step(1 / 60);
    assertFinite(restored, null, { op: 'step', dt: 1 / 60 });
  });

  it('a pressure ring 1e106 across (its bodies thrown there at 1e100 m/s for 1e6 s) under a pressure of 1e99 stays finite', () => {
    const world = new World();
    const a = world.createCircle({ x: 0, y: 0, vx: -1e100, vy: -1e100, radius: 1 });
    const b = world.createCircle({ x: 1, y: 0, vx: 1e100, radius: 1 });
    const c = world.createCircle({ x: 0, y: 1, vy: 1e100, radius: 1 });
    world.step(1e6);
    expect(world.getBody(b).x).toBe(1e106);
    world.createJoint({ kind: 'pressure', bodies: [a, b, c], pressure: 1e99 });
    for (let s = 0; s < 5; s++) {
      world.step(1 / 60);
      assertFinite(world, null, { op: 'step', dt: 1 / 60 });
    }
  });

  it('capsules whose cores round to a point (too short for where they lie) meet as circles, finite', () => {
    const cases = [
      { x: 1e17, y: 1e17, length: 3 },
      { x: 1, y: 1, length: 1e-17 },
    ];
    for (const solver of ['soft', 'elastic'] as const) {
      for (const { x, y, length } of cases) {
        for (const offset of [0, 0.5]) {
          const world = new World({ solver, gravity: { x: 0, y: 0 } });
          const a = world.createCapsule({ x, y, length, radius: 0.6 });
          world.createCapsule({ x: x + offset, y, length, radius: 0.6 });
          // and one of them against a capsule with a core of its own, across it
          world.createCapsule({ x, y: y + 0.3, length: 2, radius: 0.2, angle: 1 });
          for (let s = 0; s < 10; s++) {
            world.step(1 / 60);
            try {
              assertFinite(world, null, { op: 'step', dt: 1 / 60 });
            } catch (e) {
              throw new Error(`${solver}, capsules of length ${length} at ${x} offset ${offset}, step ${s + 1}: ${(e as Error).message}`);
            }
          }
          if (x === 1) expect(world.getBody(a).x, `${solver}: pushed apart`).not.toBe(x);
        }
      }
    }
  });
});
