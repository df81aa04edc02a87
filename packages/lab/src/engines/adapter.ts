import type { Scene } from '@maxgrid/scenes';

/**
 * One physics engine behind the lab's common interface. Every adapter builds from the same
 * `Scene` data (report pixels, y down, gravity positive downwards), converts to its own units on
 * the way in and back on the way out, so experiments only ever see scene units.
 */
export interface EngineInfo {
  /** Registry id, e.g. `maxgrid:sap` or `box2d-wasm`. */
  id: string;
  /** npm package the engine comes from. */
  package: string;
  /** Version read from that package's package.json. */
  version: string;
  /** Storage precision of positions and velocities inside the engine. */
  precision: 'f64' | 'f32';
  /** Engine length units per scene pixel (1/50 means 1 m = 50 px); 0 on a shape engine's row, whose units are per scene (shapeEngineRow). */
  lengthScale: number;
  /** The exact settings the adapter applies, as written into every output file. */
  settings: Record<string, string | number | boolean>;
}

/** Caller-owned columns that `read` fills, in scene units, index k = scene body k. */
export interface BodyState {
  x: Float64Array;
  y: Float64Array;
  vx: Float64Array;
  vy: Float64Array;
}

export interface Simulation {
  readonly count: number;
  step(dt: number): void;
  read(out: BodyState): void;
  /** Radii as the engine stores them, in scene units, for checking the build. */
  readRadii(out: Float64Array): void;
  /** Broad-phase candidates and true contacts of the last step, where the engine reports them. */
  /**
   * Broad-phase work of the last step, where the engine reports it: pairs examined (pairTests),
   * pairs passed on to the narrow-phase (candidatePairs) and true contacts.
   */
  pairStats?(): { pairTests: number; candidatePairs: number; contacts: number };
  /** Broad- and narrow-phase time of the last step, where the engine reports them. */
  phaseMs?(): { broadphaseMs: number; narrowphaseMs: number };
  /** Engine memory, where the engine reports it. */
  memoryBytes?(): number;
  /** Exact-state digest, where the engine has one (maxgrid). */
  stateHash?(): string;
  /** Frees WASM memory; the simulation is unusable afterwards. */
  dispose(): void;
}

export interface Engine {
  info: EngineInfo;
  create(scene: Scene): Simulation;
}

/**
 * Environment hooks for box2d-wasm, whose Emscripten loader cannot find its .wasm by itself
 * everywhere: the browser page says where Vite put the files, and Node passes the bytes (the
 * loader would `fetch` a bare file path, which Node's fetch rejects).
 */
export interface LoadOptions {
  box2dLocateFile?: (file: string, prefix: string) => string;
  box2dWasmBinary?: Uint8Array;
}

export interface EngineProvider {
  id: string;
  load(options?: LoadOptions): Promise<Engine>;
}

export function allocateState(count: number): BodyState {
  return {
    x: new Float64Array(count),
    y: new Float64Array(count),
    vx: new Float64Array(count),
    vy: new Float64Array(count),
  };
}

/**
 * Box2D and its relatives are tuned for bodies of 0.1 to 10 m, so scene pixels are scaled by
 * 1/50 (1 m = 50 px): the scenes' radii of 2 to 12 px become 0.04 to 0.24 m and the 1600 x 900
 * box 32 x 18 m. Matter.js is tuned for pixels and keeps scale 1.
 */
export const METERS_PER_PIXEL = 1 / 50;

/** Mass convention for every engine's energy: density 1 per square scene unit, m = pi r^2. */
export function sceneMasses(scene: Scene): Float64Array {
  const m = new Float64Array(scene.count);
  for (let k = 0; k < scene.count; k++) m[k] = Math.PI * scene.radius[k] * scene.radius[k];
  return m;
}

export interface Energy {
  kinetic: number;
  potential: number;
  total: number;
}

/**
 * Energy from read-back state in scene units, identical for all engines. Potential energy is
 * m g h with h the centre's distance from the wall gravity points at (the floor, for the scenes'
 * downward gravity), so it is never negative; the bouncing ball starts at m g (drop + radius).
 */
export function energyOf(scene: Scene, masses: Float64Array, state: BodyState): Energy {
  const gx = scene.gravity.x;
  const gy = scene.gravity.y;
  const refX = gx > 0 ? scene.bounds.width : 0;
  const refY = gy > 0 ? scene.bounds.height : 0;
  let kinetic = 0;
  let potential = 0;
  for (let k = 0; k < scene.count; k++) {
    const m = masses[k];
    kinetic += 0.5 * m * (state.vx[k] * state.vx[k] + state.vy[k] * state.vy[k]);
    potential += m * (gx * (refX - state.x[k]) + gy * (refY - state.y[k]));
  }
  return { kinetic, potential, total: kinetic + potential };
}

/** A static wall as an axis-aligned rectangle, centre and full size, in scene units. */
export interface WallRect {
  cx: number;
  cy: number;
  width: number;
  height: number;
}

/**
 * The scene's box as four thick static rectangles just outside it. Thick walls (a quarter of the
 * larger side) stop fast circles tunnelling without CCD; top and bottom overlap the corners.
 */
export function boxWalls(bounds: { width: number; height: number }): WallRect[] {
  const { width: w, height: h } = bounds;
  const t = Math.max(w, h) / 4;
  return [
    { cx: w / 2, cy: -t / 2, width: w + 2 * t, height: t },
    { cx: w / 2, cy: h + t / 2, width: w + 2 * t, height: t },
    { cx: -t / 2, cy: h / 2, width: t, height: h },
    { cx: w + t / 2, cy: h / 2, width: t, height: h },
  ];
}

/**
 * Peer adapters build only dynamic circles in the scene's box; a scene with static circles or
 * segments would silently lose them, so they refuse it by name instead (maxgrid builds them).
 */
export function requirePeerScene(scene: Scene, engineId: string): void {
  const statics = scene.fixed === null ? 0 : scene.fixed.reduce((a, f) => a + f, 0);
  if (statics > 0 || scene.segments.length > 0) {
    throw new RangeError(
      `engine '${engineId}' cannot build scene '${scene.name}': it has ${statics} static circles and ${scene.segments.length} segments, and the lab's peer adapters take only dynamic circles in a box (use a maxgrid engine)`,
    );
  }
}
