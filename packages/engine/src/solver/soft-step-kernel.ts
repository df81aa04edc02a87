import { SOFT_STEP_WASM } from '../generated/soft-step-wasm.js';
import { compileKernel, instantiateKernel, PAGE_BYTES, webAssembly, type KernelMemory } from '../util/wasm.js';

/**
 * The soft step's body states, constraints and constraint pairs laid out in one WebAssembly
 * memory, and its hot passes compiled from assembly/soft-step.ts over them: warm start, solve and
 * relax, two constraints per 128-bit SIMD instruction, and the sub-steps' body integration. They
 * give the same bits as SoftStep's TypeScript loops, which serve wherever WebAssembly or its SIMD
 * is missing, and every other stage of the step works on the same arrays either way.
 *
 * Why: the passes are most of a pile's step (Box2D's pyramid, 5,050 boxes: docs/engine.md), and
 * they are arithmetic on two independent constraints at a time, which V8's JIT cannot vectorise.
 */

interface SoftStepExports {
  warmStart(states: number, constraints: number, pairs: number, lanes: number): void;
  solve(states: number, constraints: number, pairs: number, lanes: number, inverseH: number, pushSpeed: number, touchingGap: number): void;
  relax(states: number, constraints: number, pairs: number, lanes: number, inverseH: number): void;
  integrateVelocities(states: number, n: number, dvx: number, dvy: number): void;
  integratePositions(states: number, n: number, h: number, maxLinearSpeed: number, maxAngular: number): void;
  pointDistanceWarmStart(states: number, rows: number, pairs: number, lanes: number): void;
  pointDistanceSolve(states: number, rows: number, pairs: number, lanes: number, pass: number): void;
}

/** v128 loads are fastest on 16-byte boundaries. */
const ALIGN = 16;

let compiled: object | null | undefined;
let enabled = true;

/**
 * Whether soft steps made from now on run the kernel. For tests and measurements that compare
 * the two paths; not part of the public API.
 */
export function setSoftStepKernelEnabled(on: boolean): void {
  enabled = on;
}

export function softStepKernelEnabled(): boolean {
  return enabled;
}

export class SoftStepKernel {
  states: Float64Array<ArrayBuffer>;
  constraints: Float64Array<ArrayBuffer>;
  pairs: Int32Array<ArrayBuffer>;

  /** A kernel, or null where this runtime lacks WebAssembly SIMD or the kernel is switched off. */
  static create(): SoftStepKernel | null {
    if (!enabled) return null;
    if (compiled === undefined) compiled = compileKernel(SOFT_STEP_WASM);
    if (compiled === null) return null;
    let memory: KernelMemory;
    try {
      memory = new (webAssembly()!).Memory({ initial: 1 });
    } catch {
      return null;
    }
    return new SoftStepKernel(memory, instantiateKernel<SoftStepExports>(compiled, memory));
  }

  /** The point distance joints' lanes and their bodies (see PointDistanceJoints). */
  jointRows: Float64Array<ArrayBuffer>;
  jointPairs: Int32Array<ArrayBuffer>;

  private constructor(
    private readonly memory: KernelMemory,
    private readonly fn: SoftStepExports,
  ) {
    const buffer = memory.buffer as ArrayBuffer;
    this.states = new Float64Array(buffer, 0, 0);
    this.constraints = new Float64Array(buffer, 0, 0);
    this.pairs = new Int32Array(buffer, 0, 0);
    this.jointRows = new Float64Array(buffer, 0, 0);
    this.jointPairs = new Int32Array(buffer, 0, 0);
  }

  /**
   * Gives the three arrays at least these lengths, keeping their contents (and the joints'); views
   * taken before are void after a call that grows any of them.
   */
  reserve(states: number, constraints: number, pairs: number): void {
    if (states <= this.states.length && constraints <= this.constraints.length && pairs <= this.pairs.length) return;
    this.layout([states, constraints, pairs, 0, 0]);
  }

  /** The same for the joints' lanes (doubles) and their pairs of bodies (32-bit integers). */
  reserveJoints(rows: number, pairs: number): void {
    if (rows <= this.jointRows.length && pairs <= this.jointPairs.length) return;
    this.layout([0, 0, 0, rows, pairs]);
  }

  private layout(wanted: number[]): void {
    const old = [this.states, this.constraints, this.pairs, this.jointRows, this.jointPairs];
    const lengths = old.map((view, r) => Math.max(wanted[r], view.length));
    const offsets: number[] = [];
    let end = 0;
    for (let r = 0; r < old.length; r++) {
      offsets.push(end);
      end = Math.ceil((end + lengths[r] * old[r].BYTES_PER_ELEMENT) / ALIGN) * ALIGN;
    }
    const from = old.map((view) => [view.byteOffset, view.byteLength]);
    const have = this.memory.buffer.byteLength;
    if (end > have) this.memory.grow(Math.ceil((end - have) / PAGE_BYTES));
    const buffer = this.memory.buffer as ArrayBuffer;
    // Regions only move up: move the last first, so that none overwrites one not yet moved.
    const bytes = new Uint8Array(buffer);
    for (let r = old.length - 1; r >= 0; r--) bytes.copyWithin(offsets[r], from[r][0], from[r][0] + from[r][1]);
    this.states = new Float64Array(buffer, offsets[0], lengths[0]);
    this.constraints = new Float64Array(buffer, offsets[1], lengths[1]);
    this.pairs = new Int32Array(buffer, offsets[2], lengths[2]);
    this.jointRows = new Float64Array(buffer, offsets[3], lengths[3]);
    this.jointPairs = new Int32Array(buffer, offsets[4], lengths[4]);
  }

  memoryBytes(): number {
    return this.memory.buffer.byteLength;
  }

  warmStart(lanes: number): void {
    this.fn.warmStart(this.states.byteOffset, this.constraints.byteOffset, this.pairs.byteOffset, lanes);
  }

  solve(lanes: number, inverseH: number, pushSpeed: number, touchingGap: number): void {
    this.fn.solve(this.states.byteOffset, this.constraints.byteOffset, this.pairs.byteOffset, lanes, inverseH, pushSpeed, touchingGap);
  }

  relax(lanes: number, inverseH: number): void {
    this.fn.relax(this.states.byteOffset, this.constraints.byteOffset, this.pairs.byteOffset, lanes, inverseH);
  }

  /** Bodies 1..n's velocities plus (dvx, dvy), where no body has forces, damping or a gravity scale. */
  integrateVelocities(n: number, dvx: number, dvy: number): void {
    this.fn.integrateVelocities(this.states.byteOffset, n, dvx, dvy);
  }

  integratePositions(n: number, h: number, maxLinearSpeed: number, maxAngular: number): void {
    this.fn.integratePositions(this.states.byteOffset, n, h, maxLinearSpeed, maxAngular);
  }

  pointDistanceWarmStart(lanes: number): void {
    this.fn.pointDistanceWarmStart(this.states.byteOffset, this.jointRows.byteOffset, this.jointPairs.byteOffset, lanes);
  }

  /** `pass`: the lane field offset of the softness to solve with (PointDistanceJoints' RELAX or 0). */
  pointDistanceSolve(lanes: number, pass: number): void {
    this.fn.pointDistanceSolve(this.states.byteOffset, this.jointRows.byteOffset, this.jointPairs.byteOffset, lanes, pass);
  }
}
