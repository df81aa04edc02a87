/**
 * Maps the world region (the box, or an open scene's region) onto a canvas, keeping its aspect
 * ratio and centring it. All canvases of the stage share one transform, so the overlay lines up
 * with either renderer.
 */
export class ViewTransform {
  /** Device pixels per world unit. */
  scale = 1;
  offsetX = 0;
  offsetY = 0;
  /** Canvas size in device pixels. */
  width = 1;
  height = 1;
  /** Device pixels per CSS pixel. */
  dpr = 1;

  fit(cssWidth: number, cssHeight: number, dpr: number, boxWidth: number, boxHeight: number, boxX = 0, boxY = 0): boolean {
    const width = Math.max(1, Math.round(cssWidth * dpr));
    const height = Math.max(1, Math.round(cssHeight * dpr));
    const scale = Math.min(width / boxWidth, height / boxHeight);
    const offsetX = (width - boxWidth * scale) / 2 - boxX * scale;
    const offsetY = (height - boxHeight * scale) / 2 - boxY * scale;
    const changed = width !== this.width || height !== this.height || scale !== this.scale || dpr !== this.dpr || offsetX !== this.offsetX || offsetY !== this.offsetY;
    this.width = width;
    this.height = height;
    this.dpr = dpr;
    this.scale = scale;
    this.offsetX = offsetX;
    this.offsetY = offsetY;
    return changed;
  }

  /** World coordinates of a point given in CSS pixels relative to the canvas. */
  toWorldX(cssX: number): number {
    return (cssX * this.dpr - this.offsetX) / this.scale;
  }

  toWorldY(cssY: number): number {
    return (cssY * this.dpr - this.offsetY) / this.scale;
  }
}
