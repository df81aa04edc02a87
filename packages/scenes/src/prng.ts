/**
 * mulberry32: a 32-bit seeded generator, small and fast, good enough to scatter circles. Scenes
 * never call Math.random, so a (scene, params, seed) triple always builds the same bits.
 */
export class Prng {
  private state: number;

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

  /** `mean` varied by up to +-`noise` of itself, as the report's sliders do (5.8). */
  noisy(mean: number, noise: number): number {
    return mean * (1 + noise * (2 * this.next() - 1));
  }
}
