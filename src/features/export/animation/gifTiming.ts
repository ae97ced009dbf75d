/** Shortest frame delay written, centiseconds: browsers play 0 or 1 cs as 10 cs, so faster rates are capped at 50 FPS. */
export const GIF_MIN_DELAY_CS = 2;

/**
 * Per-frame delays (centiseconds) for frameCount frames at fps frames per second. Rounded on the running
 * total, so the cycle lasts frameCount / fps seconds to within 1 cs however the single delays round
 * (30 FPS gives 3, 4, 3, 3, 4, 3, …); never below GIF_MIN_DELAY_CS. Throws for a count or rate that is not positive.
 */
export function gifFrameDelaysCs(frameCount: number, fps: number): number[] {
  if (!Number.isInteger(frameCount) || frameCount < 1) {
    throw new Error(`frameCount must be a positive integer, got ${frameCount}`);
  }
  if (!(fps > 0) || !Number.isFinite(fps)) throw new Error(`fps must be a positive finite rate, got ${fps}`);
  const at = (k: number) => Math.round((k * 100) / fps);
  return Array.from({ length: frameCount }, (_, k) => Math.max(GIF_MIN_DELAY_CS, at(k + 1) - at(k)));
}
