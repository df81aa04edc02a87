import { describe, expect, it } from 'vitest';
import { SHAPE_SCENES, SHAPE_SCENE_NAMES, buildShapeScene, buildShapeWorld } from '../src/index.js';

/** A scene as plain numbers, for comparing builds bit for bit. */
function digest(name: string, params: Record<string, number> = {}): string {
  return JSON.stringify(buildShapeScene(name, params), (_, v) => (typeof v === 'number' ? Object.is(v, -0) ? '-0' : v.toString(16) : v));
}

describe('shape scenes', () => {
  it('build the same bits every time, and a different seed builds another scene', () => {
    for (const name of SHAPE_SCENE_NAMES) expect(digest(name), name).toBe(digest(name));
    for (const name of ['uniform-polygons', 'polygon-box']) {
      expect(digest(name, { n: 50, seed: 1 })).not.toBe(digest(name, { n: 50, seed: 2 }));
    }
  });

  it("have Box2D v3's sizes: the large pyramid's 5,050 boxes, many_pyramids' 22,000, the tumbler's 2,025", () => {
    const dynamic = (name: string) => buildShapeScene(name).bodies.filter((b) => (b.type ?? 'dynamic') === 'dynamic').length;
    expect(dynamic('pyramid')).toBe(5050);
    expect(dynamic('many-pyramids')).toBe(22000);
    expect(buildShapeScene('many-pyramids').segments).toHaveLength(20);
    expect(dynamic('tumbler')).toBe(2025);
    expect(buildShapeScene('tumbler').bodies[0].type).toBe('kinematic');
  });

  it('uniform-polygons keeps its density as N grows: the box grows with the bodies, and they start apart', () => {
    const small = buildShapeScene('uniform-polygons', { n: 1000 });
    const large = buildShapeScene('uniform-polygons', { n: 4000 });
    expect(large.bounds!.width / small.bounds!.width).toBeCloseTo(2, 1);
    const world = buildShapeWorld(buildShapeScene('uniform-polygons', { n: 2000 }));
    world.step(1 / 60);
    // Elastic and apart at the start: the first step finds no overlap to push out, so energy is exact.
    expect(world.stats.contacts).toBeLessThan(20);
  });

  it('polygon-box mixes five kinds in turn and every body fits its box', () => {
    const scene = buildShapeScene('polygon-box', { n: 500 });
    const kinds = scene.bodies.slice(0, 5).map((b) => b.shapes[0].kind);
    expect(kinds).toEqual(['box', 'polygon', 'polygon', 'capsule', 'circle']);
    for (const b of scene.bodies) {
      expect(b.x).toBeGreaterThan(0);
      expect(b.x).toBeLessThan(scene.bounds!.width);
      expect(b.y).toBeGreaterThan(0);
      expect(b.y).toBeLessThan(scene.bounds!.height);
    }
  });

  it('soft bodies poured into the funnel start clear above its walls, however many there are', () => {
    for (const [name, params] of [
      ['jellies', { count: 1 }],
      ['jellies', { count: 20 }],
      ['jellies', { count: 400 }],
      ['jellies', { count: 90, side: 3, stretch: 2 }],
      ['blobs', { count: 12 }],
      ['blobs', { count: 625, segments: 3 }],
      ['blobs', { count: 2000, radius: 0.5 }],
    ] as const) {
      const scene = buildShapeScene(name, params);
      // The funnel: the first two segments, each from its top corner down to the outlet at y = 0.
      for (const wall of scene.segments.slice(0, 2)) {
        const ex = wall.x2 - wall.x1;
        const ey = wall.y2 - wall.y1;
        // Inside the funnel is the side of the wall that the point straight above the outlet lies on.
        const inside = Math.sign(ex * (-1000 - wall.y1) - ey * (0 - wall.x1));
        for (const body of scene.bodies) {
          const t = Math.max(0, Math.min(1, ((body.x - wall.x1) * ex + (body.y - wall.y1) * ey) / (ex * ex + ey * ey)));
          const gap = Math.hypot(body.x - (wall.x1 + t * ex), body.y - (wall.y1 + t * ey)) - (body.shapes[0] as { radius: number }).radius - (wall.thickness ?? 0);
          expect(gap, `${name} ${JSON.stringify(params)}`).toBeGreaterThan(0);
          if (t > 0 && t < 1) expect(Math.sign(ex * (body.y - wall.y1) - ey * (body.x - wall.x1)), `${name} ${JSON.stringify(params)}`).toBe(inside);
        }
      }
    }
  });

  it('every shape scene builds in the engine and steps', () => {
    const small: Record<string, Record<string, number>> = { pyramid: { base: 10 }, 'many-pyramids': { rows: 2, columns: 2 }, 'uniform-polygons': { n: 200 }, 'polygon-box': { n: 200 }, tumbler: { grid: 10 } };
    for (const name of SHAPE_SCENE_NAMES) {
      const world = buildShapeWorld(buildShapeScene(name, small[name] ?? {}));
      for (let s = 0; s < 10; s++) world.step(1 / 60);
      expect(world.bodyCount, name).toBe(buildShapeScene(name, small[name] ?? {}).bodies.length);
    }
  });

  it('refuse parameters out of range by name', () => {
    expect(() => buildShapeScene('polygon-box', { size: 500 })).toThrow(/polygon-box/);
    expect(() => buildShapeScene('uniform-polygons', { minRadius: 9, maxRadius: 8 })).toThrow(/minRadius/);
    expect(() => buildShapeScene('tumbler', { grid: 0 })).toThrow(/grid/);
    expect(Object.keys(SHAPE_SCENES)).toEqual(SHAPE_SCENE_NAMES);
  });
});

describe('shape scenes do what their descriptions and ranges say', () => {
  it("ragdolls: the description counts each ragdoll's parts as the scene builds them", () => {
    const scene = buildShapeScene('ragdolls', { count: 1 });
    const doll = scene.bodies.filter((b) => b.type !== 'static');
    const kinds = doll.map((b) => b.shapes[0].kind);
    const words = ['no', 'one', 'two', 'three', 'four', 'five', 'six', 'seven', 'eight', 'nine', 'ten', 'eleven'];
    const capsules = kinds.filter((k) => k === 'capsule').length;
    expect(kinds.filter((k) => k === 'circle')).toHaveLength(1);
    expect(capsules + 1).toBe(doll.length);
    expect(SHAPE_SCENES.ragdolls.description).toContain(`a round head and ${words[capsules]} capsules`);
    expect(scene.joints).toHaveLength(doll.length - 1);
  });

  it('tumbler: at either end of its speed range, stepped 60 times a second, the drum turns within 1.5 % of that speed', () => {
    // The engine turns no body more than 45 degrees a step: at 60 steps a second a drum asked for
    // 3,600 degrees a second turns 2,666.
    const { min, max } = SHAPE_SCENES.tumbler.params.speed;
    for (const speed of [min, max]) {
      const world = buildShapeWorld(buildShapeScene('tumbler', { grid: 1, speed }));
      let turned = 0;
      let last = world.getBody(0).angle;
      for (let s = 0; s < 60; s++) {
        world.step(1 / 60);
        const angle = world.getBody(0).angle;
        turned += Math.atan2(Math.sin(angle - last), Math.cos(angle - last));
        last = angle;
      }
      expect(Math.abs((turned * 180) / Math.PI / speed - 1), `speed ${speed}`).toBeLessThan(0.015);
    }
  });

  it('ramp: over its whole slope range the box sticks while tan(angle) <= friction and slides otherwise, without tipping', () => {
    const { angle: range, friction: frictions } = SHAPE_SCENES.ramp.params;
    const wrong: string[] = [];
    for (let angle = range.min; angle <= range.max; angle += (range.max - range.min) / 8) {
      const tan = Math.tan((angle * Math.PI) / 180);
      for (const friction of [0.8 * tan, 1.2 * tan + 0.05, frictions.max]) {
        const world = buildShapeWorld(buildShapeScene('ramp', { angle, friction }));
        const start = world.getBody(1);
        let turned = 0;
        for (let s = 0; s < 120; s++) {
          world.step(1 / 60);
          turned = Math.max(turned, Math.abs(world.getBody(1).angle - start.angle));
        }
        const end = world.getBody(1);
        const slid = Math.hypot(end.centerX - start.centerX, end.centerY - start.centerY);
        const theta = (angle * Math.PI) / 180;
        // Two seconds from rest: g (sin - friction cos) t^2 / 2 when it slides.
        const expected = tan <= friction ? 0 : (10 * (Math.sin(theta) - friction * Math.cos(theta)) * 4) / 2;
        if (Math.abs(slid - expected) > 0.02 + 0.03 * expected || turned > (2 * Math.PI) / 180) {
          wrong.push(`angle ${angle} friction ${friction.toFixed(2)}: slid ${slid.toFixed(3)} (expected ${expected.toFixed(3)}), turned ${((turned * 180) / Math.PI).toFixed(1)} degrees`);
        }
      }
    }
    expect(wrong).toEqual([]);
  });

  it('blobs without the funnel fall freely under gravity, and stay where they are without it', () => {
    const drop = (gravity: number) => {
      const scene = buildShapeScene('blobs', { count: 4, funnel: 0, gravity });
      const world = buildShapeWorld(scene);
      const mean = () => world.handles().reduce((sum, h) => sum + world.getBody(h).y, 0) / scene.bodies.length;
      const before = mean();
      for (let s = 0; s < 60; s++) world.step(1 / 60);
      return mean() - before;
    };
    expect(drop(10)).toBeCloseTo(5, 0);
    expect(Math.abs(drop(0))).toBeLessThan(0.01);
    expect(SHAPE_SCENES.blobs.params.funnel.description).toMatch(/0: no funnel or floor, so they fall/);
  });
});
