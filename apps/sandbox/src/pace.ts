/** Below this share of real time the page says the simulation is falling behind. */
export const BEHIND = 0.9;

/**
 * Simulated time against real time over the last second or so of frames: how far behind real
 * time the simulation runs when its steps take longer than the frames they must fit in (the page
 * then steps for at most a frame's budget and drops the rest, rather than freeze).
 */
export class Pace {
  /** Simulated seconds per real second over the last whole window; 1 until measured. */
  ratio = 1;
  /** Mean time of the window's steps, ms. */
  stepMs = 0;
  private real = 0;
  private simulated = 0;
  private stepping = 0;
  private steps = 0;

  /** One frame: its real length, the fixed steps it ran and the time they took. */
  note(realSeconds: number, steps: number, dt: number, steppingMs: number): void {
    this.real += realSeconds;
    this.simulated += steps * dt;
    this.steps += steps;
    this.stepping += steppingMs;
    if (this.real < 1) return;
    this.ratio = this.simulated / this.real;
    this.stepMs = this.steps > 0 ? this.stepping / this.steps : 0;
    this.real = this.simulated = this.stepping = this.steps = 0;
  }

  reset(): void {
    this.ratio = 1;
    this.stepMs = 0;
    this.real = this.simulated = this.stepping = this.steps = 0;
  }

  /** The page's line about it: empty while the simulation keeps up. */
  message(stepBudgetMs: number): string {
    if (this.ratio >= BEHIND) return '';
    return `Falling behind real time: ${this.ratio.toFixed(2)}× (a step takes ${this.stepMs.toFixed(0)} ms; each frame steps for at most ${stepBudgetMs} ms and drops the rest, so the page stays responsive).`;
  }
}
