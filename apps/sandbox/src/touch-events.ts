import type { World } from '@maxgrid/engine';

/** Steps a body stays highlighted after it began touching another, or a segment: long enough to be seen. */
export const FLASH_STEPS = 8;

/**
 * The Contact events toggle: counts of the last step's begin and end events for the monitor, and
 * the step at which each slot last began a touch, for the overlay's flash. Storing a step number
 * rather than a countdown means nothing has to walk every body each step to fade the flashes.
 */
export class TouchEvents {
  enabled = false;
  begins = 0;
  ends = 0;
  /** Begin events since the world was built. */
  totalBegins = 0;
  /** Step number of each slot's last begin event. */
  flashStep = new Float64Array(0);
  /** The step count after the last recorded step. */
  step = 0;

  reset(enabled: boolean): void {
    this.enabled = enabled;
    this.begins = 0;
    this.ends = 0;
    this.totalBegins = 0;
    this.step = 0;
    this.flashStep.fill(-Infinity);
  }

  record(world: World): void {
    this.step = world.stats.steps;
    if (!this.enabled) return;
    const e = world.contactEvents();
    // Touches between bodies, with segments and with the box walls alike: a ball landing on a
    // funnel wall or on the floor flashes too.
    this.begins = e.beginCount + e.segmentBeginCount + e.wallBeginCount;
    this.ends = e.endCount + e.segmentEndCount + e.wallEndCount;
    this.totalBegins += this.begins;
    const slots = world.views().slotCount;
    if (this.flashStep.length < slots) {
      const grown = new Float64Array(Math.max(slots, this.flashStep.length * 2));
      grown.fill(-Infinity);
      grown.set(this.flashStep);
      this.flashStep = grown;
    }
    for (let k = 0; k < e.beginCount; k++) {
      // Begin events name live bodies, so both handles map to slots.
      this.flashStep[world.slotOfHandle(e.beginA[k])] = this.step;
      this.flashStep[world.slotOfHandle(e.beginB[k])] = this.step;
    }
    for (let k = 0; k < e.segmentBeginCount; k++) this.flashStep[world.slotOfHandle(e.segmentBeginBody[k])] = this.step;
    for (let k = 0; k < e.wallBeginCount; k++) this.flashStep[world.slotOfHandle(e.wallBeginBody[k])] = this.step;
  }

  /** Whether slot `s` began a touch in the last few steps. */
  flashing(s: number): boolean {
    return s < this.flashStep.length && this.step - this.flashStep[s] < FLASH_STEPS;
  }
}
