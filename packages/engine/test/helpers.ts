import fc from 'fast-check';
import { expect } from 'vitest';
import { World, BROADPHASE_NAMES, type RayHit, type WorldOptions } from '../src/index.js';
import { setGridKernelEnabled } from '../src/broadphase/grid-kernel.js';
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

/** What a world's query code exposes to tests: its per-body tests, its grid and its work counter. */
interface QueriesInside {
  examined: number;
  /** The query's mask, which the per-body tests below apply to each shape. */
  mask: number;
  grid: { originX: number; originY: number; cellSize: number; columns: number; rows: number };
  contains(slot: number, px: number, py: number): boolean;
  overlaps(slot: number, minX: number, minY: number, maxX: number, maxY: number): boolean;
  rayBody(slot: number, x1: number, y1: number, dx: number, dy: number): number;
  write(hit: RayHit, slot: number, t: number, x1: number, y1: number, dx: number, dy: number): RayHit;
}

export function queriesOf(world: World): QueriesInside {
  return (world as unknown as { queries: QueriesInside }).queries;
}

function bodiesOf(world: World): BodyStore {
  return (world as unknown as { bodies: BodyStore }).bodies;
}

/**
 * The queries answered by testing every body in turn with the query code's own per-body tests:
 * what a grid search must return, hit for hit and bit for bit.
 */
export const bruteQueries = {
  point(world: World, px: number, py: number, mask: number): number[] {
    const q = queriesOf(world);
    q.mask = mask;
    const bodies = bodiesOf(world);
    return world.handles().filter((h) => {
      const s = bodies.slotOf(h);
      return (bodies.category[s] & mask) !== 0 && q.contains(s, px, py);
    });
  },
  box(world: World, minX: number, minY: number, maxX: number, maxY: number, mask: number): number[] {
    const q = queriesOf(world);
    q.mask = mask;
    const bodies = bodiesOf(world);
    return world.handles().filter((h) => {
      const s = bodies.slotOf(h);
      return (bodies.category[s] & mask) !== 0 && q.overlaps(s, minX, minY, maxX, maxY);
    });
  },
  rayAll(world: World, x1: number, y1: number, x2: number, y2: number, mask: number): RayHit[] {
    const q = queriesOf(world);
    q.mask = mask;
    const bodies = bodiesOf(world);
    const hits: RayHit[] = [];
    for (const h of world.handles()) {
      const s = bodies.slotOf(h);
      if ((bodies.category[s] & mask) === 0) continue;
      const t = q.rayBody(s, x1, y1, x2 - x1, y2 - y1);
      if (t >= 0) hits.push(q.write({ handle: 0, fraction: 0, x: 0, y: 0, normalX: 0, normalY: 0 }, s, t, x1, y1, x2 - x1, y2 - y1));
    }
    // The documented order: by fraction; fractions that tie (a ray too long for them to tell
    // hits apart) by where the points lie along the ray, beyond the points' own rounding; then by handle.
    const dx = x2 - x1;
    const dy = y2 - y1;
    const along = (a: RayHit, b: RayHit): number => {
      const d = (a.x - b.x) * dx + (a.y - b.y) * dy;
      const size = Math.abs(a.x) + Math.abs(a.y) + Math.abs(b.x) + Math.abs(b.y);
      return Math.abs(d) <= 1e-12 * size * (Math.abs(dx) + Math.abs(dy)) ? 0 : Math.sign(d);
    };
    return hits.sort((a, b) => a.fraction - b.fraction || along(a, b) || a.handle - b.handle);
  },
};

/** Whether some body of the world lies outside the extent of its query grid (binned into an edge cell). */
export function someOutsideQueryGrid(world: World): boolean {
  const { originX, originY, cellSize, columns, rows } = queriesOf(world).grid;
  const bodies = bodiesOf(world);
  return world.handles().some((h) => {
    const x = bodies.x[bodies.slotOf(h)];
    const y = bodies.y[bodies.slotOf(h)];
    return x < originX || y < originY || x >= originX + columns * cellSize || y >= originY + rows * cellSize;
  });
}

/**
 * A crowd of 260 to 1,500 bodies in a patch 150 wide, some static, one maybe destroyed, and up to
 * four more far away (10^3 to 10^9, together or apart, in any direction), binned by WebAssembly or
 * TypeScript: enough bodies that a fitted grid may leave some of the crowd out (1 in 256 at either
 * end), and far ones it must leave out.
 */
export interface FarWorldSpec {
  crowd: { u: number; v: number; size: number; angle: number; category: number; kind: number }[];
  far: { distance: number; direction: number; near: number; dx: number; dy: number }[];
  staticEvery: number;
  destroy: boolean;
  kernel: boolean;
}

export const CROWD_WIDTH = 150;

export const farWorldArbitrary: fc.Arbitrary<FarWorldSpec> = fc.record({
  crowd: fc.array(
    fc.record({
      u: fc.double({ min: 0, max: 1, noNaN: true }),
      v: fc.double({ min: 0, max: 1, noNaN: true }),
      size: fc.double({ min: 0.5, max: 2, noNaN: true }),
      angle: fc.double({ min: -4, max: 4, noNaN: true }),
      category: fc.constantFrom(1, 2, 4),
      kind: fc.integer({ min: 0, max: 3 }),
    }),
    { minLength: 260, maxLength: 1500 },
  ),
  far: fc.array(
    fc.record({
      distance: fc.constantFrom(1e3, 1e4, 1e6, 1e9),
      direction: fc.integer({ min: 0, max: 8 }),
      // Index of an earlier far body to sit beside (touching it), or none.
      near: fc.integer({ min: -1, max: 3 }),
      dx: fc.double({ min: -3, max: 3, noNaN: true }),
      dy: fc.double({ min: -3, max: 3, noNaN: true }),
    }),
    { minLength: 0, maxLength: 4 },
  ),
  staticEvery: fc.constantFrom(0, 7),
  destroy: fc.boolean(),
  kernel: fc.boolean(),
});

/** Eight directions, and one off every axis and diagonal. */
const COMPASS = [[1, 0], [1, 1], [0, 1], [-1, 1], [-1, 0], [-1, -1], [0, -1], [1, -1], [0.37, -0.81]] as const;

/** Builds a FarWorldSpec's world; `shapes` makes boxes, triangles and capsules among the circles. Returns it and its far bodies' centres. */
export function buildFarWorld(spec: FarWorldSpec, shapes: boolean): { world: World; far: { x: number; y: number }[] } {
  setGridKernelEnabled(spec.kernel);
  try {
    const world = new World();
    const make = (x: number, y: number, size: number, angle: number, category: number, kind: number, isStatic: boolean) => {
      const type = isStatic ? ('static' as const) : ('dynamic' as const);
      if (!shapes || kind === 0) return world.createCircle({ x, y, radius: size, category, type });
      if (kind === 1) return world.createBox({ x, y, width: 2 * size, height: size, angle, category, type });
      if (kind === 2) return world.createPolygon({ x, y, angle, category, type, vertices: [{ x: -size, y: -size }, { x: size, y: -size }, { x: 0, y: size }] });
      return world.createCapsule({ x, y, length: 2 * size, radius: size / 2, angle, category, type });
    };
    spec.crowd.forEach((b, k) => make(b.u * CROWD_WIDTH, b.v * CROWD_WIDTH, b.size, b.angle, b.category, b.kind, spec.staticEvery > 0 && k % spec.staticEvery === 0));
    const far: { x: number; y: number }[] = [];
    spec.far.forEach((f, k) => {
      const [ux, uy] = COMPASS[f.direction];
      const beside = f.near >= 0 && f.near < far.length ? far[f.near] : null;
      const x = beside ? beside.x + f.dx : CROWD_WIDTH / 2 + ux * f.distance;
      const y = beside ? beside.y + f.dy : CROWD_WIDTH / 2 + uy * f.distance;
      far.push({ x, y });
      make(x, y, 1.5, f.dx, 1 << (k % 3), k, false);
    });
    if (spec.destroy) world.destroyBody(world.handles()[spec.crowd.length >> 1]);
    return { world, far };
  } finally {
    setGridKernelEnabled(true);
  }
}

/**
 * A point a query is made from: in or around the crowd (kind 0), beside a far body (1), or 10^3 to
 * 10^12 beyond either (2).
 */
export interface AnchorSpec {
  kind: number;
  u: number;
  v: number;
  k: number;
  jx: number;
  jy: number;
  direction: number;
  beyond: number;
}

export const anchorArbitrary: fc.Arbitrary<AnchorSpec> = fc.record({
  kind: fc.integer({ min: 0, max: 2 }),
  u: fc.double({ min: -0.2, max: 1.2, noNaN: true }),
  v: fc.double({ min: -0.2, max: 1.2, noNaN: true }),
  k: fc.nat(7),
  jx: fc.double({ min: -4, max: 4, noNaN: true }),
  jy: fc.double({ min: -4, max: 4, noNaN: true }),
  direction: fc.integer({ min: 0, max: 8 }),
  beyond: fc.constantFrom(1e3, 1e7, 1e12),
});

export function anchorPoint(a: AnchorSpec, far: { x: number; y: number }[]): { x: number; y: number } {
  const crowd = { x: a.u * CROWD_WIDTH, y: a.v * CROWD_WIDTH };
  const base = far.length > 0 && (a.kind === 1 || (a.kind === 2 && a.k % 2 === 1)) ? far[a.k % far.length] : crowd;
  const [ux, uy] = COMPASS[a.direction];
  if (a.kind === 2) return { x: base.x + ux * a.beyond, y: base.y + uy * a.beyond };
  return { x: base.x + a.jx, y: base.y + a.jy };
}

export interface FarQuery {
  kind: 'point' | 'box' | 'around' | 'ray';
  a: AnchorSpec;
  b: AnchorSpec;
  size: number;
  mask: number;
}

/** A point, a box between two anchors or around one, or a ray from one anchor to another. */
export const farQueryArbitrary: fc.Arbitrary<FarQuery> = fc.record({
  kind: fc.constantFrom('point' as const, 'box' as const, 'around' as const, 'ray' as const),
  a: anchorArbitrary,
  b: anchorArbitrary,
  size: fc.double({ min: 0, max: 30, noNaN: true }),
  mask: fc.constantFrom(0xffffffff, 1, 6),
});

/** Runs `queries` on the world and on bruteQueries; they must agree exactly. */
export function expectQueriesAsBrute(world: World, far: { x: number; y: number }[], queries: FarQuery[]): void {
  for (const query of queries) {
    const a = anchorPoint(query.a, far);
    const b = anchorPoint(query.b, far);
    const { mask } = query;
    const what = `${query.kind} (${a.x}, ${a.y}) (${b.x}, ${b.y}) mask ${mask}`;
    if (query.kind === 'point') {
      expect(world.queryPoint(a.x, a.y, { mask }), what).toEqual(bruteQueries.point(world, a.x, a.y, mask));
    } else if (query.kind === 'box' || query.kind === 'around') {
      const [minX, minY, maxX, maxY] =
        query.kind === 'box' ? [Math.min(a.x, b.x), Math.min(a.y, b.y), Math.max(a.x, b.x), Math.max(a.y, b.y)] : [a.x - query.size, a.y - query.size, a.x + query.size, a.y + query.size];
      expect(world.queryAABB(minX, minY, maxX, maxY, { mask }), `${what} box ${minX} ${minY} ${maxX} ${maxY}`).toEqual(bruteQueries.box(world, minX, minY, maxX, maxY, mask));
    } else {
      const expected = bruteQueries.rayAll(world, a.x, a.y, b.x, b.y, mask);
      expect(world.rayCastAll(a.x, a.y, b.x, b.y, { mask }), what).toEqual(expected);
      expect(world.rayCast(a.x, a.y, b.x, b.y, { mask }), what).toEqual(expected[0] ?? null);
    }
  }
}

/**
 * Runs `numRuns` random far-body worlds (circles, or with `shapes` boxes and polygons) through
 * expectQueriesAsBrute; returns in how many the query grid left some body outside its extent.
 */
export function farQueriesAsBrute(shapes: boolean, numRuns: number, seed: number): number {
  let outside = 0;
  fc.assert(
    fc.property(farWorldArbitrary, fc.array(farQueryArbitrary, { minLength: 1, maxLength: 16 }), (spec, queries) => {
      const { world, far } = buildFarWorld(spec, shapes);
      expectQueriesAsBrute(world, far, queries);
      if (someOutsideQueryGrid(world)) outside++;
    }),
    { numRuns, seed },
  );
  return outside;
}
