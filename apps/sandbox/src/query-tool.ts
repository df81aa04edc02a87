import type { RayHit, World } from '@maxgrid/engine';
import type { ToolName } from './settings.js';

/**
 * The Ray, Point and Box tools: what the pointer asks the engine's queries, and their last answers.
 * Bodies move between frames, so the active query is asked again after every step; it allocates
 * only for what it finds (the engine's query calls return fresh arrays), never per body.
 */
export class QueryTool {
  tool: ToolName = 'drag';
  /** A ray exists once a drag with the Ray tool has begun; it stays after release. */
  hasRay = false;
  x1 = 0;
  y1 = 0;
  x2 = 0;
  y2 = 0;
  hits: RayHit[] = [];
  /** Where the Point tool's pointer hovers, while it is over the stage. */
  hasPoint = false;
  px = 0;
  py = 0;
  under: number[] = [];
  /** A box exists once a drag with the Box tool has begun; corners as dragged, in any order. */
  hasBox = false;
  bx1 = 0;
  by1 = 0;
  bx2 = 0;
  by2 = 0;
  inBox: number[] = [];
  private dirty = true;
  private askedAtStep = -1;
  /** The joint count the Pin or Cut readout shows, so its text is made again only when it changes. */
  private shownJoints = -1;

  constructor(private readonly readout: HTMLElement) {}

  setTool(tool: ToolName): void {
    if (tool === this.tool) return;
    this.tool = tool;
    this.clear();
  }

  /** Forgets the ray, the point and the box (a new world, or another tool). */
  clear(): void {
    this.hasRay = false;
    this.hasPoint = false;
    this.hasBox = false;
    this.hits = [];
    this.under = [];
    this.inBox = [];
    this.dirty = true;
    this.askedAtStep = -1;
  }

  ray(x1: number, y1: number, x2: number, y2: number): void {
    this.hasRay = true;
    this.x1 = x1;
    this.y1 = y1;
    this.x2 = x2;
    this.y2 = y2;
    this.dirty = true;
  }

  box(x1: number, y1: number, x2: number, y2: number): void {
    this.hasBox = true;
    this.bx1 = x1;
    this.by1 = y1;
    this.bx2 = x2;
    this.by2 = y2;
    this.dirty = true;
  }

  point(x: number, y: number): void {
    this.hasPoint = true;
    this.px = x;
    this.py = y;
    this.dirty = true;
  }

  leavePoint(): void {
    this.hasPoint = false;
    this.under = [];
    this.dirty = true;
  }

  /** Asks again when the pointer moved or the world stepped since the last answer. */
  update(world: World): void {
    if (this.tool === 'pin' || this.tool === 'cut') {
      // Joints also go without a click (they break, or go with a body), so the count is read every frame.
      const joints = world.jointCount;
      if (!this.dirty && joints === this.shownJoints) return;
      this.dirty = false;
      this.shownJoints = joints;
      const what = this.tool === 'pin' ? 'Pin: click a body to pin it to the world there' : "Cut: click a joint's line to cut it";
      this.readout.textContent = `${what} · ${joints.toLocaleString('en-US')} joint${joints === 1 ? '' : 's'}`;
      return;
    }
    const steps = world.stats.steps;
    if (!this.dirty && steps === this.askedAtStep) return;
    this.dirty = false;
    this.askedAtStep = steps;
    if (this.tool === 'ray' && this.hasRay) {
      // A ray of zero length (a click) has no direction; the engine would refuse it.
      const moved = this.x1 !== this.x2 || this.y1 !== this.y2;
      // The same array every time: its hit objects are reused (rayCastAll's `out`).
      this.hits = moved ? world.rayCastAll(this.x1, this.y1, this.x2, this.y2, undefined, this.hits) : [];
    } else if (this.tool === 'point' && this.hasPoint) {
      this.under = world.queryPoint(this.px, this.py);
    } else if (this.tool === 'box' && this.hasBox) {
      // The engine wants min <= max; a box dragged up or to the left has its corners swapped.
      this.inBox = world.queryAABB(
        Math.min(this.bx1, this.bx2),
        Math.min(this.by1, this.by2),
        Math.max(this.bx1, this.bx2),
        Math.max(this.by1, this.by2),
      );
    }
    this.readout.textContent = this.describe(world);
  }

  private describe(world: World): string {
    if (this.tool === 'ray') {
      if (!this.hasRay) return 'Ray: drag across the bodies to cast a ray.';
      const n = this.hits.length;
      if (n === 0) return 'Ray: 0 hits';
      const first = this.hits[0];
      const what = world.hasBody(first.handle) ? 'body' : 'segment';
      return `Ray: ${n} hit${n === 1 ? '' : 's'} · first: ${what} ${first.handle} at fraction ${first.fraction.toFixed(3)}`;
    }
    if (this.tool === 'point') {
      if (!this.hasPoint) return 'Point: hover over the bodies.';
      const n = this.under.length;
      return `Point: ${counted(world, this.under)} under the pointer${n > 0 ? ` (${this.under.slice(0, 6).join(', ')}${n > 6 ? ', …' : ''})` : ''}`;
    }
    if (this.tool === 'box') {
      if (!this.hasBox) return 'Box: drag to draw a box over the bodies.';
      return `Box: ${counted(world, this.inBox)}`;
    }
    return '';
  }
}

/** "3 bodies", or "3 bodies and 1 segment" where the queries found static segments too. */
function counted(world: World, handles: number[]): string {
  let bodies = 0;
  for (const h of handles) if (world.hasBody(h)) bodies++;
  const segments = handles.length - bodies;
  const text = `${bodies} bod${bodies === 1 ? 'y' : 'ies'}`;
  return segments === 0 ? text : `${text} and ${segments} segment${segments === 1 ? '' : 's'}`;
}
