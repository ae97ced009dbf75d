import { describe, expect, it } from 'vitest';
import { OMEGA_UNITS, effectiveInputMotion, omegaFromUnit, omegaToUnit } from '../../../src/shared/state/inputMotion';

// Independent conversions written out here: one turn is 2 pi rad = 360 degrees, a minute is 60 s.
const TURN_RAD = 2 * Math.PI;
// One or two roundings in each conversion: a few ulps relative.
const REL = 4 * Number.EPSILON;

describe('omegaFromUnit and omegaToUnit', () => {
  it('reads rpm as turns per minute', () => {
    expect(omegaFromUnit(120, 'rpm')).toBeCloseTo((120 * TURN_RAD) / 60, 13);
    expect(Math.abs(omegaFromUnit(60, 'rpm') - TURN_RAD)).toBeLessThanOrEqual(REL * TURN_RAD);
  });
  it('reads degrees per second as 360 per turn', () => {
    expect(Math.abs(omegaFromUnit(360, 'deg/s') - TURN_RAD)).toBeLessThanOrEqual(REL * TURN_RAD);
    expect(Math.abs(omegaFromUnit(-90, 'deg/s') + TURN_RAD / 4)).toBeLessThanOrEqual(REL * TURN_RAD);
  });
  it('keeps rad/s as it is', () => {
    expect(omegaFromUnit(10, 'rad/s')).toBe(10);
    expect(omegaToUnit(-3.5, 'rad/s')).toBe(-3.5);
  });
  it('shows the default 10 rad/s as 95.49 rpm and 572.96 deg/s', () => {
    expect(omegaToUnit(10, 'rpm')).toBeCloseTo((10 * 60) / TURN_RAD, 12);
    expect(omegaToUnit(10, 'deg/s')).toBeCloseTo((10 * 360) / TURN_RAD, 11);
  });
  it('round-trips every unit to a few ulps', () => {
    for (const unit of OMEGA_UNITS) {
      for (const w of [1e-6, 0.3, 10, -42.5, 1e5]) {
        expect(Math.abs(omegaFromUnit(omegaToUnit(w, unit), unit) - w)).toBeLessThanOrEqual(REL * Math.abs(w));
      }
    }
  });
});

describe('effectiveInputMotion', () => {
  it('signs ω2 by the animation direction and keeps α2', () => {
    expect(effectiveInputMotion(10, 2, 1)).toEqual({ omega2: 10, alpha2: 2 });
    expect(effectiveInputMotion(10, 2, -1)).toEqual({ omega2: -10, alpha2: 2 });
    expect(effectiveInputMotion(-4, -1, -1)).toEqual({ omega2: 4, alpha2: -1 });
  });
});
