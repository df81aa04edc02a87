import { nowMs } from '../util/timer.js';

/**
 * Starting worker threads, in Node (worker_threads) and in browsers (module Web Workers), without
 * pulling either platform's typings into the engine: the few members used are declared here.
 */

// Declared rather than taken from DOM or Node typings, which a dependency-free library does not load.
declare const URL: new (url: string, base?: string) => { readonly href: string; readonly pathname: string };
type URL = InstanceType<typeof URL>;
declare global {
  interface ImportMeta {
    url: string;
  }
}

export interface WorkerHandle {
  postMessage(message: unknown): void;
  terminate(): void;
}

interface NodeWorker extends WorkerHandle {
  on(event: 'message' | 'error', listener: (value: never) => void): void;
  unref(): void;
}

interface BrowserWorker extends WorkerHandle {
  onmessage: ((event: { data: unknown }) => void) | null;
  onerror: ((event: { message?: string }) => void) | null;
}

type Global = {
  process?: { versions?: { node?: string } };
  Worker?: new (url: URL, options: { type: 'module' }) => BrowserWorker;
  SharedArrayBuffer?: unknown;
  crossOriginIsolated?: boolean;
};

const host = globalThis as unknown as Global;

export const isNode = typeof host.process?.versions?.node === 'string';

/** Whether this thread may block in Atomics.wait: not a browser's main thread. */
export const canBlock = isNode;

/** Why threads cannot start here, or null when they can. */
export function threadsUnavailable(): string | null {
  if (typeof host.SharedArrayBuffer !== 'function') {
    return 'SharedArrayBuffer is unavailable: a browser page must be cross-origin isolated (serve it with Cross-Origin-Opener-Policy: same-origin and Cross-Origin-Embedder-Policy: require-corp)';
  }
  if (!isNode && typeof host.Worker !== 'function') return 'this environment has no Worker';
  return null;
}

/**
 * The worker script beside this module. Run from TypeScript sources (tests, tsx, a Vite dev
 * server), Node threads load the compiled twin in dist/, because a bare worker thread cannot load
 * TypeScript; a browser asks the dev server, which compiles the source on request.
 */
function workerUrl(): URL {
  const here = import.meta.url;
  // The path, not the whole URL: a dev server may add a query (`?t=...`) after the extension.
  if (!new URL(here).pathname.endsWith('.ts')) return new URL('./worker-entry.js', here);
  return isNode ? new URL('../../dist/parallel/worker-entry.js', here) : new URL('./worker-entry.ts', here);
}

// Variables, not literals, so that bundlers for the browser leave the Node-only imports alone.
const WORKER_THREADS = 'node:worker_threads';
const OS = 'node:os';

/** Logical cores this process may run on, or 0 where the host does not say. */
export async function hardwareThreads(): Promise<number> {
  if (isNode) {
    const os = (await import(/* @vite-ignore */ OS)) as { availableParallelism?: () => number; cpus(): unknown[] };
    return os.availableParallelism?.() ?? os.cpus().length;
  }
  return (globalThis as { navigator?: { hardwareConcurrency?: number } }).navigator?.hardwareConcurrency ?? 0;
}

/**
 * How long a thread that finished its share polls for the next command before it sleeps, in
 * microseconds. Commands inside a step follow each other within about a millisecond, and waking
 * a sleeping worker (Atomics.waitAsync) costs each stage: 1M bodies on 2 threads spent 0.85-1.1 ms
 * a step (five stages) between the threads' work and the next stage with a 2,000-poll spin, and
 * 0.10-0.14 ms with long polling; whole-step medians, polling on and off in paired rounds, stayed
 * within the host's noise (43.0/44.3, 43.9/44.3, 44.7/48.8, 46.8/43.0 ms). Polling holds a core, though, so where threads
 * outnumber cores (or the count is unknown) it stays a short count of polls: 3 threads on 2 cores
 * at 20k bodies stepped in 20.6 ms with 20,000 polls, 4.2 with 2,000.
 */
export function spinBudget(threads: number, cores: number): number {
  return cores > 0 && threads <= cores ? SPIN_MICROSECONDS : 0;
}

const SPIN_MICROSECONDS = 1000;

/**
 * Polls array[index] while it equals `value`, for at most `micros` microseconds; true once it
 * differs. The clock is read once per 256 polls.
 */
export function spinWhileEqual(array: Int32Array, index: number, value: number, micros: number): boolean {
  if (micros <= 0) return Atomics.load(array, index) !== value;
  const deadline = nowMs() + micros / 1000;
  for (;;) {
    for (let k = 0; k < 256; k++) if (Atomics.load(array, index) !== value) return true;
    if (nowMs() > deadline) return false;
  }
}

/**
 * Starts a worker, sends it `init` and resolves once it answers that it is ready. Node workers are
 * unref'd: a world that is never stopped does not keep the process alive.
 */
export async function startWorker(init: unknown): Promise<WorkerHandle> {
  const url = workerUrl();
  if (isNode) {
    const { Worker } = (await import(/* @vite-ignore */ WORKER_THREADS)) as { Worker: new (url: URL) => NodeWorker };
    const worker = new Worker(url);
    await new Promise<void>((resolve, reject) => {
      worker.on('message', (message: { kind?: string; error?: string }) => {
        if (message.kind === 'ready') resolve();
        if (message.kind === 'failed') reject(new Error(`worker thread failed: ${message.error}`));
      });
      worker.on('error', (error: Error) => reject(error));
      worker.postMessage(init);
    });
    worker.unref();
    return worker;
  }
  const worker = new host.Worker!(url, { type: 'module' });
  await new Promise<void>((resolve, reject) => {
    worker.onmessage = (event) => {
      const message = event.data as { kind?: string; error?: string };
      if (message.kind === 'ready') resolve();
      if (message.kind === 'failed') reject(new Error(`worker thread failed: ${message.error}`));
    };
    worker.onerror = (event) => reject(new Error(`worker thread failed to start: ${event.message ?? 'unknown error'}`));
    worker.postMessage(init);
  });
  return worker;
}
