/**
 * Seeded PRNG (mulberry32). The 3D page's layouts come from here, never from Math.random, so the
 * same seed always builds the same stack and the three experiment variants start from the very
 * same cubes: any difference in their step times then comes from the technique, not the layout.
 */
export type Rng = () => number;

export function mulberry32(seed: number): Rng {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** Uniform in [-half, half]. */
export function jitter(rng: Rng, half: number): number {
  return (rng() * 2 - 1) * half;
}
