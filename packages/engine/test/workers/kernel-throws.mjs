// The engine's worker script, whose kernels throw on every command they run: a worker's share of
// a step failing, for parallel.test.ts. Loads the compiled engine, as every worker thread does.
import { ThreadKernels } from '../../dist/parallel/kernels.js';

ThreadKernels.prototype.run = function run() {
  throw new Error('a kernel failed on purpose');
};
await import('../../dist/parallel/worker-entry.js');
