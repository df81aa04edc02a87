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
  Worker?: unknown;
  SharedArrayBuffer?: unknown;
  crossOriginIsolated?: boolean;
  location?: { href: string };
};

// A browser's Worker, named as a free variable: bundlers only recognise `new Worker(...)` itself.
declare const Worker: new (url: string | URL, options: { type: 'module' }) => BrowserWorker;

/**
 * Where a worker thread's script is (startWorkers' `workerUrl`): a URL, or a string (in a browser
 * resolved against the page; in Node a path or a file: URL, as worker_threads takes it).
 */
export type WorkerScript = string | { readonly href: string };

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
 * The worker script beside this module, for Node. Run from TypeScript sources (tests, tsx), Node
 * threads load the compiled twin in dist/, because a bare worker thread cannot load TypeScript.
 * `here` is a variable so that bundlers do not take this for an asset to emit.
 */
function nodeWorkerUrl(): URL {
  const here = import.meta.url;
  // The path, not the whole URL: a loader may add a query (`?t=...`) after the extension.
  return new URL(here).pathname.endsWith('.ts') ? new URL('../../dist/parallel/worker-entry.js', here) : new URL('./worker-entry.js', here);
}

/**
 * A module Web Worker on `script`, or on the engine's own worker script. The default is written
 * out in full, as one expression with a literal path, because that is the form Vite and webpack
 * recognise: they emit the worker script as a chunk of its own and rewrite the URL to it (and
 * Vite, serving TypeScript sources, finds worker-entry.ts for the .js). Unbundled, it is the
 * file beside this one.
 */
function browserWorker(script: WorkerScript | undefined): BrowserWorker {
  if (script !== undefined) return new Worker(typeof script === 'string' ? script : script.href, { type: 'module' });
  return new Worker(new URL('./worker-entry.js', import.meta.url), { type: 'module' });
}

/** Why a browser worker did not start, naming the script and what to do about it. */
function browserStartFailure(script: WorkerScript | undefined, detail: string | undefined): string {
  const because = detail ? `: ${detail}` : '';
  if (script !== undefined) {
    return `worker thread failed to start: the browser could not load or run the worker script ${absolute(typeof script === 'string' ? script : script.href)}${because}. startWorkers(n, { workerUrl }) must name the engine's worker script (@maxgrid/engine/worker) as your build emits and serves it`;
  }
  const here = import.meta.url;
  return (
    `worker thread failed to start: the browser could not load or run the engine's worker script ${absolute(new URL('./worker-entry.js', here).href)} ` +
    `(beside ${here}, the module that started it)${because}. Vite 8 and webpack 5 emit it by themselves (Vite 7's dev server does not: add ` +
    "optimizeDeps: { exclude: ['@maxgrid/engine'] } to vite.config); with a bundler that does not (esbuild, for one), " +
    'build @maxgrid/engine/worker as an entry point of its own and pass its URL: startWorkers(n, { workerUrl })'
  );
}

/** `url` resolved against the page, as a Worker resolves it; as given where it does not parse. */
function absolute(url: string): string {
  try {
    return new URL(url, host.location?.href).href;
  } catch {
    return url;
  }
}

// Variables, not literals, so that bundlers for the browser leave the Node-only imports alone.
const WORKER_THREADS = 'node:worker_threads';
const OS = 'node:os';

/** Logical cores this process may run on, or 0 where the host does not say. */
export async function hardwareThreads(): Promise<number> {
  if (isNode) {
    const os = (await import(/* @vite-ignore */ /* webpackIgnore: true */ OS)) as { availableParallelism?: () => number; cpus(): unknown[] };
    return os.availableParallelism?.() ?? os.cpus().length;
  }
  return (globalThis as { navigator?: { hardwareConcurrency?: number } }).navigator?.hardwareConcurrency ?? 0;
}

/**
 * How long a thread that finished its share polls for the next command before it sleeps, in
 * microseconds. Commands inside a step usually follow each other within that time, and waking a
 * sleeping worker (Atomics.waitAsync) costs each stage: long polling cuts the time between the
 * threads' work and the next stage to a fraction of what a short spin leaves, while whole steps,
 * polling on and off in paired rounds, stay within the host's noise (docs/engine.md, Numbers).
 * Polling holds a core, though, so where threads outnumber cores (or the count is unknown) it
 * stays a short count of polls: there, long polling makes steps several times slower.
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
 * Starts a worker on `script` (by default the engine's worker-entry.js), sends it `init` and
 * resolves once it answers that it is ready. Node workers are unref'd: a world that is never
 * stopped does not keep the process alive. A worker that fails later, in a step, says so through
 * the control block (worker-entry.ts's recordFailure), not in a message: the thread that started
 * it is inside that step and takes no messages until it ends.
 */
export async function startWorker(init: unknown, script?: WorkerScript): Promise<WorkerHandle> {
  if (isNode) {
    const { Worker } = (await import(/* @vite-ignore */ /* webpackIgnore: true */ WORKER_THREADS)) as { Worker: new (url: string | URL) => NodeWorker };
    const worker = new Worker(script === undefined ? nodeWorkerUrl() : typeof script === 'string' ? script : new URL(script.href));
    await new Promise<void>((resolve, reject) => {
      worker.on('message', (message: { kind?: string }) => {
        if (message.kind === 'ready') resolve();
      });
      worker.on('error', (error: Error) => reject(error));
      worker.postMessage(init);
    });
    worker.unref();
    return worker;
  }
  const worker = browserWorker(script);
  await new Promise<void>((resolve, reject) => {
    worker.onmessage = (event) => {
      if ((event.data as { kind?: string }).kind === 'ready') resolve();
    };
    // A script that could not be fetched fires a bare Event; one that threw, an ErrorEvent with a message.
    worker.onerror = (event) => reject(new Error(browserStartFailure(script, event.message)));
    worker.postMessage(init);
  });
  return worker;
}
