import type { JointViews } from '@maxgrid/engine';
import { JOINT_RGB } from '../colors.js';
import { JOINT_DOT_PX, JOINT_LINE_ALPHA, JOINT_LINE_PX } from './renderer.js';
import { link, must } from './webgl-util.js';

/** Floats per instance: the two ends of a line, or a dot given as a line of length 0. */
const INSTANCE_FLOATS = 4;

const VERTEX = `#version 300 es
in vec2 a_corner;
in vec4 a_ends;        // x1, y1, x2, y2 in world units
uniform vec2 u_scale;
uniform vec2 u_offset;
uniform float u_pixels;   // device pixels per world unit
uniform float u_radiusPx; // half the line's width, or the dot's radius, in device pixels
out vec2 v_world;
flat out vec4 v_ends;
void main() {
  vec2 a = a_ends.xy;
  vec2 b = a_ends.zw;
  vec2 ab = b - a;
  float len = length(ab);
  vec2 d = len > 0.0 ? ab / len : vec2(1.0, 0.0);
  vec2 n = vec2(-d.y, d.x);
  // A pixel of margin for the antialiased edge.
  float extent = (u_radiusPx + 1.0) / u_pixels;
  vec2 world = (a + b) * 0.5 + d * a_corner.x * (len * 0.5 + extent) + n * a_corner.y * extent;
  gl_Position = vec4(world * u_scale + u_offset, 0.0, 1.0);
  v_world = world;
  v_ends = a_ends;
}`;

const FRAGMENT = `#version 300 es
precision highp float;
in vec2 v_world;
flat in vec4 v_ends;
uniform float u_pixels;
uniform float u_radiusPx;
uniform vec3 u_color;
uniform float u_alpha;
out vec4 outColor;
void main() {
  vec2 a = v_ends.xy;
  vec2 ab = v_ends.zw - a;
  float t = clamp(dot(v_world - a, ab) / max(dot(ab, ab), 1e-12), 0.0, 1.0);
  float distPx = length(v_world - a - ab * t) * u_pixels;
  float alpha = clamp(u_radiusPx - distPx + 0.5, 0.0, 1.0);
  if (alpha <= 0.0) discard;
  outColor = vec4(u_color, alpha * u_alpha);
}`;

/**
 * Joints as the canvas renderer draws them: a line between the two anchors and a dot on each, sized
 * in pixels. Lines and dots share one shader (a dot is a line of length 0, a round cap all round)
 * and one reused buffer, lines first, then two dots per joint; two instanced draws, the second
 * reading the buffer from where the dots begin.
 */
export class JointLayer {
  private readonly program: WebGLProgram;
  private readonly vao: WebGLVertexArrayObject;
  private readonly buffer: WebGLBuffer;
  private readonly endsAt: number;
  private readonly uScale: WebGLUniformLocation | null;
  private readonly uOffset: WebGLUniformLocation | null;
  private readonly uPixels: WebGLUniformLocation | null;
  private readonly uRadius: WebGLUniformLocation | null;
  private readonly uAlpha: WebGLUniformLocation | null;
  private data = new Float32Array(0);
  private gpuCapacity = 0;

  constructor(private readonly gl: WebGL2RenderingContext, quad: WebGLBuffer) {
    this.program = link(gl, VERTEX, FRAGMENT);
    this.uScale = gl.getUniformLocation(this.program, 'u_scale');
    this.uOffset = gl.getUniformLocation(this.program, 'u_offset');
    this.uPixels = gl.getUniformLocation(this.program, 'u_pixels');
    this.uRadius = gl.getUniformLocation(this.program, 'u_radiusPx');
    this.uAlpha = gl.getUniformLocation(this.program, 'u_alpha');
    gl.useProgram(this.program);
    gl.uniform3f(gl.getUniformLocation(this.program, 'u_color'), JOINT_RGB[0] / 255, JOINT_RGB[1] / 255, JOINT_RGB[2] / 255);

    this.vao = must(gl.createVertexArray(), 'vertex array');
    gl.bindVertexArray(this.vao);
    gl.bindBuffer(gl.ARRAY_BUFFER, quad);
    const corner = gl.getAttribLocation(this.program, 'a_corner');
    gl.enableVertexAttribArray(corner);
    gl.vertexAttribPointer(corner, 2, gl.FLOAT, false, 0, 0);
    this.buffer = must(gl.createBuffer(), 'buffer');
    gl.bindBuffer(gl.ARRAY_BUFFER, this.buffer);
    this.endsAt = gl.getAttribLocation(this.program, 'a_ends');
    gl.enableVertexAttribArray(this.endsAt);
    gl.vertexAttribPointer(this.endsAt, INSTANCE_FLOATS, gl.FLOAT, false, 0, 0);
    gl.vertexAttribDivisor(this.endsAt, 1);
    gl.bindVertexArray(null);
  }

  /** Draws `joints` with the body program's transform; `pixels`: device pixels per world unit, `dpr`: per CSS pixel. */
  draw(joints: JointViews | null, sx: number, sy: number, ox: number, oy: number, pixels: number, dpr: number): void {
    if (joints === null || joints.count === 0) return;
    const gl = this.gl;
    const n = joints.count;
    const floats = 3 * n * INSTANCE_FLOATS;
    if (this.data.length < floats) this.data = new Float32Array(Math.max(floats, 2 * this.data.length));
    const out = this.data;
    const { anchorAX, anchorAY, anchorBX, anchorBY } = joints;
    for (let k = 0, o = 0, d = n * INSTANCE_FLOATS; k < n; k++, o += INSTANCE_FLOATS, d += 2 * INSTANCE_FLOATS) {
      const ax = anchorAX[k];
      const ay = anchorAY[k];
      const bx = anchorBX[k];
      const by = anchorBY[k];
      out[o] = ax;
      out[o + 1] = ay;
      out[o + 2] = bx;
      out[o + 3] = by;
      out[d] = out[d + 2] = ax;
      out[d + 1] = out[d + 3] = ay;
      out[d + 4] = out[d + 6] = bx;
      out[d + 5] = out[d + 7] = by;
    }
    gl.useProgram(this.program);
    gl.bindVertexArray(this.vao);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.buffer);
    if (this.gpuCapacity < out.length) {
      gl.bufferData(gl.ARRAY_BUFFER, out.byteLength, gl.DYNAMIC_DRAW);
      this.gpuCapacity = out.length;
    }
    gl.bufferSubData(gl.ARRAY_BUFFER, 0, out, 0, floats);
    gl.uniform2f(this.uScale, sx, sy);
    gl.uniform2f(this.uOffset, ox, oy);
    gl.uniform1f(this.uPixels, pixels);
    gl.vertexAttribPointer(this.endsAt, INSTANCE_FLOATS, gl.FLOAT, false, 0, 0);
    gl.uniform1f(this.uRadius, (JOINT_LINE_PX / 2) * dpr);
    gl.uniform1f(this.uAlpha, JOINT_LINE_ALPHA);
    gl.drawArraysInstanced(gl.TRIANGLE_STRIP, 0, 4, n);
    // WebGL 2 has no base instance: the dots are the same attribute read from further on.
    gl.vertexAttribPointer(this.endsAt, INSTANCE_FLOATS, gl.FLOAT, false, 0, n * INSTANCE_FLOATS * 4);
    gl.uniform1f(this.uRadius, JOINT_DOT_PX * dpr);
    gl.uniform1f(this.uAlpha, 1);
    gl.drawArraysInstanced(gl.TRIANGLE_STRIP, 0, 4, 2 * n);
    gl.bindVertexArray(null);
  }
}
