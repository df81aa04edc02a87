import type { BodyStore } from '../store/body-store.js';
import { ContactBuffer } from '../store/contact-buffer.js';
import { PairSink } from '../store/pair-sink.js';
import type { ContactEvents } from '../store/contact-events.js';
import type { BroadPhase } from '../broadphase/broadphase.js';
import { NarrowPhase } from '../narrowphase/narrowphase.js';
import { INTEGRATORS, type CircleIntegratorName as IntegratorName } from '../integrate/integrator.js';
import { needsGeneralMotion } from '../integrate/motion.js';
import type { BodyKernel } from '../store/body-kernel.js';
import { bounceOffBox, clampBodies, clampIntoBox, noteWallContacts } from '../solver/box-walls.js';
import { solveContacts, type SolverSettings } from '../solver/contact-solver.js';
import { IterativeSolver } from '../solver/iterative-solver.js';
import { SleepStage } from '../solver/sleep.js';
import { ContinuousCollision } from '../solver/continuous.js';
import { StaticIndex, findStaticPairs } from '../broadphase/static-pairs.js';
import { solveSegmentContacts } from '../solver/segment-contacts.js';
import { SegmentGrid, type SegmentStore } from '../store/segment-store.js';
import { emptyStats, type StepStats } from './stats.js';
import { nowMs } from '../util/timer.js';
import type { MotionSettings, ParallelStep } from '../parallel/parallel-step.js';
import { AutoBroadPhase } from '../broadphase/auto.js';
import { MaxGridBroadPhase } from '../broadphase/maxgrid.js';

export interface StepSettings {
  gravity: { x: number; y: number };
  box: { width: number; height: number } | null;
  wallRestitution: number;
  solver: SolverSettings;
  sleeping: { enabled: boolean; speed: number; time: number };
  /** Sweep fast bodies against static shapes (continuous collision). */
  continuous: boolean;
}

/**
 * One step, as a fixed sequence of named stages, each in its own module and timed into `stats`:
 *
 *   integrate -> boundary -> broad-phase -> narrow-phase -> solve -> correct -> report
 *
 * `boundary` is everything static: continuous sweeps against static shapes, then the box walls.
 * `solve` resolves circle-circle contacts, then circle-segment ones, in one pass; or with
 * solverIterations above 1 both together in IterativeSolver's passes, on this thread.
 *
 * The broad-phase hands candidates to the narrow-phase in chunks (see PairSink), so those two
 * interleave; their times are separated by timing the narrow-phase inside the sink. Everything
 * here works on buffers that persist between steps: a warm step allocates no buffers. (It still
 * boxes a few hundred bytes of numbers per step, the stage timers' readings and doubles passed to
 * calls V8 does not inline: 0.6-0.8 KB at 2,000 bodies with maxgrid, 0.7 with sap, 0.8 with hgrid,
 * sampled with V8's heap profiler every 32 bytes, collected objects included. An earlier figure
 * here, 228 B, was low: the build before the WebAssembly kernels gives 0.67 KB measured this way.)
 *
 * With `parallel` attached, motion, the Max Grid and narrow-phase, solve and correct run on
 * several threads (see ParallelStep), the rest as here; the result is the same bits either way.
 */
export class StepPipeline {
  readonly contacts = new ContactBuffer();
  readonly narrowPhase: NarrowPhase;
  readonly pairs: PairSink;
  readonly stats: StepStats = emptyStats();
  readonly continuous = new ContinuousCollision();
  /** Static circles and segments, for the static pairs and the continuous sweep. */
  readonly statics = new StaticIndex();
  readonly iterative = new IterativeSolver();
  readonly sleep = new SleepStage();
  readonly segmentGrid = new SegmentGrid();
  parallel: ParallelStep | null = null;

  constructor(
    private readonly bodies: BodyStore,
    private readonly segments: SegmentStore,
    public broadPhase: BroadPhase,
    public integrator: IntegratorName,
    readonly settings: StepSettings,
    public events: ContactEvents | null,
  ) {
    this.narrowPhase = new NarrowPhase(bodies, this.contacts);
    this.pairs = new PairSink(this.narrowPhase, nowMs);
  }

  /** One step of `dt` seconds; `staticVersion` changes whenever a static body or segment does. */
  run(dt: number, staticVersion: number): void {
    const { bodies, settings, stats, contacts, pairs, events } = this;
    const eligible = this.parallel !== null && bodies.liveCount >= this.parallel.minBodies ? this.parallel : null;
    const parallel = eligible !== null && (eligible.governor === null || eligible.governor.useThreads()) ? eligible : null;
    const box = settings.box;
    const t0 = nowMs();
    // Cleared first: the sweep records its hits (on static circles and segments) before the solvers record theirs.
    events?.clear();
    const sweep = settings.continuous && this.continuous.needed(bodies, this.segments);
    if (sweep) this.continuous.rememberPositions(bodies);

    // `auto` chooses once per step: the parallel path asks which broad-phase it picked.
    const broad = parallel && this.broadPhase instanceof AutoBroadPhase ? this.broadPhase.select(bodies) : this.broadPhase;
    // Without sweeps, parallel motion bounces off the walls in the same pass as integration; and
    // in a box without holes, where the Max Grid spans the box whatever the positions, it also
    // bins each body into the grid while the body is in cache. With events, the walls stage runs
    // apart, so that noteWallContacts sees each body between integration and its bounce.
    const bouncedInMotion = parallel !== null && !sweep && events === null;
    const binInMotion = bouncedInMotion && box !== null && bodies.liveCount === bodies.slotCount && broad instanceof MaxGridBroadPhase;
    let grid = binInMotion ? (broad as MaxGridBroadPhase).layoutForThreads(bodies, parallel!.threads) : null;
    // A single-threaded world whose columns are in the body kernel does the same in one pass there.
    const kernel = parallel === null && !sweep && box !== null && events === null && !needsGeneralMotion(bodies) ? bodies.kernel : null;
    if (parallel) parallel.motion(this.motionSettings(dt), bouncedInMotion, grid, grid ? (broad as MaxGridBroadPhase).coordPad : 0);
    else if (kernel) this.moveInBox(kernel, box!, dt);
    else INTEGRATORS[this.integrator](bodies, settings.gravity.x, settings.gravity.y, dt);
    const t1 = nowMs();

    if (sweep) this.continuous.sweep(bodies, this.segments, box, settings.wallRestitution, settings.solver.restitutionThreshold, events, settings.solver.hitThreshold, this.statics, staticVersion);
    if (box && events) noteWallContacts(bodies, box.width, box.height, events, settings.solver.hitThreshold);
    if (box && !bouncedInMotion && kernel === null) bounceOffBox(bodies, box.width, box.height, settings.wallRestitution, settings.solver.restitutionThreshold);
    const t2 = nowMs();

    contacts.clear();
    pairs.begin();
    pairs.contactsDirect = bodies.everyPairCollides;
    this.narrowPhase.begin();
    const binned = grid !== null;
    if (!binned && parallel && broad instanceof MaxGridBroadPhase) grid = broad.layoutForThreads(bodies, parallel.threads);
    let pairTests: number;
    if (grid) {
      pairTests = parallel!.findContacts(grid, (broad as MaxGridBroadPhase).coordPad, contacts, binned);
    } else {
      pairTests = broad.findPairs(bodies, pairs);
    }
    // With workers, `auto`'s choice ran here rather than inside auto: it hears what it examined.
    if (broad !== this.broadPhase && this.broadPhase instanceof AutoBroadPhase) this.broadPhase.noteExamined(broad, pairTests, bodies);
    if (bodies.staticCount > 0) pairTests += findStaticPairs(bodies, this.statics.current(bodies, this.segments, staticVersion), pairs);
    pairs.flush();
    const t3 = nowMs();

    contacts.sortCanonical(bodies.slotCount);
    const iterative = settings.solver.iterations > 1;
    const solvedInParallel = parallel !== null && events === null && bodies.sleepingCount === 0 && !iterative;
    if (solvedInParallel) parallel.solve(settings.solver, box);
    const escapesNoted = !solvedInParallel && !iterative && solveContacts(bodies, contacts, events, settings.solver, box);
    // The iterated solve takes the segments in with the circles; the single pass does them after.
    const segmentContacts = iterative
      ? this.iterative.solve(bodies, contacts, this.segments, this.segmentGrid, settings.solver, box, settings.solver.iterations, events)
      : solveSegmentContacts(bodies, this.segments, this.segmentGrid, settings.solver, events);
    const t4 = nowMs();

    if (box) {
      if (solvedInParallel && segmentContacts === 0) parallel.clampEscaped(box);
      else if (parallel && segmentContacts === 0) parallel.clamp(box);
      else if (escapesNoted && segmentContacts === 0) clampBodies(bodies, bodies.kernel!.escaped, 0, bodies.kernel!.escapedCount, box.width, box.height);
      else clampIntoBox(bodies, box.width, box.height, segmentContacts > 0 ? null : contacts);
    }
    const t5 = nowMs();

    events?.update(bodies, contacts, this.segments);
    if (settings.sleeping.enabled) this.sleep.update(bodies, contacts, dt, settings.sleeping.speed, settings.sleeping.time);
    const t6 = nowMs();

    const candidates = grid ? parallel!.candidates : pairs.total;
    const filtered = grid ? parallel!.filtered : this.narrowPhase.filtered;
    const narrowMs = grid ? parallel!.narrowMs : pairs.consumerMs;
    stats.steps++;
    stats.bodies = bodies.liveCount;
    stats.pairTests = pairTests;
    stats.candidatePairs = candidates;
    stats.contacts = contacts.count;
    stats.segmentContacts = segmentContacts;
    stats.sweptBodies = sweep ? this.continuous.swept : 0;
    stats.filteredPairs = filtered;
    stats.sleepingBodies = bodies.sleepingCount;
    stats.integrateMs = t1 - t0;
    stats.boundaryMs = t2 - t1;
    stats.narrowphaseMs = narrowMs;
    stats.broadphaseMs = t3 - t2 - narrowMs;
    stats.solveMs = t4 - t3;
    stats.correctMs = t5 - t4;
    stats.reportMs = t6 - t5;
    stats.totalMs = t6 - t0;
    stats.threads = parallel ? parallel.threads : 1;
    eligible?.governor?.note(parallel !== null, t6 - t0);
  }

  private moveInBox(kernel: BodyKernel, box: { width: number; height: number }, dt: number): void {
    const { gravity, wallRestitution, solver } = this.settings;
    const explicit = this.integrator === 'explicit-euler';
    const bodies = this.bodies;
    kernel.moveInBox(0, bodies.slotCount, gravity.x * dt, gravity.y * dt, dt, explicit, box.width, box.height, wallRestitution, solver.restitutionThreshold, bodies.maxRadius());
  }

  private readonly motion = {
    integrator: 'explicit-euler' as IntegratorName,
    gravityX: 0,
    gravityY: 0,
    dt: 0,
    box: null as { width: number; height: number } | null,
    wallRestitution: 0,
    restitutionThreshold: 0,
  };

  /** One reused record, so that a parallel step allocates nothing either. */
  private motionSettings(dt: number): MotionSettings {
    const m = this.motion;
    const s = this.settings;
    m.integrator = this.integrator;
    m.gravityX = s.gravity.x;
    m.gravityY = s.gravity.y;
    m.dt = dt;
    m.box = s.box;
    m.wallRestitution = s.wallRestitution;
    m.restitutionThreshold = s.solver.restitutionThreshold;
    return m;
  }

  memoryBytes(): number {
    return (
      (this.parallel?.memoryBytes() ?? 0) +
      this.broadPhase.memoryBytes() +
      this.contacts.memoryBytes() +
      this.pairs.memoryBytes() +
      this.continuous.memoryBytes() +
      this.statics.memoryBytes() +
      this.iterative.memoryBytes() +
      this.sleep.memoryBytes() +
      (this.events?.memoryBytes() ?? 0)
    );
  }
}
