import type { BodyStore } from '../store/body-store.js';
import type { PairSink } from '../store/pair-sink.js';
import type { SegmentStore } from '../store/segment-store.js';
import { TypeCode } from '../store/body-types.js';
import { StaticTree } from './static-tree.js';
import { paddedRadius } from './fat-bounds.js';

/** Tree ids of segments: above every body slot, so a query lists static circles first, as slots ascend. */
export const SEGMENT_ID = 2 ** 30;

/**
 * The static circles and segments of a world of circles in one static tree, rebuilt when any of
 * them changes (the world's staticVersion), shared by the static-pairs stage and the continuous
 * sweep. Boxes are padded as the broad-phases pad theirs (fat-bounds.ts), so a box test never
 * drops a pair whose exact test would touch.
 */
export class StaticIndex {
  readonly tree = new StaticTree();
  private version = -1;

  /** The tree, rebuilt first if the statics changed since the last call. */
  current(bodies: BodyStore, segments: SegmentStore, version: number): StaticTree {
    if (version !== this.version) this.rebuild(bodies, segments, version);
    return this.tree;
  }

  memoryBytes(): number {
    return this.tree.memoryBytes();
  }

  private rebuild(bodies: BodyStore, segments: SegmentStore, version: number): void {
    this.version = version;
    const { x, y, radius, type } = bodies;
    const tree = this.tree;
    tree.clear();
    for (let s = 0; s < bodies.slotCount; s++) {
      if (type[s] !== TypeCode.static) continue;
      const pad = paddedRadius(radius[s], Math.abs(x[s]) + Math.abs(y[s]));
      tree.add(s, x[s] - pad, y[s] - pad, x[s] + pad, y[s] + pad);
    }
    tree.addSegments(segments, SEGMENT_ID, true);
    tree.finish();
  }
}

/**
 * Static circles are kept out of the broad-phase (BodyStore.staticsApart): this stage pairs each
 * awake dynamic circle with the static circles whose boxes meet its own, from the static index,
 * so that no broad-phase examines a static-static pair or sizes its cells for a huge static
 * circle, and a wall of thousands of overlapping static circles costs a tree query per moving
 * body. Returns the pairs examined (found in the tree). Sleeping and kinematic bodies need no
 * contact with a static one: the narrow-phase would drop it.
 */
export function findStaticPairs(bodies: BodyStore, tree: StaticTree, out: PairSink): number {
  if (bodies.staticCount === 0) return 0;
  const { x, y, radius, type, asleep, slotCount } = bodies;
  let examined = 0;
  for (let i = 0; i < slotCount; i++) {
    if (type[i] !== TypeCode.dynamic || asleep[i]) continue;
    const pad = paddedRadius(radius[i], Math.abs(x[i]) + Math.abs(y[i]));
    const box = tree.box;
    box[0] = x[i] - pad;
    box[1] = y[i] - pad;
    box[2] = x[i] + pad;
    box[3] = y[i] + pad;
    const found = tree.queryBox();
    const ids = tree.found;
    for (let k = 0; k < found; k++) {
      const s = ids[k];
      // Ascending: the segments, listed after every static circle, end the run.
      if (s >= SEGMENT_ID) break;
      out.push(i, s);
      examined++;
    }
  }
  return examined;
}
