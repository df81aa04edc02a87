import { STATIC_RGB } from '../colors.js';
import { link, must } from './webgl-util.js';

const VERTEX = `#version 300 es
in vec2 a_corner;
in vec4 a_ends;      // x1, y1, x2, y2 in world units
in float a_thickness;
uniform vec2 u_scale;
uniform vec2 u_offset;
uniform float u_pixels;
out vec2 v_world;
flat out vec4 v_ends;
flat out float v_radius;
void main() {
  vec2 a = a_ends.xy;
  vec2 b = a_ends.zw;
  vec2 ab = b - a;
  float len = length(ab);
  vec2 d = len > 0.0 ? ab / len : vec2(1.0, 0.0);
  vec2 n = vec2(-d.y, d.x);
  // At least a pixel wide, and a pixel of margin for the antialiased edge.
  float radius = max(a_thickness, 0.5 / u_pixels);
  float extent = radius + 1.0 / u_pixels;
  vec2 world = (a + b) * 0.5 + d * a_corner.x * (len * 0.5 + extent) + n * a_corner.y * extent;
  gl_Position = vec4(world * u_scale + u_offset, 0.0, 1.0);
  v_world = world;
  v_ends = a_ends;
  v_radius = radius;
}`;

const FRAGMENT = `#version 300 es
precision highp float;
in vec2 v_world;
flat in vec4 v_ends;
flat in float v_radius;
uniform float u_pixels;
uniform vec3 u_color;
out vec4 outColor;
void main() {
  vec2 a = v_ends.xy;
  vec2 ab = v_ends.zw - a;
  float t = clamp(dot(v_world - a, ab) / max(dot(ab, ab), 1e-12), 0.0, 1.0);
  float dist = length(v_world - a - ab * t);
  float alpha = clamp((v_radius - dist) * u_pixels + 0.5, 0.0, 1.0);
  if (alpha <= 0.0) discard;
  outColor = vec4(u_color, alpha);
}`;

/**
 * Static segments as capsules: one instanced quad per segment, shaded by its distance to the
 * segment, so thick walls get round ends like the engine's capsule shape. The few segments a
 * scene has are uploaded once, when the scene changes.
 */
export class SegmentLayer {
  private readonly program: WebGLProgram;
  private readonly vao: WebGLVertexArrayObject;
  private readonly buffer: WebGLBuffer;
  private readonly uScale: WebGLUniformLocation | null;
  private readonly uOffset: WebGLUniformLocation | null;
  private readonly uPixels: WebGLUniformLocation | null;
  private uploaded: Float64Array | null = null;
  private count = 0;

  constructor(private readonly gl: WebGL2RenderingContext, quad: WebGLBuffer) {
    this.program = link(gl, VERTEX, FRAGMENT);
    this.uScale = gl.getUniformLocation(this.program, 'u_scale');
    this.uOffset = gl.getUniformLocation(this.program, 'u_offset');
    this.uPixels = gl.getUniformLocation(this.program, 'u_pixels');
    gl.useProgram(this.program);
    gl.uniform3f(gl.getUniformLocation(this.program, 'u_color'), STATIC_RGB[0] / 255, STATIC_RGB[1] / 255, STATIC_RGB[2] / 255);

    this.vao = must(gl.createVertexArray(), 'vertex array');
    gl.bindVertexArray(this.vao);
    gl.bindBuffer(gl.ARRAY_BUFFER, quad);
    const corner = gl.getAttribLocation(this.program, 'a_corner');
    gl.enableVertexAttribArray(corner);
    gl.vertexAttribPointer(corner, 2, gl.FLOAT, false, 0, 0);
    this.buffer = must(gl.createBuffer(), 'buffer');
    gl.bindBuffer(gl.ARRAY_BUFFER, this.buffer);
    const ends = gl.getAttribLocation(this.program, 'a_ends');
    gl.enableVertexAttribArray(ends);
    gl.vertexAttribPointer(ends, 4, gl.FLOAT, false, 20, 0);
    gl.vertexAttribDivisor(ends, 1);
    const thickness = gl.getAttribLocation(this.program, 'a_thickness');
    gl.enableVertexAttribArray(thickness);
    gl.vertexAttribPointer(thickness, 1, gl.FLOAT, false, 20, 16);
    gl.vertexAttribDivisor(thickness, 1);
    gl.bindVertexArray(null);
  }

  /** Draws `segments` (x1, y1, x2, y2, thickness each) with the body program's transform. */
  draw(segments: Float64Array, sx: number, sy: number, ox: number, oy: number, pixels: number): void {
    const gl = this.gl;
    if (segments !== this.uploaded) {
      gl.bindBuffer(gl.ARRAY_BUFFER, this.buffer);
      gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(segments), gl.STATIC_DRAW);
      this.uploaded = segments;
      this.count = segments.length / 5;
    }
    if (this.count === 0) return;
    gl.useProgram(this.program);
    gl.bindVertexArray(this.vao);
    gl.uniform2f(this.uScale, sx, sy);
    gl.uniform2f(this.uOffset, ox, oy);
    gl.uniform1f(this.uPixels, pixels);
    gl.drawArraysInstanced(gl.TRIANGLE_STRIP, 0, 4, this.count);
    gl.bindVertexArray(null);
  }
}
