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
// scenes are y down, like the canvas, so nothing is flipped.
const { minX, minY, maxX, maxY } = scene.view;
const scale = Math.min(width / (maxX - minX), height / (maxY - minY));
const left = (minX + maxX) / 2 - width / 2 / scale;
const top = (minY + maxY) / 2 - height / 2 / scale;

// A backing store at the device's resolution, or the lines are blurred on a high-density screen.
const dpr = window.devicePixelRatio;
canvas.width = Math.round(width * dpr);
canvas.height = Math.round(height * dpr);
const ctx = canvas.getContext('2d') as CanvasRenderingContext2D;

const hook = exposeForTests(world, { scale, left, top });

function draw(): void {
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
