import { describe, expect, it } from 'vitest';
import { chartSize, markerPlacement, plotArea } from '../../../src/shared/charts/chart';
import { createXYChart, xyFrame } from '../../../src/shared/charts/xyChart';
import { localPose } from '../../../src/shared/linkage/localPose';
import { fakeSvg } from '../../shared/charts/fakeSvgDom';
import { rateSpec } from '../../../src/shared/charts/rateChart';
import { DEFAULT_STATE } from '../../../src/shared/state/appState';
import type { AppState } from '../../../src/shared/state/appState';
import { forcesMessagesEn as t } from '../../../src/features/forces/forcesMessagesEn';
import {
  BEARING_FIT,
  FORCE_EXPORT_SIZE,
  bearingInputs,
  bearingMarker,
  pinForceInputs,
  plotUnit,
} from '../../../src/features/forces/forceCharts';
import { cycleForces } from '../../../src/features/forces/forceCycleData';
import { forceSetup, poseForces } from '../../../src/features/forces/forceModel';

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

describe('bearingMarker', () => {
  it("draws the θ2 cursor as a radius from the crank bearing's centre (0, 0) to this pose's F12, with its dot", () => {
    const setup = forceSetup(ON);
    const c = cycleForces(setup, 'open', 360);
    const { data, unit } = bearingInputs(c, t);
    const local = localPose(ON.design.linkage, 60, 'open', ON.design.coupler, false);
    const p = poseForces(setup, local.theta2Rad, local.pose);
    const f12 = p.forces!.F12;
    const frame = xyFrame(data, plotArea(chartSize(FORCE_EXPORT_SIZE.bearing)), BEARING_FIT);
    const at = markerPlacement(bearingMarker(p, unit), frame);
    // The segment's ends are the scales of the origin and of F12 in the plot unit: exact up to the scale's rounding.
    const close = (a: number, b: number) => expect(a).toBeCloseTo(b, 9);
    expect(at.segment).toBeDefined();
    close(at.segment!.x1, frame.x(0));
    close(at.segment!.y1, frame.y(0));
    close(at.segment!.x2, frame.x(f12.x * unit.factor));
    close(at.segment!.y2, frame.y(f12.y * unit.factor));
    expect(at.dots).toHaveLength(1);
    close(at.dots[0].cx, at.segment!.x2);
    close(at.dots[0].cy, at.segment!.y2);
  });

  it('draws the radius line, not a full-height vertical line, in an exported SVG', () => {
    const setup = forceSetup(ON);
    const c = cycleForces(setup, 'open', 360);
    const local = localPose(ON.design.linkage, 60, 'open', ON.design.coupler, false);
    const p = poseForces(setup, local.theta2Rad, local.pose);
    const svg = fakeSvg();
    const { data, unit, ...text } = bearingInputs(c, t);
    const chart = createXYChart(svg, { ...text, ...FORCE_EXPORT_SIZE.bearing, ...BEARING_FIT });
    chart.update(data);
    chart.setMarker(bearingMarker(p, unit));
    const line = svg.querySelector('g.marker line.mline')!;
    const dot = svg.querySelector('g.marker circle')!;
    expect(Number(line.getAttribute('x2'))).toBeCloseTo(Number(dot.getAttribute('cx')), 9);
    expect(Number(line.getAttribute('y2'))).toBeCloseTo(Number(dot.getAttribute('cy')), 9);
    expect(Number(line.getAttribute('x1'))).not.toBeCloseTo(Number(line.getAttribute('x2')), 3);
  });

  it('hides the cursor where F12 is undetermined', () => {
    const p = { status: 'limit-position' as const, forces: null, sinMu: Number.NaN };
    expect(
      markerPlacement(
        bearingMarker(p, plotUnit()),
        xyFrame({ series: [] }, plotArea(chartSize({ width: 300, height: 300 }))),
      ).x,
    ).toBeNull();
  });
});
