import { JOINT_HANDLES, JOINT_MAX_GENERATION, SLOT_SPACE } from '../store/handles.js';
import { grow, grownCapacity } from '../util/grow.js';
import { J, JOINT_STRIDE } from './joint-layout.js';

/** No body: the target joint's body A is the world. */
export const NO_BODY = -1;

/**
 * The world's joints: a record of JOINT_STRIDE doubles per slot (see joint-layout.ts), the kind
 * and the two body slots, and each body's list of joints (edges 2j and 2j + 1 are joint j's ends
 * at A and at B), so that destroying a body finds its joints and the narrow-phase can ask whether
 * two bodies are joined. Handles work as body handles do, in a space of their own (handles.ts).
 */
export class JointStore {
  count = 0;
  slotCount = 0;
  kind = new Uint8Array(0);
  bodyA = new Int32Array(0);
  bodyB = new Int32Array(0);
  /** 1 where the joined bodies still collide with each other (Box2D's collideConnected). */
  collide = new Uint8Array(0);
  live = new Uint8Array(0);
  generation = new Uint32Array(0);
  record = new Float64Array(0);
  /** Per edge, the next edge at the same body, or -1. */
  edgeNext = new Int32Array(0);
  /** Per body slot, its first edge, or -1 (slots beyond the array have none). */
  firstEdge = new Int32Array(0);
  /** Joints whose bodies do not collide: the narrow-phase asks `joined` only while there are some. */
  nonColliding = 0;
  /** Joints with a finite break force or torque: the step looks for broken joints only while there are some. */
  breakable = 0;
  /** A pressure joint's ring of body slots, in order; its first two are also its bodies A and B. */
  private readonly rings = new Map<number, Int32Array>();
  /** Per body slot, how many rings it is in (slots beyond the array are in none). */
  ringMember = new Int32Array(0);
  private freeSlots: number[] = [];

  hasRoom(): boolean {
    return this.freeSlots.length > 0 || this.slotCount < SLOT_SPACE;
  }

  /** Adds a joint whose definition is `definition` (JOINT_STRIDE doubles), a pressure joint with its ring; returns its slot. */
  add(kind: number, a: number, b: number, collide: boolean, definition: Float64Array, ring: Int32Array | null = null): number {
    let slot = this.freeSlots.pop();
    if (slot === undefined) {
      if (this.slotCount === this.kind.length) this.grow(this.slotCount + 1);
      slot = this.slotCount++;
    }
    this.kind[slot] = kind;
    this.bodyA[slot] = a;
    this.bodyB[slot] = b;
    this.collide[slot] = collide ? 1 : 0;
    if (!collide) this.nonColliding++;
    this.live[slot] = 1;
    this.record.set(definition, slot * JOINT_STRIDE);
    if (isBreakable(definition, 0)) this.breakable++;
    this.link(2 * slot, a);
    this.link(2 * slot + 1, b);
    if (ring !== null) {
      this.rings.set(slot, ring);
      for (const body of ring) {
        if (this.ringMember.length <= body) this.ringMember = grow(this.ringMember, grownCapacity(this.ringMember.length, body + 1));
        this.ringMember[body]++;
      }
    }
    this.count++;
    return slot;
  }

  /** A pressure joint's ring of body slots. */
  ring(slot: number): Int32Array {
    return this.rings.get(slot)!;
  }

  /** The pressure joints whose ring holds body `body`, in slot order. */
  ringsOf(body: number): number[] {
    const out: number[] = [];
    if (body >= this.ringMember.length || this.ringMember[body] === 0) return out;
    for (const [slot, ring] of this.rings) if (ring.includes(body)) out.push(slot);
    return out.sort((x, y) => x - y);
  }

  remove(slot: number): void {
    const ring = this.rings.get(slot);
    if (ring !== undefined) {
      for (const body of ring) this.ringMember[body]--;
      this.rings.delete(slot);
    }
    this.unlink(2 * slot, this.bodyA[slot]);
    this.unlink(2 * slot + 1, this.bodyB[slot]);
    if (this.collide[slot] === 0) this.nonColliding--;
    if (isBreakable(this.record, slot * JOINT_STRIDE)) this.breakable--;
    this.live[slot] = 0;
    this.record.fill(0, slot * JOINT_STRIDE, (slot + 1) * JOINT_STRIDE);
    this.count--;
    if (this.generation[slot] + 1 >= JOINT_MAX_GENERATION) return;
    this.generation[slot]++;
    this.freeSlots.push(slot);
  }

  handleOf(slot: number): number {
    return JOINT_HANDLES + this.generation[slot] * SLOT_SPACE + slot;
  }

  slotOf(handle: number): number {
    if (!Number.isSafeInteger(handle) || handle < JOINT_HANDLES) return -1;
    const slot = (handle - JOINT_HANDLES) % SLOT_SPACE;
    const gen = (handle - JOINT_HANDLES - slot) / SLOT_SPACE;
    return slot < this.slotCount && this.live[slot] === 1 && this.generation[slot] === gen ? slot : -1;
  }

  describeMissing(handle: number): string {
    if (!Number.isSafeInteger(handle) || handle < 0) return 'is not a joint handle';
    if (handle < JOINT_HANDLES) return 'is not a joint handle: it lies in the range of body, segment and shape handles';
    const slot = (handle - JOINT_HANDLES) % SLOT_SPACE;
    const gen = (handle - JOINT_HANDLES - slot) / SLOT_SPACE;
    if (slot >= this.slotCount || gen > this.generation[slot]) return 'is unknown to this world';
    return 'is stale: the joint was destroyed, broke, or went with one of its bodies';
  }

  /** The joint at the other end of body `slot`'s edge `edge`. */
  jointOf(edge: number): number {
    return edge >> 1;
  }

  /** Whether bodies a and b share a joint that keeps them from colliding. */
  joined(a: number, b: number): boolean {
    const first = this.firstEdge;
    if (a >= first.length || b >= first.length) return false;
    let e = first[a];
    if (e < 0 || first[b] < 0) return false;
    for (; e >= 0; e = this.edgeNext[e]) {
      const j = e >> 1;
      if (this.collide[j] === 1) continue;
      const other = (e & 1) === 0 ? this.bodyB[j] : this.bodyA[j];
      if (other === b) return true;
    }
    return false;
  }

  memoryBytes(): number {
    return this.record.byteLength + this.kind.byteLength * 3 + this.bodyA.byteLength * 2 + this.generation.byteLength + this.edgeNext.byteLength + this.firstEdge.byteLength;
  }

  private link(edge: number, body: number): void {
    if (body < 0) {
      this.edgeNext[edge] = -1;
      return;
    }
    if (this.firstEdge.length <= body) {
      const old = this.firstEdge.length;
      this.firstEdge = grow(this.firstEdge, grownCapacity(old, body + 1));
      this.firstEdge.fill(-1, old);
    }
    this.edgeNext[edge] = this.firstEdge[body];
    this.firstEdge[body] = edge;
  }

  private unlink(edge: number, body: number): void {
    if (body < 0) return;
    let e = this.firstEdge[body];
    if (e === edge) {
      this.firstEdge[body] = this.edgeNext[edge];
      return;
    }
    while (e >= 0) {
      const next = this.edgeNext[e];
      if (next === edge) {
        this.edgeNext[e] = this.edgeNext[edge];
        return;
      }
      e = next;
    }
  }

  private grow(needed: number): void {
    const capacity = grownCapacity(this.kind.length, needed);
    this.kind = grow(this.kind, capacity);
    this.bodyA = grow(this.bodyA, capacity);
    this.bodyB = grow(this.bodyB, capacity);
    this.collide = grow(this.collide, capacity);
    this.live = grow(this.live, capacity);
    this.generation = grow(this.generation, capacity);
    this.record = grow(this.record, capacity * JOINT_STRIDE);
    this.edgeNext = grow(this.edgeNext, 2 * capacity);
  }
}

export { J, JOINT_STRIDE };

function isBreakable(r: Float64Array, o: number): boolean {
  return r[o + J.breakForce] < Infinity || r[o + J.breakTorque] < Infinity;
}
