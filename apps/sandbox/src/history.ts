/**
 * What the page knows about the world at a step beyond the world itself: restored with the world's
 * bytes, so that the page around it (the clock, the followed region, the pin anchor, a held
 * circle) agrees with the bodies.
 */
export interface Mark {
  /** Simulated seconds: summed step by step, as the page does, rather than steps times DT. */
  time: number;
  /** The drawn region's left edge, which follows the car. */
  boxX: number;
  /** The static body pins hold to, or -1 before the first pin (see Simulation.pin). */
  pinAnchor: number;
  /** A circle held by the Drag tool, kinematic while held, or -1. */
  held: number;
}

/** The Drag tool's pointer during one step: what the step did besides world.step, to do it again. */
export interface DragInput {
  handle: number;
  x: number;
  y: number;
  grabX: number;
  grabY: number;
}

interface Entry {
  step: number;
  bytes: Uint8Array;
  mark: Mark;
}

/** Snapshots kept at most, in bytes; one snapshot larger than this is kept alone. */
export const HISTORY_BUDGET_BYTES = 64 * 1024 * 1024;
/** How far back the scrubber reaches at most, in steps (30 s at 60 Hz). */
export const HISTORY_SPAN_STEPS = 1800;
/** Steps between periodic snapshots: a seek replays fewer than this many steps. */
export const MIN_SPACING = 30;
/** ...widened up to this where a snapshot costs more than SNAPSHOT_SHARE of the steps between. */
export const MAX_SPACING = 120;
const SNAPSHOT_SHARE = 0.1;

/**
 * The scrubber's past: world.snapshot() bytes every `spacing` steps and after each edit, and the
 * Drag tool's input of every step that had one. The state at any step from `oldest` to `head` is
 * the snapshot at or before it stepped forward with the logged inputs, which the engine's
 * determinism makes exact. A snapshot of the default scenes measured 170 KB (seed-box, 1,000
 * circles), 300 KB (2,000 circles), 430 KB (ragdolls), 6.8 MB (pyramid), 27 MB (many-pyramids):
 * the budget holds the whole span for all but the last two, which keep 9 and 2 snapshots.
 */
export class History {
  private entries: Entry[] = [];
  private readonly inputs = new Map<number, DragInput>();
  /** Bytes held by the snapshots. */
  bytes = 0;
  /** The latest step the scrubber reaches; beyond the world's own step while scrubbed back. */
  head = 0;
  spacing = MIN_SPACING;

  /** Forgets everything: the past starts at `step`, whose snapshot is to be recorded before any seek. */
  reset(step: number): void {
    this.entries = [];
    this.inputs.clear();
    this.bytes = 0;
    this.head = step;
    this.spacing = MIN_SPACING;
  }

  get oldest(): number {
    return this.entries.length > 0 ? this.entries[0].step : this.head;
  }

  get count(): number {
    return this.entries.length;
  }

  /** Whether a periodic snapshot is due after stepping to `step`. */
  due(step: number): boolean {
    const last = this.entries[this.entries.length - 1];
    return !last || step - last.step >= this.spacing;
  }

  /**
   * Keeps the snapshot of `step`, replacing one taken there before an edit. Later entries must
   * already be gone (discardAfter): the past is one line of steps.
   */
  record(step: number, bytes: Uint8Array, mark: Mark): void {
    const last = this.entries[this.entries.length - 1];
    if (last && last.step > step) throw new Error(`history: a snapshot of step ${step} behind the latest, ${last.step}`);
    if (last && last.step === step) {
      this.bytes -= last.bytes.byteLength;
      this.entries.pop();
    }
    this.entries.push({ step, bytes, mark: { ...mark } });
    this.bytes += bytes.byteLength;
    if (step > this.head) this.head = step;
    this.prune();
  }

  /** Notes a step taken going forward, with the drag input it applied. */
  stepped(step: number, input: DragInput | null): void {
    if (input) this.inputs.set(step, { ...input });
    if (step > this.head) this.head = step;
  }

  /**
   * Widens the spacing of periodic snapshots where taking one costs more than a tenth of stepping
   * through the spacing (a large world of cheap steps), so the history never slows the page much.
   */
  adapt(snapshotMs: number, stepMs: number): void {
    if (!(stepMs > 0) || !(snapshotMs >= 0)) return;
    const wanted = Math.ceil(snapshotMs / (SNAPSHOT_SHARE * stepMs) / MIN_SPACING) * MIN_SPACING;
    this.spacing = Math.min(MAX_SPACING, Math.max(MIN_SPACING, wanted));
  }

  /** The world has left the recorded line at `step` (an edit, or stepping on from the past). */
  discardAfter(step: number): void {
    while (this.entries.length > 1 && this.entries[this.entries.length - 1].step > step) {
      this.bytes -= (this.entries.pop() as Entry).bytes.byteLength;
    }
    for (const at of this.inputs.keys()) if (at > step) this.inputs.delete(at);
    this.head = Math.max(step, this.oldest);
  }

  /** The latest snapshot at or before `step` (the oldest for a step before it). */
  nearest(step: number): Entry {
    let found = this.entries[0];
    for (const entry of this.entries) {
      if (entry.step > step) break;
      found = entry;
    }
    return found;
  }

  /** Whether a snapshot lies in the steps (after, upTo]. */
  hasEntryBetween(after: number, upTo: number): boolean {
    return this.entries.some((e) => e.step > after && e.step <= upTo);
  }

  input(step: number): DragInput | undefined {
    return this.inputs.get(step);
  }

  /** Drops the oldest snapshots past the span or the budget, and the inputs before the oldest kept. */
  private prune(): void {
    const e = this.entries;
    while (e.length > 1 && (e[1].step <= this.head - HISTORY_SPAN_STEPS || this.bytes > HISTORY_BUDGET_BYTES)) {
      this.bytes -= (e.shift() as Entry).bytes.byteLength;
    }
    const oldest = this.oldest;
    for (const at of this.inputs.keys()) if (at <= oldest) this.inputs.delete(at);
  }
}
