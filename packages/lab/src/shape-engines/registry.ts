import type { ShapeEngine, ShapeEngineProvider } from './adapter.js';
import { maxgridShapeProvider } from './maxgrid.js';
import { rapierShapeProvider } from './rapier.js';
import { box2dShapeProvider } from './box2d.js';
import { planckShapeProvider } from './planck.js';
import { matterShapeProvider } from './matter.js';
import { p2ShapeProvider } from './p2.js';

/** Every engine for shape scenes: maxgrid with the broad-phases worth comparing, then the peers. */
export const SHAPE_ENGINE_PROVIDERS: ShapeEngineProvider[] = [
  maxgridShapeProvider('maxgrid'),
  maxgridShapeProvider('hgrid'),
  maxgridShapeProvider('auto'),
  maxgridShapeProvider('sap-persistent'),
  box2dShapeProvider,
  planckShapeProvider,
  rapierShapeProvider,
  matterShapeProvider,
  p2ShapeProvider,
];

export const SHAPE_ENGINE_IDS: string[] = SHAPE_ENGINE_PROVIDERS.map((p) => p.id);

export async function loadShapeEngines(ids: readonly string[], options: Parameters<ShapeEngineProvider['load']>[0] = {}): Promise<ShapeEngine[]> {
  const engines: ShapeEngine[] = [];
  for (const id of ids) {
    const provider = SHAPE_ENGINE_PROVIDERS.find((p) => p.id === id);
    if (!provider) throw new RangeError(`unknown shape engine '${id}'; engines: ${SHAPE_ENGINE_IDS.join(', ')}`);
    engines.push(await provider.load(options));
  }
  return engines;
}
