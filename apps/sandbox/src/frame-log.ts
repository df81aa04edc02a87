import type { FrameSample } from '../../../packages/lab/src/experiments/common.js';

/**
 * Per-frame timings of the sandbox page, for the lab's `sandbox-render` experiment (issue 5, T7):
 * when each animation frame began, how long it spent stepping the world and drawing it, and how
 * many fixed steps it ran. Drawing time is the CPU side only (buffer uploads and draw calls); what
 * the GPU does afterwards shows as longer frame intervals, which is why the intervals are kept too.
 *
 * A fixed ring of typed arrays: recording allocates nothing, so measuring does not disturb what
 * it measures. Read from outside through `window.__sandboxFrames`, in the shape the lab defines.
 */
export type { FrameSample };

export class FrameLog {
  private readonly start: Float64Array;
  private readonly stepMs: Float64Array;
  private readonly drawMs: Float64Array;
  private readonly steps: Uint8Array;
  private head = 0;
  private size = 0;

  constructor(readonly capacity = 8192) {
    this.start = new Float64Array(capacity);
    this.stepMs = new Float64Array(capacity);
    this.drawMs = new Float64Array(capacity);
    this.steps = new Uint8Array(capacity);
  }

  get length(): number {
    return this.size;
  }

  record(start: number, stepMs: number, drawMs: number, steps: number): void {
    const i = this.head;
    this.start[i] = start;
    this.stepMs[i] = stepMs;
    this.drawMs[i] = drawMs;
    this.steps[i] = Math.min(255, steps);
    this.head = (i + 1) % this.capacity;
    if (this.size < this.capacity) this.size++;
  }

  clear(): void {
    this.head = 0;
    this.size = 0;
  }

  /** The recorded frames, oldest first, as plain arrays (this is the only place that allocates). */
  frames(): Pick<FrameSample, 'start' | 'stepMs' | 'drawMs' | 'steps'> {
    const out = { start: [] as number[], stepMs: [] as number[], drawMs: [] as number[], steps: [] as number[] };
    for (let k = 0; k < this.size; k++) {
      const i = (this.head - this.size + k + this.capacity) % this.capacity;
      out.start.push(this.start[i]);
      out.stepMs.push(this.stepMs[i]);
      out.drawMs.push(this.drawMs[i]);
      out.steps.push(this.steps[i]);
    }
    return out;
  }
}
