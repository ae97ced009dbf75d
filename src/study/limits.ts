/** The limit angle (degrees) nearest to theta2Deg around the circle and the distance to it; null without limits. */
export function nearestLimitDeg(
  theta2Deg: number,
  limitsDeg: readonly number[],
): { distanceDeg: number; limitDeg: number } | null {
  let best: { distanceDeg: number; limitDeg: number } | null = null;
  for (const lim of limitsDeg) {
    const d = Math.abs(((((theta2Deg - lim) % 360) + 540) % 360) - 180);
    if (!best || d < best.distanceDeg) best = { distanceDeg: d, limitDeg: lim };
  }
  return best;
}

/** Distance in degrees from theta2Deg to the nearest of limitsDeg, modulo 360; Infinity when there are none. */
export function distanceToNearestLimitDeg(theta2Deg: number, limitsDeg: readonly number[]): number {
  return nearestLimitDeg(theta2Deg, limitsDeg)?.distanceDeg ?? Infinity;
}
