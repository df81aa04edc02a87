import { Application, Graphics } from 'pixi.js';
import { ragdollExample, runAtSixtyHertz } from './example-world.js';

const canvas = document.getElementById('view') as HTMLCanvasElement;
const example = ragdollExample(canvas);
const { world, width, height, scale, left, top } = example;
// The scenes are y down, like PixiJS's stage, so nothing is flipped.

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

function draw(): number {
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
  return lineCount;
}

runAtSixtyHertz(example, draw);
