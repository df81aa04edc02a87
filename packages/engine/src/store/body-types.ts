/** Motion types, as in the report's section 3.1.2 and in Box2D / Unity. */
export type BodyType = 'static' | 'kinematic' | 'dynamic';

/** Every motion type, for option lists and validation. */
export const BODY_TYPES: readonly BodyType[] = ['static', 'kinematic', 'dynamic'];

/**
 * Codes stored in the `type` column. `FREE` marks an unused slot, so renderers and stages can walk
 * the columns linearly and skip holes left by destroyed bodies.
 */
export const TypeCode = { free: 0, static: 1, kinematic: 2, dynamic: 3 } as const;

export function typeCode(type: BodyType): number {
  return TypeCode[type];
}

export function typeName(code: number): BodyType {
  if (code === TypeCode.static) return 'static';
  if (code === TypeCode.kinematic) return 'kinematic';
  return 'dynamic';
}

/** Shape codes: the narrow-phase dispatches on the pair of codes. Only circles exist so far. */
export const ShapeCode = { circle: 0 } as const;
