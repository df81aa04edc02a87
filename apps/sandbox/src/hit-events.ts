import type { World } from '@maxgrid/engine';

/** Steps a hit ring stays on screen: a fifth of a second, long enough to be seen at 60 Hz. */
export const HIT_RING_STEPS = 12;

/**
 * The Hit events toggle: the last step's hit count and fastest approach for the monitor, and for
 * each slot the step of its last hit and that hit's speed, for the overlay's rings. As with touch
 * flashes, a step number rather than a countdown means nothing walks every body to fade them.
 */
export class HitEvents {
  enabled = false;
  /** The world's hitEventThreshold: the overlay sizes rings by speed relative to it. */
  threshold = Infinity;
  /** Hits in the last step, on bodies and on segments, and the fastest approach among them (0 when there were none). */
  count = 0;
  fastest = 0;
  /** Hits since the world was built. */
  totalHits = 0;
  /** Step number of each slot's last hit, and the fastest approach of that step. */
  hitStep = new Float64Array(0);
  hitSpeed = new Float64Array(0);
  /** The step count after the last recorded step. */
  step = 0;
  /** Step of the latest hit anywhere: lets the overlay skip its walk once every ring is gone. */
  lastHitStep = -Infinity;

  reset(enabled: boolean, threshold: number): void {
    this.enabled = enabled;
    this.threshold = threshold;
    this.count = 0;
    this.fastest = 0;
    this.totalHits = 0;
    this.step = 0;
    this.lastHitStep = -Infinity;
    this.hitStep.fill(-Infinity);
  }

  record(world: World): void {
    this.step = world.stats.steps;
    if (!this.enabled) return;
    const e = world.contactEvents();
    const hits = e.hitCount + e.segmentHitCount + e.wallHitCount;
    this.count = hits;
    this.totalHits += hits;
    this.grow(world.views().slotCount);
    let fastest = 0;
    for (let k = 0; k < e.hitCount; k++) {
      const speed = e.hitSpeed[k];
      if (speed > fastest) fastest = speed;
      // Hits name bodies that collided in this step, so both handles map to live slots.
      this.mark(world.slotOfHandle(e.hitA[k]), speed);
      this.mark(world.slotOfHandle(e.hitB[k]), speed);
    }
    // Hits on segments and box walls ring the body; neither is drawn as a body.
    for (let k = 0; k < e.segmentHitCount; k++) {
      const speed = e.segmentHitSpeed[k];
      if (speed > fastest) fastest = speed;
      this.mark(world.slotOfHandle(e.segmentHitBody[k]), speed);
    }
    for (let k = 0; k < e.wallHitCount; k++) {
      const speed = e.wallHitSpeed[k];
      if (speed > fastest) fastest = speed;
      this.mark(world.slotOfHandle(e.wallHitBody[k]), speed);
    }
    this.fastest = fastest;
    if (hits > 0) this.lastHitStep = this.step;
  }

  /** Whether any ring is still on screen. */
  get showing(): boolean {
    return this.enabled && this.step - this.lastHitStep < HIT_RING_STEPS;
  }

  /** Whether slot `s` was hit in the last few steps. */
  ringing(s: number): boolean {
    return s < this.hitStep.length && this.step - this.hitStep[s] < HIT_RING_STEPS;
  }

  // A body hit twice in one step keeps the faster hit; a later step's hit replaces an older one.
  private mark(s: number, speed: number): void {
    if (this.hitStep[s] !== this.step) {
      this.hitStep[s] = this.step;
      this.hitSpeed[s] = speed;
    } else if (speed > this.hitSpeed[s]) {
      this.hitSpeed[s] = speed;
    }
  }

  private grow(slots: number): void {
    if (this.hitStep.length >= slots) return;
    const capacity = Math.max(slots, this.hitStep.length * 2);
    const steps = new Float64Array(capacity);
    steps.fill(-Infinity);
    steps.set(this.hitStep);
    const speeds = new Float64Array(capacity);
    speeds.set(this.hitSpeed);
    this.hitStep = steps;
    this.hitSpeed = speeds;
  }
}
