import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { SCENES, SHAPE_SCENES, buildWorld, buildShapeWorld } from '@maxgrid/scenes';
import { World, type ContactEventsView } from '../src/index.js';
import { setGridKernelEnabled } from '../src/broadphase/grid-kernel.js';
import { setBodyKernelEnabled } from '../src/store/body-kernel.js';
import { setSoftStepKernelEnabled } from '../src/solver/soft-step-kernel.js';
import { applyState, captureState } from '../src/snapshot/state-graph.js';

const DT = 1 / 60;

/** Small versions of every scene, so that each one's features (joints, rings, segments, sleep) are covered quickly. */
const SHAPE_PARAMS: Record<string, Record<string, number>> = {
  pyramid: { base: 20 },
  'many-pyramids': { rows: 2, columns: 2 },
  'joint-grid': { size: 12 },
  'uniform-polygons': { n: 300 },
  'polygon-box': { n: 300 },
  tumbler: { grid: 12 },
  ragdolls: { count: 8 },
  jellies: { count: 6 },
  blobs: { count: 6 },
};

const CASES: [string, () => World][] = [
  ...Object.keys(SCENES).map((name): [string, () => World] => {
    const scene = SCENES[name as keyof typeof SCENES];
    const params = 'n' in scene.params ? { n: 300 } : {};
    return [name, () => buildWorld(scene.build(params))];
  }),
  ...Object.keys(SHAPE_SCENES).map((name): [string, () => World] => [name, () => buildShapeWorld(SHAPE_SCENES[name as keyof typeof SHAPE_SCENES].build(SHAPE_PARAMS[name] ?? {}))]),
];

function stepped(make: () => World, steps: number): World {
  const world = make();
  for (let s = 0; s < steps; s++) world.step(DT);
  return world;
}

/** The state hash after each of `steps` steps. */
function trace(world: World, steps: number): string[] {
  const out: string[] = [];
  for (let s = 0; s < steps; s++) {
    world.step(DT);
    out.push(world.stateHash());
  }
  return out;
}

describe('snapshots', () => {
  it.each(CASES)('%s: a restored world steps to the same bits as the original, new or in place', (_name, make) => {
    const original = stepped(make, 25);
    const bytes = original.snapshot();
    const restored = World.restore(bytes);
    // In place, over a world that has gone elsewhere meanwhile.
    const inPlace = stepped(make, 40);
    inPlace.restore(bytes);
    expect(restored.stateHash()).toBe(original.stateHash());
    expect(inPlace.stateHash()).toBe(original.stateHash());
    const expected = trace(original, 40);
    expect(trace(restored, 40)).toEqual(expected);
    expect(trace(inPlace, 40)).toEqual(expected);
  });

  it.each(CASES)("%s: the bytes follow the state alone: reading calls leave them, a restored world gives them back and steps on to its original's", (_name, make) => {
    const original = stepped(make, 20);
    const bytes = original.snapshot();
    // Every call that reads the world, each filling what it answers with.
    original.views();
    original.jointViews();
    original.contactPoints();
    original.debugRender();
    original.queryPoint(0, 0);
    original.queryPoint(1, 1, { mask: 1 });
    original.queryAABB(-1e3, -1e3, 1e3, 1e3);
    original.rayCast(1e3, 1e3, -1e3, -1e3, { mask: 2 });
    original.rayCast(-1e3, -1e3, 1e3, 1e3);
    original.rayCastAll(-1e3, 1e3, 1e3, -1e3);
    original.stateHash();
    original.kineticEnergy();
    expect(original.snapshot()).toEqual(bytes);
    const restored = World.restore(bytes);
    expect(restored.snapshot()).toEqual(bytes);
    const inPlace = stepped(make, 35);
    inPlace.restore(bytes);
    expect(inPlace.snapshot()).toEqual(bytes);
    for (let s = 0; s < 30; s++) {
      original.step(DT);
      restored.step(DT);
      inPlace.step(DT);
    }
    const after = original.snapshot();
    expect(restored.snapshot()).toEqual(after);
    expect(inPlace.snapshot()).toEqual(after);
  });

  it('without the WebAssembly kernels too, and a snapshot crosses between the two', () => {
    const names = ['uniform', 'funnel', 'pyramid', 'bridge', 'blobs'];
    for (const [name, make] of CASES.filter(([n]) => names.includes(n))) {
      const withKernels = stepped(make, 20);
      const bytes = withKernels.snapshot();
      const expected = trace(withKernels, 30);
      setGridKernelEnabled(false);
      setBodyKernelEnabled(false);
      setSoftStepKernelEnabled(false);
      try {
        const plain = World.restore(bytes);
        expect(plain.backend.gridKernel.running || plain.backend.bodyKernel.running || plain.backend.softStepKernel.running, name).toBe(false);
        expect(trace(plain, 30), name).toEqual(expected);
        const back = stepped(make, 20);
        const plainBytes = back.snapshot();
        expect(plainBytes, `${name}: the same bytes without kernels`).toEqual(bytes);
        setGridKernelEnabled(true);
        setBodyKernelEnabled(true);
        setSoftStepKernelEnabled(true);
        expect(trace(World.restore(plainBytes), 30), `${name}, taken without kernels`).toEqual(expected);
      } finally {
        setGridKernelEnabled(true);
        setBodyKernelEnabled(true);
        setSoftStepKernelEnabled(true);
      }
    }
  });

  it('restored in place, a world takes every field, empty ones too: its options made with none, no joint events pending', () => {
    const same = (a: Uint8Array, b: Uint8Array): boolean => a.length === b.length && a.every((x, i) => x === b[i]);
    // A world made with no options, restored onto one made with others.
    const plain = new World({});
    plain.createBox({ x: 0, y: 0, width: 1, height: 1 });
    plain.step(1 / 60);
    const bytes = plain.snapshot();
    const target = new World({ gravity: { x: 0, y: 10 }, friction: 0.5 });
    target.restore(bytes);
    expect(same(target.snapshot(), bytes)).toBe(true);
    expect(World.restore(target.snapshot()).stateHash()).toBe(plain.stateHash());
    // Taken with no joint events pending, restored over a world that has one.
    const world = new World({ gravity: { x: 0, y: 10 } });
    const a = world.createBox({ x: 0, y: 0, width: 1, height: 1, type: 'static' });
    const b = world.createBox({ x: 0, y: 2, width: 1, height: 1 });
    const joint = world.createJoint({ kind: 'revolute', bodyA: a, bodyB: b, anchorA: { x: 0, y: 0 }, anchorB: { x: 0, y: -2 } });
    world.step(1 / 60);
    const saved = world.snapshot();
    const twin = World.restore(saved);
    world.destroyBody(b);
    world.restore(saved);
    expect(same(world.snapshot(), saved)).toBe(true);
    world.step(1 / 60);
    twin.step(1 / 60);
    expect(world.jointEvents().count).toBe(0);
    expect(world.hasJoint(joint)).toBe(true);
    expect(world.stateHash()).toBe(twin.stateHash());
  });

  it('handles: held ones stay valid, and the next bodies, shapes and joints get the same handles', () => {
    const make = CASES.find(([n]) => n === 'ragdolls')![1];
    const original = stepped(make, 10);
    const held = original.handles();
    // Holes in the slot lists, so that the free lists decide the next handles.
    original.destroyBody(held[3]);
    original.destroyBody(held[7]);
    original.destroyJoint(original.jointHandles()[2]);
    const bytes = original.snapshot();
    const other = stepped(make, 30);
    other.restore(bytes);
    for (const h of held.filter((_, i) => i !== 3 && i !== 7)) expect(other.getBody(h)).toEqual(original.getBody(h));
    expect(other.hasBody(held[3])).toBe(false);
    expect(other.jointHandles()).toEqual(original.jointHandles());
    const next = (w: World) => {
      const a = w.createBox({ x: 0, y: -5, width: 1, height: 1 });
      const b = w.createCircle({ x: 2, y: -5, radius: 0.5, friction: 0.5 });
      const j = w.createJoint({ kind: 'distance', bodyA: a, bodyB: b });
      return [a, b, j, w.getBody(a).shapes[0]];
    };
    expect(next(other)).toEqual(next(original));
    expect(trace(other, 20)).toEqual(trace(original, 20));
  });

  it('carries options, pending forces, sleep and events into the restored world', () => {
    const world = new World({ bounds: { width: 40, height: 40 }, gravity: { x: 0, y: -9 }, friction: 0.4, restitution: 0.2, contactEvents: true, sleeping: true, broadphase: 'sap' });
    world.createBox({ x: 20, y: 1, width: 40, height: 2, type: 'static' });
    const boxes = Array.from({ length: 6 }, (_, i) => world.createBox({ x: 10 + 3 * i, y: 4, width: 1, height: 1 }));
    for (let s = 0; s < 200; s++) world.step(DT);
    world.applyForce(boxes[0], 600, 0);
    world.setGravity(1, -9);
    const bytes = world.snapshot();
    const restored = World.restore(bytes);
    expect(restored.gravity).toEqual({ x: 1, y: -9 });
    expect(restored.broadphase).toBe('sap');
    expect(restored.friction).toBe(0.4);
    expect(restored.getBody(boxes[5]).awake).toBe(world.getBody(boxes[5]).awake);
    const events = (w: World) => {
      const e: ContactEventsView = w.contactEvents();
      return [e.shapeBeginCount, [...e.shapeBeginA.subarray(0, e.shapeBeginCount)], e.shapeEndCount, [...e.shapeEndA.subarray(0, e.shapeEndCount)]];
    };
    let reported = 0;
    for (let s = 0; s < 30; s++) {
      world.step(DT);
      restored.step(DT);
      expect(events(restored)).toEqual(events(world));
      reported += world.contactEvents().shapeBeginCount + world.contactEvents().shapeEndCount;
    }
    // The push sends the first box into the next: events to compare, not two empty lists.
    expect(reported).toBeGreaterThan(0);
    expect(restored.stateHash()).toBe(world.stateHash());
  });

  it('a world with worker threads snapshots, and its restored twin steps to the same bits', async () => {
    const make = () => buildWorld(SCENES.uniform.build({ n: 3000 }), { broadphase: 'maxgrid' });
    const world = make();
    await world.startWorkers(2, { minBodies: 0, adaptive: false });
    try {
      for (let s = 0; s < 10; s++) world.step(DT);
      const bytes = world.snapshot();
      const restored = World.restore(bytes);
      expect(restored.workerCount).toBe(1);
      expect(trace(restored, 20)).toEqual(trace(world, 20));
      // In place over the threaded world: its threads stop, the bits go on.
      const twin = World.restore(bytes);
      world.restore(bytes);
      expect(world.workerCount).toBe(1);
      expect(trace(world, 10)).toEqual(trace(twin, 10));
    } finally {
      world.stopWorkers();
    }
  });

  it('random call sequences: a snapshot taken anywhere in them restores to the same bits', () => {
    type Call = { op: number; a: number; b: number; c: number };
    const unit = fc.double({ min: 0, max: 1, noNaN: true });
    const calls = fc.array(fc.record({ op: fc.integer({ min: 0, max: 17 }), a: unit, b: unit, c: unit }), { minLength: 10, maxLength: 60 });
    const BROADS = ['naive', 'sap', 'sap-xy', 'maxgrid', 'hgrid', 'auto'] as const;
    /** One user call; a call the world refuses leaves it as it was, alike in every copy. */
    const apply = (w: World, { op, a, b, c }: Call) => {
      const handles = w.handles();
      const pick = handles.length ? handles[Math.floor(a * handles.length) % handles.length] : -1;
      const x = 5 + 50 * b;
      const y = 5 + 50 * c;
      try {
        if (op <= 3) for (let s = 0; s < 1 + op * 3; s++) w.step(DT);
        else if (op === 4) w.createCircle({ x, y, radius: 0.5 + a, vx: 10 * a - 5 });
        else if (op === 5) w.createBox({ x, y, width: 1 + a, height: 1, angle: 3 * c, friction: a });
        else if (op === 6) w.createCapsule({ x, y, length: 1, radius: 0.3, type: a < 0.2 ? 'static' : a < 0.3 ? 'kinematic' : 'dynamic', bullet: a > 0.9 });
        else if (op === 7) w.createCircle({ x, y, radius: 1, sensor: true, type: 'static' });
        else if (op === 8 && pick >= 0) w.destroyBody(pick);
        else if (op === 9 && handles.length > 1) w.createJoint({ kind: a < 0.5 ? 'distance' : 'revolute', bodyA: handles[0], bodyB: pick, ...(a < 0.25 ? { hertz: 3 } : {}) });
        else if (op === 10) w.setBroadphase(BROADS[Math.floor(a * BROADS.length) % BROADS.length]);
        else if (op === 11) w.setIntegrator(a < 0.4 ? 'explicit-euler' : a < 0.8 ? 'semi-implicit-euler' : 'rk4');
        else if (op === 12) w.setGravity(10 * a - 5, 10 * b);
        else if (op === 13 && pick >= 0) w.applyForce(pick, 100 * b - 50, 100 * c - 50);
        else if (op === 14) w.createSegment({ x1: x, y1: y, x2: x + 10, y2: y + 5 * a });
        else if (op === 15 && pick >= 0) w.setType(pick, a < 0.3 ? 'static' : a < 0.5 ? 'kinematic' : 'dynamic');
        else if (op === 16 && pick >= 0) w.setAwake(pick, a < 0.5);
        else if (op === 17 && w.jointCount > 0) w.destroyJoint(w.jointHandles()[Math.floor(a * w.jointCount) % w.jointCount]);
      } catch (error) {
        if (!(error instanceof RangeError || error instanceof TypeError)) throw error;
      }
    };
    fc.assert(
      fc.property(calls, fc.integer({ min: 0, max: 59 }), fc.boolean(), (sequence, at, boxed) => {
        const make = () => new World({ gravity: { x: 0, y: 9 }, ...(boxed ? { bounds: { width: 60, height: 60 } } : {}), contactEvents: at % 2 === 0, sleeping: true });
        const original = make();
        const cut = Math.min(at, sequence.length);
        for (const c of sequence.slice(0, cut)) apply(original, c);
        const bytes = original.snapshot();
        const restored = World.restore(bytes);
        const inPlace = make();
        inPlace.restore(bytes);
        for (const c of [...sequence.slice(cut), { op: 3, a: 0, b: 0, c: 0 }]) {
          apply(original, c);
          apply(restored, c);
          apply(inPlace, c);
          expect(restored.stateHash()).toBe(original.stateHash());
          expect(inPlace.stateHash()).toBe(original.stateHash());
        }
        expect(restored.handles()).toEqual(original.handles());
      }),
      { numRuns: 120, seed: 2312 },
    );
  });

  /** The byte offset of the one place `value` is stored, as a little-endian double. */
  function findDouble(bytes: Uint8Array, value: number): number {
    const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    const found: number[] = [];
    for (let i = 16; i + 8 <= bytes.length; i++) if (view.getFloat64(i, true) === value) found.push(i);
    expect(found).toHaveLength(1);
    return found[0];
  }

  /** Rewrites the format's hash: FNV-1a over the payload's little-endian 32-bit words, the last zero-padded. */
  function rehash(bytes: Uint8Array): void {
    let hash = 0x811c9dc5;
    const padded = new Uint8Array(Math.ceil((bytes.length - 16) / 4) * 4);
    padded.set(bytes.subarray(16));
    const words = new DataView(padded.buffer);
    for (let i = 0; i < padded.length; i += 4) hash = Math.imul(hash ^ words.getUint32(i, true), 0x01000193);
    new DataView(bytes.buffer, bytes.byteOffset).setUint32(12, hash >>> 0, true);
  }

  describe('refused snapshots say why and build nothing', () => {
    const source = stepped(CASES.find(([n]) => n === 'bridge')![1], 5);
    const bytes = source.snapshot();

    function expectRefusedInPlace(bad: unknown, message: RegExp, Kind: typeof TypeError | typeof RangeError = RangeError) {
      const world = stepped(CASES.find(([n]) => n === 'bridge')![1], 9);
      const hash = world.stateHash();
      expect(() => world.restore(bad as Uint8Array)).toThrow(Kind);
      expect(() => world.restore(bad as Uint8Array)).toThrow(message);
      expect(() => World.restore(bad as Uint8Array)).toThrow(message);
      expect(world.stateHash()).toBe(hash);
      const twin = stepped(CASES.find(([n]) => n === 'bridge')![1], 9);
      expect(trace(world, 10)).toEqual(trace(twin, 10));
    }

    it('not bytes', () => {
      expectRefusedInPlace('abc', /snapshot must be a Uint8Array.*string/, TypeError);
      expectRefusedInPlace(null, /snapshot must be a Uint8Array.*null/, TypeError);
      expectRefusedInPlace(Array.from(bytes), /snapshot must be a Uint8Array.*Array/, TypeError);
    });

    it('truncated, at any length', () => {
      for (const length of [0, 3, 15, 16, 17, bytes.length >> 1, bytes.length - 1]) expectRefusedInPlace(bytes.subarray(0, length), /truncated/);
    });

    it('not a snapshot, or bytes past its end', () => {
      expectRefusedInPlace(new Uint8Array(64), /not a maxgrid snapshot/);
      // A short file of another kind is not called a truncated snapshot.
      expectRefusedInPlace(new TextEncoder().encode('{"bodies":[]}'), /not a maxgrid snapshot/);
      const longer = new Uint8Array(bytes.length + 3);
      longer.set(bytes);
      expectRefusedInPlace(longer, /3 bytes past its end/);
    });

    it('a layout that differs names the fields that differ, not every field', () => {
      class Part {
        a = 1;
        b = 2;
        c = 3;
      }
      const saved = captureState({ part: new Part() });
      class Changed {
        a = 1;
        b = 2;
        d = 4;
      }
      expect(() => applyState({ part: new Changed() }, saved)).toThrow(/^world\.part has d here but not in the snapshot; c in the snapshot but not here$/);
    });

    it('a future format version', () => {
      const future = bytes.slice();
      new DataView(future.buffer).setUint16(4, 2, true);
      expectRefusedInPlace(future, /format version 2 is newer than this engine .* reads \(1\)/);
    });

    it('any flipped bit of the header, its reserved field included', () => {
      for (let at = 0; at < 16; at++) {
        for (let bit = 0; bit < 8; bit++) {
          const bad = bytes.slice();
          bad[at] ^= 1 << bit;
          expect(() => World.restore(bad), `byte ${at}, bit ${bit}`).toThrow(RangeError);
        }
      }
    });

    it('any flipped byte of the payload', () => {
      fc.assert(
        fc.property(fc.integer({ min: 16, max: bytes.length - 1 }), fc.integer({ min: 1, max: 255 }), (at, flip) => {
          const bad = bytes.slice();
          bad[at] ^= flip;
          expect(() => World.restore(bad)).toThrow(/snapshot is corrupt/);
        }),
        { numRuns: 200, seed: 23 },
      );
    });

    it('damage that keeps the hash is still caught by the reader, never half applied', () => {
      // A payload rewritten with a consistent hash: the structure itself is checked.
      const forged = bytes.slice();
      const view = new DataView(forged.buffer);
      // The engine version string's length, made to run past the payload.
      view.setUint32(16, 0x7fffffff, true);
      rehash(forged);
      expectRefusedInPlace(forged, /snapshot is corrupt: a value at byte 20 runs past the payload's end/);
    });

    it('a body state no step reaches, under a consistent hash, is refused by name', () => {
      // A world whose one body holds distinctive values; each is found in the bytes and replaced.
      const world = new World({ gravity: { x: 0, y: 10 }, solver: 'soft' });
      const h = world.createBox({ x: 1.2345678901, y: 2, width: 1, height: 1, vx: 3.2109876543, angularVelocity: 0.7654321098 });
      const clean = world.snapshot();
      const cases: [number, number, RegExp][] = [
        [1.2345678901, Number.NaN, new RegExp(`body ${h} has x NaN`)],
        [3.2109876543, Number.POSITIVE_INFINITY, new RegExp(`body ${h} has vx Infinity`)],
        [0.7654321098, Number.NEGATIVE_INFINITY, new RegExp(`body ${h} has angularVelocity -Infinity`)],
      ];
      for (const [value, bad, message] of cases) {
        const at = findDouble(clean, value);
        const forged = clean.slice();
        new DataView(forged.buffer).setFloat64(at, bad, true);
        rehash(forged);
        expect(() => World.restore(forged)).toThrow(RangeError);
        expect(() => World.restore(forged)).toThrow(message);
        const before = world.stateHash();
        expect(() => world.restore(forged)).toThrow(message);
        expect(world.stateHash()).toBe(before);
      }
      // The same rewriting with a value a step could reach restores.
      const fine = clean.slice();
      new DataView(fine.buffer).setFloat64(findDouble(clean, 1.2345678901), 5, true);
      rehash(fine);
      expect(World.restore(fine).getBody(h).x).toBe(5);
    });

    it('settings other than the options give, under a consistent hash, are refused by name', () => {
      // Settings are copied from the options when the world is made; the options are validated on
      // restore, the copies are compared with what those options give again.
      const world = new World({ gravity: { x: 0, y: 10 }, solver: 'soft', contactHertz: 29.8046875, sleepTime: 0.6123046875, jointHertz: 0.4140625, bounds: { width: 40, height: 30 } });
      const box = world.createBox({ x: 5, y: 5, width: 1, height: 1 });
      world.createJoint({ kind: 'revolute', bodyA: world.createBody({ x: 5, y: 4, type: 'static' }), bodyB: box });
      world.step(1 / 60);
      const clean = world.snapshot();
      const cases: [number, number, RegExp][] = [
        [29.8046875, Number.NaN, /snapshot is corrupt: settings\.shapes\.soft\.contactHertz is NaN, not what its options give/],
        // A value the options could have given is refused too: these options did not.
        [29.8046875, 31, /settings\.shapes\.soft\.contactHertz is 31,/],
        [0.6123046875, -1, /settings\.(resolved\.sleepTime|step\.sleeping\.time|shapes\.sleeping\.time) is -1,/],
        [0.4140625, 1e300, /settings\.(resolved\.jointHertz|joints\.hertz) is 1e\+300,/],
      ];
      const view = new DataView(clean.buffer, clean.byteOffset, clean.byteLength);
      for (const [value, bad, message] of cases) {
        // The value's every copy (the options', the settings', any other) rewritten in turn: each
        // is refused, and one of them by the settings check.
        const messages: string[] = [];
        for (let at = 16; at + 8 <= clean.length; at++) {
          if (view.getFloat64(at, true) !== value) continue;
          const forged = clean.slice();
          new DataView(forged.buffer).setFloat64(at, bad, true);
          rehash(forged);
          const before = world.stateHash();
          expect(() => world.restore(forged)).toThrow(RangeError);
          expect(world.stateHash()).toBe(before);
          try {
            World.restore(forged);
          } catch (error) {
            messages.push((error as Error).message);
          }
        }
        expect(messages.length).toBeGreaterThan(1);
        expect(messages.some((m) => message.test(m)), messages.join('\n')).toBe(true);
      }
      // The integrator's name, in each place it is kept, rewritten into one that is not a name.
      // Strings are UTF-16 code units.
      const name = [...'semi-implicit-euler'].flatMap((ch) => [ch.charCodeAt(0), 0]);
      let copies = 0;
      for (let at = 16; at + name.length <= clean.length; at++) {
        if (!name.every((byte, k) => clean[at + k] === byte)) continue;
        copies++;
        const forged = clean.slice();
        forged[at + name.length - 2] = 'x'.charCodeAt(0);
        rehash(forged);
        expect(() => World.restore(forged)).toThrow(/snapshot is corrupt: .*(integrator|semi-implicit-eulex)/);
      }
      expect(copies).toBeGreaterThan(2);
      // Gravity, which setGravity moves, may differ from the options; the untouched snapshot restores.
      world.setGravity(0, 9.5);
      expect(World.restore(world.snapshot()).gravity).toEqual({ x: 0, y: 9.5 });
    });

    it('gravity no step could use, under a consistent hash, is refused by name', () => {
      // Found by an audit: the live gravity (a copy of the creation options' is checked with them)
      // came back NaN, and the first step spread it to every body.
      const world = new World({ gravity: { x: 0, y: 9.8125 }, solver: 'soft' });
      world.createBox({ x: 0, y: 0, width: 1, height: 1 });
      world.setGravity(0, 9.8130859375);
      const clean = world.snapshot();
      for (const bad of [Number.NaN, Number.POSITIVE_INFINITY, 1e300]) {
        const forged = clean.slice();
        new DataView(forged.buffer).setFloat64(findDouble(clean, 9.8130859375), bad, true);
        rehash(forged);
        expect(() => World.restore(forged)).toThrow(new RangeError(`snapshot is corrupt: gravity (0, ${bad}) is beyond 1e+100, where no step can take it`));
        const before = world.stateHash();
        expect(() => world.restore(forged)).toThrow(/snapshot is corrupt: gravity/);
        expect(world.stateHash()).toBe(before);
        expect(world.gravity).toEqual({ x: 0, y: 9.8130859375 });
      }
    });
  });
});
