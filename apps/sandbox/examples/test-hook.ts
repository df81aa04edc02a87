import type { World } from '@maxgrid/engine';

/** Where the examples draw the world: screen x = (x - left) * scale, screen y = (y - top) * scale, in CSS pixels of the canvas. */
export interface ExampleView {
  scale: number;
  left: number;
  top: number;
}

/**
 * What the examples show the end-to-end test (test/e2e/debug-draw-examples.test.ts), on
 * `window.__example`: the world and the transform, so that the test can work out from the world
 * alone which pixels should be drawn; counters, so that it can wait for steps and frames; and
 * `paused`, so that the picture it reads and the world it compares it with are of the same step.
 * Copying an example, leave this out.
 */
export interface ExampleHook {
  world: World;
  view: ExampleView;
  steps: number;
  frames: number;
  /** Lines handed to the renderer in the last frame. */
  drawnLines: number;
  paused: boolean;
}

declare global {
  interface Window {
    __example?: ExampleHook;
  }
}

export function exposeForTests(world: World, view: ExampleView): ExampleHook {
  const hook: ExampleHook = { world, view, steps: 0, frames: 0, drawnLines: 0, paused: false };
  window.__example = hook;
  return hook;
}
