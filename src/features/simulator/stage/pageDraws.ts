/**
 * A page whose recent draws of the linkage take this long (ms, their lower median) hands a θ2 drag to the stage: past
 * it, the page's frame (its React render, the drawing, its paint) no longer fits in the one frame the worker's route
 * adds.
 */
export const SLOW_PAGE_DRAW_MS = 5;
/** How many of the page's latest draws the median is taken over (a slow one, say the first, does not decide alone). */
export const DRAWS_KEPT = 5;

/** How long the page's latest draws of the linkage took, and whether it is too slow to keep up with a drag. */
export interface PageDraws {
  /** Notes one draw's time (ms); a negative or non-finite time is passed over. */
  note(ms: number): void;
  /** Whether the lower median of the latest DRAWS_KEPT draws is at least SLOW_PAGE_DRAW_MS (false before two). */
  slow(): boolean;
  /** How many draws were noted in all. */
  count(): number;
}

/** The page's draw times, for the live stage's prefersStage. */
export function createPageDraws(): PageDraws {
  const draws: number[] = [];
  let noted = 0;
  return {
    note(ms) {
      if (!Number.isFinite(ms) || ms < 0) return;
      noted += 1;
      draws.push(ms);
      if (draws.length > DRAWS_KEPT) draws.shift();
    },
    slow() {
      if (draws.length < 2) return false;
      const sorted = [...draws].sort((a, b) => a - b);
      return sorted[Math.floor((sorted.length - 1) / 2)] >= SLOW_PAGE_DRAW_MS;
    },
    count: () => noted,
  };
}
