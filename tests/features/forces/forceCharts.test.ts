import { describe, expect, it } from 'vitest';
import { chartSize, plotArea } from '../../../src/shared/charts/chart';
import { rateSpec } from '../../../src/shared/charts/rateChart';
import { DEFAULT_STATE } from '../../../src/shared/state/appState';
import type { AppState } from '../../../src/shared/state/appState';
import { forcesMessagesEn as t } from '../../../src/features/forces/forcesMessagesEn';
import { FORCE_EXPORT_SIZE, pinForceInputs } from '../../../src/features/forces/forceCharts';
import { cycleForces } from '../../../src/features/forces/forceCycleData';
import { forceSetup } from '../../../src/features/forces/forceModel';

/** The app's defaults with the forces on: 1 kg/m bars under gravity; one pin force passes within 7 N of 0. */
const ON: AppState = { ...DEFAULT_STATE, forces: { ...DEFAULT_STATE.forces, enabled: true } };
/** Weightless bars and no gravity, 40 N along x at P: every pin force stays above 17 N. */
const AWAY_FROM_ZERO: AppState = {
  ...ON,
  forces: { ...ON.forces, rhoKgPerM: 0, gravityMPerS2: 0, pointForceXN: 40 },
};

/**
 * The y axis of the pin-force chart for a state, as drawn on screen and exported (the rate spec's frame at the
 * export size), and the smallest and largest magnitude plotted (in the plot's unit).
 */
function pinForceAxis(state: AppState) {
  const c = cycleForces(forceSetup(state), 'open', 360);
  if (!c) throw new Error('the solver refused the setup');
  const { data } = pinForceInputs(c, t);
  const frame = rateSpec.frame(data, plotArea(chartSize(FORCE_EXPORT_SIZE.pinForces)));
  const plotted = data.series.flatMap((s) => Array.from(s.values)).filter(Number.isFinite);
  return { domain: frame.y.domain(), ticks: frame.yTicks, min: Math.min(...plotted), max: Math.max(...plotted) };
}

describe('pinForceInputs', () => {
  it('starts the y axis at exactly 0 where a pin force passes near 0, with no tick below it', () => {
    const { domain, ticks, min } = pinForceAxis(ON);
    // Within 1 % of the axis of 0: the data-led padding (6 % of the range) would reach below 0.
    expect(min).toBeLessThan(0.01 * domain[1]);
    expect(domain[0]).toBe(0);
    expect(ticks[0]).toBe(0);
  });

  it('starts the y axis at 0 too when every pin force stays well above 0', () => {
    const { domain, ticks, min } = pinForceAxis(AWAY_FROM_ZERO);
    expect(min).toBeGreaterThan(0.3 * domain[1]);
    expect(domain[0]).toBe(0);
    expect(ticks[0]).toBe(0);
  });

  it('ends the axis on a tick at or above the largest magnitude (the curves are compact: none is cut)', () => {
    for (const state of [ON, AWAY_FROM_ZERO]) {
      const { domain, ticks, max } = pinForceAxis(state);
      expect(domain[1]).toBeGreaterThanOrEqual(max);
      expect(ticks[ticks.length - 1]).toBe(domain[1]);
    }
  });
});
