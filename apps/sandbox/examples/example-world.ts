import type { World } from '@maxgrid/engine';
import { buildShapeWorld, ragdolls } from '@maxgrid/scenes';
import { exposeForTests, type ExampleHook } from './test-hook.js';

/**
 * What the three debug-draw examples share, so that each file holds only its renderer: the world,
 * the view that fits it in the canvas, and a loop that steps it at a fixed rate and draws.
 */
export interface ExampleWorld {
  world: World;
  /** The canvas's CSS size. */
  width: number;
  height: number;
  /** Screen x = (x - left) * scale, screen y = (y - top) * scale, in CSS pixels; the scenes are y down. */
  scale: number;
  left: number;
  top: number;
  hook: ExampleHook;
}

/**
 * Six ragdolls (capsules and circles on revolute joints) falling onto a static box: every part of
 * the debug picture shows, shapes, joints and contact normals, and the bodies move, then sleep.
 * One scale for both axes, so circles stay round, fitting the scene's view in the canvas.
 */
export function ragdollExample(canvas: HTMLCanvasElement): ExampleWorld {
  const scene = ragdolls({ count: 6, columns: 3 });
  const world = buildShapeWorld(scene);
  const width = canvas.clientWidth;
  const height = canvas.clientHeight;
  const { minX, minY, maxX, maxY } = scene.view;
  const scale = Math.min(width / (maxX - minX), height / (maxY - minY));
  const left = (minX + maxX) / 2 - width / 2 / scale;
  const top = (minY + maxY) / 2 - height / 2 / scale;
  const hook = exposeForTests(world, { scale, left, top });
  return { world, width, height, scale, left, top, hook };
}

/**
 * Steps the world at a fixed 1/60 s whatever the display's refresh rate, and calls `draw` once a
 * frame with the lines it drew. The engine gives the same motion for the same steps, and a 144 Hz
 * screen must not run the world faster: frames only decide how many steps are due.
 */
export function runAtSixtyHertz({ world, hook }: ExampleWorld, draw: () => number): void {
  const DT = 1 / 60;
  let last = performance.now();
  let due = 0;
  const frame = (now: number): void => {
    // At most a tenth of a second at once: after a hidden tab comes back, catching up on minutes
    // of steps would freeze the page.
    due += Math.min(now - last, 100) / 1000;
    last = now;
    for (; due >= DT; due -= DT) {
      if (hook.paused) continue;
      world.step(DT);
      hook.steps++;
    }
    hook.drawnLines = draw();
    hook.frames++;
    requestAnimationFrame(frame);
  };
  requestAnimationFrame(frame);
}
