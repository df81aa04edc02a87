import { BodyTypeCode, type BodyViews, type ShapeViews } from '@maxgrid/engine';
import { STATIC_RGB, type BodyColors } from '../colors.js';
import { link, must } from './webgl-util.js';

/** Points around a round shape (circle, capsule), and the fan's size for every kind. */
const SIDES = 16;
/** Vertices per instance: a fan of SIDES - 2 triangles. */
const FAN_VERTICES = 3 * (SIDES - 2);
/** Floats per shape in the static buffer: 8 vertices, then kind, count, radius, state-independent padding. */
const STATIC_FLOATS = 20;
/** Floats per shape in the per-frame buffer: x, y, cos, sin of its body, then its state. */
const POSE_FLOATS = 5;

const VERTEX = `#version 300 es
in vec4 a_v01;
in vec4 a_v23;
in vec4 a_v45;
in vec4 a_v67;
in vec4 a_meta;   // kind (0 circle, 1 capsule, 2 polygon), vertex count (0: draw nothing), radius
in vec4 a_pose;   // the body's centre of mass and rotation: x, y, cos, sin
in float a_state; // 0 normal, 1 static, 2 asleep
in vec4 a_color;
uniform vec2 u_scale;
uniform vec2 u_offset;
uniform vec3 u_static;
out vec4 v_color;
const int SIDES = ${SIDES};
void main() {
  int count = int(a_meta.y);
  if (count == 0) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    v_color = vec4(0.0);
    return;
  }
  // A fan: triangle t is (0, t + 1, t + 2).
  int t = gl_VertexID / 3;
  int corner = gl_VertexID - 3 * t;
  int k = corner == 0 ? 0 : t + corner;
  int kind = int(a_meta.x);
  float r = a_meta.z;
  vec2 local;
  if (kind == 2) {
    vec2 vs[8] = vec2[8](a_v01.xy, a_v01.zw, a_v23.xy, a_v23.zw, a_v45.xy, a_v45.zw, a_v67.xy, a_v67.zw);
    // Fan positions past the last vertex fold onto it: empty triangles.
    local = vs[min(k, count - 1)];
  } else if (kind == 0) {
    float a = 6.28318530718 * float(k) / float(SIDES);
    local = a_v01.xy + r * vec2(cos(a), sin(a));
  } else {
    // Half the points round the second end, half round the first.
    vec2 p0 = a_v01.xy;
    vec2 p1 = a_v01.zw;
    vec2 d = p1 - p0;
    float theta = atan(d.y, d.x);
    int half_ = SIDES / 2;
    float step = 3.14159265359 / float(half_ - 1);
    if (k < half_) {
      float a = theta - 1.57079632679 + step * float(k);
      local = p1 + r * vec2(cos(a), sin(a));
    } else {
      float a = theta + 1.57079632679 + step * float(k - half_);
      local = p0 + r * vec2(cos(a), sin(a));
    }
  }
  vec2 world = a_pose.xy + vec2(a_pose.z * local.x - a_pose.w * local.y, a_pose.w * local.x + a_pose.z * local.y);
  gl_Position = vec4(world * u_scale + u_offset, 0.0, 1.0);
  v_color = a_state == 1.0 ? vec4(u_static, 1.0)
          : a_state == 2.0 ? vec4(mix(a_color.rgb, vec3(0.086, 0.106, 0.133), 0.6), 1.0)
          : a_color;
}`;

const FRAGMENT = `#version 300 es
precision mediump float;
in vec4 v_color;
out vec4 outColor;
void main() {
  outColor = v_color;
}`;

/**
 * Every shape of a world with shapes in one instanced draw: each instance a triangle fan that its
 * vertex shader lays out by kind (a polygon from its vertices, a circle or capsule from its points
 * and radius) and places with its body's pose. Geometry and colours go to the GPU when the shape
 * table grows or the colours change; per frame the CPU copies each shape's body pose (x, y, cos,
 * sin) and state into one reused buffer. Rounded polygons are drawn by their core.
 */
export class ShapeLayer {
  private readonly program: WebGLProgram;
  private readonly vao: WebGLVertexArrayObject;
  private readonly staticBuffer: WebGLBuffer;
  private readonly colorBuffer: WebGLBuffer;
  private readonly poseBuffer: WebGLBuffer;
  private readonly uScale: WebGLUniformLocation | null;
  private readonly uOffset: WebGLUniformLocation | null;
  private staticData = new Float32Array(0);
  private colorData = new Uint8Array(0);
  private poses = new Float32Array(0);
  private poseCapacity = 0;
  private uploadedShapes = -1;
  private uploadedColors = -1;

  constructor(private readonly gl: WebGL2RenderingContext) {
    this.program = link(gl, VERTEX, FRAGMENT);
    this.uScale = gl.getUniformLocation(this.program, 'u_scale');
    this.uOffset = gl.getUniformLocation(this.program, 'u_offset');
    gl.useProgram(this.program);
    gl.uniform3f(gl.getUniformLocation(this.program, 'u_static'), STATIC_RGB[0] / 255, STATIC_RGB[1] / 255, STATIC_RGB[2] / 255);
    this.vao = must(gl.createVertexArray(), 'vertex array');
    gl.bindVertexArray(this.vao);
    this.staticBuffer = must(gl.createBuffer(), 'buffer');
    gl.bindBuffer(gl.ARRAY_BUFFER, this.staticBuffer);
    const attribute = (name: string, size: number, stride: number, offset: number) => {
      const at = gl.getAttribLocation(this.program, name);
      gl.enableVertexAttribArray(at);
      gl.vertexAttribPointer(at, size, gl.FLOAT, false, stride, offset);
      gl.vertexAttribDivisor(at, 1);
    };
    attribute('a_v01', 4, STATIC_FLOATS * 4, 0);
    attribute('a_v23', 4, STATIC_FLOATS * 4, 16);
    attribute('a_v45', 4, STATIC_FLOATS * 4, 32);
    attribute('a_v67', 4, STATIC_FLOATS * 4, 48);
    attribute('a_meta', 4, STATIC_FLOATS * 4, 64);
    this.poseBuffer = must(gl.createBuffer(), 'buffer');
    gl.bindBuffer(gl.ARRAY_BUFFER, this.poseBuffer);
    attribute('a_pose', 4, POSE_FLOATS * 4, 0);
    attribute('a_state', 1, POSE_FLOATS * 4, 16);
    this.colorBuffer = must(gl.createBuffer(), 'buffer');
    gl.bindBuffer(gl.ARRAY_BUFFER, this.colorBuffer);
    const color = gl.getAttribLocation(this.program, 'a_color');
    gl.enableVertexAttribArray(color);
    gl.vertexAttribPointer(color, 4, gl.UNSIGNED_BYTE, true, 0, 0);
    gl.vertexAttribDivisor(color, 1);
    gl.bindVertexArray(null);
  }

  draw(v: BodyViews, shapes: ShapeViews, colors: BodyColors, sx: number, sy: number, ox: number, oy: number): void {
    const gl = this.gl;
    const n = shapes.slotCount;
    if (n === 0) return;
    gl.useProgram(this.program);
    gl.bindVertexArray(this.vao);
    if (n !== this.uploadedShapes || colors.version !== this.uploadedColors) this.uploadStatic(shapes, colors);
    if (this.poses.length < n * POSE_FLOATS) this.poses = new Float32Array(Math.max(n, (2 * this.poses.length) / POSE_FLOATS) * POSE_FLOATS);
    const out = this.poses;
    const { x, y, c, s, type, asleep } = v;
    const turned = c.length > 0;
    const body = shapes.body;
    for (let k = 0, o = 0; k < n; k++, o += POSE_FLOATS) {
      const b = body[k];
      out[o] = x[b];
      out[o + 1] = y[b];
      out[o + 2] = turned ? c[b] : 1;
      out[o + 3] = turned ? s[b] : 0;
      out[o + 4] = type[b] === BodyTypeCode.static ? 1 : asleep[b] === 1 ? 2 : 0;
    }
    gl.bindBuffer(gl.ARRAY_BUFFER, this.poseBuffer);
    if (this.poseCapacity < out.length) {
      gl.bufferData(gl.ARRAY_BUFFER, out.byteLength, gl.DYNAMIC_DRAW);
      this.poseCapacity = out.length;
    }
    gl.bufferSubData(gl.ARRAY_BUFFER, 0, out, 0, n * POSE_FLOATS);
    gl.uniform2f(this.uScale, sx, sy);
    gl.uniform2f(this.uOffset, ox, oy);
    gl.drawArraysInstanced(gl.TRIANGLES, 0, FAN_VERTICES, n);
    gl.bindVertexArray(null);
  }

  private uploadStatic(shapes: ShapeViews, colors: BodyColors): void {
    const gl = this.gl;
    const n = shapes.slotCount;
    if (this.staticData.length < n * STATIC_FLOATS) this.staticData = new Float32Array(n * STATIC_FLOATS);
    if (this.colorData.length < n * 4) this.colorData = new Uint8Array(n * 4);
    const data = this.staticData;
    data.fill(0, 0, n * STATIC_FLOATS);
    const { vertices, stride, vertexStart, vertexCount, radius, kind, live, body } = shapes;
    for (let k = 0; k < n; k++) {
      const o = k * STATIC_FLOATS;
      if (!live[k]) continue;
      const count = vertexCount[k];
      for (let i = 0, at = k * stride + vertexStart; i < count; i++, at += 4) {
        data[o + 2 * i] = vertices[at];
        data[o + 2 * i + 1] = vertices[at + 1];
      }
      data[o + 16] = kind[k];
      data[o + 17] = count;
      data[o + 18] = radius[k];
      this.colorData.set(colors.rgba.subarray(body[k] * 4, body[k] * 4 + 4), k * 4);
    }
    gl.bindBuffer(gl.ARRAY_BUFFER, this.staticBuffer);
    gl.bufferData(gl.ARRAY_BUFFER, data.subarray(0, n * STATIC_FLOATS), gl.STATIC_DRAW);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.colorBuffer);
    gl.bufferData(gl.ARRAY_BUFFER, this.colorData.subarray(0, n * 4), gl.STATIC_DRAW);
    this.uploadedShapes = n;
    this.uploadedColors = colors.version;
  }
}
