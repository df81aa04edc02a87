import { MAX_POLYGON_VERTICES, type Geometry, type ShapeKindCode } from '../shapes/geometry.js';
import { grownCapacity, grow } from '../util/grow.js';
import { ORIENTED_BOX, setBox } from '../narrowphase/oriented-boxes.js';
import { JOINT_HANDLES, SHAPE_HANDLES, SHAPE_MAX_GENERATION, SLOT_SPACE } from './handles.js';

/** What a new shape is made of, validated: geometry in its body's frame, and material and filter. */
export interface NewShape {
  geometry: Geometry;
  density: number;
  friction: number;
  restitution: number;
  rollingResistance: number;
  category: number;
  mask: number;
  sensor: boolean;
}

/**
 * A shape's record in `record`: a header the pair tests read (a copy of the columns below), then
 * its vertices, VERTEX doubles each.
 */
export const ShapeField = { kind: 0, count: 1, radius: 2, category: 3, mask: 4, sensor: 5, next: 6, handle: 7 } as const;
/** Where a record's first vertex starts. */
export const SHAPE_VERTICES = 8;
/** Doubles per vertex in a record: x, y, and the normal of the edge that starts there. */
export const VERTEX = 4;
/** Doubles per shape record. */
const STRIDE = SHAPE_VERTICES + VERTEX * MAX_POLYGON_VERTICES;

/**
 * The shapes attached to bodies, structure-of-arrays by shape slot, each body's shapes chained
 * from RigidColumns.firstShape through `next` in the order they were added (the order the
 * narrow-phase visits them, so it is part of the canonical contact order).
 *
 * Geometry is kept relative to the body's centre of mass, the frame the step works in, so a
 * world vertex is centre + rotate(vertex) with no further offset; when the centre moves (a shape
 * added or removed) every shape of the body is shifted by the difference.
 *
 * Handles work as body handles do, in a space of their own (see handles.ts).
 */
export class ShapeStore {
  capacity = 0;
  slotCount = 0;
  count = 0;
  body = new Int32Array(0);
  next = new Int32Array(0);
  kind = new Uint8Array(0);
  vertexCount = new Uint8Array(0);
  sensor = new Uint8Array(0);
  live = new Uint8Array(0);
  generation = new Uint32Array(0);
  radius = new Float64Array(0);
  density = new Float64Array(0);
  friction = new Float64Array(0);
  restitution = new Float64Array(0);
  rollingResistance = new Float64Array(0);
  category = new Uint32Array(0);
  mask = new Uint32Array(0);
  /**
   * One record of STRIDE doubles per shape: the header of ShapeField (kind, vertex count, radius,
   * filter, sensor, next, handle: copies of the columns, kept by this store's writers), then the
   * vertices and edge normals relative to the body's centre of mass, VERTEX doubles each. A pair
   * test reads one short run of memory per shape rather than a dozen columns: at 64,000 bodies the
   * narrow-phase is bound by memory, by cache and TLB misses more than by arithmetic.
   */
  record = new Float64Array(0);
  /** The shape's own centroid, relative to the body's centre of mass, and its bounding radius about it. */
  centroidX = new Float64Array(0);
  centroidY = new Float64Array(0);
  extent = new Float64Array(0);
  /** The shape's box, turning with its body (see oriented-boxes.ts). */
  box = new Float64Array(0);
  /** Area per unit density, its centroid and polar moment about that centroid: for the body's mass. */
  area = new Float64Array(0);
  areaInertia = new Float64Array(0);
  /** Bumped whenever shapes are added, removed or changed, for structures that index them. */
  version = 0;
  /** Live shapes that take contacts and can lose energy in them: friction, rolling resistance or restitution below 1 (see World's solver 'auto'). */
  inelastic = 0;
  /** Live sensor shapes (see ShapeNarrowPhase.sense). */
  sensors = 0;
  private freeSlots: number[] = [];

  /** Stores a shape for body `slot`; returns the shape's slot. The caller links it to the body. */
  add(body: number, shape: NewShape, areaOfShape: number, areaInertia: number, centroidX: number, centroidY: number): number {
    let slot = this.freeSlots.pop();
    if (slot === undefined) {
      if (this.slotCount === this.capacity) this.grow(this.slotCount + 1);
      slot = this.slotCount++;
    }
    const g = shape.geometry;
    this.body[slot] = body;
    this.next[slot] = -1;
    this.kind[slot] = g.kind;
    this.vertexCount[slot] = g.count;
    this.sensor[slot] = shape.sensor ? 1 : 0;
    this.live[slot] = 1;
    this.radius[slot] = g.radius;
    this.density[slot] = shape.density;
    this.friction[slot] = shape.friction;
    this.restitution[slot] = shape.restitution;
    this.rollingResistance[slot] = shape.rollingResistance;
    if (this.losesEnergy(slot)) this.inelastic++;
    if (shape.sensor) this.sensors++;
    this.category[slot] = shape.category;
    this.mask[slot] = shape.mask;
    const record = this.record;
    const base = slot * STRIDE;
    record[base + ShapeField.kind] = g.kind;
    record[base + ShapeField.count] = g.count;
    record[base + ShapeField.radius] = g.radius;
    record[base + ShapeField.category] = shape.category;
    record[base + ShapeField.mask] = shape.mask;
    record[base + ShapeField.sensor] = shape.sensor ? 1 : 0;
    record[base + ShapeField.next] = -1;
    record[base + ShapeField.handle] = this.handleOf(slot);
    for (let i = 0, at = base + SHAPE_VERTICES; i < g.count; i++, at += VERTEX) {
      record[at] = g.x[i];
      record[at + 1] = g.y[i];
      record[at + 2] = g.nx[i];
      record[at + 3] = g.ny[i];
    }
    this.area[slot] = areaOfShape;
    this.areaInertia[slot] = areaInertia;
    this.centroidX[slot] = centroidX;
    this.centroidY[slot] = centroidY;
    this.extent[slot] = g.extentFrom(centroidX, centroidY);
    this.fitBox(slot);
    this.count++;
    this.version++;
    return slot;
  }

  remove(slot: number): void {
    if (this.losesEnergy(slot)) this.inelastic--;
    if (this.sensor[slot] === 1) this.sensors--;
    this.live[slot] = 0;
    this.count--;
    this.version++;
    if (this.generation[slot] + 1 >= SHAPE_MAX_GENERATION) return;
    this.generation[slot]++;
    this.freeSlots.push(slot);
  }

  /** Whether shape `slot` takes contacts (not a sensor) in which it can lose energy. */
  private losesEnergy(slot: number): boolean {
    return this.sensor[slot] === 0 && (this.friction[slot] > 0 || this.rollingResistance[slot] > 0 || this.restitution[slot] < 1);
  }

  /** Moves every vertex and centroid of a shape by (dx, dy) in its body's frame. */
  shift(slot: number, dx: number, dy: number): void {
    const record = this.record;
    for (let i = 0, at = slot * STRIDE + SHAPE_VERTICES; i < this.vertexCount[slot]; i++, at += VERTEX) {
      record[at] += dx;
      record[at + 1] += dy;
    }
    this.centroidX[slot] += dx;
    this.centroidY[slot] += dy;
    this.fitBox(slot);
    this.version++;
  }

  /** Sets a shape's box from its vertices and rounding. */
  private fitBox(slot: number): void {
    const record = this.record;
    const r = this.radius[slot];
    let loX = Infinity;
    let loY = Infinity;
    let hiX = -Infinity;
    let hiY = -Infinity;
    for (let i = 0, at = slot * STRIDE + SHAPE_VERTICES; i < this.vertexCount[slot]; i++, at += VERTEX) {
      loX = Math.min(loX, record[at] - r);
      loY = Math.min(loY, record[at + 1] - r);
      hiX = Math.max(hiX, record[at] + r);
      hiY = Math.max(hiY, record[at + 1] + r);
    }
    setBox(this.box, slot * ORIENTED_BOX, loX, loY, hiX, hiY);
  }

  /** Copies a shape's geometry into `g` (in its body's centre-of-mass frame). */
  readGeometry(slot: number, g: Geometry): Geometry {
    const n = this.vertexCount[slot];
    const record = this.record;
    g.kind = this.kind[slot] as ShapeKindCode;
    g.count = n;
    g.radius = this.radius[slot];
    for (let i = 0, at = slot * STRIDE + SHAPE_VERTICES; i < n; i++, at += VERTEX) {
      g.x[i] = record[at];
      g.y[i] = record[at + 1];
      g.nx[i] = record[at + 2];
      g.ny[i] = record[at + 3];
    }
    return g;
  }

  /** Sets shape `slot`'s collision layers, in its columns and in its record, which the narrow-phase reads. */
  setFilter(slot: number, category: number, mask: number): void {
    this.category[slot] = category;
    this.mask[slot] = mask;
    this.record[slot * STRIDE + ShapeField.category] = category;
    this.record[slot * STRIDE + ShapeField.mask] = mask;
    this.version++;
  }

  /** Links shape `slot` to `next` in its body's chain (-1 ends it). */
  setNext(slot: number, next: number): void {
    this.next[slot] = next;
    this.record[slot * STRIDE + ShapeField.next] = next;
  }

  /** Writes slot's handle into out[at] (see SlotOwner: a handle passed through memory is never boxed). */
  writeHandle(slot: number, out: Float64Array, at: number): void {
    out[at] = this.handleOf(slot);
  }

  /** Whether slot's handle is handles[at] (see SlotOwner). */
  holdsHandle(slot: number, handles: Float64Array, at: number): boolean {
    return this.handleOf(slot) === handles[at];
  }

  handleOf(slot: number): number {
    return SHAPE_HANDLES + this.generation[slot] * SLOT_SPACE + slot;
  }

  /** The slot of a live shape's handle, or -1. */
  slotOf(handle: number): number {
    if (!Number.isSafeInteger(handle) || handle < SHAPE_HANDLES || handle >= JOINT_HANDLES) return -1;
    const slot = (handle - SHAPE_HANDLES) % SLOT_SPACE;
    const gen = (handle - SHAPE_HANDLES - slot) / SLOT_SPACE;
    return slot < this.slotCount && this.live[slot] === 1 && this.generation[slot] === gen ? slot : -1;
  }

  describeMissing(handle: number): string {
    if (!Number.isSafeInteger(handle) || handle < 0) return 'is not a shape handle';
    if (handle < SHAPE_HANDLES) return 'is a body or segment handle, not a shape handle';
    if (handle >= JOINT_HANDLES) return 'is a joint handle, not a shape handle';
    const slot = (handle - SHAPE_HANDLES) % SLOT_SPACE;
    const gen = (handle - SHAPE_HANDLES - slot) / SLOT_SPACE;
    if (slot >= this.slotCount || gen > this.generation[slot]) return 'is unknown to this world';
    return 'is stale: its shape or its body was destroyed';
  }

  hasRoom(): boolean {
    return this.freeSlots.length > 0 || this.slotCount < SLOT_SPACE;
  }

  memoryBytes(): number {
    return this.capacity * (4 * 2 + 4 + 4 * 3 + 8 * 12 + 8 * ORIENTED_BOX + 8 * STRIDE);
  }

  private grow(needed: number): void {
    const capacity = grownCapacity(this.capacity, needed);
    this.body = grow(this.body, capacity);
    this.next = grow(this.next, capacity);
    this.kind = grow(this.kind, capacity);
    this.vertexCount = grow(this.vertexCount, capacity);
    this.sensor = grow(this.sensor, capacity);
    this.live = grow(this.live, capacity);
    this.generation = grow(this.generation, capacity);
    this.radius = grow(this.radius, capacity);
    this.density = grow(this.density, capacity);
    this.friction = grow(this.friction, capacity);
    this.restitution = grow(this.restitution, capacity);
    this.rollingResistance = grow(this.rollingResistance, capacity);
    this.category = grow(this.category, capacity);
    this.mask = grow(this.mask, capacity);
    this.record = grow(this.record, capacity * STRIDE);
    this.centroidX = grow(this.centroidX, capacity);
    this.centroidY = grow(this.centroidY, capacity);
    this.extent = grow(this.extent, capacity);
    this.area = grow(this.area, capacity);
    this.box = grow(this.box, capacity * ORIENTED_BOX);
    this.areaInertia = grow(this.areaInertia, capacity);
    this.capacity = capacity;
  }
}

export const SHAPE_STRIDE = STRIDE;
