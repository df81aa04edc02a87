import type { BodyStore } from '../store/body-store.js';
import type { ContactBuffer } from '../store/contact-buffer.js';
import type { PairConsumer } from '../store/pair-sink.js';
import { TypeCode } from '../store/body-types.js';
import { circlesOverlap } from './circle-circle.js';

/**
 * Filters candidate pairs to touching ones and records them as (lo, hi) slot pairs.
 *
 * Pairs with no dynamic body are dropped first: static and kinematic bodies are infinitely
 * massive, so nothing between them needs resolving. Only circles exist today; when polygons come,
 * the test below becomes a dispatch on the pair of shape codes (`bodies.shape`).
 */
export class NarrowPhase implements PairConsumer {
  constructor(
    private readonly bodies: BodyStore,
    private readonly contacts: ContactBuffer,
  ) {}

  consume(a: Int32Array, b: Int32Array, count: number): void {
    const bodies = this.bodies;
    const type = bodies.type;
    const contacts = this.contacts;
    for (let k = 0; k < count; k++) {
      const i = a[k];
      const j = b[k];
      if (type[i] !== TypeCode.dynamic && type[j] !== TypeCode.dynamic) continue;
      if (circlesOverlap(bodies, i, j)) {
        if (i < j) contacts.push(i, j);
        else contacts.push(j, i);
      }
    }
  }
}
