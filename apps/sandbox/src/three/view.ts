import * as THREE from 'three';
import type * as CANNON from 'cannon-es';
import { CUBE_SIZE, isSleeping, isStatic } from './physics.js';

/**
 * The three.js side of 5.3.1: a scene, a perspective camera, a hemisphere light (ambient sky
 * light) plus a directional light casting shadows, and cubes with a standard material.
 *
 * Cubes are one InstancedMesh rather than a mesh each: the experiment can hold hundreds of cubes
 * and one draw call keeps swiftshader (software WebGL in CI) responsive. Each frame copies every
 * body's position and rotation onto its instance, which is 5.3.2's "the objects being visualised
 * follow the objects in the physics world".
 */

/** Figure 9's colours: dynamic objects in yellow, static objects in red. Sleeping ones, which
 *  figure 9 does not show, are a muted blue. */
export const COLOURS = { dynamic: 0xf2c12e, static: 0xd63a2f, sleeping: 0x6f8caf } as const;

const MAX_CUBES = 4096;

export class CubeView {
  readonly renderer: THREE.WebGLRenderer;
  private readonly scene = new THREE.Scene();
  private readonly camera = new THREE.PerspectiveCamera(45, 1, 0.1, 200);
  private readonly cubes: THREE.InstancedMesh;
  private readonly matrix = new THREE.Matrix4();
  private readonly position = new THREE.Vector3();
  private readonly rotation = new THREE.Quaternion();
  private readonly scale = new THREE.Vector3(1, 1, 1);
  private readonly colour = new THREE.Color();

  constructor(private readonly host: HTMLElement) {
    // No MSAA: software WebGL (swiftshader, as in CI and on GPU-less machines) pays for it with
    // a third of the frame rate, and at devicePixelRatio >= 2 the edges are fine without it.
    // preserveDrawingBuffer keeps the last frame readable, so the page's pixels can be checked
    // (and screenshotted) after the frame was presented. The cost is one copy per frame.
    this.renderer = new THREE.WebGLRenderer({ antialias: false, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
    this.renderer.shadowMap.enabled = true;
    this.renderer.shadowMap.type = THREE.PCFShadowMap;
    host.appendChild(this.renderer.domElement);

    this.scene.background = new THREE.Color(0xbfd8ee);
    this.scene.add(new THREE.HemisphereLight(0xdfefff, 0x5a4a3a, 1.2));
    const sun = new THREE.DirectionalLight(0xffffff, 2.2);
    sun.position.set(12, 22, 9);
    sun.castShadow = true;
    sun.shadow.mapSize.set(1024, 1024);
    // The shadow camera must cover the floor area the cubes can reach, and no more, or the
    // shadow map's texels get coarse.
    const reach = 14;
    Object.assign(sun.shadow.camera, { left: -reach, right: reach, top: reach, bottom: -reach, near: 1, far: 60 });
    this.scene.add(sun);

    const floor = new THREE.Mesh(
      new THREE.PlaneGeometry(60, 60),
      new THREE.MeshStandardMaterial({ color: 0x9aa59a, roughness: 0.95 }),
    );
    floor.rotation.x = -Math.PI / 2;
    floor.receiveShadow = true;
    this.scene.add(floor);

    const box = new THREE.BoxGeometry(CUBE_SIZE, CUBE_SIZE, CUBE_SIZE);
    // White base colour: the per-instance colour then shows as is.
    const material = new THREE.MeshStandardMaterial({ color: 0xffffff, roughness: 0.6 });
    this.cubes = new THREE.InstancedMesh(box, material, MAX_CUBES);
    this.cubes.castShadow = true;
    this.cubes.receiveShadow = true;
    this.cubes.count = 0;
    // Cubes fly well outside their rest-pose bounds; skip per-mesh culling rather than recompute it.
    this.cubes.frustumCulled = false;
    this.scene.add(this.cubes);

    this.aim(8);
    this.resize();
  }

  /** Points the camera at a stack of the given height, from a three-quarter view. */
  aim(height: number): void {
    const d = Math.max(14, height * 1.6);
    this.camera.position.set(d * 0.75, Math.max(6, height * 0.9), d);
    this.camera.lookAt(0, height * 0.35, 0);
  }

  resize(): void {
    const width = Math.max(1, this.host.clientWidth);
    const height = Math.max(1, this.host.clientHeight);
    this.renderer.setSize(width, height, true);
    this.camera.aspect = width / height;
    this.camera.updateProjectionMatrix();
  }

  /** Copies the cube bodies (not the floor) onto the instances and draws a frame. */
  render(bodies: readonly CANNON.Body[]): void {
    let n = 0;
    for (const body of bodies) {
      if (n === MAX_CUBES) break;
      const p = body.position;
      const q = body.quaternion;
      this.position.set(p.x, p.y, p.z);
      this.rotation.set(q.x, q.y, q.z, q.w);
      this.matrix.compose(this.position, this.rotation, this.scale);
      this.cubes.setMatrixAt(n, this.matrix);
      const hex = isStatic(body) ? COLOURS.static : isSleeping(body) ? COLOURS.sleeping : COLOURS.dynamic;
      this.cubes.setColorAt(n, this.colour.setHex(hex));
      n++;
    }
    this.cubes.count = n;
    this.cubes.instanceMatrix.needsUpdate = true;
    if (this.cubes.instanceColor) this.cubes.instanceColor.needsUpdate = true;
    this.renderer.render(this.scene, this.camera);
  }
}
