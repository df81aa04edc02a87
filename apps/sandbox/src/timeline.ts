import { HISTORY_BUDGET_BYTES, HISTORY_SPAN_STEPS, MAX_SPACING, MIN_SPACING } from './history.js';
import type { Simulation } from './simulation.js';

function byId<T extends HTMLElement>(id: string): T {
  const el = document.getElementById(id);
  if (!el) throw new Error(`sandbox page is missing #${id}`);
  return el as T;
}

export interface TimelineEvents {
  /** The scrubber moved: show that step (coalesced by the page, once a frame). */
  seek(step: number): void;
  save(): void;
  /** A file was chosen to load, as its name and bytes. */
  load(name: string, bytes: Uint8Array): void;
}

const MB = 1024 * 1024;
const integer = (v: number) => v.toLocaleString('en-US');

/**
 * The bar under the stage: the scrubber over the history's steps, a step back, Save and Load, and
 * a line for what a load said. It holds no state: `update` shows the simulation's, every frame,
 * writing to the DOM only what changed.
 */
export class TimelineBar {
  private readonly scrubber = byId<HTMLInputElement>('scrubber');
  private readonly readout = byId<HTMLOutputElement>('scrub-step');
  private readonly kept = byId<HTMLSpanElement>('history-kept');
  private readonly status = byId<HTMLParagraphElement>('timeline-status');
  private readonly file = byId<HTMLInputElement>('load-file');
  private shown = { min: -1, max: -1, value: -1, count: -1, bytes: -1, spacing: -1 };

  constructor(
    private readonly sim: Simulation,
    events: TimelineEvents,
  ) {
    this.scrubber.addEventListener('input', () => events.seek(Number(this.scrubber.value)));
    byId('step-back').addEventListener('click', () => events.seek(this.sim.step - 1));
    byId('save').addEventListener('click', () => events.save());
    byId('load').addEventListener('click', () => this.file.click());
    this.file.addEventListener('change', () => {
      const chosen = this.file.files?.[0];
      // Cleared, so that choosing the same file again loads it again.
      this.file.value = '';
      if (!chosen) return;
      chosen.arrayBuffer().then(
        (buffer) => events.load(chosen.name, new Uint8Array(buffer)),
        (error: unknown) => this.say(`Could not read ${chosen.name}: ${error instanceof Error ? error.message : String(error)}`, true),
      );
    });
  }

  /** A line under the bar: what a load did, or why it did not (`error`); '' hides it. */
  say(message: string, error = false): void {
    this.status.textContent = message;
    this.status.hidden = message === '';
    this.status.classList.toggle('error', error);
  }

  update(): void {
    const history = this.sim.history;
    const step = this.sim.step;
    const s = this.shown;
    if (s.min !== history.oldest || s.max !== history.head || s.value !== step) {
      // Bounds before the value: the browser clamps a value outside the current range.
      this.scrubber.min = String(history.oldest);
      this.scrubber.max = String(history.head);
      this.scrubber.value = String(step);
      this.readout.value = step < history.head ? `step ${integer(step)} of ${integer(history.head)}` : `step ${integer(step)}`;
      this.scrubber.setAttribute('aria-valuetext', this.readout.value);
      s.min = history.oldest;
      s.max = history.head;
      s.value = step;
      const kept = `${((history.head - history.oldest) / 60).toFixed(1)} s kept, ${(history.bytes / MB).toFixed(1)} MB`;
      if (this.kept.textContent !== kept) this.kept.textContent = kept;
    }
    if (s.count !== history.count || s.bytes !== history.bytes || s.spacing !== history.spacing) {
      s.count = history.count;
      s.bytes = history.bytes;
      s.spacing = history.spacing;
      this.kept.title =
        `The scrubber goes back over the last ${HISTORY_SPAN_STEPS / 60} s at most, within ${HISTORY_BUDGET_BYTES / MB} MB of snapshots ` +
        `(world.snapshot() every ${MIN_SPACING} steps, up to ${MAX_SPACING} where snapshots are slow to take, and after each edit; ` +
        `now every ${history.spacing}): ${history.count} snapshots, ${(history.bytes / MB).toFixed(1)} MB. ` +
        'Going back pauses; stepping on from there, or any edit, forgets the steps after.';
    }
  }
}
