import { wrapDeg360 } from '../../solver/angles';
import type { AngleInterval } from '../../solver/types';
import { inputTurnsFully, rangeToDeg } from './animation';
import { formatDeg } from '../format';
import type { Messages } from '../i18n/messages';

/**
 * A reachable input interval in the θ2 slider's convention: loDeg in [0, 360); when it wraps, the interval
 * runs from loDeg up to 360° = 0° and on to hiDeg (hiDeg < loDeg); otherwise loDeg <= hiDeg <= 360.
 */
export interface SliderInterval {
  loDeg: number;
  hiDeg: number;
  wraps: boolean;
}

/** Intervals in degrees (lo <= hi, any turn) mapped to the slider's [0, 360) convention, sorted by their start. */
export function sliderIntervals(intervalsDeg: readonly AngleInterval[]): SliderInterval[] {
  return intervalsDeg
    .map((iv) => {
      const loDeg = wrapDeg360(iv.lo);
      // Shift hi by the same whole number of turns as lo, so the interval keeps its width.
      const hi = iv.hi + 360 * Math.round((loDeg - iv.lo) / 360);
      return hi > 360 ? { loDeg, hiDeg: hi - 360, wraps: true } : { loDeg, hiDeg: hi, wraps: false };
    })
    .sort((a, b) => a.loDeg - b.loDeg);
}

/**
 * The input's reachable range (the solver's, in radians) as the analysis panel and the canvas warning say it:
 * full turn, none, or the intervals in the slider's 0°–360° convention, "224.05° through 0° to 135.95°" for one
 * that passes 0°. Two decimals, the precision of every other θ2 shown.
 */
export function formatInputRange(range: { full: boolean; intervals: readonly AngleInterval[] }, t: Messages): string {
  if (inputTurnsFully(range)) return t.fullTurn;
  if (range.intervals.length === 0) return t.noRange;
  return sliderIntervals(rangeToDeg(range).intervals)
    .map((iv) =>
      iv.wraps
        ? t.rangeWrapped(formatDeg(iv.loDeg, 2), formatDeg(iv.hiDeg, 2))
        : t.rangeInterval(formatDeg(iv.loDeg, 2), formatDeg(iv.hiDeg, 2)),
    )
    .join('; ');
}
