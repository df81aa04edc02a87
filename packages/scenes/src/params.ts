/** One numeric scene parameter: its default, its allowed range, and what it means. */
export interface ParamSpec {
  default: number;
  min: number;
  max: number;
  integer?: boolean;
  description: string;
}

/** A scene's parameters by name. */
export type ParamSpecs = Record<string, ParamSpec>;

/** A scene's parameter values by name, defaults filled in, as resolveParams returns them. */
export type ParamValues<S extends ParamSpecs> = { [K in keyof S]: number };

/** Fills defaults and rejects unknown names, non-numbers and out-of-range values by name. */
export function resolveParams<S extends ParamSpecs>(
  scene: string,
  specs: S,
  given: Partial<Record<string, number>> = {},
): ParamValues<S> {
  if (given === null || typeof given !== 'object' || Array.isArray(given)) {
    throw new TypeError(`scene '${scene}' takes its parameters as an object of numbers, got ${Array.isArray(given) ? 'an array' : String(given)}`);
  }
  // Own names only: 'constructor' or 'toString' are not parameters, whatever Object.prototype holds.
  for (const key of Object.keys(given)) {
    if (!Object.hasOwn(specs, key)) {
      throw new TypeError(`scene '${scene}' has no parameter '${key}'; it has: ${Object.keys(specs).join(', ')}`);
    }
  }
  const out: Record<string, number> = {};
  for (const [key, spec] of Object.entries(specs)) {
    const value = Object.hasOwn(given, key) ? (given[key] ?? spec.default) : spec.default;
    if (typeof value !== 'number' || !Number.isFinite(value)) {
      throw new TypeError(`${scene}.${key} must be a finite number, got ${String(value)}`);
    }
    if (value < spec.min || value > spec.max) {
      throw new RangeError(`${scene}.${key} must be in [${spec.min}, ${spec.max}], got ${value}`);
    }
    if (spec.integer && !Number.isInteger(value)) {
      throw new RangeError(`${scene}.${key} must be an integer, got ${value}`);
    }
    out[key] = value;
  }
  return out as ParamValues<S>;
}
