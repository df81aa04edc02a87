import type { BodyViews } from '@maxgrid/engine';
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
