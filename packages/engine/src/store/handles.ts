/**
 * Handles pack a slot index and that slot's generation: `base + generation * SLOT_SPACE + slot`.
 * When a slot is reused its generation goes up, so an old handle to it no longer matches and is
 * refused as stale. Bodies, segments, shapes and joints each have a space of their own below 2^53, so a
 * handle of one kind passed where another is expected is refused by name instead of reaching
 * whatever shares its slot:
 *
 *   bodies    [0, 2^52)            2^28 generations of 2^24 slots; the first body gets handle 0
 *   segments  [2^52, 2^52 + 2^51)  2^27 generations
 *   shapes    [2^52 + 2^51, 2^52 + 2^51 + 2^50)  2^26 generations
 *   joints    [2^52 + 2^51 + 2^50, 2^53)         2^26 generations
 *
 * A slot whose generation would overflow its space is retired rather than reused.
 */
export const SLOT_SPACE = 2 ** 24;
export const MAX_GENERATION = 2 ** 28;
export const SEGMENT_HANDLES = 2 ** 52;
export const SEGMENT_MAX_GENERATION = 2 ** 27;
export const SHAPE_HANDLES = 2 ** 52 + 2 ** 51;
export const SHAPE_MAX_GENERATION = 2 ** 26;
export const JOINT_HANDLES = 2 ** 52 + 2 ** 51 + 2 ** 50;
export const JOINT_MAX_GENERATION = 2 ** 26;
