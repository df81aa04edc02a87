import { BodyTypeCode, type BodyViews } from '@maxgrid/engine';
import type { BodyColors } from '../colors.js';
import type { ViewTransform } from '../view.js';
import type { Renderer } from './renderer.js';

const VERTEX = `#version 300 es
in vec2 a_corner;
in vec3 a_body;   // x, y, radius in world units
in vec4 a_color;
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
  v_color = a_color;
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
 * copying x, y and radius from the engine's Float64 views into one reused Float32 buffer; colours
 * are uploaded only when they change. Free slots get radius 0, which the shaders skip.
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
  private bodies = new Float32Array(0);
  private gpuCapacity = 0;
  private colorVersion = -1;
  private colorCapacity = 0;

  /** Throws when WebGL 2 is unavailable; the caller falls back to canvas 2D. */
  constructor(readonly canvas: HTMLCanvasElement) {
    const gl = canvas.getContext('webgl2', { alpha: false, antialias: false, preserveDrawingBuffer: false });
    if (!gl) throw new Error('this browser gives no WebGL 2 context');
    this.gl = gl;
    this.program = link(gl, VERTEX, FRAGMENT);
    this.uScale = gl.getUniformLocation(this.program, 'u_scale');
    this.uOffset = gl.getUniformLocation(this.program, 'u_offset');
    this.uPixels = gl.getUniformLocation(this.program, 'u_pixels');

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
    gl.vertexAttribPointer(body, 3, gl.FLOAT, false, 0, 0);
    gl.vertexAttribDivisor(body, 1);

    this.colorBuffer = must(gl.createBuffer(), 'buffer');
    gl.bindBuffer(gl.ARRAY_BUFFER, this.colorBuffer);
    const color = gl.getAttribLocation(this.program, 'a_color');
    gl.enableVertexAttribArray(color);
    gl.vertexAttribPointer(color, 4, gl.UNSIGNED_BYTE, true, 0, 0);
    gl.vertexAttribDivisor(color, 1);
    gl.bindVertexArray(null);

    gl.enable(gl.BLEND);
    gl.blendFunc(gl.SRC_ALPHA, gl.ONE_MINUS_SRC_ALPHA);
  }

  draw(v: BodyViews, colors: BodyColors, view: ViewTransform, box: { width: number; height: number }): void {
    const gl = this.gl;
    const n = v.slotCount;
    gl.viewport(0, 0, view.width, view.height);
    gl.disable(gl.SCISSOR_TEST);
    gl.clearColor(0x0d / 255, 0x11 / 255, 0x17 / 255, 1);
    gl.clear(gl.COLOR_BUFFER_BIT);
    // The box: a scissored clear is cheaper than another program.
    gl.enable(gl.SCISSOR_TEST);
    gl.scissor(
      Math.round(view.offsetX),
      Math.round(view.height - view.offsetY - box.height * view.scale),
      Math.round(box.width * view.scale),
      Math.round(box.height * view.scale),
    );
    gl.clearColor(0x16 / 255, 0x1b / 255, 0x22 / 255, 1);
    gl.clear(gl.COLOR_BUFFER_BIT);
    gl.disable(gl.SCISSOR_TEST);
    if (n === 0) return;

    if (this.bodies.length < n * 3) this.bodies = new Float32Array(Math.max(n, (this.bodies.length / 3) * 2) * 3);
    const out = this.bodies;
    const { x, y, radius, type } = v;
    for (let s = 0, o = 0; s < n; s++, o += 3) {
      out[o] = x[s];
      out[o + 1] = y[s];
      out[o + 2] = type[s] === BodyTypeCode.free ? 0 : radius[s];
    }

    gl.useProgram(this.program);
    gl.bindVertexArray(this.vao);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.bodyBuffer);
    if (this.gpuCapacity < out.length) {
      gl.bufferData(gl.ARRAY_BUFFER, out.byteLength, gl.DYNAMIC_DRAW);
      this.gpuCapacity = out.length;
    }
    gl.bufferSubData(gl.ARRAY_BUFFER, 0, out, 0, n * 3);
    if (colors.version !== this.colorVersion || this.colorCapacity < n) {
      gl.bindBuffer(gl.ARRAY_BUFFER, this.colorBuffer);
      gl.bufferData(gl.ARRAY_BUFFER, colors.rgba, gl.STATIC_DRAW);
      this.colorVersion = colors.version;
      this.colorCapacity = colors.rgba.length / 4;
    }

    // World (0,0) at the top left with y down, as the engine's box is.
    const sx = (2 * view.scale) / view.width;
    const sy = (-2 * view.scale) / view.height;
    gl.uniform2f(this.uScale, sx, sy);
    gl.uniform2f(this.uOffset, (2 * view.offsetX) / view.width - 1, 1 - (2 * view.offsetY) / view.height);
    gl.uniform1f(this.uPixels, view.scale);
    gl.drawArraysInstanced(gl.TRIANGLE_STRIP, 0, 4, n);
    gl.bindVertexArray(null);
  }
}

function must<T>(value: T | null, what: string): T {
  if (value === null) throw new Error(`WebGL could not create a ${what}`);
  return value;
}

function compile(gl: WebGL2RenderingContext, kind: number, source: string): WebGLShader {
  const shader = must(gl.createShader(kind), 'shader');
  gl.shaderSource(shader, source);
  gl.compileShader(shader);
  if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) throw new Error(`shader: ${gl.getShaderInfoLog(shader) ?? 'unknown error'}`);
  return shader;
}

function link(gl: WebGL2RenderingContext, vertex: string, fragment: string): WebGLProgram {
  const program = must(gl.createProgram(), 'program');
  gl.attachShader(program, compile(gl, gl.VERTEX_SHADER, vertex));
  gl.attachShader(program, compile(gl, gl.FRAGMENT_SHADER, fragment));
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error(`program: ${gl.getProgramInfoLog(program) ?? 'unknown error'}`);
  return program;
}
