import { World, type WorldOptions } from '@maxgrid/engine';

/**
 * A scene as plain data: every engine adapter in the lab builds from the same numbers, and the
 * maxgrid world is just one more consumer (`buildWorld`). Coordinates are the report's canvas
 * units (pixels, y pointing down, gravity positive downwards).
 */
export interface Scene {
  name: string;
  params: Readonly<Record<string, number>>;
  /** The world's box; with `open`, only the region the bodies start in (for framing a view). */
  bounds: { width: number; height: number };
  /** True where the world has no box: bodies may go anywhere. */
  open?: boolean;
  gravity: { x: number; y: number };
  /** Restitution of every circle and of the walls. */
  restitution: number;
  count: number;
  x: Float64Array;
  y: Float64Array;
  vx: Float64Array;
  vy: Float64Array;
  radius: Float64Array;
  /**
   * 1 where circle k is static (pegs, obstacles), or null when every circle is dynamic. Peer
   * engines in the lab only take scenes without static circles or segments.
   */
  fixed: Uint8Array | null;
  /** Static walls at any angle, besides the box. */
  segments: SceneSegment[];
}

/** A static wall from (x1, y1) to (x2, y2), as the engine's createSegment takes it. */
export interface SceneSegment {
  x1: number;
  y1: number;
  x2: number;
  y2: number;
  thickness: number;
}

export function allocateScene(
  name: string,
  params: Record<string, number>,
  count: number,
  world: Pick<Scene, 'bounds' | 'gravity' | 'restitution'>,
): Scene {
  return {
    name,
    params: Object.freeze({ ...params }),
    ...world,
    count,
    x: new Float64Array(count),
    y: new Float64Array(count),
    vx: new Float64Array(count),
    vy: new Float64Array(count),
    radius: new Float64Array(count),
    fixed: null,
    segments: [],
  };
}

const bits = new Float64Array(1);
const word = new BigUint64Array(bits.buffer);

/**
 * `at` moved, where it must be, into the span of centres from which a circle of radius r lies
 * inside [0, side] as the engine tests it (centre - r >= 0, centre + r <= side, both rounded).
 * side - r rounds up for some radii, and a centre there pokes an ulp past the wall, which the
 * engine refuses; so the upper end steps down an ulp at a time until it holds. A centre already
 * inside is returned as it is, so scenes that fitted keep their bits. Needs 2r <= side.
 */
export function clampInside(at: number, r: number, side: number): number {
  let high = side - r;
  while (high + r > side) {
    // The next double below a positive one: its bit pattern, less one.
    bits[0] = high;
    word[0] -= 1n;
    high = bits[0];
  }
  return Math.min(high, Math.max(r, at));
}

/** Layers of one body: see the engine's `category` and `mask`. */
export interface Layers {
  category: number;
  mask: number;
}

/**
 * Every World option the scene does not fix (bounds, gravity and restitution come from the scene),
 * plus collision layers: `layers(k, isStatic)` for circle k, and `segmentLayers` for every segment.
 */
export interface BuildOptions extends Omit<WorldOptions, 'bounds' | 'gravity' | 'restitution'> {
  /** The collision layers of circle k; without it every circle keeps the defaults (category 1, every mask bit). */
  layers?: (k: number, isStatic: boolean) => Layers;
  /** The collision layers of every segment. */
  segmentLayers?: Layers;
}

/** A maxgrid world holding the scene; circle k gets handle k. */
export function buildWorld(scene: Scene, options: BuildOptions = {}): World {
  const { layers, segmentLayers, ...worldOptions } = options;
  const world = new World({
    bounds: scene.open ? null : scene.bounds,
    gravity: scene.gravity,
    restitution: scene.restitution,
    ...worldOptions,
  });
  world.reserve(scene.count);
  for (let k = 0; k < scene.count; k++) {
    const isStatic = scene.fixed !== null && scene.fixed[k] === 1;
    world.createCircle({
      x: scene.x[k],
      y: scene.y[k],
      vx: isStatic ? 0 : scene.vx[k],
      vy: isStatic ? 0 : scene.vy[k],
      radius: scene.radius[k],
      type: isStatic ? 'static' : 'dynamic',
      ...(layers ? layers(k, isStatic) : {}),
    });
  }
  for (const s of scene.segments) world.createSegment(segmentLayers ? { ...s, ...segmentLayers } : s);
  return world;
}
