/**
 * mulberry32: a 32-bit seeded generator, small and fast, good enough to scatter circles. Scenes
 * never call Math.random, so a (scene, params, seed) triple always builds the same bits.
 */
export class Prng {
  private state: number;

  /** A generator whose sequence depends only on the low 32 bits of `seed`. */
  constructor(seed: number) {
    this.state = seed >>> 0;
  }

  /** Uniform in [0, 1). */
  next(): number {
    this.state = (this.state + 0x6d2b79f5) | 0;
    let t = this.state;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  }

  /** Uniform in [min, max). */
  range(min: number, max: number): number {
    return min + (max - min) * this.next();
  }

  /**
   * A direction uniform on the circle, as [x, y] with x^2 + y^2 = 1 to round-off. Drawn by
   * rejection from the unit disc and normalised with Math.sqrt, never with Math.sin/cos: those
   * round differently across JavaScript engines (Node 20 and Chromium 156 disagree), and a scene
   * must be the same bits everywhere so that runs can be compared across runtimes.
   */
  direction(): [number, number] {
    for (;;) {
      const x = 2 * this.next() - 1;
      const y = 2 * this.next() - 1;
      const lengthSq = x * x + y * y;
      if (lengthSq > 1e-12 && lengthSq <= 1) {
        const length = Math.sqrt(lengthSq);
        return [x / length, y / length];
      }
    }
  }

  /**
   * Log-uniform in [min, max): min * (max / min)^u. The power is built from u's first 30 binary
   * digits and repeated square roots, because Math.pow, like sin and cos, may round differently
   * from one JavaScript engine to another while Math.sqrt may not.
   */
  logRange(min: number, max: number): number {
    let u = this.next();
    let factor = 1;
    let root = max / min;
    for (let bit = 0; bit < 30; bit++) {
      root = Math.sqrt(root);
      u *= 2;
      if (u >= 1) {
        factor *= root;
        u -= 1;
      }
    }
    return min * factor;
  }

  /** `mean` varied by up to +-`noise` of itself, as the report's sliders do (5.8). */
  noisy(mean: number, noise: number): number {
    return mean * (1 + noise * (2 * this.next() - 1));
  }
}
