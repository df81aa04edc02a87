import { Worker } from 'node:worker_threads';
import type { HostScaling } from '../experiments/common.js';

// Each worker runs one kernel on request and answers with its time in ms. Plain JavaScript, in a
// string: the probe must not depend on the engine whose scaling it puts in context.
const WORKER_SOURCE = `
const { parentPort } = require('node:worker_threads');
let column = null;
parentPort.on('message', (m) => {
  const t = performance.now();
  let sink = 0;
  if (m.kind === 'compute') {
    // A dependent chain of multiply-adds: registers only, no memory traffic.
    let a = 1.0001, b = 0.9999;
    for (let i = 0; i < m.iterations; i++) { a = a * b + 1e-9; b = b * a - 1e-9; }
    sink = a + b;
  } else {
    if (column === null || column.length !== m.doubles) column = new Float64Array(m.doubles).fill(1);
    // One double per 64-byte line: every load is a fresh cache line.
    for (let pass = 0; pass < m.passes; pass++) for (let i = 0; i < column.length; i += 8) sink += column[i];
  }
  parentPort.postMessage({ ms: performance.now() - t, sink });
});`;

/** How much work each probe does; the defaults take about a second in all on this machine. */
export interface HostScalingOptions {
  /** Iterations of the compute chain (about 5 ns each). */
  iterations: number;
  /** Doubles each thread streams: 16M is 128 MiB, past the shared L3 together. */
  doubles: number;
  passes: number;
  /** Alternations of 1 and 2 threads; the ratio is the median over them. */
  rounds: number;
}

export const DEFAULT_HOST_SCALING: HostScalingOptions = { iterations: 20_000_000, doubles: 16 * 1024 * 1024, passes: 2, rounds: 3 };

/**
 * How much faster two threads get through twice the work of one, right now: for a compute-bound
 * kernel and for a memory-bound one. 2 is perfect scaling. On a shared host the memory figure
 * moves with what other tenants do; read next to T4, it says whether a low speed-up came from
 * the engine or from the machine.
 */
export async function measureHostScaling(options: HostScalingOptions = DEFAULT_HOST_SCALING): Promise<HostScaling> {
  const workers = [new Worker(WORKER_SOURCE, { eval: true }), new Worker(WORKER_SOURCE, { eval: true })];
  const run = (worker: Worker, message: object) =>
    new Promise<number>((resolve, reject) => {
      const done = (reply: { ms: number }) => {
        worker.off('error', failed);
        resolve(reply.ms);
      };
      const failed = (error: Error) => {
        worker.off('message', done);
        reject(error);
      };
      worker.once('message', done);
      worker.once('error', failed);
      worker.postMessage(message);
    });
  const ratio = async (message: object): Promise<number> => {
    // One untimed round each way: allocates the columns and warms the JIT.
    await run(workers[0], message);
    await Promise.all(workers.map((w) => run(w, message)));
    const ratios: number[] = [];
    for (let round = 0; round < options.rounds; round++) {
      const one = await run(workers[0], message);
      const both = await Promise.all(workers.map((w) => run(w, message)));
      ratios.push((2 * one) / Math.max(...both));
    }
    ratios.sort((a, b) => a - b);
    return ratios[ratios.length >> 1];
  };
  try {
    const compute = await ratio({ kind: 'compute', iterations: options.iterations });
    const memory = await ratio({ kind: 'memory', doubles: options.doubles, passes: options.passes });
    return { compute, memory };
  } finally {
    await Promise.all(workers.map((w) => w.terminate()));
  }
}
