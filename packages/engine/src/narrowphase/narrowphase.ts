import type { BodyStore } from '../store/body-store.js';
import type { ContactSink } from '../store/contact-buffer.js';
import type { PairConsumer } from '../store/pair-sink.js';
import { TypeCode } from '../store/body-types.js';
import { circlesOverlap } from './circle-circle.js';

/**
 * Filters candidate pairs to touching ones and records them as (lo, hi) slot pairs.
 *
 * Dropped before any geometry, in this order:
 * - pairs with no awake dynamic body: static and kinematic bodies are infinitely massive, and a
 *   sleeper needs nothing from another sleeper or from a static body;
 * - pairs filtered by collision layers (report 3.1.4.2): each body's category must be in the
 *   other's mask. These are counted in `filtered`.
 * Only circles exist today; when polygons come, the test below becomes a dispatch on the pair of
 * shape codes (`bodies.shape`).
 */
export class NarrowPhase implements PairConsumer {
  /** Pairs dropped by collision layers since `begin`. */
  filtered = 0;

  constructor(
    private readonly bodies: BodyStore,
    private readonly contacts: ContactSink,
  ) {}

  begin(): void {
    this.filtered = 0;
  }

  accept(pairs: Int32Array, from: number, to: number): void {
    this.contacts.pushPairs(pairs, from, to);
  }

  consume(a: Int32Array, b: Int32Array, count: number): void {
    const bodies = this.bodies;
    // The same filters and test, in the body kernel where the columns live there.
    if (bodies.kernel) {
      this.filtered += bodies.kernel.narrowPhase(a, b, count, this.contacts);
      return;
    }
    const { type, asleep, category, mask } = bodies;
    const contacts = this.contacts;
    for (let k = 0; k < count; k++) {
      const i = a[k];
      const j = b[k];
      const movingI = type[i] === TypeCode.kinematic || (type[i] === TypeCode.dynamic && asleep[i] === 0);
      const movingJ = type[j] === TypeCode.kinematic || (type[j] === TypeCode.dynamic && asleep[j] === 0);
      if (!(movingI || movingJ)) continue;
      if (type[i] !== TypeCode.dynamic && type[j] !== TypeCode.dynamic) continue;
      if ((category[i] & mask[j]) === 0 || (category[j] & mask[i]) === 0) {
        this.filtered++;
        continue;
      }
      if (circlesOverlap(bodies, i, j)) {
        if (i < j) contacts.push(i, j);
        else contacts.push(j, i);
      }
    }
  }
}
