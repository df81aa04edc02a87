import type { QueryTool } from './query-tool.js';
import type { SpawnKind } from './settings.js';
import type { Simulation } from './simulation.js';
import type { ViewTransform } from './view.js';

/** Pointer travel, in CSS pixels, below which a press on empty space counts as a click. */
const CLICK_SLOP = 5;
/** How near a joint's drawn line, in CSS pixels, a Cut click must land: a finger's width, about. */
const CUT_REACH = 8;

/**
 * Mouse, pen and touch through pointer events, by tool. Drag: press on a body to drag it
 * (releasing throws it with the pointer's velocity), click empty space to add a body of the
 * scene's size, of the kind chosen. Ray: press and drag to cast a ray from the press to the pointer. Point: hover to
 * ask which circles contain the pointer. Box: press and drag to span a box from the press to the
 * pointer and ask which circles overlap it. Pin: press on a body to pin it to the world there.
 * Cut: press near a joint's line to destroy that joint.
 */
export function attachPointer(
  target: HTMLElement,
  sim: Simulation,
  view: ViewTransform,
  query: QueryTool,
  spawnRadius: () => number,
  spawnKind: () => SpawnKind,
  onChange: () => void,
  say: (message: string) => void,
): void {
  let pointerId = -1;
  let startX = 0;
  let startY = 0;
  let onEmpty = false;
  // Where a Ray or Box drag began: the fixed end of the ray, the fixed corner of the box.
  let anchorX = 0;
  let anchorY = 0;

  const worldX = (e: PointerEvent) => view.toWorldX(e.clientX - target.getBoundingClientRect().left);
  const worldY = (e: PointerEvent) => view.toWorldY(e.clientY - target.getBoundingClientRect().top);

  /** The ray or box from the drag's anchor to a world point, by tool. */
  const spanTo = (x: number, y: number) => {
    if (query.tool === 'ray') query.ray(anchorX, anchorY, x, y);
    else query.box(anchorX, anchorY, x, y);
  };

  target.addEventListener('pointerdown', (e) => {
    if (pointerId >= 0 || e.button !== 0) return;
    pointerId = e.pointerId;
    target.setPointerCapture(e.pointerId);
    startX = e.clientX;
    startY = e.clientY;
    const x = worldX(e);
    const y = worldY(e);
    e.preventDefault();
    if (query.tool === 'ray' || query.tool === 'box') {
      anchorX = x;
      anchorY = y;
      spanTo(x, y);
      return;
    }
    if (query.tool === 'point') {
      query.point(x, y);
      return;
    }
    if (query.tool === 'pin') {
      const body = sim.bodyAt(x, y);
      if (body < 0) return;
      try {
        sim.pin(body, x, y);
      } catch (error) {
        say(`Cannot pin body ${body}: ${error instanceof Error ? error.message : String(error)}.`);
      }
      onChange();
      return;
    }
    if (query.tool === 'cut') {
      const joint = sim.jointNear(x, y, (CUT_REACH * view.dpr) / view.scale);
      if (joint < 0) return;
      sim.cut(joint);
      onChange();
      return;
    }
    const handle = sim.bodyAt(x, y);
    onEmpty = handle < 0;
    if (!onEmpty) sim.beginDrag(handle, x, y);
  });

  target.addEventListener('pointermove', (e) => {
    // The Point tool follows a hovering mouse too, not only a pressed one.
    if (query.tool === 'point') {
      if (pointerId < 0 || e.pointerId === pointerId) query.point(worldX(e), worldY(e));
      return;
    }
    if (e.pointerId !== pointerId) return;
    if (query.tool === 'ray' || query.tool === 'box') spanTo(worldX(e), worldY(e));
    else if (query.tool === 'drag' && !onEmpty) sim.moveDrag(worldX(e), worldY(e));
  });

  target.addEventListener('pointerleave', (e) => {
    if (query.tool === 'point' && e.pointerId !== pointerId) query.leavePoint();
  });

  const finish = (e: PointerEvent, cancelled: boolean) => {
    if (e.pointerId !== pointerId) return;
    pointerId = -1;
    if (query.tool === 'ray' || query.tool === 'box') {
      if (!cancelled) spanTo(worldX(e), worldY(e));
      onChange();
      return;
    }
    if (query.tool === 'point' || query.tool === 'pin' || query.tool === 'cut') return;
    if (!onEmpty) {
      sim.endDrag();
      return;
    }
    const moved = Math.hypot(e.clientX - startX, e.clientY - startY);
    if (cancelled || moved > CLICK_SLOP) return;
    const x = worldX(e);
    const y = worldY(e);
    const box = sim.box;
    if (x < box.x || y < box.y || x > box.x + box.width || y > box.y + box.height) return;
    sim.spawn(x, y, spawnRadius(), spawnKind());
    onChange();
  };
  target.addEventListener('pointerup', (e) => finish(e, false));
  target.addEventListener('pointercancel', (e) => finish(e, true));
}
