// The rates module alone: the solver's barrel would pull the sweep and NR into the main bundle.
import { degPerSToRadPerS, radPerSToDegPerS, radPerSToRpm, rpmToRadPerS } from '../../solver/angles';
import type { InputMotion } from '../../solver/rates';
import type { Direction } from './appState';

/** Units the ω2 control offers; the state always stores rad/s. */
export type OmegaUnit = 'rad/s' | 'rpm' | 'deg/s';

/** The ω2 units in the order the unit select lists them. */
export const OMEGA_UNITS: readonly OmegaUnit[] = ['rad/s', 'rpm', 'deg/s'];

/** Slider range and step of the ω2 control in each unit (the field accepts any value FIELD_SPECS allows). */
export const OMEGA_SLIDER: Record<OmegaUnit, { min: number; max: number; step: number }> = {
  'rad/s': { min: -100, max: 100, step: 0.5 },
  rpm: { min: -1000, max: 1000, step: 5 },
  'deg/s': { min: -6000, max: 6000, step: 30 },
};

/** Slider range and step of the α2 control, rad/s². */
export const ALPHA_SLIDER = { min: -1000, max: 1000, step: 5 } as const;

/** ω2 in the given unit from rad/s. */
export function omegaToUnit(radPerS: number, unit: OmegaUnit): number {
  if (unit === 'rpm') return radPerSToRpm(radPerS);
  if (unit === 'deg/s') return radPerSToDegPerS(radPerS);
  return radPerS;
}

/** ω2 in rad/s from a value in the given unit. */
export function omegaFromUnit(value: number, unit: OmegaUnit): number {
  if (unit === 'rpm') return rpmToRadPerS(value);
  if (unit === 'deg/s') return degPerSToRadPerS(value);
  return value;
}

/**
 * The input motion the rates are computed for: ω2 (rad/s) signed by the animation's direction, α2 (rad/s²)
 * as set. A rocking input reverses at its limits (the animation flips direction there), so ω2 changes sign
 * in step with it; α2 keeps its sign (reversing time flips velocities, not accelerations).
 */
export function effectiveInputMotion(omega2RadPerS: number, alpha2RadPerS2: number, direction: Direction): InputMotion {
  return { omega2: direction * omega2RadPerS, alpha2: alpha2RadPerS2 };
}
