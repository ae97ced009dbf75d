import { radToDeg360 } from '../../solver/angles';
import { formatDeg, formatNumber, roundingNoiseToZero } from '../../shared/format';
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

/** The largest finite |value|: the scale beside which a panel's rounding noise shows as 0. */
function scaleOf(values: readonly number[]): number {
  return values.reduce((m, v) => (Number.isFinite(v) ? Math.max(m, Math.abs(v)) : m), 0);
}

/** A rate with its unit (0 when rounding noise beside scale), or the limit-position text when it is not finite. */
export function rateText(x: number, unit: string, t: Pick<Messages, 'limitPosition'>, scale = 0): string {
  return Number.isFinite(x) ? `${formatNumber(x, MOTION_DIGITS, scale)} ${unit}` : t.limitPosition;
}

/**
 * A vector's magnitude with its unit and direction (degrees counter-clockwise from +x in [0, 360)); limit text when
 * not finite; 0 without a direction when the magnitude is rounding noise beside scale (default 0: never).
 */
export function magnitudeDirectionText(
  x: number,
  y: number,
  unit: string,
  t: Pick<Messages, 'limitPosition' | 'directionDeg'>,
  scale = 0,
): string {
  if (!Number.isFinite(x) || !Number.isFinite(y)) return t.limitPosition;
  // A magnitude that is rounding noise has no direction either: 0, not "1e-17, at 315°".
  const m = roundingNoiseToZero(Math.hypot(x, y), scale);
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
  // Each group's scale is the largest value computed beside it (with the input's), so noise of a zero shows as 0.
  const { omega2, alpha2 } = m.input;
  const omegaScale = scaleOf([omega2, r.omega3, r.omega4]);
  const alphaScale = scaleOf([alpha2, omega2 * omega2, r.alpha3, r.alpha4]);
  const points = [m.A, m.B, m.P];
  const speedScale = scaleOf(points.map((p) => Math.hypot(p.vx, p.vy)));
  const speed = (p: PointRates) => magnitudeDirectionText(p.vx, p.vy, unitSpeed, t, speedScale);
  const accelerationScale = scaleOf(points.map((p) => Math.hypot(p.ax, p.ay)));
  return [
    { key: 'omega3', label: `${t.angularVelocity}3`, value: rateText(r.omega3, 'rad/s', t, omegaScale) },
    { key: 'omega4', label: `${t.angularVelocity}4`, value: rateText(r.omega4, 'rad/s', t, omegaScale) },
    { key: 'alpha3', label: `${t.angularAcceleration}3`, value: rateText(r.alpha3, 'rad/s²', t, alphaScale) },
    { key: 'alpha4', label: `${t.angularAcceleration}4`, value: rateText(r.alpha4, 'rad/s²', t, alphaScale) },
    { key: 'vA', label: t.pointSpeed('A'), value: speed(m.A) },
    { key: 'vB', label: t.pointSpeed('B'), value: speed(m.B) },
    { key: 'vP', label: t.pointSpeed('P'), value: speed(m.P) },
    {
      key: 'aP',
      label: t.pointAcceleration('P'),
      value: magnitudeDirectionText(m.P.ax, m.P.ay, unitAcceleration, t, accelerationScale),
    },
  ];
}
