import { radToDeg, radToDeg360 } from '../../solver/angles';
import type { Point } from '../../solver/kinematics';
import type { TorqueCycleStats } from '../../solver/forcesCycle';
import { formatDeg, formatNumber, roundingNoiseToZero } from '../../shared/format';
import type { CycleForcesView } from './forceCycleData';
import type { PoseForces } from './forceModel';
import type { CycleGap, ForcesMessages, PinForce } from './forcesMessages';

/** Significant digits of the forces panel's numbers. */
export const FORCE_DIGITS = 6;

/** |sin μ| below which the panel says the pin forces grow like 1 / sin μ (μ within about 15° of 0 or 180°). */
export const TOGGLE_NOTE_SIN_MU = 0.26;

/** The text of a missing number: never NaN. */
export const MISSING = '—';

/** A value with its unit (0 when rounding noise beside scale, default 0: never), or MISSING when not finite. */
export function quantityText(x: number, unit: string, scale = 0): string {
  return Number.isFinite(x) ? `${formatNumber(x, FORCE_DIGITS, scale)} ${unit}` : MISSING;
}

/**
 * A force's magnitude (N) and direction (degrees CCW from +x in [0, 360)); MISSING when not finite; 0 without a
 * direction when the magnitude is rounding noise beside scale (N, default 0: never).
 */
export function forceText(f: Point, t: Pick<ForcesMessages, 'directionDeg'>, scale = 0): string {
  if (!Number.isFinite(f.x) || !Number.isFinite(f.y)) return MISSING;
  const m = roundingNoiseToZero(Math.hypot(f.x, f.y), scale);
  const magnitude = `${formatNumber(m, FORCE_DIGITS)} N`;
  return m > 0 ? `${magnitude}, ${t.directionDeg(formatDeg(radToDeg360(Math.atan2(f.y, f.x)), 1))}` : magnitude;
}

/** One line of the forces panel: a stable key (e2e reads data-testid forces-<key>), its label and its value. */
export interface ForceFact {
  key: 'torque' | PinForce | 'shakingForce' | 'shakingMoment';
  label: string;
  value: string;
}

/** The largest finite |value| (0 when none). */
function largest(values: readonly number[]): number {
  return values.reduce((m, v) => (Number.isFinite(v) ? Math.max(m, Math.abs(v)) : m), 0);
}

/** The panel's lines at a pose: T12, F12, F32, F43, F14, the shaking force and moment (MISSING where undetermined). */
export function poseFacts(p: PoseForces, t: ForcesMessages): ForceFact[] {
  const f = p.forces;
  // Forces beside forces and moments beside moments: a value 1e-12 of its group's largest is rounding of a zero.
  const forceScale = f ? largest([f.F12, f.F32, f.F43, f.F14, f.shakingForce].map((v) => Math.hypot(v.x, v.y))) : 0;
  const momentScale = f ? largest([f.torque, f.shakingMoment]) : 0;
  const force = (v: Point) => (f ? forceText(v, t, forceScale) : MISSING);
  const pin = (k: PinForce): ForceFact => ({ key: k, label: t.pinNames[k], value: f ? force(f[k]) : MISSING });
  return [
    { key: 'torque', label: t.inputTorque, value: f ? quantityText(f.torque, 'N·m', momentScale) : MISSING },
    pin('F12'),
    pin('F32'),
    pin('F43'),
    pin('F14'),
    { key: 'shakingForce', label: t.shakingForce, value: f ? force(f.shakingForce) : MISSING },
    {
      key: 'shakingMoment',
      label: t.shakingMoment,
      value: f ? quantityText(f.shakingMoment, 'N·m', momentScale) : MISSING,
    },
  ];
}

/** Why the numbers at a pose are missing, or null when they are there. */
export function poseReason(p: PoseForces, t: ForcesMessages): string | null {
  if (p.status === 'limit-position') return t.limitReason;
  if (p.status === 'no-pose') return t.noPoseReason;
  if (p.status === 'overflow') return t.overflowReason;
  return null;
}

/** The near-toggle note (μ in radians, shown in degrees, and 1 / |sin μ|), or null away from a toggle. */
export function toggleNote(p: PoseForces, muRad: number, t: ForcesMessages): string | null {
  const s = Math.abs(p.sinMu);
  if (p.status !== 'ok' || !(s < TOGGLE_NOTE_SIN_MU)) return null;
  return t.toggleNote(formatDeg(radToDeg(muRad), 1), formatNumber(1 / s, 3));
}

/**
 * The mean torque as shown: a mean below 1e-9 of the peak is rounding of a zero (loads that do no net work over a
 * turn give a zero mean, summed from samples of the peak's size), shown as 0 rather than as 1.6e-13.
 */
export function shownMean(s: Pick<TorqueCycleStats, 'mean' | 'peak'>): number {
  return Math.abs(s.mean) <= 1e-9 * s.peak ? 0 : s.mean;
}

/** The cycle's lines: mean, RMS and peak torque (N·m), ΔE (J) and the flywheel inertia (kg·m²) for k. */
export interface TorqueCycleFacts {
  mean: string;
  rms: string;
  peak: string;
  energy: string;
  flywheel: string;
  /** Why they are MISSING, or null. */
  reason: string | null;
}

/** Why the cycle numbers are missing: the solver's status, or a crank at rest for the flywheel. */
function cycleGap(c: CycleForcesView | null, omega2: number): CycleGap | null {
  if (!c || c.status === 'crank-does-not-turn') return 'crank-does-not-turn';
  if (c.status === 'limit-position') return 'limit-position';
  if (c.status === 'overflow') return 'overflow';
  return omega2 === 0 ? 'omega-zero' : null;
}

/** The cycle's facts for the input speed omega2 (rad/s). */
export function cycleFacts(c: CycleForcesView | null, omega2: number, t: ForcesMessages): TorqueCycleFacts {
  const s: TorqueCycleStats | null = c && c.status === 'ok' ? c.stats : null;
  const gap = cycleGap(c, omega2);
  return {
    mean: s ? quantityText(shownMean(s), 'N·m') : MISSING,
    rms: s ? quantityText(s.rms, 'N·m') : MISSING,
    peak: s ? quantityText(s.peak, 'N·m') : MISSING,
    energy: s ? quantityText(s.energyFluctuation, 'J') : MISSING,
    flywheel: s ? quantityText(s.flywheelInertia, 'kg·m²') : MISSING,
    reason: gap ? t.cycleGaps[gap] : null,
  };
}
