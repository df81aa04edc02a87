import { BufferAttribute, BufferGeometry, Color, LineBasicMaterial, LineSegments, LinearSRGBColorSpace, OrthographicCamera, Scene, Sphere, Vector3, WebGLRenderer } from 'three';
import { ragdollExample, runAtSixtyHertz } from './example-world.js';

const canvas = document.getElementById('view') as HTMLCanvasElement;
const example = ragdollExample(canvas);
const { world, width, height, scale, left, top } = example;

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

function draw(): number {
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
  return lineCount;
}

runAtSixtyHertz(example, draw);
