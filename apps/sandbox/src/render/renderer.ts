import type { BodyViews } from '@maxgrid/engine';
import type { BodyColors } from '../colors.js';
import type { ViewTransform } from '../view.js';

/** Draws every live body from the engine's bulk views; one per canvas, chosen in the UI. */
export interface Renderer {
  readonly canvas: HTMLCanvasElement;
  draw(views: BodyViews, colors: BodyColors, view: ViewTransform, box: { width: number; height: number }): void;
}

export const BACKGROUND = '#0d1117';
export const BOX_FILL = '#161b22';
