import { World, BodyTypeCode, type BroadPhaseName, type IntegratorName } from '@maxgrid/engine';
import { buildScene } from '@maxgrid/scenes';
import { sceneParams, type Settings } from './settings.js';
import { BodyColors } from './colors.js';
import { Recorder } from './monitor/recorder.js';
import { HitEvents } from './hit-events.js';
import { TouchEvents } from './touch-events.js';
import { buildSandboxWorld, flatSegments, hitThreshold, layerMask, layerOf } from './scene-world.js';

/** The fixed physics step: rendering runs at whatever rate the display gives. */
export const DT = 1 / 60;
/** At most this many steps per frame, so one slow frame cannot make the next one slower still. */
const MAX_STEPS_PER_FRAME = 4;
/** ...and no more catching up once a frame has spent this long stepping. */
const STEP_BUDGET_MS = 40;

/**
 * The world plus everything that runs it: the fixed-step accumulator, the recorded series and the
 * pointer drag. A rebuild replaces the world; switching broad-phase or integrator does not.
 */
export class Simulation {
  world!: World;
  readonly colors = new BodyColors();
  readonly recorder = new Recorder();
  time = 0;
  paused = false;
  /** Steps dropped because a frame ran out of budget: shown so a slowed-down run is visible. */
  droppedSteps = 0;
  private accumulator = 0;
  /** Total mass of dynamic bodies: moves the potential energy's zero to the floor (see below). */
  private dynamicMass = 0;
  private boxWidth = 1600;
  private boxHeight = 900;
  private gravityY = 0;
  /** Read every frame by the renderers, so one object kept up to date rather than a new one. */
  readonly box = { width: 1600, height: 900 };
  /** Static segments of the scene (x1, y1, x2, y2, thickness each); they never change. */
  segments: Float64Array = new Float64Array(0);
  /** Static circles in the scene: renderers skip their extra pass when there are none. */
  staticCircles = 0;
  /** Begin and end touch events of the last step, and which bodies to flash. */
  readonly touches = new TouchEvents();
  /** Hits of the last step (collisions above the threshold), and which bodies to ring. */
  readonly hits = new HitEvents();
  /** World options of the current world, for the monitor to show what applies. */
  layers = false;
  continuous = true;
  private dragHandle = -1;
  private dragX = 0;
  private dragY = 0;

  constructor(private readonly now: () => number = () => performance.now()) {}

  /**
   * Rebuilds the scene from the settings: the same settings always give the same bodies. Throws,
   * leaving the current world as it was, when the scene refuses its parameters (too many circles
   * to fit the funnel, a minimum radius above the maximum).
   */
  rebuild(settings: Settings): void {
    const scene = buildScene(settings.scene, sceneParams(settings));
    const world = buildSandboxWorld(scene, DT, settings);
    this.world?.stopWorkers();
    this.world = world;
    this.layers = settings.layers;
    this.continuous = settings.continuous;
    this.segments = flatSegments(scene);
    this.touches.reset(settings.events);
    this.hits.reset(settings.hits, hitThreshold(scene, DT));
    this.boxWidth = scene.bounds.width;
    this.boxHeight = scene.bounds.height;
    this.box.width = this.boxWidth;
    this.box.height = this.boxHeight;
    this.gravityY = scene.gravity.y;
    const v = this.world.views();
    this.colors.reset(settings.seed, v.slotCount, settings.layers);
    this.dynamicMass = 0;
    this.staticCircles = 0;
    for (let s = 0; s < v.slotCount; s++) {
      if (v.type[s] === BodyTypeCode.dynamic) this.dynamicMass += v.mass[s];
      else if (v.type[s] === BodyTypeCode.static) this.staticCircles++;
    }
    this.recorder.clear();
    this.time = 0;
    this.accumulator = 0;
    this.droppedSteps = 0;
    this.dragHandle = -1;
  }

  setBroadphase(name: BroadPhaseName): void {
    this.world.setBroadphase(name);
  }

  setIntegrator(name: IntegratorName): void {
    this.world.setIntegrator(name);
  }

  /**
   * Steps the world on `threads` threads (world.startWorkers). The workers start asynchronously;
   * until they run, and for worlds under the engine's minimum size, steps stay on this thread,
   * with the same results either way. `failed` hears why workers could not start.
   */
  setThreads(threads: number, failed: (message: string) => void): void {
    const world = this.world;
    if (threads <= 1) {
      world.stopWorkers();
      return;
    }
    if (world.workerCount === threads) return;
    world.startWorkers(threads).then(
      () => {
        // Rebuilt while the workers were starting: they belong to a world no longer shown.
        if (this.world !== world) world.stopWorkers();
      },
      (error: unknown) => failed(error instanceof Error ? error.message : String(error)),
    );
  }

  /** Advances by the real time elapsed since the last frame, in whole fixed steps. */
  advance(elapsedSeconds: number): number {
    if (this.paused) return 0;
    this.accumulator += elapsedSeconds;
    const start = this.now();
    let steps = 0;
    while (this.accumulator >= DT) {
      if (steps >= MAX_STEPS_PER_FRAME || this.now() - start > STEP_BUDGET_MS) {
        // Behind real time: drop the backlog and run slow rather than spiral.
        this.droppedSteps += Math.floor(this.accumulator / DT);
        this.accumulator = 0;
        break;
      }
      this.stepOnce();
      this.accumulator -= DT;
      steps++;
    }
    return steps;
  }

  stepOnce(): void {
    const world = this.world;
    this.applyDrag();
    world.step(DT);
    this.time += DT;
    this.touches.record(world);
    this.hits.record(world);
    const stats = world.stats;
    this.recorder.record(this.time, stats.totalMs, world.kineticEnergy(), this.potentialEnergy(), stats.candidatePairs, stats.contacts);
  }

  /**
   * The report's E_P = m g h with h the height above the floor the bodies fall towards. The engine
   * measures from y = 0 (the top of the box), which gives large negative numbers that swamp the
   * kinetic energy on a graph; the difference is a constant, g H times the dynamic mass.
   */
  potentialEnergy(): number {
    const g = this.gravityY;
    return this.world.potentialEnergy() + (g > 0 ? g * this.boxHeight * this.dynamicMass : 0);
  }

  /** Whether gravity pulls bodies down, towards the floor. */
  get falls(): boolean {
    return this.gravityY > 0;
  }

  /** Dynamic bodies whose centre is in the lower half of the box: shows a scene falling. */
  lowerHalf(): number {
    const v = this.world.views();
    const half = this.boxHeight / 2;
    let n = 0;
    for (let s = 0; s < v.slotCount; s++) if (v.type[s] === BodyTypeCode.dynamic && v.y[s] > half) n++;
    return n;
  }

  /**
   * The handle of the topmost movable body under a world point, or -1. Static pegs are not
   * picked up: a drag ends by making the body dynamic. Scans every body: per click only.
   */
  bodyAt(x: number, y: number): number {
    const v = this.world.views();
    let found = -1;
    for (let s = 0; s < v.slotCount; s++) {
      if (v.type[s] === BodyTypeCode.free || v.type[s] === BodyTypeCode.static) continue;
      const dx = v.x[s] - x;
      const dy = v.y[s] - y;
      const r = Math.max(v.radius[s], 3);
      if (dx * dx + dy * dy <= r * r) found = s;
    }
    return found < 0 ? -1 : this.world.handleAtSlot(found);
  }

  /**
   * Holds a body at the pointer. It becomes kinematic while held, so it pushes others without being
   * pushed back or pulled by gravity, and is thrown with the pointer's velocity when released.
   */
  beginDrag(handle: number, x: number, y: number): void {
    this.dragHandle = handle;
    this.dynamicMass -= this.world.getCircle(handle).mass;
    this.world.setType(handle, 'kinematic');
    this.dragX = x;
    this.dragY = y;
  }

  moveDrag(x: number, y: number): void {
    this.dragX = x;
    this.dragY = y;
    // While paused nothing steps, so move the body now for the user to see it follow.
    if (this.paused && this.dragHandle >= 0) this.placeDragged(x, y);
  }

  endDrag(): void {
    const h = this.dragHandle;
    this.dragHandle = -1;
    if (h < 0 || !this.world.hasBody(h)) return;
    const c = this.world.getCircle(h);
    this.world.setType(h, 'dynamic');
    this.dynamicMass += c.mass;
    this.world.setVelocity(h, c.vx, c.vy);
  }

  get dragging(): number {
    return this.dragHandle;
  }

  /** Adds a circle of the current mean size at a world point, clamped into the box. */
  spawn(x: number, y: number, radius: number): number {
    const r = Math.min(radius, this.boxWidth / 2, this.boxHeight / 2);
    const cx = Math.min(this.boxWidth - r, Math.max(r, x));
    const cy = Math.min(this.boxHeight - r, Math.max(r, y));
    const handle = this.world.createCircle({ x: cx, y: cy, radius: r });
    // The new body joins the layer of its slot, as built ones do.
    const slot = this.world.slotOfHandle(handle);
    if (this.layers) this.world.setCollisionFilter(handle, layerOf(slot), layerMask(slot));
    this.dynamicMass += this.world.getCircle(handle).mass;
    this.colors.ensure(this.world.views().slotCount);
    return handle;
  }

  // The held body is steered by velocity, not teleported: the step then carries it exactly onto
  // the pointer, and the solver sees a real velocity for the bodies it pushes.
  private applyDrag(): void {
    const h = this.dragHandle;
    if (h < 0) return;
    if (!this.world.hasBody(h)) {
      this.dragHandle = -1;
      return;
    }
    const c = this.world.getCircle(h);
    const x = Math.min(this.boxWidth - c.radius, Math.max(c.radius, this.dragX));
    const y = Math.min(this.boxHeight - c.radius, Math.max(c.radius, this.dragY));
    this.world.setVelocity(h, (x - c.x) / DT, (y - c.y) / DT);
  }

  private placeDragged(px: number, py: number): void {
    const h = this.dragHandle;
    const r = this.world.getCircle(h).radius;
    this.world.setPosition(h, Math.min(this.boxWidth - r, Math.max(r, px)), Math.min(this.boxHeight - r, Math.max(r, py)));
  }
}
