import type { Engine, EngineProvider, LoadOptions } from './adapter.js';
import { MAXGRID_PROVIDERS, maxgridPilesProvider } from './maxgrid.js';
import { box2dProvider } from './box2d.js';
import { planckProvider } from './planck.js';
import { rapierProvider } from './rapier.js';
import { matterProvider } from './matter.js';
import { p2Provider } from './p2.js';

/** Every engine the lab knows, maxgrid once per broad-phase first. */
export const ENGINE_PROVIDERS: EngineProvider[] = [
  ...MAXGRID_PROVIDERS,
  maxgridPilesProvider,
  box2dProvider,
  planckProvider,
  rapierProvider,
  matterProvider,
  p2Provider,
];

export const ENGINE_IDS: string[] = ENGINE_PROVIDERS.map((p) => p.id);

export function isEngineId(id: string): boolean {
  return ENGINE_IDS.includes(id);
}

/** Loads engines by id, in the order given; an unknown id is an error naming it. */
export async function loadEngines(ids: readonly string[], options: LoadOptions = {}): Promise<Engine[]> {
  const providers = ids.map((id) => {
    const provider = ENGINE_PROVIDERS.find((p) => p.id === id);
    if (!provider) throw new RangeError(`unknown engine '${id}'; engines: ${ENGINE_IDS.join(', ')}`);
    return provider;
  });
  const engines: Engine[] = [];
  for (const provider of providers) engines.push(await provider.load(options));
  return engines;
}
