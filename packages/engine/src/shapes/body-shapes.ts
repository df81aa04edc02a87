import type { BodyStore } from '../store/body-store.js';
import { TypeCode } from '../store/body-types.js';
import { ShapeStore, SHAPE_STRIDE, SHAPE_VERTICES, VERTEX, type NewShape } from '../store/shape-store.js';
import { areaProperties, emptyAreaProperties, Geometry } from './geometry.js';
import { MAX_MAGNITUDE } from '../util/validate.js';

const props = emptyAreaProperties();
const plainCircle = new Geometry();

/**
 * Bodies' shapes and what follows from them: mass, centre of mass, rotational inertia, the
 * bounding radius the broad-phase uses, and the body-level collision filter.
 *
 * A world of the report's circles keeps its circles in the body columns alone, with no shape
 * store (`engaged` false): its memory per body and its hot loops stay as they were. The first
 * shape of any other kind, or a circle with friction, engages the world: every body then has its
 * shapes listed here, statics leave the broad-phase for the static index, and each body's
 * broad-phase radius becomes its bounding radius plus `margin` (so that pairs within the
 * solver's speculative distance are found). Engagement lasts for the world's life.
 */
export class BodyShapes {
  readonly store = new ShapeStore();
  engaged = false;
  margin = 0;

  constructor(private readonly bodies: BodyStore) {}

  /** Lists every body's circle as a shape (in slot order) and sets statics apart. */
  engage(margin: number): void {
    if (this.engaged) return;
    const bodies = this.bodies;
    const rigid = bodies.useRigid();
    this.engaged = true;
    this.margin = margin;
    for (let slot = 0; slot < bodies.slotCount; slot++) {
      if (bodies.type[slot] === TypeCode.free) continue;
      const r = bodies.radius[slot];
      const mass = bodies.mass[slot];
      const shape: NewShape = {
        geometry: plainCircle.setCircle(0, 0, r),
        density: mass / (Math.PI * r * r),
        friction: 0,
        restitution: bodies.restitution[slot],
        rollingResistance: 0,
        category: bodies.category[slot],
        mask: bodies.mask[slot],
        sensor: false,
      };
      this.link(slot, shape);
      // The circle keeps the exact mass it was made with; its inertia is that of a uniform disc.
      bodies.setMass(slot, mass, (mass * r * r) / 2);
      bodies.setRadius(slot, r + margin);
      rigid.minExtent[slot] = r;
    }
    bodies.setStaticsApart();
  }

  /** Adds a shape (geometry in the body's own frame, from its origin) and updates the body; returns the shape's slot. */
  add(slot: number, shape: NewShape): number {
    const rigid = this.bodies.useRigid();
    // Stored relative to the current centre of mass, then everything shifts to the new one.
    shape.geometry.translate(-rigid.localCenterX[slot], -rigid.localCenterY[slot]);
    const s = this.link(slot, shape);
    this.update(slot);
    return s;
  }

  /** Removes a shape and updates its body. */
  remove(shapeSlot: number): void {
    const slot = this.store.body[shapeSlot];
    this.unlink(slot, shapeSlot);
    this.store.remove(shapeSlot);
    this.update(slot);
  }

  /** Removes every shape of a body that is being destroyed. */
  removeAll(slot: number): void {
    const rigid = this.bodies.rigid;
    if (!rigid) return;
    const store = this.store;
    for (let s = rigid.firstShape[slot]; s >= 0; ) {
      const next = store.next[s];
      store.remove(s);
      s = next;
    }
    rigid.firstShape[slot] = -1;
    rigid.shapeCount[slot] = 0;
  }

  /**
   * The mass a body would have with one more shape: for refusing a dynamic body that would stay
   * without mass before anything changes.
   */
  massWith(slot: number, shape: NewShape | null): number {
    const rigid = this.bodies.rigid;
    let mass = shape ? shape.density * areaProperties(shape.geometry, props).area : 0;
    if (!rigid) return mass;
    const store = this.store;
    for (let s = rigid.firstShape[slot]; s >= 0; s = store.next[s]) mass += store.density[s] * store.area[s];
    return mass;
  }

  /** The mass the body would have without one of its shapes. */
  massWithout(slot: number, shapeSlot: number): number {
    const rigid = this.bodies.rigid!;
    const store = this.store;
    let mass = 0;
    for (let s = rigid.firstShape[slot]; s >= 0; s = store.next[s]) if (s !== shapeSlot) mass += store.density[s] * store.area[s];
    return mass;
  }

  /**
   * The mass and the rotational inertia about the centre of mass that `update` would give a
   * dynamic body with `shape` added (geometry from its origin; null: none) and its shape in slot
   * `without` removed (-1: none), into out[0] and out[1], changing nothing: for refusing a change
   * under which the loads already applied to the body would overflow. Before the world is
   * engaged, the body's circle counts as the disc it becomes.
   */
  massPropertiesAfter(slot: number, shape: NewShape | null, without: number, out: Float64Array): Float64Array {
    const bodies = this.bodies;
    const rigid = bodies.rigid;
    const store = this.store;
    const listed = this.engaged && rigid !== null;
    // Pass 1: mass and centre, in the body's frame from its origin.
    let mass = 0;
    let mx = 0;
    let my = 0;
    if (listed) {
      for (let s = rigid.firstShape[slot]; s >= 0; s = store.next[s]) {
        if (s === without) continue;
        const m = store.density[s] * store.area[s];
        mass += m;
        mx += m * (store.centroidX[s] + rigid.localCenterX[slot]);
        my += m * (store.centroidY[s] + rigid.localCenterY[slot]);
      }
    } else if (shape !== null) {
      mass = bodies.mass[slot];
    }
    let added = 0;
    if (shape !== null) {
      areaProperties(shape.geometry, props);
      added = shape.density * props.area;
      mass += added;
      mx += added * props.cx;
      my += added * props.cy;
    }
    if (!(mass > 0)) {
      // A dynamic body without shapes has mass 1 and does not turn.
      out[0] = 1;
      out[1] = 0;
      return out;
    }
    const cx = mx / mass;
    const cy = my / mass;
    // Pass 2: each part's inertia about its own centroid, moved to the body's centre.
    let inertia = 0;
    if (listed) {
      for (let s = rigid.firstShape[slot]; s >= 0; s = store.next[s]) {
        if (s === without) continue;
        const m = store.density[s] * store.area[s];
        const dx = store.centroidX[s] + rigid.localCenterX[slot] - cx;
        const dy = store.centroidY[s] + rigid.localCenterY[slot] - cy;
        inertia += store.density[s] * store.areaInertia[s] + m * (dx * dx + dy * dy);
      }
    } else if (shape !== null) {
      const m = bodies.mass[slot];
      const r = bodies.radius[slot];
      inertia += (m * r * r) / 2 + m * (cx * cx + cy * cy);
    }
    if (shape !== null) {
      const dx = props.cx - cx;
      const dy = props.cy - cy;
      inertia += shape.density * props.inertia + added * (dx * dx + dy * dy);
    }
    out[0] = mass;
    out[1] = inertia;
    return out;
  }

  /**
   * Recomputes a body's mass, centre of mass and inertia from its shapes, moving its centre (and
   * so its position column) while its origin stays put; then its bounding radius and filter.
   * Static and kinematic bodies keep their centre at their origin, as in Box2D: they turn about it.
   * A dynamic body without shapes gets mass 1 and no rotational inertia.
   */
  update(slot: number): void {
    const bodies = this.bodies;
    const rigid = bodies.useRigid();
    const store = this.store;
    let mass = 0;
    let mx = 0;
    let my = 0;
    for (let s = rigid.firstShape[slot]; s >= 0; s = store.next[s]) {
      const m = store.density[s] * store.area[s];
      mass += m;
      mx += m * store.centroidX[s];
      my += m * store.centroidY[s];
    }
    // The new centre, in the current centre's frame.
    let shiftX: number;
    let shiftY: number;
    if (bodies.type[slot] === TypeCode.dynamic && mass > 0) {
      shiftX = mx / mass;
      shiftY = my / mass;
    } else {
      shiftX = -rigid.localCenterX[slot];
      shiftY = -rigid.localCenterY[slot];
    }
    if (shiftX !== 0 || shiftY !== 0) {
      for (let s = rigid.firstShape[slot]; s >= 0; s = store.next[s]) store.shift(s, -shiftX, -shiftY);
      rigid.localCenterX[slot] += shiftX;
      rigid.localCenterY[slot] += shiftY;
      const c = rigid.c[slot];
      const sn = rigid.s[slot];
      const dx = c * shiftX - sn * shiftY;
      const dy = sn * shiftX + c * shiftY;
      bodies.x[slot] += dx;
      bodies.y[slot] += dy;
      // The velocity is the centre's: the new centre's is the old one's plus w x d, so that every
      // point of the body keeps its velocity (Box2D's mass data update does the same).
      const w = rigid.angularVelocity[slot];
      if (w !== 0 && bodies.type[slot] !== TypeCode.static) {
        // Within the bound every velocity keeps: a spin and a shift at theirs would pass it.
        bodies.vx[slot] = clampMagnitude(bodies.vx[slot] - w * dy);
        bodies.vy[slot] = clampMagnitude(bodies.vy[slot] + w * dx);
      }
    }
    let inertia = 0;
    let reach = 0;
    let category = 0;
    let mask = 0;
    let first = true;
    let minExtent = Infinity;
    for (let s = rigid.firstShape[slot]; s >= 0; s = store.next[s]) {
      minExtent = Math.min(minExtent, innerExtent(store, s));
      const m = store.density[s] * store.area[s];
      const cx = store.centroidX[s];
      const cy = store.centroidY[s];
      inertia += store.density[s] * store.areaInertia[s] + m * (cx * cx + cy * cy);
      let far = 0;
      for (let i = 0, at = s * SHAPE_STRIDE + SHAPE_VERTICES; i < store.vertexCount[s]; i++, at += VERTEX) {
        const vx = store.record[at];
        const vy = store.record[at + 1];
        const d = vx * vx + vy * vy;
        if (d > far) far = d;
      }
      reach = Math.max(reach, Math.sqrt(far) + store.radius[s]);
      category |= store.category[s];
      mask |= store.mask[s];
      if (first) bodies.restitution[slot] = store.restitution[s];
      first = false;
    }
    const shapeless = rigid.firstShape[slot] < 0;
    rigid.minExtent[slot] = shapeless ? 0 : minExtent;
    bodies.setMass(slot, shapeless ? 1 : mass, inertia);
    bodies.setRadius(slot, reach + this.margin);
    // A body collides if any of its shapes may: the narrow-phase then checks shape by shape.
    bodies.setFilter(slot, category >>> 0, mask >>> 0);
  }

  private link(slot: number, shape: NewShape): number {
    const rigid = this.bodies.useRigid();
    const store = this.store;
    const props2 = areaProperties(shape.geometry, props);
    const s = store.add(slot, shape, props2.area, props2.inertia, props2.cx, props2.cy);
    let last = rigid.firstShape[slot];
    if (last < 0) rigid.firstShape[slot] = s;
    else {
      while (store.next[last] >= 0) last = store.next[last];
      store.setNext(last, s);
    }
    rigid.shapeCount[slot]++;
    return s;
  }

  private unlink(slot: number, shapeSlot: number): void {
    const rigid = this.bodies.rigid!;
    const store = this.store;
    if (rigid.firstShape[slot] === shapeSlot) rigid.firstShape[slot] = store.next[shapeSlot];
    else {
      let s = rigid.firstShape[slot];
      while (store.next[s] !== shapeSlot) s = store.next[s];
      store.setNext(s, store.next[shapeSlot]);
    }
    rigid.shapeCount[slot]--;
  }
}

function clampMagnitude(v: number): number {
  return v > MAX_MAGNITUDE ? MAX_MAGNITUDE : v < -MAX_MAGNITUDE ? -MAX_MAGNITUDE : v;
}

/** How far a shape's surface is from its centroid at the nearest: its radius, plus for a polygon the distance to its nearest edge line. */
function innerExtent(store: ShapeStore, s: number): number {
  if (store.kind[s] !== 2) return store.radius[s];
  const g = store.record;
  const cx = store.centroidX[s];
  const cy = store.centroidY[s];
  let least = Infinity;
  for (let i = 0, at = s * SHAPE_STRIDE + SHAPE_VERTICES; i < store.vertexCount[s]; i++, at += VERTEX) {
    const d = g[at + 2] * (g[at] - cx) + g[at + 3] * (g[at + 1] - cy);
    if (d < least) least = d;
  }
  return least + store.radius[s];
}
