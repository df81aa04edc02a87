import type { BroadPhase } from './broadphase.js';
import type { BodyStore } from '../store/body-store.js';
import type { PairSink } from '../store/pair-sink.js';
import { TypeCode } from '../store/body-types.js';

/** Every unordered pair of live bodies once: n(n-1)/2 candidates, the report's starting point (5.9). */
export class NaiveBroadPhase implements BroadPhase {
  readonly name = 'naive';

  findPairs(bodies: BodyStore, out: PairSink): number {
    const { type, slotCount } = bodies;
    const n = bodies.proxyCount;
    for (let i = 0; i < slotCount; i++) {
      if (!bodies.isProxyType(type[i])) continue;
      for (let j = i + 1; j < slotCount; j++) {
        if (bodies.isProxyType(type[j])) out.push(i, j);
      }
    }
    return (n * (n - 1)) / 2;
  }

  memoryBytes(): number {
    return 0;
  }
}
