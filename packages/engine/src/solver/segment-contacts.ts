import type { BodyStore } from '../store/body-store.js';
import type { SegmentStore, SegmentGrid } from '../store/segment-store.js';
import type { ContactEvents } from '../store/contact-events.js';
import { TypeCode } from '../store/body-types.js';
import { closestOnSegment, segmentNormal } from '../narrowphase/circle-segment.js';
import { mixRestitution } from './restitution.js';
import type { SolverSettings } from './contact-solver.js';

const closest = new Float64Array(2);
const normal = new Float64Array(2);

/**
 * Dynamic circles against static segments, after the circle-circle contacts. Bodies in slot order,
 * and for each its segments in slot order, so the result does not depend on the broad-phase.
 * A segment is a capsule of radius `thickness`; a touching circle is pushed out along the normal
 * from the closest point (by the settings' positionCorrection of its overlap beyond contactSlop,
 * as between bodies), and its velocity reflected with the pair's restitution if it approaches.
 * A circle whose centre lies exactly on the segment is pushed along the segment's left normal.
 * With `events`, each touching pair is noted for the touch events, and an approach at least
 * the settings' `hitThreshold` fast is recorded as a segment hit.
 * Returns the number of circle-segment contacts.
 */
export function solveSegmentContacts(
  bodies: BodyStore,
  segments: SegmentStore,
  grid: SegmentGrid,
  settings: SolverSettings,
  events: ContactEvents | null,
): number {
  const { restitutionThreshold, hitThreshold, positionCorrection, contactSlop } = settings;
  if (segments.count === 0) return 0;
  const { x, y, vx, vy, radius, restitution, type, asleep, category, mask, slotCount } = bodies;
  let contacts = 0;
  for (let i = 0; i < slotCount; i++) {
    if (type[i] !== TypeCode.dynamic || asleep[i]) continue;
    const r = radius[i];
    // The box in the grid's typed array: see SegmentGrid.queryBox.
    const box = grid.box;
    box[0] = x[i] - r;
    box[1] = y[i] - r;
    box[2] = x[i] + r;
    box[3] = y[i] + r;
    const found = grid.queryBox(segments);
    for (let k = 0; k < found; k++) {
      const s = grid.found[k];
      if ((category[i] & segments.mask[s]) === 0 || (segments.category[s] & mask[i]) === 0) continue;
      const ax = segments.ax[s];
      const ay = segments.ay[s];
      const bx = segments.bx[s];
      const by = segments.by[s];
      closestOnSegment(x[i], y[i], ax, ay, bx, by, closest);
      const dx = x[i] - closest[0];
      const dy = y[i] - closest[1];
      const reach = r + segments.thickness[s];
      const distSq = dx * dx + dy * dy;
      if (distSq >= reach * reach) continue;
      contacts++;
      events?.noteSegmentTouch(i, s);
      const dist = Math.sqrt(distSq);
      segmentNormal(dx, dy, dist, ax, ay, bx, by, normal);
      const nx = normal[0];
      const ny = normal[1];
      const vn = vx[i] * nx + vy[i] * ny;
      if (vn < 0) {
        if (events !== null && -vn >= hitThreshold) events.recordSegmentHit(bodies, i, segments, s, -vn);
        const e = -vn < restitutionThreshold ? 0 : mixRestitution(restitution[i], segments.restitution[s]);
        vx[i] -= (1 + e) * vn * nx;
        vy[i] -= (1 + e) * vn * ny;
      }
      const excess = reach - dist - contactSlop;
      if (excess > 0) {
        x[i] += excess * positionCorrection * nx;
        y[i] += excess * positionCorrection * ny;
      }
    }
  }
  return contacts;
}
