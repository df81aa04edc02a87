// The engine's worker script, which cannot take the step's shared buffers: a worker failing
// between commands, for parallel.test.ts. Loads the compiled engine, as every worker thread does.
import { ThreadKernels } from '../../dist/parallel/kernels.js';

ThreadKernels.prototype.install = function install() {
  throw new Error('buffers refused on purpose');
};
await import('../../dist/parallel/worker-entry.js');
