import type { BodyViews, JointViews } from '@maxgrid/engine';
import type { BodyColors } from '../colors.js';
import type { ViewTransform } from '../view.js';

/** What the scene holds besides its moving circles; one object, updated in place every frame. */
export interface SceneShapes {
  /** x1, y1, x2, y2, thickness per static segment. */
  segments: Float64Array;
  /** How many circles are static: when none, renderers skip the pass that colours them. */
  staticCircles: number;
  /** How many bodies sleep: when none, renderers skip the pass that dims them. */
  sleepers: number;
  /** Every joint's world anchors (world.jointViews(), reused arrays), or null for none to draw. */
  joints: JointViews | null;
}

/** Draws every live body from the engine's bulk views; one per canvas, chosen in the UI. */
export interface Renderer {
  readonly canvas: HTMLCanvasElement;
  /** `box`: the region drawn (the scene's box, or an open scene's region), filled as the box. */
  draw(views: BodyViews, colors: BodyColors, view: ViewTransform, box: { x: number; y: number; width: number; height: number }, shapes: SceneShapes): void;
}

export const BACKGROUND = '#0d1117';
export const BOX_FILL = '#161b22';
/** Laid over sleeping bodies: the box colour, mostly opaque, so they read as dimmed. */
export const SLEEP_DIM = 'rgba(22, 27, 34, 0.6)';
/**
 * A joint's line width and its anchors' dot radius, in CSS pixels, and the line's opacity: a
 * jelly's lattice has a spring every few pixels, and opaque lines would hide its circles.
 */
export const JOINT_LINE_PX = 1;
export const JOINT_LINE_ALPHA = 0.55;
export const JOINT_DOT_PX = 1.75;
