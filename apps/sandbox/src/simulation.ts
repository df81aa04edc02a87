import { World, BodyTypeCode, type BroadPhaseName, type IntegratorName } from '@maxgrid/engine';
import { buildScene, buildShapeScene } from '@maxgrid/scenes';
import { isShapeScene, sceneParams, type Settings, type SpawnKind } from './settings.js';
import { followedBody } from './scene-specs.js';
import { BodyColors } from './colors.js';
import { Recorder } from './monitor/recorder.js';
import { HitEvents } from './hit-events.js';
import { TouchEvents } from './touch-events.js';
import { buildSandboxShapeWorld, buildSandboxWorld, flatSegments, hitThreshold, layerMask, layerOf } from './scene-world.js';
import { History, MIN_SPACING, type DragInput, type Mark } from './history.js';

/** The drag spring on shapes: its frequency (Hz), damping ratio, and the most it accelerates a body, in gravities (or in scene sizes per second squared without gravity). */
const DRAG_HERTZ = 4;
const DRAG_DAMPING = 0.7;
const DRAG_MAX_G = 10;

/** The fixed physics step: rendering runs at whatever rate the display gives. */
export const DT = 1 / 60;
/** At most this many steps per frame, so one slow frame cannot make the next one slower still. */
const MAX_STEPS_PER_FRAME = 4;
/** ...and no more catching up once a frame has spent this long stepping. */
export const STEP_BUDGET_MS = 40;

/** The mean step time of the last steps recorded, in ms: what a snapshot's cost is weighed against. */
function meanStepMs(recorder: Recorder): number {
  const ring = recorder.series.step_ms;
  const n = Math.min(ring.length, MIN_SPACING);
  let sum = 0;
  for (let i = ring.length - n; i < ring.length; i++) sum += ring.at(i);
  return n > 0 ? sum / n : NaN;
}

/** A scene as the page draws it, and how to build its world. */
interface SceneFrame {
  segments: Float64Array;
  region: { x: number; y: number; width: number; height: number };
  gravity: { x: number; y: number };
  bounded: boolean;
  threshold: number;
  /** Whether the world takes joints: World.createJoint refuses them in a world made with solver 'elastic'. */
  joints: boolean;
  build(): World;
}

function sceneFrame(settings: Settings): SceneFrame {
  if (isShapeScene(settings.scene)) {
    const scene = buildShapeScene(settings.scene, sceneParams(settings));
    const v = scene.view;
    const gravity = scene.gravity;
    return {
      segments: flatSegments(scene),
      region: scene.bounds ? { x: 0, y: 0, width: scene.bounds.width, height: scene.bounds.height } : { x: v.minX, y: v.minY, width: v.maxX - v.minX, height: v.maxY - v.minY },
      gravity,
      bounded: scene.bounds !== null,
      threshold: Math.max(8 * Math.hypot(gravity.x, gravity.y) * DT, (scene.world.lengthUnit ?? 1) * 0.5),
      joints: scene.world.solver !== 'elastic',
      build: () => buildSandboxShapeWorld(scene, DT, settings, settings.substeps),
    };
  }
  const scene = buildScene(settings.scene, sceneParams(settings));
  return {
    segments: flatSegments(scene),
    region: { x: 0, y: 0, width: scene.bounds.width, height: scene.bounds.height },
    gravity: scene.gravity,
    bounded: true,
    threshold: hitThreshold(scene, DT),
    // Circle worlds are made with the default solver, 'auto', which moves to the soft step with a first joint.
    joints: true,
    build: () => buildSandboxWorld(scene, DT, settings),
  };
}

/**
 * The world plus everything that runs it: the fixed-step accumulator, the recorded series and the
 * pointer drag, and the history the scrubber seeks in. A rebuild replaces the world; switching
 * broad-phase or integrator, a seek and a load of a save do not.
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
  /**
   * The region drawn: the scene's box, or for an open scene of shapes the region its bodies
   * occupy. Read every frame by the renderers, so one object kept up to date rather than a new one.
   */
  readonly box = { x: 0, y: 0, width: 1600, height: 900 };
  /** Whether the scene has a box of walls (shape scenes may be open: a pyramid on its ground). */
  bounded = true;
  /** A world of shapes (boxes, polygons, capsules that turn), or of circles. */
  shapes = false;
  /** Whether the world takes joints, so that the Pin and Cut tools have something to do. */
  acceptsJoints = true;
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
  /** Where a dragged shape was grabbed, in its body's frame from its origin. */
  private grabX = 0;
  private grabY = 0;
  /** Gravity's magnitude, or a scene size per second squared: what the drag spring's force is capped by. */
  private dragLimit = 0;
  /**
   * The static body every pin holds to, made by the world's first pin: a body without shapes, so
   * nothing draws it, hits it or picks it, at the world's origin so its frame is the world's.
   */
  private pinAnchor = -1;
  /** The body the region follows across (the car), and where the region's left edge is from it. */
  private followHandle = -1;
  private followOffset = 0;
  /** The scrubber's past (history.ts): every change to the world below keeps it one line of steps. */
  readonly history = new History();
  /**
   * A circle a seek left kinematic, held at the step sought by a drag whose pointer is long gone:
   * released (made dynamic) as the world leaves that step, so it does not float there for good.
   */
  private heldAfterSeek = -1;
  /** Edited since the last snapshot: one is taken before the next step or seek, so edits between two steps cost one. */
  private dirty = false;

  constructor(private readonly now: () => number = () => performance.now()) {}

  /**
   * Rebuilds the scene from the settings: the same settings always give the same bodies. Throws,
   * leaving the current world as it was, when the scene refuses its parameters (too many circles
   * to fit the funnel, a minimum radius above the maximum).
   */
  rebuild(settings: Settings): void {
    const frame = sceneFrame(settings);
    this.adopt(settings, frame, frame.build(), null);
  }

  /**
   * Shows `world` (World.restore of a save) as the scene of `settings`, where it was at `mark`:
   * the scene gives what the world does not hold (its segments as drawn, the region, the hit
   * threshold). `snapshot` is the world's bytes, the first entry of the new history. Throws,
   * leaving the current world as it was, when the settings' scene does not build.
   */
  load(settings: Settings, world: World, snapshot: Uint8Array, mark: Mark): void {
    this.adopt(settings, sceneFrame(settings), world, { snapshot, mark });
  }

  private adopt(settings: Settings, frame: SceneFrame, world: World, saved: { snapshot: Uint8Array; mark: Mark } | null): void {
    const { segments, region, gravity, threshold } = frame;
    this.bounded = frame.bounded;
    this.world?.stopWorkers();
    this.world = world;
    this.shapes = world.route.route === 'shapes';
    this.acceptsJoints = frame.joints;
    this.layers = settings.layers && !this.shapes;
    this.continuous = settings.continuous;
    this.segments = segments;
    this.touches.reset(settings.events);
    this.hits.reset(settings.hits, threshold);
    this.boxWidth = region.width;
    this.boxHeight = region.height;
    Object.assign(this.box, region);
    this.gravityY = gravity.y;
    const g = Math.hypot(gravity.x, gravity.y);
    this.dragLimit = DRAG_MAX_G * (g > 0 ? g : Math.min(region.width, region.height) / 10);
    const v = this.world.views();
    this.colors.reset(settings.seed, v.slotCount, this.layers);
    this.staticCircles = 0;
    for (let s = 0; s < v.slotCount; s++) if (v.type[s] === BodyTypeCode.static) this.staticCircles++;
    this.countDynamicMass();
    this.recorder.clear();
    this.time = 0;
    this.accumulator = 0;
    this.droppedSteps = 0;
    this.dragHandle = -1;
    this.heldAfterSeek = -1;
    this.pinAnchor = -1;
    const follow = isShapeScene(settings.scene) ? followedBody(settings.scene) : -1;
    this.followHandle = follow >= 0 && world.hasBody(follow) ? follow : -1;
    if (saved) {
      // The region followed the car from where the scene put it: the same offset from it now.
      if (this.followHandle >= 0) this.followOffset = saved.mark.boxX - v.x[world.slotOfHandle(this.followHandle)];
      this.applyMark(saved.mark);
      this.history.reset(world.stats.steps);
      this.history.record(world.stats.steps, saved.snapshot, saved.mark);
      this.dirty = false;
    } else {
      if (this.followHandle >= 0) this.followOffset = region.x - v.x[world.slotOfHandle(this.followHandle)];
      // Taken before the first step or seek: a slider dragged through many worlds snapshots none of them.
      this.history.reset(world.stats.steps);
      this.dirty = true;
    }
  }

  setBroadphase(name: BroadPhaseName): void {
    this.world.setBroadphase(name);
  }

  /** Another integrator changes what the steps do: an edit. A seek brings back the one of its step. */
  setIntegrator(name: IntegratorName): void {
    if (name === this.world.integrator) return;
    this.beginEdit();
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

  /** One step forward; from a step the scrubber went back to, the steps after it are forgotten. */
  stepOnce(): void {
    // The snapshot at or before this step, and the inputs up to it, still hold: only later ones go.
    if (this.scrubbed) this.history.discardAfter(this.world.stats.steps);
    if (this.heldAfterSeek >= 0) this.beginEdit();
    this.flush();
    const input = this.dragInput();
    this.advanceOne();
    const step = this.world.stats.steps;
    this.history.stepped(step, input);
    if (this.history.due(step)) {
      const start = this.now();
      const bytes = this.world.snapshot();
      const ms = this.now() - start;
      this.history.record(step, bytes, this.mark());
      this.history.adapt(ms, meanStepMs(this.recorder));
    }
  }

  /** The world's step count: the scrubber's position. */
  get step(): number {
    return this.world.stats.steps;
  }

  /** Whether the scrubber is back in time: steps after this one are kept to seek forward to. */
  get scrubbed(): boolean {
    return this.world.stats.steps < this.history.head;
  }

  /**
   * Shows the world at `target` (clamped to the history's steps), paused: the latest snapshot at or
   * before it, restored in place so handles stay valid, and stepped on to it with each step's drag
   * input as logged. Forward within the stretch before the next snapshot it steps on from here.
   * Worker threads stop (world.restore): setThreads starts them again.
   */
  seek(target: number): void {
    if (this.dragHandle >= 0) this.endDrag();
    this.flush();
    const world = this.world;
    const from = world.stats.steps;
    const to = Math.min(this.history.head, Math.max(this.history.oldest, Math.round(target)));
    this.paused = true;
    this.accumulator = 0;
    if (to === from) return;
    let held = this.heldAfterSeek;
    if (to < from || this.history.hasEntryBetween(from, to)) {
      const entry = this.history.nearest(to);
      world.restore(entry.bytes);
      // The steps undone leave the graphs; a jump forward over a snapshot leaves a gap there.
      this.recorder.dropLast(Math.max(0, from - entry.step));
      this.applyMark(entry.mark);
      held = this.heldAfterSeek;
      this.heldAfterSeek = -1;
      this.afterRestore();
    }
    // Flashes and rings are by step number: ones from the steps undone would never fade.
    this.touches.reset(this.touches.enabled);
    this.hits.reset(this.hits.enabled, this.hits.threshold);
    this.touches.record(world);
    this.hits.record(world);
    while (world.stats.steps < to) {
      const input = this.history.input(world.stats.steps + 1);
      this.useInput(input);
      this.advanceOne();
      held = input ? input.handle : -1;
    }
    this.dragHandle = -1;
    this.heldAfterSeek = this.shapes ? -1 : held;
  }

  /** The world's bytes and what the page knows besides, for a save. */
  save(): { snapshot: Uint8Array; mark: Mark } {
    return { snapshot: this.world.snapshot(), mark: this.mark() };
  }

  private mark(): Mark {
    return { time: this.time, boxX: this.box.x, pinAnchor: this.pinAnchor, held: this.dragHandle >= 0 && !this.shapes ? this.dragHandle : this.heldAfterSeek };
  }

  private applyMark(mark: Mark): void {
    this.time = mark.time;
    this.box.x = mark.boxX;
    this.pinAnchor = mark.pinAnchor;
    this.heldAfterSeek = mark.held;
  }

  /** What the page derives from the bodies, read again from a restored world. */
  private afterRestore(): void {
    const world = this.world;
    this.shapes = world.route.route === 'shapes';
    this.colors.ensure(world.views().slotCount);
    this.countDynamicMass();
  }

  /** Total mass of the dynamic bodies; a circle held by a drag is kinematic and left out. */
  private countDynamicMass(): void {
    const v = this.world.views();
    this.dynamicMass = 0;
    for (let s = 0; s < v.slotCount; s++) if (v.type[s] === BodyTypeCode.dynamic) this.dynamicMass += v.mass[s];
  }

  /**
   * Before any change to the world other than a step: the steps after this one no longer follow
   * from it, and a circle left held by a seek is let go. Its snapshot is taken lazily (flush).
   */
  private beginEdit(): void {
    this.history.discardAfter(this.world.stats.steps);
    this.dirty = true;
    const held = this.heldAfterSeek;
    this.heldAfterSeek = -1;
    if (held >= 0 && this.world.hasBody(held) && this.world.getBody(held).type === 'kinematic') {
      this.dragHandle = held;
      this.endDrag();
    }
  }

  private flush(): void {
    if (!this.dirty) return;
    this.dirty = false;
    this.history.record(this.world.stats.steps, this.world.snapshot(), this.mark());
  }

  private dragInput(): DragInput | null {
    return this.dragHandle >= 0 ? { handle: this.dragHandle, x: this.dragX, y: this.dragY, grabX: this.grabX, grabY: this.grabY } : null;
  }

  private useInput(input: DragInput | undefined): void {
    this.dragHandle = input ? input.handle : -1;
    if (!input) return;
    this.dragX = input.x;
    this.dragY = input.y;
    this.grabX = input.grabX;
    this.grabY = input.grabY;
  }

  private advanceOne(): void {
    const world = this.world;
    this.applyDrag();
    world.step(DT);
    this.time += DT;
    this.follow();
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
    return this.world.potentialEnergy() + (g > 0 ? g * (this.box.y + this.boxHeight) * this.dynamicMass : 0);
  }

  /** Whether gravity pulls bodies down, towards the floor. */
  get falls(): boolean {
    return this.gravityY > 0;
  }

  /** Dynamic bodies whose centre is in the lower half of the box: shows a scene falling. */
  lowerHalf(): number {
    const v = this.world.views();
    const half = this.box.y + this.boxHeight / 2;
    let n = 0;
    for (let s = 0; s < v.slotCount; s++) if (v.type[s] === BodyTypeCode.dynamic && v.y[s] > half) n++;
    return n;
  }

  /**
   * The handle of the topmost movable body under a world point, or -1. Static pegs are not
   * picked up: a drag ends by making the body dynamic. Circles: scans every body (per click only);
   * shapes: the engine's point query, shape by shape.
   */
  bodyAt(x: number, y: number): number {
    const v = this.world.views();
    if (this.shapes) {
      const found = this.world.queryPoint(x, y).filter((h) => this.world.hasBody(h) && v.type[this.world.slotOfHandle(h)] !== BodyTypeCode.static);
      return found.length > 0 ? found[found.length - 1] : -1;
    }
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
   * Holds a body at the pointer. A circle becomes kinematic while held, so it pushes others
   * without being pushed back or pulled by gravity, and is thrown with the pointer's velocity when
   * released. A shape stays dynamic and is pulled by a damped spring from the point where it was
   * grabbed towards the pointer (a force and its torque each step): pulling a box out of a stack
   * topples the stack rather than teleporting the box through it.
   */
  beginDrag(handle: number, x: number, y: number): void {
    this.beginEdit();
    this.dragHandle = handle;
    this.dragX = x;
    this.dragY = y;
    if (this.shapes) {
      const b = this.world.getBody(handle);
      const c = Math.cos(b.angle);
      const s = Math.sin(b.angle);
      this.grabX = c * (x - b.x) + s * (y - b.y);
      this.grabY = -s * (x - b.x) + c * (y - b.y);
      this.world.setAwake(handle, true);
      return;
    }
    this.dynamicMass -= this.world.getCircle(handle).mass;
    this.world.setType(handle, 'kinematic');
  }

  moveDrag(x: number, y: number): void {
    this.dragX = x;
    this.dragY = y;
    // While paused nothing steps, so move a circle now for the user to see it follow.
    if (this.paused && this.dragHandle >= 0 && !this.shapes) {
      this.beginEdit();
      this.placeDragged(x, y);
    }
  }

  endDrag(): void {
    const h = this.dragHandle;
    this.dragHandle = -1;
    // A shape's drag only pulled it, step by step, as the history logged; a circle changes type.
    if (h < 0 || !this.world.hasBody(h) || this.shapes) return;
    this.beginEdit();
    const c = this.world.getCircle(h);
    this.world.setType(h, 'dynamic');
    this.dynamicMass += c.mass;
    this.world.setVelocity(h, c.vx, c.vy);
  }

  get dragging(): number {
    return this.dragHandle;
  }

  /** Where the held shape is grabbed, in the world, or null when nothing is held. */
  grabPoint(): { x: number; y: number; toX: number; toY: number } | null {
    const h = this.dragHandle;
    if (h < 0 || !this.shapes || !this.world.hasBody(h)) return null;
    const b = this.world.getBody(h);
    const c = Math.cos(b.angle);
    const s = Math.sin(b.angle);
    return { x: b.x + c * this.grabX - s * this.grabY, y: b.y + s * this.grabX + c * this.grabY, toX: this.dragX, toY: this.dragY };
  }

  /**
   * Adds a body of the current size (`radius`: half its size) at a world point, kept inside the
   * box: a circle, a box, a hexagon or a capsule. Anything but a circle moves a world of circles
   * to the shape route, once (the engine's rule).
   */
  spawn(x: number, y: number, radius: number, kind: SpawnKind = 'circle'): number {
    const r = Math.min(radius, this.boxWidth / 2, this.boxHeight / 2);
    const cx = this.bounded ? Math.min(this.box.x + this.boxWidth - r, Math.max(this.box.x + r, x)) : x;
    const cy = this.bounded ? Math.min(this.box.y + this.boxHeight - r, Math.max(this.box.y + r, y)) : y;
    const world = this.world;
    this.beginEdit();
    let handle: number;
    if (kind === 'box') handle = world.createBox({ x: cx, y: cy, width: 1.4 * r, height: 1.4 * r });
    else if (kind === 'capsule') handle = world.createCapsule({ x: cx, y: cy, length: r, radius: r / 2 });
    else if (kind === 'polygon') {
      const h = (Math.sqrt(3) / 2) * r;
      handle = world.createPolygon({ x: cx, y: cy, vertices: [{ x: r, y: 0 }, { x: r / 2, y: h }, { x: -r / 2, y: h }, { x: -r, y: 0 }, { x: -r / 2, y: -h }, { x: r / 2, y: -h }] });
    } else handle = world.createCircle({ x: cx, y: cy, radius: r });
    this.shapes = world.route.route === 'shapes';
    // The new body joins the layer of its slot, as built ones do.
    const slot = world.slotOfHandle(handle);
    if (this.layers) world.setCollisionFilter(handle, layerOf(slot), layerMask(slot));
    this.dynamicMass += world.getBody(handle).mass;
    this.colors.ensure(world.views().slotCount);
    return handle;
  }

  // A held circle is steered by velocity, not teleported: the step then carries it exactly onto
  // the pointer, and the solver sees a real velocity for the bodies it pushes. A held shape is
  // pulled by the spring.
  private applyDrag(): void {
    const h = this.dragHandle;
    if (h < 0) return;
    if (!this.world.hasBody(h)) {
      this.dragHandle = -1;
      return;
    }
    if (this.shapes) {
      this.pullShape(h);
      return;
    }
    const c = this.world.getCircle(h);
    const x = Math.min(this.box.x + this.boxWidth - c.radius, Math.max(this.box.x + c.radius, this.dragX));
    const y = Math.min(this.box.y + this.boxHeight - c.radius, Math.max(this.box.y + c.radius, this.dragY));
    this.world.setVelocity(h, (x - c.x) / DT, (y - c.y) / DT);
  }

  /**
   * A damped spring of DRAG_HERTZ from the grab point to the pointer, as a force at the grab
   * point (so a torque too), scaled by the body's mass so every body follows alike, capped at
   * DRAG_MAX_G gravities so a far pointer cannot fling a body through a wall.
   */
  private pullShape(h: number): void {
    const world = this.world;
    const b = world.getBody(h);
    if (b.type !== 'dynamic') return;
    const slot = world.slotOfHandle(h);
    const v = world.views();
    const cx = v.x[slot];
    const cy = v.y[slot];
    const c = Math.cos(b.angle);
    const s = Math.sin(b.angle);
    const px = b.x + c * this.grabX - s * this.grabY;
    const py = b.y + s * this.grabX + c * this.grabY;
    const rx = px - cx;
    const ry = py - cy;
    // The grab point's velocity: the centre's plus the spin's (w x r, y down: (-w ry, w rx)).
    const vx = b.vx - b.angularVelocity * ry;
    const vy = b.vy + b.angularVelocity * rx;
    const omega = 2 * Math.PI * DRAG_HERTZ;
    let ax = omega * omega * (this.dragX - px) - 2 * DRAG_DAMPING * omega * vx;
    let ay = omega * omega * (this.dragY - py) - 2 * DRAG_DAMPING * omega * vy;
    const a = Math.hypot(ax, ay);
    if (a > this.dragLimit) {
      ax *= this.dragLimit / a;
      ay *= this.dragLimit / a;
    }
    const fx = b.mass * ax;
    const fy = b.mass * ay;
    world.applyForce(h, fx, fy);
    // The force at the grab point turns the body: torque r x F.
    const torque = rx * fy - ry * fx;
    if (torque !== 0 && world.getBody(h).inertia > 0) world.applyTorque(h, torque);
  }

  /**
   * Pins body `handle` to the world at the world point (x, y): a revolute joint from the shared
   * static anchor, so the body hangs from there and turns about it. Returns the joint's handle;
   * throws the engine's RangeError when the world refuses (a kinematic body: nothing to act on).
   */
  pin(handle: number, x: number, y: number): number {
    this.beginEdit();
    const world = this.world;
    const b = world.getBody(handle);
    const c = Math.cos(b.angle);
    const s = Math.sin(b.angle);
    const dx = x - b.x;
    const dy = y - b.y;
    const made = this.pinAnchor < 0 || !world.hasBody(this.pinAnchor);
    if (made) this.pinAnchor = world.createBody({ x: 0, y: 0, type: 'static' });
    try {
      const joint = world.createJoint({ kind: 'revolute', bodyA: this.pinAnchor, bodyB: handle, anchorA: { x, y }, anchorB: { x: c * dx + s * dy, y: -s * dx + c * dy } });
      // A world of circles moves to the shape route with its first joint, as with a spawned box.
      this.shapes = world.route.route === 'shapes';
      this.colors.ensure(world.views().slotCount);
      return joint;
    } catch (error) {
      if (made) {
        world.destroyBody(this.pinAnchor);
        this.pinAnchor = -1;
      }
      throw error;
    }
  }

  /**
   * The joint whose line (anchor to anchor) passes nearest a world point, within `tolerance`
   * world units, or -1. Per click only: a scan of every joint's drawn line.
   */
  jointNear(x: number, y: number, tolerance: number): number {
    const j = this.world.jointViews();
    let best = -1;
    let bestSq = tolerance * tolerance;
    for (let k = 0; k < j.count; k++) {
      const ax = j.anchorAX[k];
      const ay = j.anchorAY[k];
      const ex = j.anchorBX[k] - ax;
      const ey = j.anchorBY[k] - ay;
      const lengthSq = ex * ex + ey * ey;
      const t = lengthSq > 0 ? Math.min(1, Math.max(0, ((x - ax) * ex + (y - ay) * ey) / lengthSq)) : 0;
      const dx = x - ax - t * ex;
      const dy = y - ay - t * ey;
      const dSq = dx * dx + dy * dy;
      if (dSq <= bestSq) {
        bestSq = dSq;
        best = j.handle[k];
      }
    }
    return best;
  }

  /** Destroys a joint (the Cut tool); its bodies wake and go their own ways. */
  cut(joint: number): void {
    this.beginEdit();
    this.world.destroyJoint(joint);
  }

  // Keeps the followed body where it started across the region: a car would otherwise drive out
  // of the picture within seconds. Only across, so the road stays where it is on screen.
  private follow(): void {
    const h = this.followHandle;
    if (h < 0) return;
    if (!this.world.hasBody(h)) {
      this.followHandle = -1;
      return;
    }
    const x = this.world.views().x[this.world.slotOfHandle(h)];
    if (Number.isFinite(x)) this.box.x = x + this.followOffset;
  }

  private placeDragged(px: number, py: number): void {
    const h = this.dragHandle;
    const r = this.world.getCircle(h).radius;
    this.world.setPosition(h, Math.min(this.box.x + this.boxWidth - r, Math.max(this.box.x + r, px)), Math.min(this.box.y + this.boxHeight - r, Math.max(this.box.y + r, py)));
  }
}
