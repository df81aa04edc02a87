import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { World, BROADPHASE_NAMES } from '../src/index.js';

const SIZE = 200;

/** One user call, its arguments drawn as fractions so that every world receives the same ones. */
type Call =
  | { kind: 'step' }
  | { kind: 'create'; x: number; y: number; r: number; vx: number; vy: number; type: number }
  | { kind: 'destroy' | 'wake' | 'sleep' | 'filter'; pick: number; bits: number }
  | { kind: 'move' | 'push' | 'velocity'; pick: number; x: number; y: number }
  | { kind: 'retype'; pick: number; type: number }
  | { kind: 'segment'; x: number; y: number; length: number }
  | { kind: 'unsegment'; pick: number };

const unit = fc.double({ min: 0, max: 1, noNaN: true });
const call: fc.Arbitrary<Call> = fc.oneof(
  { weight: 6, arbitrary: fc.constant({ kind: 'step' as const }) },
  { weight: 3, arbitrary: fc.record({ kind: fc.constant('create' as const), x: unit, y: unit, r: unit, vx: unit, vy: unit, type: fc.integer({ min: 0, max: 5 }) }) },
  { weight: 1, arbitrary: fc.record({ kind: fc.constantFrom('destroy' as const, 'wake' as const, 'sleep' as const, 'filter' as const), pick: unit, bits: fc.integer({ min: 0, max: 3 }) }) },
  { weight: 1, arbitrary: fc.record({ kind: fc.constantFrom('move' as const, 'push' as const, 'velocity' as const), pick: unit, x: unit, y: unit }) },
  { weight: 1, arbitrary: fc.record({ kind: fc.constant('retype' as const), pick: unit, type: fc.integer({ min: 0, max: 2 }) }) },
  { weight: 1, arbitrary: fc.record({ kind: fc.constant('segment' as const), x: unit, y: unit, length: unit }) },
  { weight: 1, arbitrary: fc.record({ kind: fc.constant('unsegment' as const), pick: unit }) },
);

const TYPES = ['static', 'kinematic', 'dynamic'] as const;

function pickFrom(handles: number[], pick: number): number | undefined {
  return handles.length === 0 ? undefined : handles[Math.min(handles.length - 1, Math.floor(pick * handles.length))];
}

/** Applies `c` to `world`; a call the world refuses must leave it as it was, so it is skipped alike everywhere. */
function apply(world: World, c: Call, segments: number[]): void {
  const handles = world.handles();
  switch (c.kind) {
    case 'step':
      world.step(1 / 60);
      return;
    case 'create': {
      const r = 2 + 10 * c.r;
      // A static body takes no velocity (createCircle refuses one).
      const still = c.type === 0;
      world.createCircle({ x: r + (SIZE - 2 * r) * c.x, y: r + (SIZE - 2 * r) * c.y, radius: r, vx: still ? 0 : 400 * c.vx - 200, vy: still ? 0 : 400 * c.vy - 200, type: still ? 'static' : c.type === 1 ? 'kinematic' : 'dynamic' });
      return;
    }
    case 'segment':
      segments.push(world.createSegment({ x1: SIZE * c.x, y1: SIZE * c.y, x2: SIZE * c.x + 60 * c.length, y2: SIZE * c.y + 20, thickness: 1 }));
      return;
    case 'unsegment': {
      const s = pickFrom(segments, c.pick);
      if (s !== undefined) {
        world.destroySegment(s);
        segments.splice(segments.indexOf(s), 1);
      }
      return;
    }
  }
  const h = pickFrom(handles, c.pick);
  if (h === undefined) return;
  switch (c.kind) {
    case 'destroy':
      world.destroyBody(h);
      return;
    case 'wake':
      world.setAwake(h, true);
      return;
    case 'sleep':
      world.setAwake(h, false);
      return;
    case 'filter':
      world.setCollisionFilter(h, 1 << c.bits, c.bits === 3 ? 0 : 0xffffffff);
      return;
    case 'retype':
      world.setType(h, TYPES[c.type]);
      return;
    case 'move': {
      const r = world.getCircle(h).radius;
      world.setPosition(h, r + (SIZE - 2 * r) * c.x, r + (SIZE - 2 * r) * c.y);
      return;
    }
    case 'velocity':
      if (world.getCircle(h).type !== 'static') world.setVelocity(h, 300 * c.x - 150, 300 * c.y - 150);
      return;
    case 'push':
      if (world.getCircle(h).type === 'dynamic') world.applyImpulse(h, 1000 * c.x - 500, 1000 * c.y - 500);
      return;
  }
}

describe('random sequences of user calls', () => {
  it('give the same bits and events on every broad-phase, keep every body in the box, and stay finite', () => {
    fc.assert(
      fc.property(fc.array(call, { minLength: 20, maxLength: 200 }), fc.boolean(), fc.integer({ min: 1, max: 3 }), (calls, sleeping, solverIterations) => {
        const worlds = BROADPHASE_NAMES.map(
          (broadphase) =>
            new World({
              broadphase,
              bounds: { width: SIZE, height: SIZE },
              gravity: { x: 0, y: 200 },
              restitution: 0.7,
              sleeping,
              sleepSpeed: 30,
              sleepTime: 0.1,
              solverIterations,
              contactEvents: true,
              hitEventThreshold: 1,
            }),
        );
        const segments = worlds.map((): number[] => []);
        for (const c of calls) {
          worlds.forEach((world, w) => apply(world, c, segments[w]));
          const hash = worlds[0].stateHash();
          const events = worlds[0].contactEvents();
          const counts = [events.beginCount, events.endCount, events.hitCount, events.wallBeginCount, events.segmentBeginCount];
          for (const world of worlds) {
            expect(world.stateHash(), `${world.broadphase} after ${c.kind}`).toBe(hash);
            const e = world.contactEvents();
            expect([e.beginCount, e.endCount, e.hitCount, e.wallBeginCount, e.segmentBeginCount], world.broadphase).toEqual(counts);
          }
        }
        const v = worlds[0].views();
        for (let s = 0; s < v.slotCount; s++) {
          if (v.type[s] === 0) continue;
          expect(Number.isFinite(v.vx[s]) && Number.isFinite(v.vy[s])).toBe(true);
          expect(v.x[s] - v.radius[s]).toBeGreaterThanOrEqual(-1e-9);
          expect(v.x[s] + v.radius[s]).toBeLessThanOrEqual(SIZE + 1e-9);
          expect(v.y[s] - v.radius[s]).toBeGreaterThanOrEqual(-1e-9);
          expect(v.y[s] + v.radius[s]).toBeLessThanOrEqual(SIZE + 1e-9);
        }
      }),
      { numRuns: 100, seed: 20261122 },
    );
  });
});
