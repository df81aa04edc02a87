/**
 * The slice of the WebAssembly API the kernels use, typed locally: the engine compiles against
 * plain ES2022, whose lib has no WebAssembly declarations.
 */
export interface KernelMemory {
  // ArrayBufferLike, which includes SharedArrayBuffer where the lib has it: naming it would fail
  // the declarations of a consumer compiling for an older target.
  readonly buffer: ArrayBufferLike;
  grow(pages: number): number;
}

interface WebAssemblyApi {
  Memory: new (descriptor: { initial: number; maximum?: number; shared?: boolean }) => KernelMemory;
  Module: new (bytes: Uint8Array) => object;
  Instance: new (module: object, imports: object) => { exports: unknown };
}

export const PAGE_BYTES = 65536;

/** This runtime's WebAssembly, or null where it has none (the TypeScript paths then serve). */
export function webAssembly(): WebAssemblyApi | null {
  return (globalThis as { WebAssembly?: WebAssemblyApi }).WebAssembly ?? null;
}

/**
 * Compiles kernel bytes synchronously, or gives null where that fails (no WebAssembly, or no
 * threads for a shared-memory module). Chromium compiles up to 8 MB synchronously on a page's
 * main thread (tried with Chromium 156: 4 MB compiles, 9 MB is refused); the kernels are 1-4 KB.
 */
export function compileKernel(bytes: Uint8Array): object | null {
  const api = webAssembly();
  if (api === null) return null;
  try {
    return new api.Module(bytes);
  } catch {
    return null;
  }
}

/** An instance of `module` over `memory`, its exports typed by the caller. */
export function instantiateKernel<T>(module: object, memory: KernelMemory): T {
  return new (webAssembly()!).Instance(module, { env: { memory } }).exports as T;
}
