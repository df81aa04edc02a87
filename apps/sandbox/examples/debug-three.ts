import { BufferAttribute, BufferGeometry, Color, LineBasicMaterial, LineSegments, LinearSRGBColorSpace, OrthographicCamera, Scene, Sphere, Vector3, WebGLRenderer } from 'three';
import { buildShapeWorld, ragdolls } from '@maxgrid/scenes';
import { exposeForTests } from './test-hook.js';

// Six ragdolls (capsules and circles on revolute joints) falling onto a static box: every part of
// the debug picture shows, shapes, joints and contact normals, and the bodies move, then sleep.
const scene = ragdolls({ count: 6, columns: 3 });
const world = buildShapeWorld(scene);

const canvas = document.getElementById('view') as HTMLCanvasElement;
const width = canvas.clientWidth;
const height = canvas.clientHeight;

// One scale for both axes, so circles stay round, fitting the scene's view in the canvas.
const { minX, minY, maxX, maxY } = scene.view;
const scale = Math.min(width / (maxX - minX), height / (maxY - minY));
const left = (minX + maxX) / 2 - width / 2 / scale;
const top = (minY + maxY) / 2 - height / 2 / scale;

const renderer = new WebGLRenderer({ canvas, antialias: true });
renderer.setPixelRatio(window.devicePixelRatio);
// false: keep the canvas's CSS size, only size its backing store.
renderer.setSize(width, height, false);
// debugRender's colours are meant as they are on screen, while three.js takes vertex colours as
// linear and brightens them on output: no conversion on output, and the clear colour given as
// linear too, so that it is not converted on the way in.
renderer.outputColorSpace = LinearSRGBColorSpace;
renderer.setClearColor(new Color().setHex(0x11161c, LinearSRGBColorSpace));

// The camera sees the world's rectangle that fills the canvas. three.js is y up and the scenes are
// y down: giving the camera a top smaller than its bottom flips y in the projection, so the
// vertices need no flipping.
const camera = new OrthographicCamera(left, left + width / scale, top, top + height / scale, -1, 1);

// Vertex colours with alpha: debugRender gives four components per vertex.
const material = new LineBasicMaterial({ vertexColors: true });
const geometry = new BufferGeometry();
// three.js measures a geometry's bounding sphere from x, y, z positions, and these are x, y only
// and move every frame: one sphere around everything keeps it from measuring (and culling).
geometry.boundingSphere = new Sphere(new Vector3(), Infinity);
const stage = new Scene();
stage.add(new LineSegments(geometry, material));

const hook = exposeForTests(world, { scale, left, top });

function draw(): void {
  const { lineCount, vertices, colors } = world.debugRender();
  // The buffers are uploaded as they are, two floats per position (z is 0 in the shader). They
  // are the same arrays every frame until the world outgrows them: then new attributes, and the
  // old GPU buffers are let go; otherwise only an upload.
  const position = geometry.getAttribute('position') as BufferAttribute | undefined;
  if (position?.array !== vertices) {
    geometry.dispose();
    geometry.setAttribute('position', new BufferAttribute(vertices, 2));
    geometry.setAttribute('color', new BufferAttribute(colors, 4));
  } else {
    position.needsUpdate = true;
    geometry.getAttribute('color').needsUpdate = true;
  }
  // Only the lines of this frame: the arrays are longer than lineCount.
  geometry.setDrawRange(0, 2 * lineCount);
  renderer.render(stage, camera);
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
