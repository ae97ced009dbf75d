import { radToDeg360 } from '../../solver/angles';
import { formatDeg, formatNumber } from '../../shared/format';
import type { Messages } from '../../shared/i18n/messages';
import type { FrameMotion, PointRates } from '../../shared/linkage/frameMotion';

/** One line of the motion panel: a stable key (for tests), its label and its formatted value with unit. */
export interface MotionFact {
  key: 'omega3' | 'omega4' | 'alpha3' | 'alpha4' | 'vA' | 'vB' | 'vP' | 'aP';
  label: string;
  value: string;
}

/** Significant digits of the panel's rates. */
export const MOTION_DIGITS = 6;

/** A rate with its unit, or the limit-position text when it is not finite (never a huge number). */
export function rateText(x: number, unit: string, t: Pick<Messages, 'limitPosition'>): string {
  return Number.isFinite(x) ? `${formatNumber(x, MOTION_DIGITS)} ${unit}` : t.limitPosition;
}

/** A vector's magnitude with its unit and direction (degrees counter-clockwise from +x in [0, 360)); limit text when not finite. */
export function magnitudeDirectionText(
  x: number,
  y: number,
  unit: string,
  t: Pick<Messages, 'limitPosition' | 'directionDeg'>,
): string {
  if (!Number.isFinite(x) || !Number.isFinite(y)) return t.limitPosition;
  const m = Math.hypot(x, y);
  const magnitude = `${formatNumber(m, MOTION_DIGITS)} ${unit}`;
  return m > 0 ? `${magnitude}, ${t.directionDeg(formatDeg(radToDeg360(Math.atan2(y, x)), 1))}` : magnitude;
}

/**
 * The motion panel's lines at this frame: ω3, ω4, α3, α4, the speeds of A, B and P, and P's acceleration; speeds
 * in lengthUnit/s and lengthUnit/s² when the unit is given, else in the generic length/s.
 */
export function motionFacts(m: FrameMotion, t: Messages, lengthUnit?: string): MotionFact[] {
  const r = m.rates;
  const unitSpeed = lengthUnit ? `${lengthUnit}/s` : t.unitSpeed;
  const unitAcceleration = lengthUnit ? `${lengthUnit}/s²` : t.unitAcceleration;
  const speed = (p: PointRates) => magnitudeDirectionText(p.vx, p.vy, unitSpeed, t);
  return [
    { key: 'omega3', label: `${t.angularVelocity}3`, value: rateText(r.omega3, 'rad/s', t) },
    { key: 'omega4', label: `${t.angularVelocity}4`, value: rateText(r.omega4, 'rad/s', t) },
    { key: 'alpha3', label: `${t.angularAcceleration}3`, value: rateText(r.alpha3, 'rad/s²', t) },
    { key: 'alpha4', label: `${t.angularAcceleration}4`, value: rateText(r.alpha4, 'rad/s²', t) },
    { key: 'vA', label: t.pointSpeed('A'), value: speed(m.A) },
    { key: 'vB', label: t.pointSpeed('B'), value: speed(m.B) },
    { key: 'vP', label: t.pointSpeed('P'), value: speed(m.P) },
    { key: 'aP', label: t.pointAcceleration('P'), value: magnitudeDirectionText(m.P.ax, m.P.ay, unitAcceleration, t) },
  ];
}
