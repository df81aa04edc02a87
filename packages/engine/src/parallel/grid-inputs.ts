import type { BodyStore } from '../store/body-store.js';
import type { GridKernel } from '../broadphase/grid-kernel.js';

/**
 * One thread's copies of body positions and radii into a shared grid kernel's memory of its own,
 * where the kernel's bin passes read them: only for a grid that could not live in the body memory
 * (CellGrid.useArena), such as one whose bodies have no WebAssembly memory. Positions go over a
 * cache-sized chunk at a time, right after motion wrote them; radii, which never change while a
 * body lives, only when membership or the grid's arrays changed (GridKernel.copyRadii). Copies
 * are one memcpy per column through views made once per share, because subarray() allocates and
 * this runs every step.
 */
export class GridInputs {
  private x: Float64Array[] = [];
  private y: Float64Array[] = [];
  private radius = new Float64Array(0);
  private source: Float64Array | null = null;
  private from = -1;
  private to = -1;

  constructor(private readonly chunk: number) {}

  /** Views over this thread's share [from, to) of `bodies`, in chunks of `chunk` bodies from `from`. */
  prepare(bodies: BodyStore, from: number, to: number): void {
    if (this.source === bodies.x && this.from === from && this.to === to) return;
    this.source = bodies.x;
    this.from = from;
    this.to = to;
    this.x = [];
    this.y = [];
    for (let at = from; at < to; at += this.chunk) {
      const end = Math.min(at + this.chunk, to);
      this.x.push(bodies.x.subarray(at, end));
      this.y.push(bodies.y.subarray(at, end));
    }
    this.radius = bodies.radius.subarray(from, to);
  }

  /** Copies the positions of the chunk that starts at body `at`. */
  copyPositions(kernel: GridKernel, at: number): void {
    const chunk = (at - this.from) / this.chunk;
    kernel.inputX.set(this.x[chunk], at);
    kernel.inputY.set(this.y[chunk], at);
  }

  /** Copies the share's radii, unless the kernel still holds this copy (see GridKernel.copyRadii). */
  copyRadii(kernel: GridKernel, membership: number): void {
    kernel.copyRadii(this.radius, this.from, membership);
  }
}
