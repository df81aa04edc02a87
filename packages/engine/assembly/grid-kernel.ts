// AssemblyScript source of the Max Grid's WebAssembly kernel (compiled by scripts/build-kernel.mjs
// into src/generated/, loaded by src/broadphase/grid-kernel.ts). It is CellGrid.bin and
// CellGrid.scanRows operation for operation, on arrays the caller lays out in the imported memory
// and passes as byte offsets, so its pairs, and every result downstream, are the same bits as the
// TypeScript path's.
//
// Why WebAssembly for these two loops: in V8's optimized code every typed-array access inside a
// loop re-checks the array's map, base pointer and length (nothing is hoisted; seen with
// --print-opt-code), which leaves them well behind the same loops in C; here the memory base
// stays in a register and bounds are checked by guard pages, and both loops run close to C
// (measured against TypeScript and C: docs/engine.md, Numbers). The scan also avoids loop-exit
// mispredictions (see pushOverlaps). SIMD is not used: the scan examines about 2.1 pairs per
// body (137,000 per step at 64,000 bodies) in ranges of 0 to 3 bodies, so branches rather than
// arithmetic bound it. Tried: one f64x2 test for each range's two-body head, with the scalar tests
// only when a lane hits. It saved a few per cent of the scan alone and less of a step, not worth
// a module that fails to compile where SIMD is missing.
//
// The entry module only gathers the kernel's exports; the code lives in assembly/grid/.

export { examined } from './grid/scan';
export { jumps } from './grid/bin';
export { candidates } from './grid/scan';
export { bin, binBanded, bandCounts, partition, sortBand } from './grid/bin';
export { cellsOf, countCells, scatterCells } from './grid/parallel-bin';
export { scan, scanWindow } from './grid/scan';
