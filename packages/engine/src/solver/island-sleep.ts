import type { BodyStore } from '../store/body-store.js';
import { TypeCode } from '../store/body-types.js';
import { ContactList, WORLD } from '../narrowphase/contact-list.js';
import { grownCapacity } from '../util/grow.js';
import type { JointStore } from '../joints/joint-store.js';
import { JointKind } from '../joints/joint-layout.js';

/**
 * Island sleeping for worlds with shapes (Box2D v3's islands, computed afresh each step): the
 * awake dynamic bodies linked by touching contacts or by joints form islands (union-find over this step's
 * contact list); an island whose every body has been slower than the sleep speed for the sleep
 * time falls asleep at once, its bodies linked in a ring (RigidColumns.islandNext), so that
 * waking any one of them wakes all of it (BodyStore.wake). A body's speed counts its rim:
 * |v| + r |w|, r its bounding radius. An island touching a moving kinematic body stays awake.
 *
 * Static bodies and world shapes join no island (they hold any number of islands apart). A
 * sleeper stays asleep when a slow body rests on it; a faster one wakes its island (the
 * narrow-phase notes it, ShapeNarrowPhase.wake) before the solve, and the step collides again,
 * so that the island wakes whole, with its own contacts, and takes its share of the hit (see
 * ShapeRoute.run).
 */
export class IslandSleep {
  private parent = new Int32Array(0);
  private rank = new Uint8Array(0);
  private islandTime = new Float64Array(0);
  private blocked = new Uint8Array(0);
  private ringHead = new Int32Array(0);

  update(bodies: BodyStore, contacts: ContactList, joints: JointStore | null, dt: number, speed: number, time: number): void {
    const { vx, vy, type, asleep, sleepTime, radius, slotCount } = bodies;
    const rigid = bodies.rigid!;
    const w = rigid.angularVelocity;
    this.ensure(slotCount);
    const { parent, rank, islandTime, blocked, ringHead } = this;
    for (let i = 0; i < slotCount; i++) {
      parent[i] = i;
      rank[i] = 0;
      if (type[i] !== TypeCode.dynamic || asleep[i]) continue;
      const v = Math.sqrt(vx[i] * vx[i] + vy[i] * vy[i]) + radius[i] * Math.abs(w[i]);
      if (v > speed) sleepTime[i] = 0;
      else sleepTime[i] += dt;
    }
    for (let i = 0; i < slotCount; i++) {
      islandTime[i] = Infinity;
      blocked[i] = 0;
      ringHead[i] = -1;
    }
    const { bodyA, bodyB, pointCount, count, order } = contacts;
    for (let n = 0; n < count; n++) {
      const k = order[n];
      if (pointCount[k] === 0) continue;
      const a = bodyA[k];
      const b = bodyB[k];
      if (b === WORLD) continue;
      const ta = type[a];
      const tb = type[b];
      const awakeA = ta === TypeCode.dynamic && asleep[a] === 0;
      const awakeB = tb === TypeCode.dynamic && asleep[b] === 0;
      if (awakeA && awakeB) this.union(a, b);
      else if (awakeA && ta !== tb && tb === TypeCode.kinematic && isMoving(bodies, b)) blocked[a] = 1;
      else if (awakeB && ta === TypeCode.kinematic && isMoving(bodies, a)) blocked[b] = 1;
    }
    // Joined bodies share an island, touching or not; a joint to a moving kinematic body keeps it awake.
    if (joints !== null) {
      for (let j = 0; j < joints.slotCount; j++) {
        if (joints.live[j] === 0) continue;
        const a = joints.bodyA[j];
        const b = joints.bodyB[j];
        if (joints.kind[j] === JointKind.pressure) {
          // A ring is one island.
          const ring = joints.ring(j);
          for (let k = 1; k < ring.length; k++) {
            const p = ring[k - 1];
            const q = ring[k];
            if (type[p] === TypeCode.dynamic && asleep[p] === 0 && type[q] === TypeCode.dynamic && asleep[q] === 0) this.union(p, q);
          }
          continue;
        }
        const awakeB = type[b] === TypeCode.dynamic && asleep[b] === 0;
        if (a < 0) {
          // A target joint pulls its body somewhere: it stays awake while it has one.
          if (awakeB) blocked[b] = 1;
          continue;
        }
        const awakeA = type[a] === TypeCode.dynamic && asleep[a] === 0;
        if (awakeA && awakeB) this.union(a, b);
        else if (awakeA && type[b] === TypeCode.kinematic && isMoving(bodies, b)) blocked[a] = 1;
        else if (awakeB && type[a] === TypeCode.kinematic && isMoving(bodies, a)) blocked[b] = 1;
      }
    }
    // Each island's shortest still time, and whether anything blocks it.
    for (let i = 0; i < slotCount; i++) {
      if (type[i] !== TypeCode.dynamic || asleep[i]) continue;
      const root = this.find(i);
      if (sleepTime[i] < islandTime[root]) islandTime[root] = sleepTime[i];
      if (blocked[i]) blocked[root] = 1;
    }
    for (let i = 0; i < slotCount; i++) {
      if (type[i] !== TypeCode.dynamic || asleep[i]) continue;
      const root = this.find(i);
      if (blocked[root] || !(islandTime[root] > 0 && islandTime[root] >= time)) continue;
      // Into the root's ring: i goes after the head, so the ring closes on the head.
      const head = ringHead[root];
      if (head < 0) {
        ringHead[root] = i;
        rigid.islandNext[i] = i;
      } else {
        rigid.islandNext[i] = rigid.islandNext[head];
        rigid.islandNext[head] = i;
      }
    }
    for (let i = 0; i < slotCount; i++) {
      if (ringHead[i] < 0) continue;
      const head = ringHead[i];
      let s = head;
      do {
        bodies.fallAsleep(s);
        s = rigid.islandNext[s];
      } while (s !== head);
      // A lone body needs no ring.
      if (rigid.islandNext[head] === head) rigid.islandNext[head] = -1;
    }
  }

  memoryBytes(): number {
    return this.parent.byteLength * 2 + this.rank.byteLength + this.islandTime.byteLength + this.blocked.byteLength;
  }

  private ensure(n: number): void {
    if (this.parent.length >= n) return;
    const capacity = grownCapacity(this.parent.length, n);
    this.parent = new Int32Array(capacity);
    this.rank = new Uint8Array(capacity);
    this.islandTime = new Float64Array(capacity);
    this.blocked = new Uint8Array(capacity);
    this.ringHead = new Int32Array(capacity);
  }

  private find(i: number): number {
    const parent = this.parent;
    let root = i;
    while (parent[root] !== root) root = parent[root];
    while (parent[i] !== root) {
      const next = parent[i];
      parent[i] = root;
      i = next;
    }
    return root;
  }

  private union(a: number, b: number): void {
    const ra = this.find(a);
    const rb = this.find(b);
    if (ra === rb) return;
    // Union by rank, ties to the lower slot: the same islands whatever the contact order.
    if (this.rank[ra] < this.rank[rb] || (this.rank[ra] === this.rank[rb] && rb < ra)) {
      this.parent[ra] = rb;
      if (this.rank[ra] === this.rank[rb]) this.rank[rb]++;
    } else {
      this.parent[rb] = ra;
      if (this.rank[ra] === this.rank[rb]) this.rank[ra]++;
    }
  }
}

function isMoving(bodies: BodyStore, slot: number): boolean {
  return bodies.vx[slot] !== 0 || bodies.vy[slot] !== 0 || bodies.rigid!.angularVelocity[slot] !== 0;
}
