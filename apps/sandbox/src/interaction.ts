import type { Simulation } from './simulation.js';
import type { ViewTransform } from './view.js';

/** Pointer travel, in CSS pixels, below which a press on empty space counts as a click. */
const CLICK_SLOP = 5;

/**
 * Mouse, pen and touch through pointer events: press on a circle to drag it (releasing throws it
 * with the pointer's velocity), click empty space to add a circle of the current size.
 */
export function attachPointer(
  target: HTMLElement,
  sim: Simulation,
  view: ViewTransform,
  spawnRadius: () => number,
  onSpawn: () => void,
): void {
  let pointerId = -1;
  let startX = 0;
  let startY = 0;
  let onEmpty = false;

  const local = (e: PointerEvent): { x: number; y: number } => {
    const rect = target.getBoundingClientRect();
    return { x: view.toWorldX(e.clientX - rect.left), y: view.toWorldY(e.clientY - rect.top) };
  };

  target.addEventListener('pointerdown', (e) => {
    if (pointerId >= 0 || e.button !== 0) return;
    pointerId = e.pointerId;
    target.setPointerCapture(e.pointerId);
    startX = e.clientX;
    startY = e.clientY;
    const p = local(e);
    const handle = sim.bodyAt(p.x, p.y);
    onEmpty = handle < 0;
    if (!onEmpty) sim.beginDrag(handle, p.x, p.y);
    e.preventDefault();
  });

  target.addEventListener('pointermove', (e) => {
    if (e.pointerId !== pointerId || onEmpty) return;
    const p = local(e);
    sim.moveDrag(p.x, p.y);
  });

  const finish = (e: PointerEvent, cancelled: boolean) => {
    if (e.pointerId !== pointerId) return;
    pointerId = -1;
    if (!onEmpty) {
      sim.endDrag();
      return;
    }
    const moved = Math.hypot(e.clientX - startX, e.clientY - startY);
    if (cancelled || moved > CLICK_SLOP) return;
    const p = local(e);
    const box = sim.box;
    if (p.x < 0 || p.y < 0 || p.x > box.width || p.y > box.height) return;
    sim.spawn(p.x, p.y, spawnRadius());
    onSpawn();
  };
  target.addEventListener('pointerup', (e) => finish(e, false));
  target.addEventListener('pointercancel', (e) => finish(e, true));
}
