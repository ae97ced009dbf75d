/**
 * How often Play commits its frame to the app state, paced by the page's own frame rate. Each commit re-renders
 * the panels (the θ2 field, the numbers, the worker's answer, the address bar); on a slow device those renders take
 * frames from the animation, and the plot markers visibly lag the linkage. The pacer watches the page's frame
 * intervals while Play runs: while frames are dropped (the mean interval well over the shortest, which is the
 * display's refresh; not the median, as intervals come in whole refreshes and a page at 40 frames/s on a 60 Hz display
 * has more one-refresh intervals than two-refresh ones) it doubles the gap between commits, up to PLAY_COMMIT_MAX_MS; while the page keeps up with the
 * display it halves the gap again, down to the render-based floor (playCommitGapMs). Pure: no clock, no DOM.
 */

/** How often Play commits its frame at most, ms (five times a second). */
export const PLAY_COMMIT_MS = 200;
/** A slow device commits less often: the gap is at least this many times the last commit's render (ms). */
const COMMIT_SHARE = 8;
/** ...and at most this (ms): the panels still follow Play once a second. */
export const PLAY_COMMIT_MAX_MS = 1000;
/** Frame intervals the pacer keeps (about half a second at 60 frames/s). */
const WINDOW = 30;
/** Frames are being dropped when the mean interval is more than this many times the shortest (under 50/s at 60 Hz). */
const DROPPING = 1.2;
/** The page keeps up with the display when the mean interval is within this many times the shortest. */
const KEEPING_UP = 1.06;
/** Frame intervals longer than this (ms) are pauses (a hidden tab, a breakpoint), not frames: left out. */
const PAUSE_MS = 250;

/**
 * The gap before Play's next commit, ms: PLAY_COMMIT_MS, or longer on a device where rendering the committed state
 * took lastRenderMs, so the commits take at most about 1/COMMIT_SHARE of the time the animation has (at most
 * PLAY_COMMIT_MAX_MS).
 */
export function playCommitGapMs(lastRenderMs: number): number {
  const ms = Number.isFinite(lastRenderMs) && lastRenderMs > 0 ? lastRenderMs : 0;
  return Math.min(PLAY_COMMIT_MAX_MS, Math.max(PLAY_COMMIT_MS, COMMIT_SHARE * ms));
}

/** The mean of a non-empty list. */
function mean(values: readonly number[]): number {
  let sum = 0;
  for (const v of values) sum += v;
  return sum / values.length;
}

/** Paces Play's commits by the page's frame intervals (see the module's comment). */
export class CommitPacer {
  private readonly intervals: number[] = [];
  private shortest = Number.POSITIVE_INFINITY;
  private gap = PLAY_COMMIT_MS;

  /** Notes one frame interval (ms) of the page while Play runs. */
  noteFrame(intervalMs: number): void {
    if (!(intervalMs > 0) || intervalMs > PAUSE_MS) return;
    this.intervals.push(intervalMs);
    if (this.intervals.length > WINDOW) this.intervals.shift();
    this.shortest = Math.min(this.shortest, intervalMs);
  }

  /**
   * The gap before the next commit (ms), after a commit rendered in lastRenderMs: adjusted once per commit, so
   * the pace settles within a few commits and a single slow frame does not move it.
   */
  nextGap(lastRenderMs: number): number {
    const floor = playCommitGapMs(lastRenderMs);
    if (this.intervals.length >= WINDOW / 2) {
      const ratio = mean(this.intervals) / this.shortest;
      if (ratio > DROPPING) this.gap = Math.min(PLAY_COMMIT_MAX_MS, this.gap * 2);
      else if (ratio <= KEEPING_UP) this.gap = Math.max(PLAY_COMMIT_MS, this.gap / 2);
    }
    return Math.max(floor, this.gap);
  }

  /** Forgets the frames seen (Play stopped): the next run starts at the render-based gap. */
  reset(): void {
    this.intervals.length = 0;
    this.shortest = Number.POSITIVE_INFINITY;
    this.gap = PLAY_COMMIT_MS;
  }
}
