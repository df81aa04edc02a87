import { BodyTypeCode, type BodyViews } from '@maxgrid/engine';
import { STATIC_RGB, type BodyColors } from '../colors.js';
import type { ViewTransform } from '../view.js';
import type { Renderer, SceneShapes } from './renderer.js';
import { JointLayer } from './webgl-joints.js';
import { SegmentLayer } from './webgl-segments.js';
import { ShapeLayer } from './webgl-shapes.js';
import { link, must } from './webgl-util.js';

/** Per-instance state codes, the fourth float of each body. */
const NORMAL = 0;
const STATIC = 1;
const ASLEEP = 2;

const VERTEX = `#version 300 es
in vec2 a_corner;
in vec4 a_body;   // x, y, radius in world units, state (0 normal, 1 static, 2 asleep)
in vec4 a_color;
uniform vec3 u_static;
uniform vec2 u_scale;   // world units -> clip space
uniform vec2 u_offset;
uniform float u_pixels; // device pixels per world unit
out vec2 v_local;
out float v_radiusPx;
out vec4 v_color;
void main() {
  // Grow every quad by a pixel so the antialiased edge is not clipped, and keep sub-pixel bodies
  // at least a pixel wide so 100k tiny circles stay visible.
  float rPx = max(a_body.z * u_pixels, 0.6);
  float extent = (rPx + 1.0) / u_pixels;
  vec2 world = a_body.xy + a_corner * extent;
  gl_Position = vec4(world * u_scale + u_offset, 0.0, 1.0);
  v_local = a_corner * (rPx + 1.0);
  v_radiusPx = a_body.z > 0.0 ? rPx : -1.0;
  // Static circles share the segments' colour; sleepers fade towards the box, as on canvas 2D.
  v_color = a_body.w == 1.0 ? vec4(u_static, 1.0)
          : a_body.w == 2.0 ? vec4(mix(a_color.rgb, vec3(0.086, 0.106, 0.133), 0.6), 1.0)
          : a_color;
}`;

const FRAGMENT = `#version 300 es
precision mediump float;
in vec2 v_local;
in float v_radiusPx;
in vec4 v_color;
out vec4 outColor;
void main() {
  float alpha = clamp(v_radiusPx - length(v_local) + 0.5, 0.0, 1.0);
  if (alpha <= 0.0) discard;
  outColor = vec4(v_color.rgb, alpha);
}`;

/**
 * Instanced WebGL 2: one quad, one draw call for every body. Per frame the only work on the CPU is
 * copying x, y, radius and a state code (static, asleep) from the engine's Float64 views into one
 * reused Float32 buffer; colours are uploaded only when they change. Free slots get radius 0,
 * which the shaders skip. Segments are a second instanced draw (webgl-segments.ts).
 */
export class WebGLRenderer implements Renderer {
  private readonly gl: WebGL2RenderingContext;
  private readonly program: WebGLProgram;
  private readonly bodyBuffer: WebGLBuffer;
  private readonly colorBuffer: WebGLBuffer;
  private readonly vao: WebGLVertexArrayObject;
  private readonly uScale: WebGLUniformLocation | null;
  private readonly uOffset: WebGLUniformLocation | null;
  private readonly uPixels: WebGLUniformLocation | null;
  private readonly segments: SegmentLayer;
  private readonly joints: JointLayer;
  private shapeLayer: ShapeLayer | null = null;
  private bodies = new Float32Array(0);
  private gpuCapacity = 0;
  private colorVersion = -1;
  private colorCapacity = 0;
  /** The GPU (or software rasteriser) behind the context, as the browser names it. */
  readonly device: string;

  /** Throws when WebGL 2 is unavailable; the caller falls back to canvas 2D. */
  constructor(readonly canvas: HTMLCanvasElement) {
    const gl = canvas.getContext('webgl2', { alpha: false, antialias: false, preserveDrawingBuffer: false });
    if (!gl) throw new Error('this browser gives no WebGL 2 context');
    this.gl = gl;
    // Chromium names the real GPU only through this extension; without it, a generic "WebKit WebGL".
    const debug = gl.getExtension('WEBGL_debug_renderer_info');
    this.device = String(gl.getParameter(debug ? debug.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
    this.program = link(gl, VERTEX, FRAGMENT);
    this.uScale = gl.getUniformLocation(this.program, 'u_scale');
    this.uOffset = gl.getUniformLocation(this.program, 'u_offset');
    this.uPixels = gl.getUniformLocation(this.program, 'u_pixels');
    gl.useProgram(this.program);
    gl.uniform3f(gl.getUniformLocation(this.program, 'u_static'), STATIC_RGB[0] / 255, STATIC_RGB[1] / 255, STATIC_RGB[2] / 255);

    this.vao = must(gl.createVertexArray(), 'vertex array');
    gl.bindVertexArray(this.vao);
    const quad = must(gl.createBuffer(), 'buffer');
    gl.bindBuffer(gl.ARRAY_BUFFER, quad);
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array([-1, -1, 1, -1, -1, 1, 1, 1]), gl.STATIC_DRAW);
    const corner = gl.getAttribLocation(this.program, 'a_corner');
    gl.enableVertexAttribArray(corner);
    gl.vertexAttribPointer(corner, 2, gl.FLOAT, false, 0, 0);

    this.bodyBuffer = must(gl.createBuffer(), 'buffer');
    gl.bindBuffer(gl.ARRAY_BUFFER, this.bodyBuffer);
    const body = gl.getAttribLocation(this.program, 'a_body');
    gl.enableVertexAttribArray(body);
    gl.vertexAttribPointer(body, 4, gl.FLOAT, false, 0, 0);
    gl.vertexAttribDivisor(body, 1);

    this.colorBuffer = must(gl.createBuffer(), 'buffer');
    gl.bindBuffer(gl.ARRAY_BUFFER, this.colorBuffer);
    const color = gl.getAttribLocation(this.program, 'a_color');
    gl.enableVertexAttribArray(color);
    gl.vertexAttribPointer(color, 4, gl.UNSIGNED_BYTE, true, 0, 0);
    gl.vertexAttribDivisor(color, 1);
    gl.bindVertexArray(null);
    this.segments = new SegmentLayer(gl, quad);
    this.joints = new JointLayer(gl, quad);

    gl.enable(gl.BLEND);
    gl.blendFunc(gl.SRC_ALPHA, gl.ONE_MINUS_SRC_ALPHA);
  }

  draw(v: BodyViews, colors: BodyColors, view: ViewTransform, box: { x: number; y: number; width: number; height: number }, shapes: SceneShapes): void {
    const gl = this.gl;
    const n = v.slotCount;
    gl.viewport(0, 0, view.width, view.height);
    gl.disable(gl.SCISSOR_TEST);
    gl.clearColor(0x0d / 255, 0x11 / 255, 0x17 / 255, 1);
    gl.clear(gl.COLOR_BUFFER_BIT);
    // The box: a scissored clear is cheaper than another program.
    gl.enable(gl.SCISSOR_TEST);
    gl.scissor(
      Math.round(view.offsetX + box.x * view.scale),
      Math.round(view.height - view.offsetY - (box.y + box.height) * view.scale),
      Math.round(box.width * view.scale),
      Math.round(box.height * view.scale),
    );
    gl.clearColor(0x16 / 255, 0x1b / 255, 0x22 / 255, 1);
    gl.clear(gl.COLOR_BUFFER_BIT);
    gl.disable(gl.SCISSOR_TEST);

    // World (0,0) at the top left with y down, as the engine's box is.
    const sx = (2 * view.scale) / view.width;
    const sy = (-2 * view.scale) / view.height;
    const ox = (2 * view.offsetX) / view.width - 1;
    const oy = 1 - (2 * view.offsetY) / view.height;
    this.segments.draw(shapes.segments, sx, sy, ox, oy, view.scale);
    if (v.shapes) {
      colors.ensure(n);
      this.shapeLayer ??= new ShapeLayer(gl);
      this.shapeLayer.draw(v, v.shapes, colors, sx, sy, ox, oy);
      this.joints.draw(shapes.joints, sx, sy, ox, oy, view.scale, view.dpr);
      return;
    }
    if (n === 0) return;

    if (this.bodies.length < n * 4) this.bodies = new Float32Array(Math.max(n, (this.bodies.length / 4) * 2) * 4);
    const out = this.bodies;
    const { x, y, radius, type, asleep } = v;
    for (let s = 0, o = 0; s < n; s++, o += 4) {
      const t = type[s];
      out[o] = x[s];
      out[o + 1] = y[s];
      out[o + 2] = t === BodyTypeCode.free ? 0 : radius[s];
      out[o + 3] = t === BodyTypeCode.static ? STATIC : asleep[s] === 1 ? ASLEEP : NORMAL;
    }

    gl.useProgram(this.program);
    gl.bindVertexArray(this.vao);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.bodyBuffer);
    if (this.gpuCapacity < out.length) {
      gl.bufferData(gl.ARRAY_BUFFER, out.byteLength, gl.DYNAMIC_DRAW);
      this.gpuCapacity = out.length;
    }
    gl.bufferSubData(gl.ARRAY_BUFFER, 0, out, 0, n * 4);
    if (colors.version !== this.colorVersion || this.colorCapacity < n) {
      gl.bindBuffer(gl.ARRAY_BUFFER, this.colorBuffer);
      gl.bufferData(gl.ARRAY_BUFFER, colors.rgba, gl.STATIC_DRAW);
      this.colorVersion = colors.version;
      this.colorCapacity = colors.rgba.length / 4;
    }

    gl.uniform2f(this.uScale, sx, sy);
    gl.uniform2f(this.uOffset, ox, oy);
    gl.uniform1f(this.uPixels, view.scale);
    gl.drawArraysInstanced(gl.TRIANGLE_STRIP, 0, 4, n);
    gl.bindVertexArray(null);
    this.joints.draw(shapes.joints, sx, sy, ox, oy, view.scale, view.dpr);
  }
}
