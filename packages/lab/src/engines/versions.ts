// Versions come from the installed packages' own package.json, so outputs name exactly what ran.
// Relative paths because some packages' "exports" hide package.json; these resolve the same
// way under tsx in Node and under Vite in the browser. planck is nested under the lab package
// (npm could not hoist it); the rest are hoisted to the workspace root.
import box2d from '../../../../node_modules/box2d-wasm/package.json' with { type: 'json' };
import planck from '../../node_modules/planck/package.json' with { type: 'json' };
import rapier from '../../../../node_modules/@dimforge/rapier2d-simd-compat/package.json' with { type: 'json' };
import matter from '../../../../node_modules/matter-js/package.json' with { type: 'json' };
import p2 from '../../../../node_modules/p2-es/package.json' with { type: 'json' };
import maxgrid from '../../../engine/package.json' with { type: 'json' };

/**
 * The Box2D release box2d-wasm compiles (its README: "Compatibility: Box2D v2.4.1"), which tables
 * and headlines name (report/tables.ts engineLabel) so that no reader takes it for Box2D v3.
 */
export const BOX2D_WASM_CORE = '2.4.1';

export const VERSIONS = {
  maxgrid: maxgrid.version,
  'box2d-wasm': box2d.version,
  planck: planck.version,
  '@dimforge/rapier2d-simd-compat': rapier.version,
  'matter-js': matter.version,
  'p2-es': p2.version,
} as const;
