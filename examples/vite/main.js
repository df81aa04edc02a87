import { World } from '@maxgrid/engine';

const STEPS = 120;

/** A few thousand circles in a box, from a seeded random sequence: the same world every time. */
function circles() {
  const world = new World({ bounds: { width: 200, height: 200 }, broadphase: 'maxgrid' });
  let seed = 1;
  const random = () => (seed = (seed * 16807) % 2147483647) / 2147483647;
  for (let i = 0; i < 4000; i++) {
    world.createCircle({ x: 2 + random() * 196, y: 2 + random() * 196, radius: 0.4 + random() * 0.6, vx: random() * 20 - 10, vy: random() * 20 - 10 });
  }
  return world;
}

async function main() {
  const threaded = circles();
  // Vite finds the engine's worker script itself. minBodies: 0 and adaptive: false make a world
  // this small step on both threads anyway; by default it would stay on one, which is faster here.
  await threaded.startWorkers(2, { minBodies: 0, adaptive: false });
  const single = circles();
  for (let i = 0; i < STEPS; i++) {
    threaded.step(1 / 60);
    single.step(1 / 60);
  }
  // The engine promises the same bits on any number of threads.
  return {
    threads: threaded.backend.threads,
    lastStepThreads: threaded.backend.lastStepThreads,
    stateHash: threaded.stateHash(),
    sameAsOneThread: threaded.stateHash() === single.stateHash(),
  };
}

const out = document.getElementById('result');
main().then(
  (result) => (out.textContent = JSON.stringify(result, null, 2)),
  (error) => (out.textContent = JSON.stringify({ error: String(error?.message ?? error) }, null, 2)),
);
