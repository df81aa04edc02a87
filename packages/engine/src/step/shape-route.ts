import type { BodyStore } from '../store/body-store.js';
import type { SegmentStore } from '../store/segment-store.js';
import type { ShapeStore } from '../store/shape-store.js';
import { TypeCode } from '../store/body-types.js';
import type { BroadPhase } from '../broadphase/broadphase.js';
import { PairSink } from '../store/pair-sink.js';
import { StaticTree } from '../broadphase/static-tree.js';
import { ShapeNarrowPhase, SEGMENT_ENTRY, type WorldShapes } from '../narrowphase/shape-narrowphase.js';
import { SoftStep, type SoftSettings } from '../solver/soft-step.js';
import type { JointSolver } from '../solver/joint-solver.js';
import type { IntegratorName } from '../integrate/integrator.js';
import { ElasticPass, type ElasticSettings } from '../solver/elastic-pass.js';
import { integrateRigid } from '../integrate/rigid-motion.js';
import { IslandSleep } from '../solver/island-sleep.js';
import { ContinuousShapes } from '../solver/continuous-shapes.js';
import type { Queries } from '../query/queries.js';
import type { ContactEvents } from '../store/contact-events.js';
import { clearForces } from '../integrate/motion.js';
import { bodyBounds, poseOf, shapeBounds } from '../shapes/bounds.js';
import type { StepStats } from './stats.js';
import { nowMs } from '../util/timer.js';

export type SolverName = 'auto' | 'elastic' | 'soft';
export const SOLVER_NAMES: readonly SolverName[] = ['auto', 'elastic', 'soft'];

/** What the shape route reads each step, derived once from the world's options. */
export interface ShapeRouteSettings {
  gravity: { x: number; y: number };
  box: { width: number; height: number } | null;
  /** 'soft': Box2D v3's soft step; 'elastic': the report's single pass. */
  solver: 'soft' | 'elastic';
  /** How the elastic pass moves bodies, and how the soft step integrates force-driven springs. */
  integrator: IntegratorName;
  soft: SoftSettings;
  elastic: ElasticSettings;
  /** Speculative distance: contact points are kept up to this far apart. */
  margin: number;
  /** The solver's linear slop (Box2D's B2_LINEAR_SLOP), for the narrow-phase's tie-breaking. */
  slop: number;
  wallFriction: number;
  wallRestitution: number;
  sleeping: { enabled: boolean; speed: number; time: number };
  /** Sweep fast bodies against static things (continuous collision). */
  continuous: boolean;
}

const bounds = new Float64Array(4);
const pose = new Float64Array(4);

/**
 * The step of a world with shapes, as a list of stages over the stores:
 *
 *   soft:    broad-phase -> narrow-phase -> solve (sub-steps, contacts and joints) -> contain -> report
 *   elastic: integrate -> broad-phase -> narrow-phase -> solve (one pass) -> contain -> report
 *
 * The soft step collides first, from where the bodies stand, and moves them inside its solve with
 * speculative contacts (Box2D v3's order); the elastic pass keeps the report's order, moving
 * first and resolving the overlaps found. Static bodies, segments and the box's walls (four thick
 * rectangles outside it) live in a static tree, rebuilt only when they change; `contain` keeps
 * every shape inside the box whatever got past the walls.
 */
export class ShapeRoute {
  readonly narrow: ShapeNarrowPhase;
  readonly pairs: PairSink;
  readonly tree = new StaticTree();
  readonly soft = new SoftStep();
  readonly elastic = new ElasticPass();
  readonly islands = new IslandSleep();
  readonly continuous = new ContinuousShapes();
  private treeVersion = -1;
  readonly world: WorldShapes;

  constructor(
    private readonly bodies: BodyStore,
    private readonly shapes: ShapeStore,
    private readonly segments: SegmentStore,
    readonly settings: ShapeRouteSettings,
  ) {
    this.narrow = new ShapeNarrowPhase(bodies);
    this.pairs = new PairSink(this.narrow, nowMs);
    const box = settings.box;
    this.world = { segments, box, wallThickness: box ? Math.max(box.width, box.height) : 0 };
  }

  run(dt: number, broad: BroadPhase, staticVersion: number, stats: StepStats, queries: Queries, queryVersion: number, events: ContactEvents | null, hitThreshold: number): void {
    const { bodies, settings, narrow, pairs } = this;
    const t0 = nowMs();
    events?.clear();
    const elastic = settings.solver === 'elastic';
    if (staticVersion !== this.treeVersion) this.rebuildTree(staticVersion);
    const joints = this.joints !== null && this.joints.count > 0 ? this.joints : null;
    if (joints) joints.wakeJoined(bodies);
    const sweep = settings.continuous && (this.tree.count > 0 || this.bullets > 0);
    if (sweep) this.continuous.remember(bodies);
    if (elastic) {
      integrateRigid(bodies, settings.gravity.x, settings.gravity.y, dt, settings.integrator, settings.soft.maxLinearSpeed);
      if (sweep) this.sweep(queries, -1 - queryVersion, true, events === null ? Infinity : hitThreshold);
    }
    const t1 = nowMs();
    let pairTests = this.findPairs(broad, elastic);
    // The narrow-phase's share of the broad-phase's time: the pairs it consumed on the way.
    const consumerMs = pairs.consumerMs;
    const t2 = nowMs();
    this.build(elastic, dt);
    if (narrow.wakeCount > 0) {
      // Sleepers that a body hit this step wake before the solve, whole, and their islands
      // collide again with everything, their own contacts included: left asleep through the step,
      // a sleeper met the body that hit it as a wall would, and took none of its momentum.
      for (let k = 0; k < narrow.wakeCount; k++) bodies.wake(narrow.wake[k]);
      pairTests = this.findPairs(broad, elastic);
      this.build(elastic, dt);
    }
    const t3 = nowMs();
    const contacts = narrow.current;
    if (elastic) this.elastic.solve(bodies, contacts, settings.elastic);
    else {
      this.soft.solve(bodies, contacts, settings.gravity.x, settings.gravity.y, dt, settings.soft, joints);
      if (sweep) this.sweep(queries, -1 - queryVersion, false, Infinity);
    }
    const t4 = nowMs();
    if (settings.box) this.contain(settings.box, elastic ? 0 : settings.slop);
    // Sensors see where the bodies ended the step; the queries' grid built for it serves the
    // caller's queries after the step too (the world's next geometry version).
    if (events !== null) narrow.sense(this.shapes, queries, queryVersion + 1, settings.slop);
    const t5 = nowMs();
    const sleeping = settings.sleeping;
    if (sleeping.enabled) this.islands.update(bodies, contacts, joints?.store ?? null, dt, sleeping.speed, sleeping.time);
    // Whatever the second pass noted, if anything, wakes after the step.
    for (let k = 0; k < narrow.wakeCount; k++) bodies.wake(narrow.wake[k]);
    if (events !== null) {
      events.updateShapes(bodies, this.shapes, this.segments, contacts, hitThreshold, narrow.sensorSlots, narrow.visitorSlots, narrow.sensorCount);
      if (sweep && elastic) this.continuous.reportBounces(bodies, this.shapes, this.world, events);
    }
    if (dt > 0) clearForces(bodies);
    const t6 = nowMs();
    stats.steps++;
    stats.bodies = bodies.liveCount;
    stats.pairTests = pairTests;
    stats.candidatePairs = pairs.total;
    stats.contacts = contacts.count;
    stats.segmentContacts = 0;
    stats.sweptBodies = sweep ? this.continuous.swept : 0;
    stats.filteredPairs = narrow.filtered;
    stats.sleepingBodies = bodies.sleepingCount;
    stats.integrateMs = t1 - t0;
    stats.boundaryMs = 0;
    // A second pass for woken sleepers counts as narrow-phase, its broad-phase included.
    stats.broadphaseMs = t2 - t1 - consumerMs;
    stats.narrowphaseMs = t3 - t2 + consumerMs;
    stats.solveMs = t4 - t3;
    stats.correctMs = t5 - t4;
    stats.reportMs = t6 - t5;
    stats.totalMs = t6 - t0;
    // The shape route runs on the calling thread alone (see startWorkers).
    stats.threads = 1;
  }

  /** The broad-phase's candidate pairs, and the static ones, into the narrow-phase; returns the pair tests. */
  private findPairs(broad: BroadPhase, elastic: boolean): number {
    const { bodies, narrow, pairs } = this;
    narrow.begin();
    pairs.begin();
    pairs.contactsDirect = false;
    const pairTests = broad.findPairs(bodies, pairs);
    pairs.flush();
    narrow.gatherStatic(this.tree, this.shapes, this.world, this.recycleDistance(elastic));
    return pairTests;
  }

  /** The step's contacts from the candidate pairs. Only the soft step keeps manifolds between steps: the elastic pass works on fresh overlaps. */
  private build(elastic: boolean, dt: number): void {
    const settings = this.settings;
    this.narrow.build(this.shapes, this.world, elastic ? 0 : settings.margin, settings.slop, settings.wallFriction, settings.wallRestitution, settings.sleeping.speed, this.recycleDistance(elastic), dt);
  }

  /** How far a kept manifold's bodies may have drifted (see ShapeNarrowPhase.recycle). */
  private recycleDistance(elastic: boolean): number {
    return elastic ? 0 : 10 * this.settings.slop;
  }

  /** Bullets in the world: the continuous stage runs for them even with nothing static. */
  bullets = 0;
  /** The world's joints, once it has any; solved inside the soft step. */
  joints: JointSolver | null = null;

  /** `queryVersion`: one no later query shares, since bodies move again after the sweep. */
  /** `hitThreshold`: the bounces to note as hits (Infinity for none). */
  private sweep(queries: Queries, queryVersion: number, bounce: boolean, hitThreshold: number): void {
    const { settings } = this;
    const threshold = bounce ? settings.elastic.restitutionThreshold : settings.soft.restitutionThreshold;
    this.continuous.run(this.bodies, this.shapes, this.tree, this.world, this.bullets > 0 ? queries : null, queryVersion, settings.margin, settings.slop, bounce, threshold, hitThreshold);
  }

  memoryBytes(): number {
    return this.continuous.memoryBytes() + this.narrow.memoryBytes() + this.pairs.memoryBytes() + this.tree.memoryBytes() + this.soft.memoryBytes() + this.islands.memoryBytes();
  }

  /**
   * Static bodies' shapes and the segments, each under its entry id. The box's walls are not in
   * the tree: a body meets one exactly when its bounding circle reaches past that side of the box,
   * which gatherStatic tests directly.
   */
  private rebuildTree(version: number): void {
    this.treeVersion = version;
    const { tree, bodies, shapes, segments } = this;
    const rigid = bodies.rigid!;
    tree.clear();
    for (let slot = 0; slot < bodies.slotCount; slot++) {
      if (bodies.type[slot] !== TypeCode.static) continue;
      for (let s = rigid.firstShape[slot]; s >= 0; s = shapes.next[s]) {
        shapeBounds(shapes, s, poseOf(pose, bodies.x[slot], bodies.y[slot], rigid.c[slot], rigid.s[slot]), bounds);
        tree.add(s, bounds[0], bounds[1], bounds[2], bounds[3]);
      }
    }
    tree.addSegments(segments, SEGMENT_ENTRY, false);
    tree.finish();
  }

  /**
   * Moves each moving body whose shapes reach past the box by more than `allowance` back to that
   * far in (centred if it is wider). The soft step's wall contacts, as all its contacts, rest up
   * to a slop deep: moved out of that, bodies along a wall were pushed into their neighbours
   * every step, which the solve made motion, and a pile of 300 boxes in the box never slept
   * where it slept between static walls.
   */
  private contain(box: { width: number; height: number }, allowance: number): void {
    const { bodies, shapes } = this;
    const { x, y, radius, type, slotCount } = bodies;
    const rigid = bodies.rigid!;
    const { width, height } = box;
    for (let i = 0; i < slotCount; i++) {
      const t = type[i];
      if (t !== TypeCode.dynamic && t !== TypeCode.kinematic) continue;
      const px = x[i];
      const py = y[i];
      const r = radius[i];
      // At most half the body's smallest extent, so that a body smaller than the slop keeps its centre inside.
      const a = Math.min(allowance, 0.5 * rigid.minExtent[i]);
      if (px - r >= -a && px + r <= width + a && py - r >= -a && py + r <= height + a) continue;
      if (rigid.firstShape[i] < 0) {
        this.containPoint(i, width, height);
        continue;
      }
      // A body thrown far past a wall in one step (1e18 out of a box 100 wide) is first brought to
      // it: at that distance its own extent and the box's size would round away in the shift, and
      // leave it on or through the opposite wall.
      const qx = px < -width || px > 2 * width ? (px < 0 ? 0 : width) : px;
      const qy = py < -height || py > 2 * height ? (py < 0 ? 0 : height) : py;
      // Written here rather than through poseOf: four numbers passed to a call are what the array spares.
      pose[0] = qx;
      pose[1] = qy;
      pose[2] = rigid.c[i];
      pose[3] = rigid.s[i];
      bodyBounds(shapes, rigid.firstShape[i], pose, bounds);
      // Each axis's shift written out here: a call V8 does not inline boxes the doubles passed
      // to it and returned, and this runs for every body that reaches past a wall (a pile on the floor).
      for (let k = 0; k < 2; k++) {
        const lo = bounds[k];
        const hi = bounds[k + 2];
        const size = k === 0 ? width : height;
        // Centred in [0, size] when wider than it; else moved to lie within [-a, size + a].
        const shift = hi - lo > size ? size / 2 - (lo + hi) / 2 : lo < -a ? -a - lo : hi > size + a ? size + a - hi : 0;
        if (k === 0) x[i] = qx + shift;
        else y[i] = qy + shift;
      }
    }
  }

  /**
   * A body without shapes meets no wall, so the box holds its centre instead: it stops at the
   * side it crossed, keeping the velocity along that side (a later shape then fits inside).
   */
  private containPoint(i: number, width: number, height: number): void {
    const { x, y, vx, vy } = this.bodies;
    if (x[i] < 0 || x[i] > width) {
      x[i] = x[i] < 0 ? 0 : width;
      vx[i] = 0;
    }
    if (y[i] < 0 || y[i] > height) {
      y[i] = y[i] < 0 ? 0 : height;
      vy[i] = 0;
    }
  }
}
