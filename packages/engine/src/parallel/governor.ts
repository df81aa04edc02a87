/** Steps on the threads before the first try of the calling thread alone: the threaded path compiles and warms up over its first dozen steps, which cost many times a settled step (docs/engine.md, Numbers). */
const FIRST_TRY = 16;
/** Steps between tries of the mode not in use, after a switch; four times as many after each try that loses. */
const MIN_INTERVAL = 8;
const MAX_INTERVAL = 1024;
/** Recent steps of the mode in use that a try is compared with (their lower quartile). */
const RECENT = 8;
/**
 * Steps in a try. The first pays for the switch (workers woken from their sleep, caches refilled)
 * and only ends the try if it is a clear loss; the others are judged by the slower of them, so
 * that one lucky step on a busy machine (threads that happened to run together) does not switch.
 */
const TRIAL = 3;
/** A try's step this many times the recent quartile ends the try at once, lost. */
const CLEAR_LOSS = 4;
/** When the recent quartile grows this much past what it was at the last try, the other mode is tried at once: load came back. */
const DRIFT = 1.5;

/**
 * Whether a world with worker threads steps on them or on the calling thread alone, chosen step by
 * step from what the steps cost. On a machine whose cores are busy with other work, a parallel
 * step waits at each of its stages for a worker the scheduler has not run yet, and can take many
 * times as long as the calling thread alone (docs/engine.md, Numbers); spinning cannot help a
 * thread that is not running. So the governor times every step and, now
 * and then, runs three steps the other way: when the slower of the last two beats the lower
 * quartile of the recent steps, it switches. A try that loses makes the interval to the next four
 * times longer (8, 32, 128, 512, then 1,024 steps), sixteen times after a clear loss (a first
 * step more than four times the recent ones, which ends the try); by that schedule a mode ten
 * times slower, settled, costs one step in 1,024 at ten times: about 1% of the steps' time. When
 * the steps in use grow half as slow again as they were at the last try (load came back), the
 * other mode is tried at once. Both ways give the same bits (the parallel step's guarantee), so
 * switching never changes a result.
 */
export class ThreadGovernor {
  /** Steps taken on the calling thread alone, and on the threads. */
  serialSteps = 0;
  threadedSteps = 0;
  private onThreads = true;
  private trying = false;
  private trialLeft = 0;
  /** The slowest of the try's steps after its first. */
  private trialWorst = 0;
  private untilTry = FIRST_TRY;
  private interval = MIN_INTERVAL;
  private readonly recent = new Float64Array(RECENT);
  private readonly sorted = new Float64Array(RECENT);
  private recentCount = 0;
  private recentNext = 0;
  /** The recent quartile at the last try (or, after a switch, of the first full window); Infinity until known. */
  private reference = Infinity;

  /** Whether the next step runs on the threads. */
  useThreads(): boolean {
    if (!this.trying && --this.untilTry <= 0) {
      this.trying = true;
      this.trialLeft = TRIAL;
      this.trialWorst = 0;
    }
    return this.trying ? !this.onThreads : this.onThreads;
  }

  /** The step just taken: whether on the threads, and its time in ms. */
  note(threaded: boolean, ms: number): void {
    if (threaded) this.threadedSteps++;
    else this.serialSteps++;
    if (!this.trying) {
      this.recent[this.recentNext] = ms;
      this.recentNext = (this.recentNext + 1) % RECENT;
      if (this.recentCount < RECENT) {
        // A new mode's reference is its first full window's quartile, not one step.
        if (++this.recentCount === RECENT && this.reference === Infinity) this.reference = this.recentQuartile();
      } else if (this.untilTry > 1 && this.recentQuartile() > DRIFT * this.reference) this.untilTry = 1;
      return;
    }
    const first = this.trialLeft === TRIAL;
    if (!first) this.trialWorst = Math.max(this.trialWorst, ms);
    // A first step far slower than the recent ones is a clear loss: no more of the try.
    const clear = first && this.recentCount > 0 && ms > CLEAR_LOSS * this.recentQuartile();
    if (--this.trialLeft > 0 && !clear) return;
    this.trying = false;
    const best = clear ? Infinity : this.trialWorst;
    const quartile = this.recentCount > 0 ? this.recentQuartile() : Infinity;
    if (best < quartile) {
      this.onThreads = threaded;
      this.interval = MIN_INTERVAL;
      this.recentCount = 0;
      this.recentNext = 0;
      this.recent[this.recentNext++] = best;
      this.recentCount = 1;
      this.reference = Infinity;
    } else {
      // A clear loss (threads preempted on a busy machine cost tens of times a step) waits longer.
      this.interval = Math.min(MAX_INTERVAL, (clear ? 16 : 4) * this.interval);
      // Only up while tries keep losing: steps that swing between fast and preempted (a busy
      // machine) would otherwise move the quartile past DRIFT and bring on try after try.
      this.reference = this.reference === Infinity ? quartile : Math.max(this.reference, quartile);
    }
    this.untilTry = this.interval;
  }

  /**
   * The lower quartile of the recent steps: what a step costs when it is not preempted. On a busy
   * machine steps swing between that and several times it, and a median jumps between the two.
   */
  private recentQuartile(): number {
    const n = this.recentCount;
    const s = this.sorted;
    for (let k = 0; k < n; k++) {
      const v = this.recent[k];
      let j = k - 1;
      while (j >= 0 && s[j] > v) {
        s[j + 1] = s[j];
        j--;
      }
      s[j + 1] = v;
    }
    return s[(n - 1) >> 2];
  }
}
