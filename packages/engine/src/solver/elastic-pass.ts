import type { BodyStore } from '../store/body-store.js';
import { TypeCode } from '../store/body-types.js';
import { ContactList, ContactPoint, POINT_STRIDE, WORLD } from '../narrowphase/contact-list.js';
import { twoPointImpulses } from './two-point-impulses.js';
import { coulombImpulse } from './coulomb-friction.js';

// The contact point record's fields as this module's own constants, which V8 folds into the code.
const { anchorAX: PT_ANCHOR_AX, anchorAY: PT_ANCHOR_AY, anchorBX: PT_ANCHOR_BX, anchorBY: PT_ANCHOR_BY, approachSpeed: PT_APPROACH_SPEED, normalImpulse: PT_NORMAL_IMPULSE, separation: PT_SEPARATION, totalNormalImpulse: PT_TOTAL_NORMAL_IMPULSE } = ContactPoint;

/** twoPointImpulses' answer. */
const impulses = new Float64Array(2);

export interface ElasticSettings {
  restitutionThreshold: number;
  positionCorrection: number;
  contactSlop: number;
}

/**
 * The report's single pass (3.1.5, 5.10; the circle route's contact-solver.ts) for shapes that
 * turn: each contact in canonical order, from the velocities as earlier contacts left them,
 *
 * 1. takes the collision impulse that reverses its points' approach, scaled by restitution e
 *    (the largest of the two shapes', 0 below the threshold): with one point,
 *    j = -(1 + e) vn / K, K = 1/ma + 1/mb + (ra x n)^2 / Ia + (rb x n)^2 / Ib; with two, the
 *    two-point problem is solved as a block (twoPointImpulses). Every point that takes an impulse
 *    leaves with -e times its approach speed, so at e = 1 without friction each contact keeps
 *    the kinetic energy, linear plus rotational, to round-off (see the energy test);
 * 2. with friction, a Coulomb impulse along the tangent at each point, at most mu times its
 *    normal impulse;
 * 3. removes the overlap (beyond contactSlop, times positionCorrection) by moving the two bodies
 *    apart along the normal in proportion to their inverse masses, without turning them: a move
 *    of position, not velocity, so energy is untouched.
 *
 * Sleeping, static and kinematic bodies are infinitely massive here. One pass cannot hold a
 * stack up (each contact forgets the others); the soft step does (solver: 'soft').
 */
export class ElasticPass {
  solve(bodies: BodyStore, contacts: ContactList, settings: ElasticSettings): void {
    noteApproach(bodies, contacts);
    const { x, y, vx, vy, invMass, type, asleep } = bodies;
    const rigid = bodies.rigid!;
    const { angularVelocity, invInertia } = rigid;
    const count = contacts.count;
    const threshold = settings.restitutionThreshold;
    const correction = settings.positionCorrection;
    const slop = settings.contactSlop;
    const order = contacts.order;
    for (let listed = 0; listed < count; listed++) {
      const k = order[listed];
      const a = contacts.bodyA[k];
      const b = contacts.bodyB[k];
      const movesA = type[a] === TypeCode.dynamic && asleep[a] === 0;
      const movesB = b !== WORLD && type[b] === TypeCode.dynamic && asleep[b] === 0;
      const mA = movesA ? invMass[a] : 0;
      const iA = movesA ? invInertia[a] : 0;
      const mB = movesB ? invMass[b] : 0;
      const iB = movesB ? invInertia[b] : 0;
      if (mA + mB === 0) continue;
      let vax = vx[a];
      let vay = vy[a];
      let wa = angularVelocity[a];
      let vbx = b === WORLD ? 0 : vx[b];
      let vby = b === WORLD ? 0 : vy[b];
      let wb = b === WORLD ? 0 : angularVelocity[b];
      const nx = contacts.normalX[k];
      const ny = contacts.normalY[k];
      let n = contacts.pointCount[k];
      let at0 = 2 * k;
      // Points apart (a polygon face keeps its second point, see polygon-polygon.ts) take no part.
      if (n === 2 && !(contacts.points[(at0 + 1) * POINT_STRIDE + PT_SEPARATION] < 0)) n = 1;
      else if (n === 2 && !(contacts.points[at0 * POINT_STRIDE + PT_SEPARATION] < 0)) {
        n = 1;
        at0++;
      }
      // Each point's record: the first point taking part, and the one after it.
      const o0 = at0 * POINT_STRIDE;
      const o1 = o0 + POINT_STRIDE;
      if (!(contacts.points[o0 + PT_SEPARATION] < 0)) continue;
      const r0ax = contacts.points[o0 + PT_ANCHOR_AX];
      const r0ay = contacts.points[o0 + PT_ANCHOR_AY];
      const r0bx = contacts.points[o0 + PT_ANCHOR_BX];
      const r0by = contacts.points[o0 + PT_ANCHOR_BY];
      const rn0a = r0ax * ny - r0ay * nx;
      const rn0b = r0bx * ny - r0by * nx;
      const u0 = (vbx - wb * r0by - (vax - wa * r0ay)) * nx + (vby + wb * r0bx - (vay + wa * r0ax)) * ny;
      let p0 = 0;
      let p1 = 0;
      let r1ax = 0;
      let r1ay = 0;
      let r1bx = 0;
      let r1by = 0;
      let rn1a = 0;
      let rn1b = 0;
      let u1 = 0;
      const k00 = mA + mB + iA * rn0a * rn0a + iB * rn0b * rn0b;
      if (n === 2) {
        r1ax = contacts.points[o1 + PT_ANCHOR_AX];
        r1ay = contacts.points[o1 + PT_ANCHOR_AY];
        r1bx = contacts.points[o1 + PT_ANCHOR_BX];
        r1by = contacts.points[o1 + PT_ANCHOR_BY];
        rn1a = r1ax * ny - r1ay * nx;
        rn1b = r1bx * ny - r1by * nx;
        u1 = (vbx - wb * r1by - (vax - wa * r1ay)) * nx + (vby + wb * r1bx - (vay + wa * r1ax)) * ny;
      }
      const approach = Math.max(-u0, n === 2 ? -u1 : -Infinity);
      if (approach > 0) {
        const e = approach < threshold ? 0 : contacts.restitution[k];
        const scale = 1 + e;
        if (n === 1) {
          if (u0 < 0 && k00 > 0) p0 = (-scale * u0) / k00;
        } else {
          const k11 = mA + mB + iA * rn1a * rn1a + iB * rn1b * rn1b;
          const k01 = mA + mB + iA * rn0a * rn1a + iB * rn0b * rn1b;
          twoPointImpulses(k00, k11, k01, scale * u0, scale * u1, impulses);
          p0 = impulses[0];
          p1 = impulses[1];
        }
        if (p0 !== 0 || p1 !== 0) {
          const px = (p0 + p1) * nx;
          const py = (p0 + p1) * ny;
          vax -= mA * px;
          vay -= mA * py;
          vbx += mB * px;
          vby += mB * py;
          wa -= iA * (p0 * rn0a + p1 * rn1a);
          wb += iB * (p0 * rn0b + p1 * rn1b);
          contacts.points[o0 + PT_NORMAL_IMPULSE] = p0;
          contacts.points[o0 + PT_TOTAL_NORMAL_IMPULSE] = p0;
          if (n === 2) {
            contacts.points[o1 + PT_NORMAL_IMPULSE] = p1;
            contacts.points[o1 + PT_TOTAL_NORMAL_IMPULSE] = p1;
          }
        }
        const friction = contacts.friction[k];
        if (friction > 0) {
          const tx = ny;
          const ty = -nx;
          for (let p = 0; p < n; p++) {
            const limit = friction * (p === 0 ? p0 : p1);
            if (limit === 0) continue;
            const rax = p === 0 ? r0ax : r1ax;
            const ray = p === 0 ? r0ay : r1ay;
            const rbx = p === 0 ? r0bx : r1bx;
            const rby = p === 0 ? r0by : r1by;
            const vt = (vbx - wb * rby - (vax - wa * ray)) * tx + (vby + wb * rbx - (vay + wa * rax)) * ty;
            const rta = rax * ty - ray * tx;
            const rtb = rbx * ty - rby * tx;
            const kt = mA + mB + iA * rta * rta + iB * rtb * rtb;
            const jt = coulombImpulse(vt, kt, limit);
            vax -= mA * jt * tx;
            vay -= mA * jt * ty;
            vbx += mB * jt * tx;
            vby += mB * jt * ty;
            wa -= iA * jt * rta;
            wb += iB * jt * rtb;
          }
        }
        if (movesA) {
          vx[a] = vax;
          vy[a] = vay;
          angularVelocity[a] = wa;
        }
        if (movesB) {
          vx[b] = vbx;
          vy[b] = vby;
          angularVelocity[b] = wb;
        }
      }
      let deepest = contacts.points[o0 + PT_SEPARATION];
      if (n === 2 && contacts.points[o1 + PT_SEPARATION] < deepest) deepest = contacts.points[o1 + PT_SEPARATION];
      const excess = -deepest - slop;
      if (!(excess > 0)) continue;
      const push = (excess * correction) / (mA + mB);
      if (movesA) {
        x[a] -= push * mA * nx;
        y[a] -= push * mA * ny;
      }
      if (movesB) {
        x[b] += push * mB * nx;
        y[b] += push * mB * ny;
      }
    }
  }
}

/**
 * Each contact point's approach speed as the pass begins (positive when approaching), for hit
 * events: the speed it met the other shape at. Taken in the pass, a contact's came after the
 * impulses of the contacts before it: a compound of two boxes meeting a wall flat at 5 m/s
 * reported its second box's hit at 2.06, below a threshold of 3, where the soft step reports both
 * at 5.
 */
function noteApproach(bodies: BodyStore, contacts: ContactList): void {
  const { vx, vy } = bodies;
  const w = bodies.rigid!.angularVelocity;
  const { order, count, points, bodyA, bodyB, normalX, normalY, pointCount } = contacts;
  for (let listed = 0; listed < count; listed++) {
    const k = order[listed];
    const a = bodyA[k];
    const b = bodyB[k];
    const vbx = b === WORLD ? 0 : vx[b];
    const vby = b === WORLD ? 0 : vy[b];
    const wb = b === WORLD ? 0 : w[b];
    const nx = normalX[k];
    const ny = normalY[k];
    for (let p = 0; p < pointCount[k]; p++) {
      const o = (2 * k + p) * POINT_STRIDE;
      const rax = points[o + PT_ANCHOR_AX];
      const ray = points[o + PT_ANCHOR_AY];
      const rbx = points[o + PT_ANCHOR_BX];
      const rby = points[o + PT_ANCHOR_BY];
      points[o + PT_APPROACH_SPEED] = -((vbx - wb * rby - (vx[a] - w[a] * ray)) * nx + (vby + wb * rbx - (vy[a] + w[a] * rax)) * ny);
    }
  }
}
