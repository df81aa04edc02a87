// Prints the state hashes of scene-hash-cases.mjs as JSON, for runtimes.test.ts to run under Node
// and Bun; `--no-wasm` removes WebAssembly first, so that the TypeScript paths run.
if (process.argv.includes('--no-wasm')) delete globalThis.WebAssembly;
const { sceneHashes } = await import('./scene-hash-cases.mjs');
console.log(JSON.stringify(sceneHashes(await import('../../dist/index.js'), await import('../../../scenes/dist/index.js'))));
