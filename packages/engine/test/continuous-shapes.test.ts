import { describe, expect, it } from 'vitest';
import { World } from '../src/index.js';
import { impact, timeOfImpact, type Sweep } from '../src/solver/time-of-impact.js';
import { WorldShape } from '../src/narrowphase/world-shape.js';
import type { ShapeStore } from '../src/store/shape-store.js';

const DT = 1 / 60;

describe('continuous collision with shapes', () => {
  it.each([10, 100, 1000, 10_000, 1e6])('a thin static wall stops a spinning box and a capsule at %s m/s', (speed) => {
    const world = new World({ restitution: 0.5, friction: 0.3 });
    world.createBox({ x: 10, y: 0, width: 0.05, height: 10, type: 'static' });
    const box = world.createBox({ x: 0, y: -2, width: 0.5, height: 0.5, vx: speed, angularVelocity: 3 });
    const capsule = world.createCapsule({ x: 0, y: 2, length: 1, radius: 0.1, vx: speed, angle: 1 });
    for (let s = 0; s < 120; s++) {
      world.step(DT);
      expect(world.getBody(box).x).toBeLessThan(10);
      expect(world.getBody(capsule).x).toBeLessThan(10);
    }
  });

  it('a thin segment and a wall of the box stop them too', () => {
    const world = new World({ bounds: { width: 20, height: 20 }, restitution: 0.5 });
    world.createSegment({ x1: 10, y1: 0, x2: 10, y2: 10 });
    const box = world.createBox({ x: 2, y: 5, width: 0.5, height: 0.5, vx: 5000, angularVelocity: 2 });
    const low = world.createBox({ x: 2, y: 15, width: 0.5, height: 0.5, vx: 5000, angularVelocity: -2 });
    for (let s = 0; s < 60; s++) {
      world.step(DT);
      expect(world.getBody(box).x).toBeLessThan(10);
      expect(world.getBody(low).x).toBeLessThan(20);
    }
  });

  it('the sweep catches a fast circle or capsule grazing a segment\'s end, not only one aimed at its middle', () => {
    // The segment runs from (10, -1) to (10, 1); each body's centre passes above its upper end by
    // less than the body's reach, so only its rim meets the end, within the first step.
    for (const [kind, reach] of [['circle', 0.5], ['capsule', 0.35]] as const) {
      for (const fraction of [0, 0.3, 0.6, 0.9, 0.98]) {
        const world = new World({ restitution: 0, friction: 0 });
        world.createSegment({ x1: 10, y1: -1, x2: 10, y2: 1 });
        // A box far off puts the circle on the shape route too.
        world.createBox({ x: -100, y: 0, width: 1, height: 1, type: 'static' });
        const y = 1 + fraction * reach;
        const body =
          kind === 'circle'
            ? world.createCircle({ x: 5, y, radius: reach, vx: 300 })
            : world.createCapsule({ x: 5, y, length: 0.5, radius: 0.1, angle: Math.PI / 2, vx: 300 });
        world.step(DT);
        // Passed by, it would end the step at x = 10; held at its impact, its rim on the end.
        expect(world.getBody(body).x, `${kind} ${fraction}`).toBeLessThan(10);
        world.step(DT);
        // Then the end stops or deflects it (frictionless, without restitution).
        const at = world.getBody(body);
        expect(Math.hypot(at.vx - 300, at.vy), `${kind} ${fraction}`).toBeGreaterThan(10);
      }
    }
  });

  it('a long plank arriving tilted does not swing its far end, then its centre, through the wall it first touched', () => {
    // Put back where its corner met the wall, the plank turns about that corner in the next
    // step; the contact held that corner only, so the sweep of its core must hold the rest.
    for (const dt of [1 / 60, 1 / 120]) {
      for (const wall of ['box', 'segment'] as const) {
        for (const angle of [0.3, 0.5, 0.8, 1]) {
          for (const speed of [50, 100, 200, 400]) {
            const world = new World({ friction: 0.3, restitution: 0 });
            if (wall === 'box') world.createBox({ x: 0, y: 0.1, width: 200, height: 0.2, type: 'static' });
            else world.createSegment({ x1: -100, y1: 0, x2: 100, y2: 0, thickness: 0.1 });
            const plank = world.createBox({ x: 0.123, y: -3, vy: speed, angle, width: 1, height: 0.1 });
            for (let s = 0; s < 2 / dt; s++) {
              world.step(dt);
              expect(world.getBody(plank).centerY, `${wall}, angle ${angle}, ${speed} m/s, dt ${dt}, step ${s + 1}`).toBeLessThan(0.1);
            }
          }
        }
      }
    }
  });

  it('planks, boxes, flat polygons and capsules thrown tilted at thin walls never end on the far side', () => {
    // Put back at the impact of one corner, a long body turns about it in the next step; a far
    // corner (a capsule's far end) that starts that step clear and would end it inside or past
    // the wall is swept too.
    let cases = 0;
    for (const dt of [1 / 60, 1 / 120]) {
      for (const wall of ['box', 'segment'] as const) {
        for (const thickness of [0.002, 0.01, 0.05, 0.2]) {
          for (const body of ['plank', 'thin plank', 'box', 'polygon', 'capsule', 'thin capsule'] as const) {
            for (const angle of [0.03, 0.2, 0.5, 0.8, 1.1, 1.4]) {
              for (const speed of [50, 100, 200, 400]) {
                const world = new World({ friction: 0.3, restitution: 0, gravity: { x: 0, y: 10 } });
                // The wall's far face at y = thickness, 200 m long: a body past its ends has gone round it.
                if (wall === 'box') world.createBox({ x: 0, y: thickness / 2, width: 200, height: thickness, type: 'static' });
                else world.createSegment({ x1: -100, y1: thickness / 2, x2: 100, y2: thickness / 2, thickness: thickness / 2 });
                const start = { x: 0.123, y: -3, vx: 0.3 * speed, vy: speed, angle };
                const handle =
                  body === 'plank'
                    ? world.createBox({ ...start, width: 1, height: 0.1 })
                    : body === 'thin plank'
                      ? world.createBox({ ...start, width: 1.5, height: 0.02 })
                      : body === 'box'
                        ? world.createBox({ ...start, width: 0.5, height: 0.5 })
                        : body === 'capsule'
                          ? world.createCapsule({ ...start, length: 1.2, radius: 0.03 })
                          : body === 'thin capsule'
                            ? world.createCapsule({ ...start, length: 1.5, radius: 0.01 })
                            : world.createPolygon({ ...start, vertices: [{ x: -0.6, y: 0 }, { x: -0.3, y: -0.08 }, { x: 0.3, y: -0.08 }, { x: 0.6, y: 0 }, { x: 0.3, y: 0.08 }, { x: -0.3, y: 0.08 }] });
                cases++;
                for (let s = 0; s < 1 / dt; s++) {
                  world.step(dt);
                  const b = world.getBody(handle);
                  if (Math.abs(b.centerX) < 99) expect(b.centerY, `${wall} ${thickness} m, ${body} at ${angle} rad, ${speed} m/s, dt ${dt}, step ${s + 1}`).toBeLessThan(thickness);
                }
              }
            }
          }
        }
      }
    }
    expect(cases).toBe(2304);
  }, 120_000);

  it('bodies thrown spinning at thin walls of any direction never end on the far side (random throws)', async () => {
    const fc = (await import('fast-check')).default;
    // Unbiased: fast-check's default leans to the ends of each range, where few throws fail.
    const throwAt = fc.noBias(fc.record({
      wall: fc.constantFrom('box', 'segment'),
      thickness: fc.constantFrom(0.002, 0.01, 0.05, 0.2),
      direction: fc.double({ min: 0, max: Math.PI, noNaN: true }),
      body: fc.constantFrom('plank', 'box', 'capsule', 'polygon'),
      length: fc.double({ min: 0.3, max: 1.8, noNaN: true }),
      width: fc.double({ min: 0.01, max: 0.1, noNaN: true }),
      speed: fc.double({ min: 10, max: 1500, noNaN: true }),
      aim: fc.double({ min: -0.5, max: 0.5, noNaN: true }),
      angle: fc.double({ min: 0, max: 2 * Math.PI, noNaN: true }),
      spin: fc.double({ min: -50, max: 50, noNaN: true }),
      friction: fc.double({ min: 0, max: 1, noNaN: true }),
      restitution: fc.double({ min: 0, max: 0.5, noNaN: true }),
      gravity: fc.boolean(),
    }));
    fc.assert(
      fc.property(throwAt, (t) => {
        // The wall through the origin along (ux, uy), 400 m long; the body starts 3 m before it.
        const ux = Math.cos(t.direction);
        const uy = Math.sin(t.direction);
        const world = new World({ friction: t.friction, restitution: t.restitution, gravity: { x: 0, y: t.gravity ? 10 : 0 } });
        if (t.wall === 'box') world.createBox({ x: 0, y: 0, width: 400, height: t.thickness, angle: t.direction, type: 'static' });
        else world.createSegment({ x1: -200 * ux, y1: -200 * uy, x2: 200 * ux, y2: 200 * uy, thickness: t.thickness / 2 });
        const start = { x: 3 * uy, y: -3 * ux, vx: t.speed * (-uy + t.aim * ux), vy: t.speed * (ux + t.aim * uy), angle: t.angle, angularVelocity: t.spin };
        const body =
          t.body === 'plank'
            ? world.createBox({ ...start, width: t.length, height: t.width })
            : t.body === 'box'
              ? world.createBox({ ...start, width: 0.3, height: 0.3 })
              : t.body === 'capsule'
                ? world.createCapsule({ ...start, length: t.length, radius: t.width / 2 })
                : world.createPolygon({ ...start, vertices: [0, 1, 2, 3, 4].map((k) => ({ x: (t.length / 2) * Math.cos((2 * Math.PI * k) / 5), y: t.width * Math.sin((2 * Math.PI * k) / 5) })) });
        for (let s = 0; s < 60; s++) {
          world.step(DT);
          const b = world.getBody(body);
          const side = -b.centerX * uy + b.centerY * ux;
          const along = b.centerX * ux + b.centerY * uy;
          if (side > t.thickness / 2 && Math.abs(along) < 195) return false;
        }
        return true;
      }),
      { numRuns: 1500, seed: 7 },
    );
  }, 120_000);

  it('sharp polygons thrown spinning at a thin wall never end on the far side, though a corner starts a step parked at it', () => {
    // Found by an audit: a corner stopped one slop short of the wall by one step's sweep starts
    // the next within the sweep's target; left to the contact, a fast turn carried it through.
    const shapes = {
      triangle: [{ x: -0.1, y: -0.05 }, { x: 0.15, y: 0 }, { x: -0.1, y: 0.05 }],
      wedge: [{ x: 0, y: 0 }, { x: 0.4, y: 0.05 }, { x: 0, y: 0.1 }],
      'flat hexagon': [{ x: -0.3, y: 0 }, { x: -0.2, y: -0.03 }, { x: 0.2, y: -0.03 }, { x: 0.3, y: 0 }, { x: 0.2, y: 0.03 }, { x: -0.2, y: 0.03 }],
    };
    let seed = 12345;
    const random = (): number => {
      seed = (seed * 1103515245 + 12345) & 0x7fffffff;
      return seed / 0x7fffffff;
    };
    const through: string[] = [];
    for (const [name, vertices] of Object.entries(shapes)) {
      for (let k = 0; k < 400; k++) {
        const speed = 10 * Math.pow(40, random());
        const angle = random() * 2 * Math.PI;
        const spin = (random() * 2 - 1) * 40;
        const dt = random() < 0.5 ? 1 / 60 : 1 / 30;
        const segment = random() < 0.5;
        const world = new World({ gravity: { x: 0, y: 0 }, restitution: 0, friction: 0.3 });
        if (segment) world.createSegment({ x1: 5, y1: -3, x2: 5, y2: 3 });
        else world.createBox({ x: 5, y: 0, width: 0.002, height: 6, type: 'static' });
        const h = world.createPolygon({ x: 0, y: 0.1, vx: speed, angle, angularVelocity: spin, vertices });
        for (let i = 0; i < Math.round(2 / dt); i++) {
          world.step(dt);
          const b = world.getBody(h);
          if (b.centerX > 5 && Math.abs(b.centerY) < 3) {
            through.push(`${name} at ${speed.toFixed(1)} m/s, angle ${angle.toFixed(3)}, spin ${spin.toFixed(2)}, dt ${dt.toFixed(4)}, ${segment ? 'segment' : 'box'}`);
            break;
          }
        }
      }
    }
    expect(through).toEqual([]);
  }, 60_000);

  it('a capsule thrown tilted and spinning at a thin segment or box stays on its side', () => {
    // Its first end to arrive is put back at the wall; the contact must then hold its other end,
    // which the turn about the first swings towards the wall.
    for (const dt of [1 / 60, 1 / 30]) {
      for (const wall of ['segment', 'box'] as const) {
        for (const thickness of [0.002, 0.2]) {
          for (const angle of [0, 0.4, 0.8, 1.3]) {
            for (const spin of [0, 20, -40]) {
              for (const speed of [20, 100, 1000]) {
                const world = new World({ friction: 0.3, restitution: 0 });
                if (wall === 'box') world.createBox({ x: 0, y: thickness / 2, width: 400, height: thickness, type: 'static' });
                else world.createSegment({ x1: -200, y1: 0, x2: 200, y2: 0, thickness: thickness / 2 });
                const capsule = world.createCapsule({ x: 0.37, y: -3, vx: speed / 10, vy: speed, angle, angularVelocity: spin, length: 0.6, radius: 0.1 });
                for (let s = 0; s < 40; s++) {
                  world.step(dt);
                  expect(world.getBody(capsule).centerY, `${wall} ${thickness}, angle ${angle}, spin ${spin}, ${speed} m/s, dt ${dt}, step ${s + 1}`).toBeLessThan(0);
                }
              }
            }
          }
        }
      }
    }
  });

  it('without continuous collision the box tunnels (negative control)', () => {
    const world = new World({ restitution: 0.5, continuous: false });
    world.createBox({ x: 10, y: 0, width: 0.05, height: 10, type: 'static' });
    const box = world.createBox({ x: 0, y: 0, width: 0.5, height: 0.5, vx: 1000 });
    for (let s = 0; s < 10; s++) world.step(DT);
    expect(world.getBody(box).x).toBeGreaterThan(10);
  });

  it('a bullet does not pass through a thin moving plank; an ordinary fast body does', () => {
    for (const bullet of [true, false]) {
      const world = new World({ restitution: 0 });
      const plank = world.createBox({ x: 10, y: 0, width: 0.05, height: 4, density: 10 });
      const shot = world.createCircle({ x: 0, y: 0, radius: 0.05, vx: 900, bullet });
      let crossed = false;
      for (let s = 0; s < 5; s++) {
        world.step(DT);
        if (world.getBody(shot).x > world.getBody(plank).x + 0.2) crossed = true;
      }
      expect(crossed).toBe(!bullet);
    }
  });

  it('a bullet does not pass through a thin plank coming at it, whatever the two speeds', () => {
    // Swept against where the plank ended the step alone, a bullet meeting a plank that closes on
    // it finds the plank already behind it.
    for (const speed of [30, 120, 2000, 10000]) {
      for (const plankSpeed of [-10, -50, -1000]) {
        for (const kind of ['box', 'circle'] as const) {
          const world = new World({ restitution: 0 });
          const shot =
            kind === 'box'
              ? world.createBox({ x: 0, y: 0, width: 0.1, height: 0.1, vx: speed, bullet: true })
              : world.createCircle({ x: 0, y: 0, radius: 0.05, vx: speed, bullet: true });
          const plank = world.createBox({ x: 10, y: 0, width: 0.05, height: 2, vx: plankSpeed });
          let crossed = false;
          for (let s = 0; s < 120; s++) {
            world.step(DT);
            if (world.getBody(shot).x > world.getBody(plank).x) crossed = true;
          }
          expect(crossed, `${kind} at ${speed} m/s, plank at ${plankSpeed}`).toBe(false);
          // The plank took the shot's momentum: restitution 0, so the two move on together.
          expect(world.getBody(plank).vx, `${kind} at ${speed} m/s, plank at ${plankSpeed}`).toBeGreaterThan(plankSpeed);
        }
      }
    }
  });

  it('bodies smaller than the slop, starting within it of a thin wall, do not pass through it, in either solver', () => {
    // Shape, core disc and centroid all start within the sweep's target (a slop): the centroid is
    // swept to half its gap. The elastic pass has no speculative contact to stop them otherwise.
    for (const solver of ['elastic', 'soft'] as const)
      for (const wall of ['segment', 'box'] as const)
        for (const shape of ['circle', 'box'] as const)
          for (const r of [0.002, 0.005, 0.01])
            for (const gap of [0.0005, 0.002, 0.005])
              for (const v of [3, 30, 300]) {
                const world = new World({ solver, restitution: 0, friction: 0 });
                const half = wall === 'segment' ? 0 : 0.005;
                if (wall === 'segment') world.createSegment({ x1: 0, y1: -50, x2: 0, y2: 50 });
                else world.createBox({ x: 0, y: 0, width: 2 * half, height: 100, type: 'static' });
                const x = -(half + gap + r);
                const h = shape === 'circle' ? world.createCircle({ x, y: 0, radius: r, vx: v }) : world.createBox({ x, y: 0, width: 2 * r, height: r, vx: v });
                for (let s = 0; s < 10; s++) {
                  world.step(DT);
                  expect(world.getBody(h).x, `${solver} ${wall} ${shape} ${r} ${gap} ${v} ${s}`).toBeLessThan(half);
                }
              }
  });

  it("in the elastic pass a bullet's bounce off a body shares momentum with it, and one coming at the bullet carries it", () => {
    for (const restitution of [0, 0.5, 1])
      for (const speed of [30, 300, 3000])
        for (const plankType of ['dynamic', 'kinematic'] as const)
          for (const plankSpeed of [0, -100, -1000]) {
            const world = new World({ solver: 'elastic', restitution, friction: 0, maxLinearSpeed: 1e6 });
            const plank = world.createBox({ x: 0, y: 0, width: 0.05, height: 2, type: plankType, vx: plankSpeed, density: 5 });
            const shot = world.createBox({ x: -0.2 - (0.4 * (speed - plankSpeed)) / 60, y: 0.1, width: 0.1, height: 0.05, vx: speed, bullet: true });
            const before = world.momentum().x;
            const label = `e ${restitution} at ${speed} m/s, ${plankType} plank at ${plankSpeed}`;
            for (let s = 0; s < 4; s++) {
              world.step(DT);
              const b = world.getBody(shot);
              const p = world.getBody(plank);
              expect(b.x, label).toBeLessThan(p.x);
              // The bullet leaves a kinematic plank no faster towards it than the plank goes.
              if (s > 0 && plankType === 'kinematic') expect(b.vx, label).toBeLessThanOrEqual(p.vx + 1e-9 * speed);
            }
            if (plankType === 'dynamic') expect(world.momentum().x, label).toBeCloseTo(before, 9);
          }
  });

  it('a box that bounced off a segment of no thickness leaves it: a corner coming back from past the line is not swept', () => {
    for (const vx of [10, 30, 60]) {
      for (const thickness of [0, 0.05]) {
        const world = new World({ solver: 'soft' });
        world.createSegment({ x1: 5, y1: -2, x2: 5, y2: 2, thickness });
        const box = world.createBox({ x: 0, y: 0, width: 0.5, height: 0.5, vx });
        let parked = 0;
        let bounced = false;
        for (let s = 0; s < 120; s++) {
          world.step(1 / 60);
          const b = world.getBody(box);
          if (b.vx < 0) bounced = true;
          // Moving away at vx: within two steps it is a stride from the segment.
          if (b.vx < 0 && b.x > 4.6) parked++;
          expect(b.x, `vx ${vx}, thickness ${thickness}`).toBeLessThan(5);
        }
        expect(bounced).toBe(true);
        expect(parked, `vx ${vx}, thickness ${thickness}`).toBeLessThanOrEqual(1);
      }
    }
  });

  it("a plank spun about a ledge's end, its centre past the end, does not swing its far end through the ledge", () => {
    for (const thickness of [0.02, 0.1]) {
      for (const spin of [30, 45]) {
        const world = new World({ solver: 'soft' });
        world.createSegment({ x1: 0, y1: 0, x2: 10, y2: 0 });
        const length = 4.3;
        const angle = Math.atan2(-0.8, 2);
        const dx = Math.cos(angle);
        const dy = Math.sin(angle);
        // Lying across the ledge's end, its bottom face on it, 1.04 m of it past the end.
        const cx = -1.04 * dx + (thickness / 2 + 0.002) * dy;
        const cy = -1.04 * dy - (thickness / 2 + 0.002) * dx;
        const plank = world.createBox({ x: cx, y: cy, width: length, height: thickness, angle, vx: spin * -cy, vy: spin * cx, angularVelocity: spin });
        for (let s = 0; s < 40; s++) {
          world.step(1 / 60);
          const b = world.getBody(plank);
          // Its far end, while above the ledge, stays on the near side of it (y <= 0, y down).
          const ex = b.x + (length / 2) * Math.cos(b.angle);
          const ey = b.y + (length / 2) * Math.sin(b.angle);
          if (ex > 0.1 && ex < 10) expect(ey, `thickness ${thickness}, spin ${spin}, step ${s}`).toBeLessThan(0.01);
        }
      }
    }
  });

  it("the elastic pass's sweep bounces with friction, and its bounces are hit events", () => {
    // A box sliding along a wall as it meets it: swept (fast) or not (slow), friction takes from
    // its slide along the wall and turns it, and the hit is listed at its approach speed.
    for (const wall of ['box', 'segment'] as const) {
      const slides: number[] = [];
      for (const vx of [10, 20, 60]) {
        const world = new World({ solver: 'elastic', friction: 0.6, restitution: 1, hitEventThreshold: 1 });
        const segment = wall === 'segment' ? world.createSegment({ x1: 5, y1: -50, x2: 5, y2: 50 }) : -1;
        const block = wall === 'box' ? world.createBox({ x: 5.05, y: 0, width: 0.1, height: 100, type: 'static' }) : -1;
        const box = world.createBox({ x: 0, y: 0, width: 1, height: 1, vx, vy: 3 });
        let hit = 0;
        let swept = 0;
        for (let s = 0; s < 60 && world.getBody(box).vx > 0; s++) {
          world.step(1 / 60);
          swept += world.stats.sweptBodies;
          const e = world.contactEvents();
          const pairs = new Set<string>();
          for (let k = 0; k < e.hitCount; k++) pairs.add(`${e.hitA[k]} ${e.hitB[k]}`);
          for (let k = 0; k < e.segmentHitCount; k++) pairs.add(`${e.segmentHitBody[k]} segment ${e.segmentHitSegment[k]}`);
          expect(pairs.size, 'one hit per pair and step').toBe(e.hitCount + e.segmentHitCount);
          for (let k = 0; k < e.hitCount; k++) if (e.hitA[k] === Math.min(box, block) && e.hitB[k] === Math.max(box, block)) hit = e.hitSpeed[k];
          for (let k = 0; k < e.segmentHitCount; k++) if (e.segmentHitBody[k] === box && e.segmentHitSegment[k] === segment) hit = e.segmentHitSpeed[k];
        }
        const b = world.getBody(box);
        expect(b.vx, `${wall} ${vx}`).toBeCloseTo(-vx, 9);
        expect(hit, `${wall} ${vx}: the hit`).toBeCloseTo(vx, 6);
        if (vx >= 20) expect(swept, `${wall} ${vx}`).toBeGreaterThan(0);
        // Friction slowed the slide along the wall (from 3) and spun the box.
        expect(b.vy, `${wall} ${vx}`).toBeLessThan(2.5);
        expect(b.vy, `${wall} ${vx}`).toBeGreaterThan(0);
        expect(Math.abs(b.angularVelocity), `${wall} ${vx}`).toBeGreaterThan(1);
        slides.push(b.vy);
      }
      // Swept or not, the same impact takes about the same slide.
      expect(Math.max(...slides) - Math.min(...slides), wall).toBeLessThan(0.5);
    }
  });

  it('a fast box sliding along the ground is not stopped by the ground it rests on', () => {
    const world = new World({ gravity: { x: 0, y: 10 }, friction: 0 });
    world.createBox({ x: 0, y: 1, width: 4000, height: 2, type: 'static' });
    const box = world.createBox({ x: 0, y: -0.5, width: 1, height: 1, vx: 300 });
    for (let s = 0; s < 60; s++) world.step(DT);
    expect(world.getBody(box).x).toBeGreaterThan(295);
  });

  it('a round body swept onto the ground is put back a slop into it, as Box2D v3 does, not a slop short', () => {
    // A ball skimming the ground at 20 m/s crosses the speculative margin in one step: parked a
    // slop short of the surface, it lost a fifth of that step's travel for good (x 0.161 where
    // Box2D's reaches 0.2255).
    for (const lengthUnit of [1, 50])
      for (const shape of ['circle', 'capsule', 'rounded box'] as const) {
        const u = lengthUnit;
        const world = new World({ gravity: { x: 0, y: 10 * u }, friction: 0.6, restitution: 0, lengthUnit });
        world.createBox({ x: 0, y: 0.5 * u, width: 1000 * u, height: u, type: 'static' });
        const start = { x: 0, y: -0.13 * u, vx: 20 * u, vy: 3 * u, friction: 0.6 };
        const h =
          shape === 'circle'
            ? world.createCircle({ ...start, radius: 0.1 * u })
            : shape === 'capsule'
              ? world.createCapsule({ ...start, length: 0.4 * u, radius: 0.1 * u })
              : world.createBox({ ...start, width: 0.4 * u, height: 0.2 * u, radius: 0.05 * u });
        world.step(DT);
        const b = world.getBody(h);
        expect(world.stats.sweptBodies, shape).toBe(1);
        // Its lowest point, 0.1 below its centre, a slop (5 mm) into the ground at y = 0.
        expect((b.y + 0.1 * u) / u, `${lengthUnit} ${shape}`).toBeCloseTo(0.005, 6);
        expect(b.x / u, `${lengthUnit} ${shape}`).toBeCloseTo(0.2255, 3);
      }
  });

  it('a box or a hexagon that lands while sliding slides on as far as without the sweep', () => {
    // After a landing the body rests tilted by a hair, its lower corners a rounding or a
    // micrometre above the ground at a step's start and as much into it at its end: no crossing.
    const hexagon = Array.from({ length: 6 }, (_, k) => ({ x: 0.25 * Math.cos((k * Math.PI) / 3), y: 0.25 * Math.sin((k * Math.PI) / 3) }));
    for (const lengthUnit of [1, 50])
      for (const ground of ['segment', 'box'] as const)
        for (const body of ['box', 'wide box', 'hexagon'] as const)
          for (const drop of [0, 0.01, 0.2, 1]) {
            const travel: number[] = [];
            for (const continuous of [true, false]) {
              const u = lengthUnit;
              const world = new World({ gravity: { x: 0, y: 10 * u }, friction: 0, restitution: 0, lengthUnit, continuous });
              if (ground === 'segment') world.createSegment({ x1: -10 * u, y1: 0, x2: 1000 * u, y2: 0 });
              else world.createBox({ x: 500 * u, y: 0.05 * u, width: 1020 * u, height: 0.1 * u, type: 'static' });
              const half = body === 'hexagon' ? (0.25 * Math.sqrt(3)) / 2 : body === 'box' ? 0.1 : 0.4;
              const y = -(half + drop) * u;
              const h =
                body === 'hexagon'
                  ? world.createPolygon({ x: 0, y, vertices: hexagon.map((v) => ({ x: v.x * u, y: v.y * u })), vx: 20 * u })
                  : world.createBox({ x: 0, y, width: (body === 'box' ? 0.5 : 2) * u, height: 2 * half * u, vx: 20 * u });
              for (let s = 0; s < 180; s++) world.step(DT);
              travel.push(world.getBody(h).x / u);
            }
            // The landing step's sweep puts the body back at its impact (Box2D v3's 59.9 m of 60).
            expect(travel[0], `${lengthUnit} ${ground} ${body} ${drop}`).toBeGreaterThan(0.995 * travel[1]);
          }
  });

  it('a time of impact out of iterations gives the impact of the pose it stops at, not the last one found', () => {
    // A rotation interpolated across an exact half turn has no bound on its rate: the advancement
    // stays at t = 0 and runs out of iterations. It returned with `impact` as the last impact
    // found anywhere, in any world, and a bounce read it: the same calls gave other bits after
    // other worlds had swept (found by a fuzzing audit).
    const world = new World();
    world.createBox({ x: 0, y: 0, width: 1, height: 0.5 });
    const store = (world as unknown as { shapes: { store: ShapeStore } }).shapes.store;
    const other = new WorldShape().circle(10, 0, 1);
    const sweep: Sweep = { x0: 0, y0: 0, c0: 1, s0: 0, x1: 5, y1: 0, c1: -1, s1: 0, reach: 0.6, split: false, cm: 1, sm: 0 };
    for (const stale of [0.6, -0.8]) {
      impact.nx = stale;
      impact.ny = 0.8;
      expect(timeOfImpact(store, 0, sweep, other, 0.005, 0.00125)).toBe(0);
      expect([impact.nx, impact.ny]).toEqual([1, 0]);
      expect(impact.x).toBeCloseTo(0.5 + (10 - 1 - 0.5) / 2, 12);
    }
  });

  it('the elastic pass bounces a plank spun near a half turn a step off a segment, rather than holding it there', () => {
    // Interpolated in one piece across nearly a half turn, the rotation's rate bound grew without
    // limit: the time of impact ran out of iterations step after step, and a capsule spun 179
    // degrees a step stood by the segment, never bouncing. Split at the turn's midpoint, it bounces.
    for (const turn of [150, 170, 175, 179, 179.9, 181, 190])
      for (const kind of ['box', 'capsule'] as const) {
        const world = new World({ solver: 'elastic', restitution: 1, friction: 0, maxLinearSpeed: 1e7 });
        world.createSegment({ x1: 0, y1: -100, x2: 0, y2: 100 });
        const start = { x: -3, y: 0.3, angle: 0.5, vx: 30, angularVelocity: ((turn * Math.PI) / 180) * 60 };
        const h = kind === 'box' ? world.createBox({ ...start, width: 1.7, height: 0.1 }) : world.createCapsule({ ...start, length: 1.7, radius: 0.11 });
        const energy = world.kineticEnergy();
        for (let s = 0; s < 16; s++) {
          world.step(DT);
          expect(world.getBody(h).x, `${kind} ${turn} ${s}`).toBeLessThan(0);
        }
        expect(world.getBody(h).x, `${kind} ${turn}`).toBeLessThan(-3);
        expect(world.getBody(h).vx, `${kind} ${turn}`).toBeLessThan(0);
        expect(world.kineticEnergy() / energy, `${kind} ${turn}`).toBeCloseTo(1, 9);
      }
  });

  it('the elastic pass, which caps no spin, stops a plank turning up to a whole turn a step at a segment', () => {
    for (const kind of ['box', 'capsule'] as const)
      for (const turn of [90, 135, 150, 170, 179, 190, 230, 350])
        for (let a = 0; a < 24; a++)
          for (const speed of [20, 60, 200]) {
            const world = new World({ solver: 'elastic', restitution: 1, friction: 0, maxLinearSpeed: 1e7 });
            world.createSegment({ x1: 0, y1: -100, x2: 0, y2: 100 });
            const start = { x: -0.6 - 0.013 * a, y: 0, angle: a * 0.26, vx: speed, angularVelocity: ((turn * Math.PI) / 180) * 60 };
            const h = kind === 'box' ? world.createBox({ ...start, width: 1, height: 0.05 }) : world.createCapsule({ ...start, length: 1, radius: 0.025 });
            for (let s = 0; s < 20; s++) {
              world.step(DT);
              expect(world.getBody(h).x, `${kind} ${turn} ${a} ${speed} ${s}`).toBeLessThan(0);
            }
          }
  });

  it('the elastic pass bounces a box meeting a face flat straight back, unspun, wherever its step starts', () => {
    // A body that starts a step within the slop of the face it then crosses is swept as a core
    // disc and by its corners, whose impact is a single point: the bounce there must still be the
    // face's, both corners at once, as the contact solve gives it.
    let worst = 0;
    for (const size of [0.1, 0.4, 1]) {
      for (const speed of [2, 10, 50]) {
        for (const gap of [0, 0.001, 0.004, 0.008, 0.02]) {
          for (const shape of ['box', 'hexagon'] as const) {
            const world = new World({ restitution: 1, friction: 0 });
            world.createBox({ x: 0, y: 0.5, width: 40, height: 1, type: 'static' });
            const half = size / 2;
            const body = shape === 'box'
              ? world.createBox({ x: 0.3, y: -half - gap, width: size, height: size, vy: speed })
              : world.createPolygon({ x: 0.3, y: -half - gap, vy: speed, vertices: [0, 1, 2, 3, 4, 5].map((k) => ({ x: half * Math.cos((k * Math.PI) / 3), y: half * Math.sin((k * Math.PI) / 3) })) });
            const height = shape === 'box' ? half : half * Math.sin(Math.PI / 3);
            if (shape === 'hexagon') world.setTransform(body, 0.3, -height - gap, 0);
            for (let s = 0; s < 10; s++) world.step(DT);
            const b = world.getBody(body);
            expect(world.route).toEqual({ route: 'shapes', solver: 'elastic' });
            expect(b.vy, `${shape} ${size} at ${speed} m/s, ${gap} m away`).toBeCloseTo(-speed, 6);
            worst = Math.max(worst, Math.abs(b.angularVelocity));
          }
        }
      }
    }
    expect(worst).toBeLessThan(1e-9);
  });

  it.each([5, 20])('the elastic pass bounces a row of boxes struck at %s m/s off a wall along the row, unspun', (speed) => {
    for (const gap of [0, 0.001, 0.005, 0.02]) {
      const world = new World({ restitution: 1, friction: 0 });
      world.createBox({ x: -0.5, y: 0, width: 1, height: 40, type: 'static' });
      const near = world.createBox({ x: 0.05 + gap, y: 0, width: 0.1, height: 0.1 });
      const far = world.createBox({ x: 1, y: 0, width: 0.1, height: 0.1, vx: -speed });
      for (let s = 0; s < 30; s++) world.step(DT);
      const a = world.getBody(near);
      const b = world.getBody(far);
      expect(Math.abs(a.angularVelocity) + Math.abs(b.angularVelocity), `${gap} m from the wall`).toBeLessThan(1e-9);
      expect(Math.abs(a.vy) + Math.abs(b.vy)).toBeLessThan(1e-9);
      // Equal masses in a line: the wall sends the struck box back at full speed, whichever box carries it.
      expect(Math.max(a.vx, b.vx)).toBeCloseTo(speed, 6);
      expect(world.kineticEnergy()).toBeCloseTo(0.5 * 0.01 * speed * speed, 9);
    }
  });
  it.each(['elastic', 'soft'] as const)('a box struck into a thin wall it touches does not go through it (%s)', (solver) => {
    for (const speed of [5, 20]) {
      for (const gap of [0, 0.001, 0.01]) {
        const world = new World({ restitution: 1, friction: 0, solver });
        world.createBox({ x: -0.025, y: 0, width: 0.05, height: 40, type: 'static' });
        const near = world.createBox({ x: 0.05 + gap, y: 0, width: 0.1, height: 0.1 });
        world.createBox({ x: 1, y: 0, width: 0.1, height: 0.1, vx: -speed });
        for (let s = 0; s < 60; s++) {
          world.step(DT);
          expect(world.getBody(near).x, `${speed} m/s, ${gap} m away, step ${s}`).toBeGreaterThan(0);
        }
      }
    }
  });
});
