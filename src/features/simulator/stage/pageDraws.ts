/**
 * A page whose recent draws of the linkage take this long (ms, their lower median) hands a θ2 drag to the stage: past
 * it, the page's frame (its React render, the drawing, its paint) no longer fits in the one frame the worker's route
 * adds.
 */
export const SLOW_PAGE_DRAW_MS = 5;
/** How many of the page's latest draws the median is taken over (a slow one, say the first, does not decide alone). */
export const DRAWS_KEPT = 5;
/**
 * The page is judged from this many draws on: its first draws carry one-time costs (fonts, compiling, the
 * background's bitmap; 23 and 12 ms at 1x), and the page times its first frame again at idle until it has as many
 * (useLinkageDrawing's MEASURED_DRAWS), so the judgement is ready before the first drag.
 */
export const JUDGED_AFTER_DRAWS = 6;

/**
 * How long the page's latest draws of the linkage took, and whether it is too slow to keep up with a drag. The first
 * draws are the page's own idle redraws of its first frame (useLinkageDrawing), so the answer is known before the
 * first drag. Once slow, a page stays slow: CDP's CPU throttle lets single short draws through at full speed (a
 * drag's draws over the cached background at 6x took 1.5 to 35 ms), and a window of such lucky draws must not hand
 * the next drag back to the page, whose commits then take 70 to 460 ms.
 */
export interface PageDraws {
  /** Notes one draw's time (ms); a negative or non-finite time is passed over. */
  note(ms: number): void;
  /**
   * Whether the lower median of the latest DRAWS_KEPT draws is, or ever was, at least SLOW_PAGE_DRAW_MS (false
   * before JUDGED_AFTER_DRAWS draws).
   */
  slow(): boolean;
  /** Whether the page has been judged (JUDGED_AFTER_DRAWS draws noted). */
  judged(): boolean;
}

/** The page's draw times, for the live stage's prefersStage. */
export function createPageDraws(): PageDraws {
  const draws: number[] = [];
  let noted = 0;
  let judgedSlow = false;
  return {
    note(ms) {
      if (!Number.isFinite(ms) || ms < 0) return;
      noted += 1;
      draws.push(ms);
      if (draws.length > DRAWS_KEPT) draws.shift();
      if (noted < JUDGED_AFTER_DRAWS || judgedSlow) return;
      const sorted = [...draws].sort((a, b) => a - b);
      judgedSlow = sorted[Math.floor((sorted.length - 1) / 2)] >= SLOW_PAGE_DRAW_MS;
    },
    slow: () => judgedSlow,
    judged: () => noted >= JUDGED_AFTER_DRAWS,
  };
}

/**
 * Whether a θ2 drag's next frame goes to the stage: at the drag's first move, whether the page is slow; later, the
 * stage keeps a drag it has, and a drag the page draws goes over to the stage once the page is found slow (never
 * back within a drag, so its frames do not jump between two canvases).
 */
export function dragViaStage(firstMove: boolean, viaStageSoFar: boolean, pageSlow: boolean): boolean {
  if (firstMove) return pageSlow;
  return viaStageSoFar || pageSlow;
}
