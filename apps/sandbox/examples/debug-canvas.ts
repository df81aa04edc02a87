import { ragdollExample, runAtSixtyHertz } from './example-world.js';

const canvas = document.getElementById('view') as HTMLCanvasElement;
const example = ragdollExample(canvas);
const { world, width, height, scale, left, top } = example;
// The scenes are y down, like the canvas, so nothing is flipped.

// A backing store at the device's resolution, or the lines are blurred on a high-density screen.
const dpr = window.devicePixelRatio;
canvas.width = Math.round(width * dpr);
canvas.height = Math.round(height * dpr);
const ctx = canvas.getContext('2d') as CanvasRenderingContext2D;

function draw(): number {
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.fillStyle = '#11161c';
  ctx.fillRect(0, 0, canvas.width, canvas.height);
  // The vertices go in as world coordinates and the canvas transform maps them: no per-vertex
  // arithmetic here, and the line width, in world units, is one CSS pixel.
  const s = scale * dpr;
  ctx.setTransform(s, 0, 0, s, -left * s, -top * s);
  ctx.lineWidth = 1 / scale;
  const { lineCount, vertices, colors } = world.debugRender();
  // One path per run of lines of one colour (a body's outline, the joints, the contacts): a
  // stroke per line would cost a thousand draw calls a frame.
  let k = 0;
  while (k < lineCount) {
    const c = 8 * k;
    const r = colors[c];
    const g = colors[c + 1];
    const b = colors[c + 2];
    const a = colors[c + 3];
    ctx.beginPath();
    for (; k < lineCount && colors[8 * k] === r && colors[8 * k + 1] === g && colors[8 * k + 2] === b && colors[8 * k + 3] === a; k++) {
      ctx.moveTo(vertices[4 * k], vertices[4 * k + 1]);
      ctx.lineTo(vertices[4 * k + 2], vertices[4 * k + 3]);
    }
    ctx.strokeStyle = `rgba(${255 * r}, ${255 * g}, ${255 * b}, ${a})`;
    ctx.stroke();
  }
  return lineCount;
}

runAtSixtyHertz(example, draw);
