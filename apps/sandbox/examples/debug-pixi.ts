import { Application, Graphics } from 'pixi.js';
import { buildShapeWorld, ragdolls } from '@maxgrid/scenes';
import { exposeForTests } from './test-hook.js';

// Six ragdolls (capsules and circles on revolute joints) falling onto a static box: every part of
// the debug picture shows, shapes, joints and contact normals, and the bodies move, then sleep.
const scene = ragdolls({ count: 6, columns: 3 });
const world = buildShapeWorld(scene);

const canvas = document.getElementById('view') as HTMLCanvasElement;
const width = canvas.clientWidth;
const height = canvas.clientHeight;

// One scale for both axes, so circles stay round, fitting the scene's view in the canvas. The
// scenes are y down, like PixiJS's stage, so nothing is flipped.
const { minX, minY, maxX, maxY } = scene.view;
const scale = Math.min(width / (maxX - minX), height / (maxY - minY));
const left = (minX + maxX) / 2 - width / 2 / scale;
const top = (minY + maxY) / 2 - height / 2 / scale;

const app = new Application();
// autoStart off: the loop below renders after stepping, instead of PixiJS's ticker rendering on a
// schedule of its own. autoDensity keeps the canvas's CSS size while resolution sharpens it.
await app.init({ canvas, width, height, background: '#11161c', antialias: true, resolution: window.devicePixelRatio, autoDensity: true, autoStart: false });

// The Graphics object carries the world-to-screen transform, so the buffers' vertices go in as
// they are.
const graphics = new Graphics();
graphics.scale.set(scale);
graphics.position.set(-left * scale, -top * scale);
app.stage.addChild(graphics);

const hook = exposeForTests(world, { scale, left, top });

function draw(): void {
  const { lineCount, vertices, colors } = world.debugRender();
  // Rebuilt every frame: every line may have moved, and a Graphics keeps no per-line handles.
  graphics.clear();
  // One stroke per run of lines of one colour (a body's outline, the joints, the contacts), since
  // a stroke has one style. pixelLine keeps the lines one pixel wide under the graphics' scale.
  let k = 0;
  while (k < lineCount) {
    const c = 8 * k;
    const r = colors[c];
    const g = colors[c + 1];
    const b = colors[c + 2];
    const a = colors[c + 3];
    for (; k < lineCount && colors[8 * k] === r && colors[8 * k + 1] === g && colors[8 * k + 2] === b && colors[8 * k + 3] === a; k++) {
      graphics.moveTo(vertices[4 * k], vertices[4 * k + 1]);
      graphics.lineTo(vertices[4 * k + 2], vertices[4 * k + 3]);
    }
    graphics.stroke({ color: [r, g, b], alpha: a, width: 1, pixelLine: true });
  }
  app.render();
  hook.drawnLines = lineCount;
}

// A fixed step of 1/60 s whatever the display's refresh rate: the engine gives the same motion for
// the same steps, and a 144 Hz screen must not run the world faster. Frames only decide how many
// steps are due.
const DT = 1 / 60;
let last = performance.now();
let due = 0;
function frame(now: number): void {
  // At most a tenth of a second at once: after a hidden tab comes back, catching up on minutes of
  // steps would freeze the page.
  due += Math.min(now - last, 100) / 1000;
  last = now;
  for (; due >= DT; due -= DT) {
    if (hook.paused) continue;
    world.step(DT);
    hook.steps++;
  }
  draw();
  hook.frames++;
  requestAnimationFrame(frame);
}
requestAnimationFrame(frame);
