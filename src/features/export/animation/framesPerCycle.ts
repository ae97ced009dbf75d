/** Fewest frames per cycle the export offers. */
export const FRAMES_PER_CYCLE_MIN = 36;
/** Most frames per cycle the export offers. */
export const FRAMES_PER_CYCLE_MAX = 720;
/** Frames per cycle unless the user picks another number. */
export const FRAMES_PER_CYCLE_DEFAULT = 120;
