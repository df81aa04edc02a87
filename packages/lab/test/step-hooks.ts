import type { ShapeEngine } from '../src/shape-engines/adapter.js';

/**
 * `real`'s simulation under another id, with `onStep` called before each of its steps: for the
 * timing tests, which log the order engines step in or move a fake clock.
 */
export function hookedEngine(real: ShapeEngine, id: string, onStep: () => void): ShapeEngine {
  return {
    info: { ...real.info, id },
    create: (scene, profile) => {
      const sim = real.create(scene, profile);
      return {
        count: sim.count,
        step: (dt) => {
          onStep();
          sim.step(dt);
        },
        read: (p) => sim.read(p),
        dispose: () => sim.dispose(),
      };
    },
  };
}

/** Runs `run` with performance.now reading `clock.t`, which only the hooked engines' steps move. */
export async function withClock<T>(clock: { t: number }, run: () => Promise<T>): Promise<T> {
  const realNow = performance.now;
  performance.now = () => clock.t;
  try {
    return await run();
  } finally {
    performance.now = realNow;
  }
}
