// The scenes whose state hashes every JavaScript engine must agree on (runtimes.test.ts, and the
// Firefox test in apps/sandbox): plain JavaScript over the built packages, so that every runtime
// runs the same code. `engine` and `scenes` are the two packages' modules, as each runtime loads them.
export function sceneHashes(engine, scenes) {
  const { World } = engine;
  const { buildScene, buildWorld, buildShapeScene, buildShapeWorld } = scenes;
  const cases = [
    ['uniform, maxgrid', () => buildWorld(buildScene('uniform', { n: 2000, seed: 5 }), { broadphase: 'maxgrid' })],
    ['uniform, sap', () => buildWorld(buildScene('uniform', { n: 2000, seed: 5 }), { broadphase: 'sap' })],
    ['uniform, hgrid', () => buildWorld(buildScene('uniform', { n: 2000, seed: 5 }), { broadphase: 'hgrid' })],
    ['seed-box, explicit Euler', () => buildWorld(buildScene('seed-box', { n: 1500, seed: 2 }), { integrator: 'explicit-euler' })],
    ['pyramid', () => buildShapeWorld(buildShapeScene('pyramid', { base: 20 }))],
    ['polygon-box', () => buildShapeWorld(buildShapeScene('polygon-box', { n: 400 }))],
    ['ragdolls', () => buildShapeWorld(buildShapeScene('ragdolls', { count: 8 }))],
    ['car', () => buildShapeWorld(buildShapeScene('car', { bumps: 5 }))],
    ['blobs', () => buildShapeWorld(buildShapeScene('blobs', { count: 4 }))],
    ['jellies, force springs, rk4', () => buildShapeWorld(buildShapeScene('jellies', { count: 3, side: 4, stiffness: 800 }), { integrator: 'rk4' })],
    [
      'turned circles with torque',
      () => {
        const world = new World({ gravity: { x: 0, y: 10 }, bounds: { width: 100, height: 100 } });
        for (let k = 0; k < 50; k++) world.createCircle({ x: 10 + k, y: 20 + (k % 7), radius: 0.4, angle: k / 3, angularVelocity: k / 5 });
        return world;
      },
    ],
  ];
  const hashes = {};
  for (const [name, build] of cases) {
    const world = build();
    let restored = null;
    let snapshot = '';
    for (let s = 0; s < 150; s++) {
      if (s === 75) {
        // Taken halfway, restored here and stepped on: the bytes themselves must agree across runtimes too.
        const bytes = world.snapshot();
        snapshot = `${bytes.length}:${new DataView(bytes.buffer, bytes.byteOffset).getUint32(12, true).toString(16)}`;
        restored = World.restore(bytes);
      }
      world.step(1 / 60);
      if (restored) restored.step(1 / 60);
    }
    const b = world.backend;
    hashes[name] = { hash: world.stateHash(), restored: restored.stateHash(), snapshot, kernels: b.softStepKernel.running || b.gridKernel.running || b.bodyKernel.running };
  }
  return hashes;
}
