// AssemblyScript source of the Max Grid's WebAssembly kernel (compiled by scripts/build-kernel.mjs
// into src/generated/, loaded by src/broadphase/grid-kernel.ts). It is CellGrid.bin and
// CellGrid.scanRows operation for operation, on arrays the caller lays out in the imported memory
// and passes as byte offsets, so its pairs, and every result downstream, are the same bits as the
// TypeScript path's.
//
// Why WebAssembly for these two loops: in V8's optimized code every typed-array access inside a
// loop re-checks the array's map, base pointer and length (nothing is hoisted; seen with
// --print-opt-code), which made them about 2x the same loops in C; here the memory base stays in
// a register and bounds are checked by guard pages.
// Measured at 64,000 bodies: bin 1.6-1.7 ms in TS, 0.9 in WebAssembly; scan 2.6-3.1 ms against
// 1.8-2.1 (C: bin 0.7-0.8, scan 1.6-1.9); the scan then lost its loop-exit mispredictions (see
// pushOverlaps) and takes 1.06-1.16. SIMD is not used: the scan examines about 2.1 pairs per
// body (137,000 per step at 64,000 bodies) in ranges of 0 to 3 bodies, so branches rather than
// arithmetic bound it. Tried: one f64x2 test for each range's two-body head, with the scalar tests
// only when a lane hits. The scan alone took 0.95-0.96x as long (64k and 1M, same pairs), about
// 2 % of a step, not worth a module that fails to compile where SIMD is missing.
//
// The entry module only gathers the kernel's exports; the code lives in assembly/grid/.

export { examined } from './grid/scan';
export { jumps } from './grid/bin';
export { candidates } from './grid/scan';
export { bin, binBanded, bandCounts, partition, sortBand } from './grid/bin';
export { cellsOf, countCells, scatterCells } from './grid/parallel-bin';
export { scan, scanWindow } from './grid/scan';
