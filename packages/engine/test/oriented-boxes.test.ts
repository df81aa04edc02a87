import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { World } from '../src/index.js';
import { boxesApart, ORIENTED_BOX } from '../src/narrowphase/oriented-boxes.js';
import { collide } from '../src/narrowphase/dispatch.js';
import { WorldShape } from '../src/narrowphase/world-shape.js';
import { Manifold } from '../src/narrowphase/manifold.js';
import type { ShapeOptions } from '../src/index.js';

/** A shape of any kind, possibly rounded and placed off its body's origin. */
const shapeArbitrary: fc.Arbitrary<ShapeOptions> = fc
  .record({
    kind: fc.constantFrom('circle', 'box', 'polygon', 'capsule'),
    size: fc.double({ min: 0.05, max: 3, noNaN: true }),
    aspect: fc.double({ min: 0.02, max: 1, noNaN: true }),
    rounding: fc.oneof(fc.constant(0), fc.double({ min: 0, max: 1, noNaN: true })),
    offsetX: fc.double({ min: -2, max: 2, noNaN: true }),
    offsetY: fc.double({ min: -2, max: 2, noNaN: true }),
    // Square with the body as often as not: long thin boxes whose sides are the body's axes.
    offsetAngle: fc.oneof(fc.constant(0), fc.double({ min: -4, max: 4, noNaN: true })),
    corners: fc.integer({ min: 3, max: 8 }),
    phase: fc.double({ min: 0, max: 1, noNaN: true }),
  })
  .map((p): ShapeOptions => {
    const place = { offsetX: p.offsetX, offsetY: p.offsetY };
    if (p.kind === 'circle') return { kind: 'circle', radius: p.size, ...place };
    if (p.kind === 'capsule') return { kind: 'capsule', length: p.size, radius: p.size * p.aspect + 0.01, ...place, offsetAngle: p.offsetAngle };
    // Rounding as a fraction of what each kind allows (less than half a box's smaller side).
    if (p.kind === 'box') return { kind: 'box', width: p.size, height: p.size * p.aspect, radius: 0.45 * p.rounding * p.size * p.aspect, ...place, offsetAngle: p.offsetAngle };
    // A regular polygon squashed along y: convex, counter-clockwise, no three corners in line.
    const vertices = Array.from({ length: p.corners }, (_, k) => {
      const a = (2 * Math.PI * (k + p.phase)) / p.corners;
      return { x: p.size * Math.cos(a), y: p.size * (0.3 + 0.7 * p.aspect) * Math.sin(a) };
    });
    return { kind: 'polygon', vertices, radius: 0.2 * p.rounding * p.size * (0.3 + 0.7 * p.aspect), ...place, offsetAngle: p.offsetAngle };
  });

const bodyArbitrary = fc.record({
  x: fc.double({ min: -4, max: 4, noNaN: true }),
  y: fc.double({ min: -4, max: 4, noNaN: true }),
  angle: fc.oneof(fc.constantFrom(0, Math.PI / 2, Math.PI / 4), fc.double({ min: -7, max: 7, noNaN: true })),
  shapes: fc.array(shapeArbitrary, { minLength: 1, maxLength: 3 }),
});

describe('oriented boxes', () => {
  // boxesApart drops a shape pair before its pair function: it must never drop one that the
  // pair function would give a point, at any speculative margin.
  it('a pair whose boxes are apart has no contact, for every kind of shape, rounding, offset and pose', () => {
    const manifold = new Manifold();
    const shapeA = new WorldShape();
    const shapeB = new WorldShape();
    let apart = 0;
    let together = 0;
    fc.assert(
      fc.property(bodyArbitrary, bodyArbitrary, fc.constantFrom(0, 0.005, 0.3), (first, second, margin) => {
        const world = new World({ gravity: { x: 0, y: 0 } });
        const handles = [first, second].map((b) => {
          const h = world.createBody({ x: b.x, y: b.y, angle: b.angle });
          for (const shape of b.shapes) world.addShape(h, shape);
          return h;
        });
        const internals = world as unknown as { bodies: { x: Float64Array; y: Float64Array; rigid: { c: Float64Array; s: Float64Array; firstShape: Int32Array } }; shapes: { store: { box: Float64Array; next: Int32Array } } };
        const { x, y, rigid } = internals.bodies;
        const store = internals.shapes.store;
        const [i, j] = handles.map((h) => (world as unknown as { slot(h: number): number }).slot(h));
        for (let sa = rigid.firstShape[i]; sa >= 0; sa = store.next[sa]) {
          for (let sb = rigid.firstShape[j]; sb >= 0; sb = store.next[sb]) {
            if (!boxesApart(x, y, rigid.c, rigid.s, i, store.box, sa * ORIENTED_BOX, j, store.box, sb * ORIENTED_BOX, Float64Array.of(margin))) {
              together++;
              continue;
            }
            apart++;
            const a = shapeA.fromStore(store as never, sa, x[i], y[i], rigid.c[i], rigid.s[i]);
            const b = shapeB.fromStore(store as never, sb, x[j], y[j], rigid.c[j], rigid.s[j]);
            manifold.margin = margin;
            manifold.slop = 0.005;
            collide(a, b, manifold);
            expect(manifold.pointCount).toBe(0);
          }
        }
      }),
      { numRuns: 1000, seed: 7 },
    );
    // Both outcomes occur, so the assertion above was exercised.
    expect(apart).toBeGreaterThan(100);
    expect(together).toBeGreaterThan(100);
  });

  it('boxes that overlap are not apart, and a long wall turned with its body keeps its shape', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    // A drum's wall, 20 x 1, turned a quarter turn: a small box 3 beside its middle is far from
    // it, though well within its bounding circle; 0.5 beside it, it touches.
    const wall = world.createBody({ x: 0, y: 0, angle: Math.PI / 2, type: 'static' });
    world.addShape(wall, { kind: 'box', width: 20, height: 1 });
    const far = world.createBox({ x: 3, y: 0, width: 0.5, height: 0.5 });
    const near = world.createBox({ x: 0.7, y: 5, width: 0.5, height: 0.5 });
    const internals = world as unknown as { bodies: { x: Float64Array; y: Float64Array; rigid: { c: Float64Array; s: Float64Array; firstShape: Int32Array } }; shapes: { store: { box: Float64Array } }; slot(h: number): number };
    const { x, y, rigid } = internals.bodies;
    const box = internals.shapes.store.box;
    const apart = (h: number) => {
      const i = internals.slot(wall);
      const j = internals.slot(h);
      return boxesApart(x, y, rigid.c, rigid.s, i, box, rigid.firstShape[i] * ORIENTED_BOX, j, box, rigid.firstShape[j] * ORIENTED_BOX, Float64Array.of(0));
    };
    expect(apart(far)).toBe(true);
    expect(apart(near)).toBe(false);
  });
});
