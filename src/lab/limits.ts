/** Distance in degrees from theta2Deg to the nearest of limitsDeg, modulo 360; Infinity when there are none. */
export function distanceToNearestLimitDeg(theta2Deg: number, limitsDeg: readonly number[]): number {
  let best = Infinity;
  for (const lim of limitsDeg) {
    const d = Math.abs(((((theta2Deg - lim) % 360) + 540) % 360) - 180);
    best = Math.min(best, d);
  }
  return best;
}
