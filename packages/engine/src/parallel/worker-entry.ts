/**
 * A worker thread of a parallel step. It idles in Atomics.waitAsync, so its event loop stays free
 * to receive new buffers, runs each command the caller publishes on its share, and counts itself
 * done. See control.ts for the protocol and kernels.ts for the work.
 */
import { Command, ERROR_TEXT, Slot, type BufferMessage, type InitMessage } from './control.js';
import { workerKernels, type ThreadKernels } from './kernels.js';
import { isNode, spinWhileEqual } from './host.js';

type Post = (message: unknown) => void;
type WaitAsync = (array: Int32Array, index: number, value: number) => { async: boolean; value: Promise<string> | string };

/** Polls before sleeping, besides the caller's time budget (Slot.spinMicroseconds, see spinBudget in host.ts). */
const SPIN = 2_000;

const waitAsync = (Atomics as unknown as { waitAsync: WaitAsync }).waitAsync;

let kernels: ThreadKernels | null = null;
/** This worker's thread index (1 and up; the caller is 0). */
let index = 0;
let epoch = 0;
let epochWaiter: (() => void) | null = null;
let post: Post = () => {};

function receive(message: InitMessage | BufferMessage): void {
  if (message.kind === 'init') {
    index = message.index;
    kernels = workerKernels(message.index, new Int32Array(message.control), new Float64Array(message.params), new Float64Array(message.results));
    // The command count is read before answering: once the caller hears "ready" it may publish at
    // any moment, and a count read after that could already include the first command, which
    // this worker would then wait past forever.
    void serve(kernels, Atomics.load(kernels.control, Slot.seq));
    post({ kind: 'ready' });
    return;
  }
  try {
    kernels!.install(message);
    kernels!.bindContactList();
  } catch (error) {
    // The caller waits on the sync command for this epoch: it ends, and the step fails with this.
    recordFailure(kernels!.control, error);
  }
  epoch = message.epoch;
  epochWaiter?.();
}

async function nextCommand(control: Int32Array, seen: number): Promise<void> {
  for (let spin = 0; spin < SPIN; spin++) if (Atomics.load(control, Slot.seq) !== seen) return;
  if (spinWhileEqual(control, Slot.seq, seen, control[Slot.spinMicroseconds])) return;
  while (Atomics.load(control, Slot.seq) === seen) {
    const wait = waitAsync(control, Slot.seq, seen);
    if (wait.async) await wait.value;
  }
}

function epochReached(wanted: number): Promise<void> {
  if (epoch >= wanted) return Promise.resolve();
  return new Promise((resolve) => {
    epochWaiter = () => {
      if (epoch < wanted) return;
      epochWaiter = null;
      resolve();
    };
  });
}

async function serve(k: ThreadKernels, seen: number): Promise<void> {
  const control = k.control;
  for (;;) {
    await nextCommand(control, seen);
    seen = Atomics.load(control, Slot.seq);
    const command = control[Slot.command];
    if (command === Command.stop) return;
    try {
      if (command === Command.sync) await epochReached(control[Slot.epoch]);
      else {
        k.loadScalars();
        k.run(command);
      }
    } catch (error) {
      // The caller is waiting on DONE: leave the failure beside it, then count in as usual.
      recordFailure(control, error);
    }
    Atomics.add(control, Slot.done, 1);
    Atomics.notify(control, Slot.done);
  }
}

/**
 * Counts this worker as failed and, where it is the first, writes its index and error into the
 * control block, where the caller reads them once every worker is done (awaitWorkers). The
 * Atomics.add on DONE that follows publishes these plain writes.
 */
function recordFailure(control: Int32Array, error: unknown): void {
  if (Atomics.add(control, Slot.failed, 1) !== 0) return;
  const text = String((error as Error | null)?.stack ?? error);
  const length = Math.min(text.length, ERROR_TEXT);
  for (let i = 0; i < length; i++) control[Slot.errorText + i] = text.charCodeAt(i);
  control[Slot.errorLength] = length;
  control[Slot.failedWorker] = index;
}

// A variable, not a literal, so that bundlers for the browser leave the Node-only import alone.
const WORKER_THREADS = 'node:worker_threads';

type ParentPort = { on(event: 'message', listener: (message: InitMessage | BufferMessage) => void): void; postMessage: Post };

// No top-level await: bundlers build worker scripts as classic scripts by default (Vite's iife),
// which cannot hold one. Node queues the init message until the listener is on. Outside a worker
// thread (parentPort null) there is nothing to serve.
if (isNode) {
  void import(/* @vite-ignore */ /* webpackIgnore: true */ WORKER_THREADS).then(({ parentPort }: { parentPort: ParentPort | null }) => {
    if (!parentPort) return;
    post = (message) => parentPort.postMessage(message);
    parentPort.on('message', receive);
  });
} else {
  const self = globalThis as unknown as { onmessage: (event: { data: InitMessage | BufferMessage }) => void; postMessage: Post };
  post = (message) => self.postMessage(message);
  self.onmessage = (event) => receive(event.data);
}
