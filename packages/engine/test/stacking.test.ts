import { describe, expect, it } from 'vitest';
import { buildShapeScene, buildShapeWorld } from '@maxgrid/scenes';
import { World } from '../src/index.js';

const DT = 1 / 60;

function settle(world: World, steps: number): void {
  for (let s = 0; s < steps; s++) world.step(DT);
}

/** The largest sideways move and the top body's drop (as a fraction of its start height above the ground at y = 0). */
function measure(world: World, handles: number[], start: { x: number; y: number }[]): { drift: number; drop: number } {
  let drift = 0;
  for (let k = 0; k < handles.length; k++) drift = Math.max(drift, Math.abs(world.getBody(handles[k]).x - start[k].x));
  const top = handles[handles.length - 1];
  const y0 = start[start.length - 1].y;
  return { drift, drop: (world.getBody(top).y - y0) / -y0 };
}

describe("stacks that stand (Box2D v3's soft step)", () => {
  it("Box2D's large_pyramid: 5,050 boxes, 10 s, sleeping off: top within 1.5 % of its height, no box 0.25 sideways", () => {
    const world = buildShapeWorld(buildShapeScene('pyramid', { base: 100 }));
    const handles = world.handles().slice(1);
    const start = handles.map((h) => world.getBody(h));
    expect(handles).toHaveLength(5050);
    settle(world, 600);
    const { drift, drop } = measure(world, handles, start);
    // Measured: drop 0.74 %, drift 0.17 (Box2D v3 in C: 0.74 %, 0.18).
    expect(drop).toBeLessThan(0.015);
    expect(drift).toBeLessThan(0.25);
    expect(world.stats.contacts).toBe(14950);
  }, 120_000);

  it('stepped at 20 Hz a bridge of 30 planks settles, and at 20 and 30 Hz a pyramid of 55 boxes (contacts and joints no stiffer than the step can hold, as Box2D caps them)', () => {
    const lateEnergy = (name: string, params: Record<string, number>, dt: number): number => {
      const scene = buildShapeScene(name, params);
      const world = buildShapeWorld({ ...scene, world: { ...scene.world, sleeping: false } }, { sleeping: false });
      let most = 0;
      for (let s = 0; s < Math.round(20 / dt); s++) {
        world.step(dt);
        if (s * dt > 15) most = Math.max(most, world.kineticEnergy());
      }
      return most;
    };
    // At 60 Hz, 15 to 20 s on: the bridge under its boxes 3 J, the pyramid 3e-20 J.
    expect(lateEnergy('bridge', {}, 1 / 20), 'bridge at 20 Hz').toBeLessThan(100);
    for (const dt of [1 / 20, 1 / 30]) expect(lateEnergy('pyramid', { base: 10 }, dt), `pyramid at ${1 / dt} Hz`).toBeLessThan(1e-9);
  });

  it('a 15-box vertical stack stands straight', () => {
    const world = buildShapeWorld(buildShapeScene('vertical-stack', { count: 15 }));
    const handles = world.handles().slice(1);
    const start = handles.map((h) => world.getBody(h));
    settle(world, 600);
    const { drift, drop } = measure(world, handles, start);
    expect(drift).toBeLessThan(0.01);
    expect(drop).toBeLessThan(0.01);
  });

  it('15-box stacks of boxes from 1 m to 3 cm stand alike, wherever they are placed', () => {
    // Boxes placed exactly on one another, as a user builds a stack: whether their faces then
    // touch at 0 or at 1 ulp either way depends on the size's binary expansion and the place,
    // and must not matter. Box2D v3 (C) sways such a stack 1.16 cm at every size (its soft
    // contacts' give is set in metres); 0.1 m boxes swung 17 cm here, and 5 cm boxes fell.
    for (const size of [1, 0.3, 0.1, 0.05, 0.03]) {
      for (const [ox, oy] of [[0, 0], [0, -1000], [123.456, 77.7], [1e5, 1e5]]) {
        const world = new World({ gravity: { x: 0, y: 10 }, friction: 0.6, restitution: 0 });
        world.createBox({ x: ox, y: oy + 1, width: 40, height: 2, type: 'static' });
        const boxes: number[] = [];
        for (let k = 0; k < 15; k++) boxes.push(world.createBox({ x: ox, y: oy - (k + 0.5) * size, width: size, height: size }));
        let sway = 0;
        for (let s = 0; s < 600; s++) {
          world.step(DT);
          for (const h of boxes) sway = Math.max(sway, Math.abs(world.getBody(h).x - ox));
        }
        expect(sway, `size ${size} at (${ox}, ${oy})`).toBeLessThan(0.015);
        // Standing: each box still on the one below (the soft contacts give 7.5 cm in all, in metres).
        const top = world.getBody(boxes[14]);
        expect(oy - top.y, `size ${size} at (${ox}, ${oy})`).toBeGreaterThan(14.5 * size - 0.08);
      }
    }
  });

  it('15-box stacks stand alike placed with gaps between their boxes, or turned with their gravity', () => {
    // A speculative point (a gap) is rigid and a touching one soft; the speculative branch closes
    // a gap to a hair above 0, where the point stayed rigid among soft neighbours. Found by an
    // audit: 1 m boxes placed 1e-12 to 1e-3 m apart swayed 17-26 cm, 0.1 m boxes fell, and a
    // stack turned by 1 rad (ground, boxes and gravity) swayed 4 cm; Box2D v3 sways 1.1-1.2 cm.
    const run = (size: number, gap: number, turn: number): number => {
      const c = Math.cos(turn);
      const s = Math.sin(turn);
      // Up the stack is (s, -c) turned from -y; gravity pulls the other way.
      const world = new World({ gravity: { x: -10 * s, y: 10 * c }, friction: 0.6, restitution: 0 });
      world.createBox({ x: -s, y: c, width: 40, height: 2, angle: turn, type: 'static' });
      const boxes: number[] = [];
      for (let k = 0; k < 15; k++) {
        const up = (k + 0.5) * size + (k + 1) * gap;
        boxes.push(world.createBox({ x: s * up, y: -c * up, width: size, height: size, angle: turn }));
      }
      let sway = 0;
      for (let step = 0; step < 600; step++) {
        world.step(DT);
        for (const h of boxes) {
          const b = world.getBody(h);
          sway = Math.max(sway, Math.abs(b.x * c + b.y * s));
        }
      }
      return sway;
    };
    for (const size of [1, 0.1]) {
      for (const gap of [1e-12, 1e-6, 1e-3]) expect(run(size, gap, 0), `size ${size}, gap ${gap}`).toBeLessThan(0.015);
    }
    for (const turn of [0.3, 1, 2.5]) expect(run(1, 0, turn), `turned ${turn}`).toBeLessThan(0.015);
  });

  it('a box 100 times heavier on three light ones holds them up without toppling', () => {
    const world = buildShapeWorld(buildShapeScene('vertical-stack', { count: 4, massRatio: 100 }));
    const handles = world.handles().slice(1);
    const start = handles.map((h) => world.getBody(h));
    expect(world.getBody(handles[3]).mass).toBeCloseTo(100 * world.getBody(handles[0]).mass, 9);
    settle(world, 600);
    const { drift, drop } = measure(world, handles, start);
    // The light boxes' contacts give under the load (as in Box2D: the top sinks 0.19), but nothing slides or tips.
    expect(drift).toBeLessThan(0.02);
    expect(drop).toBeLessThan(0.1);
    for (const h of handles) expect(Math.abs(world.getBody(h).angle)).toBeLessThan(0.01);
  });

  it("Box2D's card house stands: cards 2 mm thick leaning in pairs on friction alone", () => {
    const world = buildShapeWorld(buildShapeScene('card-house'));
    const handles = world.handles().slice(1);
    const start = handles.map((h) => world.getBody(h));
    settle(world, 600);
    let moved = 0;
    for (let k = 0; k < handles.length; k++) {
      const b = world.getBody(handles[k]);
      moved = Math.max(moved, Math.hypot(b.x - start[k].x, b.y - start[k].y));
    }
    expect(moved).toBeLessThan(0.05);
  });

  it('the card house falls without friction (so the test above can fail)', () => {
    const world = buildShapeWorld(buildShapeScene('card-house', { friction: 0.05 }));
    const handles = world.handles().slice(1);
    const start = handles.map((h) => world.getBody(h));
    settle(world, 300);
    let moved = 0;
    for (let k = 0; k < handles.length; k++) moved = Math.max(moved, Math.abs(world.getBody(handles[k]).y - start[k].y));
    expect(moved).toBeGreaterThan(0.1);
  });
});
