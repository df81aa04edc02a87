import type { BodyType } from './store/body-types.js';

export interface CircleState {
  x: number;
  y: number;
  vx: number;
  vy: number;
  radius: number;
  mass: number;
  type: BodyType;
  restitution: number;
  category: number;
  mask: number;
  gravityScale: number;
  linearDamping: number;
  awake: boolean;
}

export interface QueryOptions {
  /** Only bodies whose category shares a bit with this mask. Default: all. */
  mask?: number;
}

/**
 * Read-only, zero-copy views of the body columns for renderers, indexed by slot. Walk slots
 * [0, slotCount) and skip those whose `type` is `BodyTypeCode.free`. The arrays are replaced when
 * the world grows, so fetch the views again after adding bodies rather than keeping them.
 */
export interface BodyViews {
  readonly slotCount: number;
  readonly liveCount: number;
  readonly x: Readonly<Float64Array>;
  readonly y: Readonly<Float64Array>;
  readonly vx: Readonly<Float64Array>;
  readonly vy: Readonly<Float64Array>;
  readonly radius: Readonly<Float64Array>;
  readonly mass: Readonly<Float64Array>;
  readonly type: Readonly<Uint8Array>;
  /** 1 while a body sleeps. */
  readonly asleep: Readonly<Uint8Array>;
}
