import { MAX_POLYGON_VERTICES, type Geometry, type ShapeKindCode } from '../shapes/geometry.js';
import { grownCapacity, grow } from '../util/grow.js';
import { SHAPE_HANDLES, SHAPE_MAX_GENERATION, SLOT_SPACE } from './handles.js';

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

const STRIDE = MAX_POLYGON_VERTICES;

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
  /** Vertices and edge normals, STRIDE per shape, relative to the body's centre of mass. */
  vx = new Float64Array(0);
  vy = new Float64Array(0);
  nx = new Float64Array(0);
  ny = new Float64Array(0);
  /** The shape's own centroid, relative to the body's centre of mass, and its bounding radius about it. */
  centroidX = new Float64Array(0);
  centroidY = new Float64Array(0);
  extent = new Float64Array(0);
  /** Area per unit density, its centroid and polar moment about that centroid: for the body's mass. */
  area = new Float64Array(0);
  areaInertia = new Float64Array(0);
  /** Bumped whenever shapes are added, removed or changed, for structures that index them. */
  version = 0;
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
    this.category[slot] = shape.category;
    this.mask[slot] = shape.mask;
    const base = slot * STRIDE;
    for (let i = 0; i < g.count; i++) {
      this.vx[base + i] = g.x[i];
      this.vy[base + i] = g.y[i];
      this.nx[base + i] = g.nx[i];
      this.ny[base + i] = g.ny[i];
    }
    this.area[slot] = areaOfShape;
    this.areaInertia[slot] = areaInertia;
    this.centroidX[slot] = centroidX;
    this.centroidY[slot] = centroidY;
    this.extent[slot] = g.extentFrom(centroidX, centroidY);
    this.count++;
    this.version++;
    return slot;
  }

  remove(slot: number): void {
    this.live[slot] = 0;
    this.count--;
    this.version++;
    if (this.generation[slot] + 1 >= SHAPE_MAX_GENERATION) return;
    this.generation[slot]++;
    this.freeSlots.push(slot);
  }

  /** Moves every vertex and centroid of a shape by (dx, dy) in its body's frame. */
  shift(slot: number, dx: number, dy: number): void {
    const base = slot * STRIDE;
    for (let i = 0; i < this.vertexCount[slot]; i++) {
      this.vx[base + i] += dx;
      this.vy[base + i] += dy;
    }
    this.centroidX[slot] += dx;
    this.centroidY[slot] += dy;
    this.version++;
  }

  /** Copies a shape's geometry into `g` (in its body's centre-of-mass frame). */
  readGeometry(slot: number, g: Geometry): Geometry {
    const n = this.vertexCount[slot];
    const base = slot * STRIDE;
    g.kind = this.kind[slot] as ShapeKindCode;
    g.count = n;
    g.radius = this.radius[slot];
    for (let i = 0; i < n; i++) {
      g.x[i] = this.vx[base + i];
      g.y[i] = this.vy[base + i];
      g.nx[i] = this.nx[base + i];
      g.ny[i] = this.ny[base + i];
    }
    return g;
  }

  handleOf(slot: number): number {
    return SHAPE_HANDLES + this.generation[slot] * SLOT_SPACE + slot;
  }

  /** The slot of a live shape's handle, or -1. */
  slotOf(handle: number): number {
    if (!Number.isSafeInteger(handle) || handle < SHAPE_HANDLES) return -1;
    const slot = (handle - SHAPE_HANDLES) % SLOT_SPACE;
    const gen = (handle - SHAPE_HANDLES - slot) / SLOT_SPACE;
    return slot < this.slotCount && this.live[slot] === 1 && this.generation[slot] === gen ? slot : -1;
  }

  describeMissing(handle: number): string {
    if (!Number.isSafeInteger(handle) || handle < 0) return 'is not a shape handle';
    if (handle < SHAPE_HANDLES) return 'is a body or segment handle, not a shape handle';
    const slot = (handle - SHAPE_HANDLES) % SLOT_SPACE;
    const gen = (handle - SHAPE_HANDLES - slot) / SLOT_SPACE;
    if (slot >= this.slotCount || gen > this.generation[slot]) return 'is unknown to this world';
    return 'is stale: its shape or its body was destroyed';
  }

  hasRoom(): boolean {
    return this.freeSlots.length > 0 || this.slotCount < SLOT_SPACE;
  }

  memoryBytes(): number {
    return this.capacity * (4 * 2 + 4 + 4 * 3 + 8 * 12 + 8 * 4 * STRIDE);
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
    this.vx = grow(this.vx, capacity * STRIDE);
    this.vy = grow(this.vy, capacity * STRIDE);
    this.nx = grow(this.nx, capacity * STRIDE);
    this.ny = grow(this.ny, capacity * STRIDE);
    this.centroidX = grow(this.centroidX, capacity);
    this.centroidY = grow(this.centroidY, capacity);
    this.extent = grow(this.extent, capacity);
    this.area = grow(this.area, capacity);
    this.areaInertia = grow(this.areaInertia, capacity);
    this.capacity = capacity;
  }
}

export const SHAPE_STRIDE = STRIDE;
