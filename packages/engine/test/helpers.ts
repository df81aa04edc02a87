import fc from 'fast-check';
import { World, BROADPHASE_NAMES, type WorldOptions } from '../src/index.js';
import { BodyStore } from '../src/store/body-store.js';
import { TypeCode } from '../src/store/body-types.js';

export interface CircleSpec {
  x: number;
  y: number;
  vx: number;
  vy: number;
  radius: number;
}

export interface SceneSpec {
  width: number;
  height: number;
  gravity: number;
  restitution: number;
  circles: CircleSpec[];
}

/**
 * Random boxed scenes: non-square boxes, radius ratios up to 1:50, mixed speeds, and circles
 * that may start overlapping. Positions are generated as fractions so every circle fits.
 */
export const sceneArbitrary: fc.Arbitrary<SceneSpec> = fc
  .record({
    width: fc.double({ min: 50, max: 2000, noNaN: true }),
    aspect: fc.double({ min: 0.2, max: 5, noNaN: true }),
    minRadius: fc.double({ min: 0.5, max: 4, noNaN: true }),
    ratio: fc.double({ min: 1, max: 50, noNaN: true }),
    gravity: fc.oneof(fc.constant(0), fc.double({ min: -500, max: 500, noNaN: true })),
    restitution: fc.oneof(fc.constant(1), fc.double({ min: 0, max: 1, noNaN: true })),
    raw: fc.array(
      fc.record({
        fx: fc.double({ min: 0, max: 1, noNaN: true }),
        fy: fc.double({ min: 0, max: 1, noNaN: true }),
        fr: fc.double({ min: 0, max: 1, noNaN: true }),
        vx: fc.double({ min: -400, max: 400, noNaN: true }),
        vy: fc.double({ min: -400, max: 400, noNaN: true }),
      }),
      { minLength: 2, maxLength: 120 },
    ),
  })
  .map(({ width, aspect, minRadius, ratio, gravity, restitution, raw }) => {
    const height = Math.max(20, width * aspect);
    const maxRadius = Math.min(minRadius * ratio, Math.min(width, height) / 4);
    const circles = raw.map(({ fx, fy, fr, vx, vy }) => {
      const radius = Math.min(maxRadius, minRadius + fr * (maxRadius - minRadius));
      return {
        x: radius + fx * (width - 2 * radius),
        y: radius + fy * (height - 2 * radius),
        vx,
        vy,
        radius,
      };
    });
    return { width, height, gravity, restitution, circles };
  });

export function buildSpec(spec: SceneSpec, options: WorldOptions = {}): World {
  const world = new World({
    bounds: { width: spec.width, height: spec.height },
    gravity: { x: 0, y: spec.gravity },
    restitution: spec.restitution,
    ...options,
  });
  for (const c of spec.circles) world.createCircle(c);
  return world;
}

/** mulberry32, for tests that need many random numbers outside fast-check. */
export function rng(seed: number): () => number {
  let state = seed >>> 0;
  return () => {
    state = (state + 0x6d2b79f5) | 0;
    let t = Math.imul(state ^ (state >>> 15), state | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** n random circles (radius 2..6) in a box, or around the origin when `box` is false. */
export function randomWorld(n: number, seed: number, options: WorldOptions = {}, speed = 100): World {
  const random = rng(seed);
  const world = new World(options);
  const width = options.bounds?.width ?? 600;
  const height = options.bounds?.height ?? 400;
  for (let i = 0; i < n; i++) {
    const radius = 2 + 4 * random();
    world.createCircle({
      x: radius + random() * (width - 2 * radius),
      y: radius + random() * (height - 2 * radius),
      vx: (random() - 0.5) * 2 * speed,
      vy: (random() - 0.5) * 2 * speed,
      radius,
    });
  }
  return world;
}

export { BROADPHASE_NAMES };

/** A body store of resting dynamic circles (x, y, radius r), then with the given slots destroyed. */
export function storeOf(list: { x: number; y: number; r: number }[], holes: number[] = []): BodyStore {
  const store = new BodyStore();
  for (const c of list) {
    store.add({ x: c.x, y: c.y, vx: 0, vy: 0, radius: c.r, mass: 1, restitution: 1, type: TypeCode.dynamic, category: 1, mask: 0xffffffff, gravityScale: 1, linearDamping: 0 });
  }
  for (const slot of holes) if (slot < store.slotCount && store.type[slot] !== TypeCode.free) store.remove(slot);
  return store;
}

/**
 * Steps a world from `build` with one of the engine's path switches (setGridKernelEnabled,
 * setBodyKernelEnabled) set to `on` while it is built and stepped, and returns its state hash;
 * `mutate` runs before each step.
 */
export function hashWithPath(
  setEnabled: (on: boolean) => void,
  on: boolean,
  build: () => World,
  steps: number,
  mutate?: (world: World, step: number) => void,
): string {
  setEnabled(on);
  try {
    const world = build();
    for (let s = 0; s < steps; s++) {
      mutate?.(world, s);
      world.step(1 / 60);
    }
    return world.stateHash();
  } finally {
    setEnabled(true);
  }
}
