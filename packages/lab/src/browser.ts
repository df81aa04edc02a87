// Everything the browser lab page uses: the same adapters and experiments as the CLI, none of
// the Node-only modules (fs, resvg, cli-progress live under node/).
export type { Engine, EngineInfo, LoadOptions } from './engines/adapter.js';
export { ENGINE_IDS, loadEngines } from './engines/registry.js';
export { maxgridBuildOptions } from './engines/maxgrid.js';
export type { Environment, Profile, RunContext } from './experiments/common.js';
export { EXPERIMENTS, type AnyExperiment } from './experiments/registry.js';
export { renderSvg } from './report/render.js';
export { tablesFor } from './report/html.js';
export { engineTable, htmlTable, type Table } from './report/tables.js';
