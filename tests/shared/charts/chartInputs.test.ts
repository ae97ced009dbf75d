import { describe, expect, it } from 'vitest';
import type { AngleSeries } from '../../../src/shared/charts/theta2Chart';
import { angleSpec } from '../../../src/shared/charts/theta2Chart';
import { chartFrame, chartSize, curvePath, markerPlacement } from '../../../src/shared/charts/chart';
import type { AngleChartKind } from '../../../src/shared/charts/chartInputs';
import {
  angleChartInputs,
  angleMarker,
  convergenceInputs,
  cycleDegrees,
  plotDegrees,
} from '../../../src/shared/charts/chartInputs';
import type { Branch } from '../../../src/solver/types';
import { messagesEn } from '../../../src/shared/i18n/messagesEn';
import { COLORS } from '../../../src/shared/theme/tokens';
import type { CycleResponse, NewtonSummary, PlotSeries, PointResponse } from '../../../src/shared/solution';
import type { LinkLengths, Sigma } from '../../oracle/reference';
import { deg, exactToDeg, referenceAngles } from '../../oracle/reference';

/** Grashof crank-rocker (the app's default): the crank turns fully. */
const CRANK_ROCKER: LinkLengths = { r1: 6, r2: 2, r3: 5, r4: 5 };
/** Grashof with the coupler shortest: a double rocker, so both branches have gaps where they cannot assemble. */
const DOUBLE_ROCKER: LinkLengths = { r1: 5, r2: 3.5, r3: 2, r4: 4 };
const SIGMA: Record<Branch, Sigma> = { open: 1, crossed: -1 };
/** Degrees: the code converts radians once (radToDeg180), the oracle exactly; a few ulps of 180. */
const DEG_TOL = 1e-9;

/** theta2 grid in degrees, 0 to 360 every 1.5 degrees (the oracle's 60-digit solves are slow). */
const GRID_DEG = Float64Array.from({ length: 241 }, (_v, k) => 1.5 * k);

const oracleCache = new Map<string, { theta3: number; theta4: number } | null>();

/** The oracle's pose on a branch at theta2 degrees (memoised), or null where it cannot assemble. */
function oraclePose(l: LinkLengths, theta2Deg: number, branch: Branch): { theta3: number; theta4: number } | null {
  const key = `${l.r1} ${l.r2} ${l.r3} ${l.r4} ${theta2Deg} ${branch}`;
  if (!oracleCache.has(key)) oracleCache.set(key, referenceAngles(l, deg(theta2Deg), SIGMA[branch]));
  return oracleCache.get(key)!;
}

/** The oracle's angle (radians) of one quantity on one branch at theta2 degrees; NaN where it cannot assemble. */
function oracleRad(l: LinkLengths, theta2Deg: number, branch: Branch, key: 'theta3' | 'theta4'): number {
  const p = oraclePose(l, theta2Deg, branch);
  return p ? p[key] : Number.NaN;
}

/** The oracle's angle in degrees in (-180, 180], NaN where it cannot assemble. */
function oracleDeg(l: LinkLengths, theta2Deg: number, branch: Branch, key: 'theta3' | 'theta4'): number {
  const r = oracleRad(l, theta2Deg, branch, key);
  return Number.isNaN(r) ? Number.NaN : exactToDeg(r);
}

/** Both branches' angles on the grid from the oracle (radians). */
function oracleBranch(l: LinkLengths, b: Branch) {
  return {
    theta3: GRID_DEG.map((t) => oracleRad(l, t, b, 'theta3')),
    theta4: GRID_DEG.map((t) => oracleRad(l, t, b, 'theta4')),
  };
}

/** A cycle answer as the worker sends it, its angles from the oracle; the fields the charts do not read are left out. */
function oracleCycle(l: LinkLengths): CycleResponse {
  const cycle = { theta2Deg: GRID_DEG, open: oracleBranch(l, 'open'), crossed: oracleBranch(l, 'crossed') };
  return cycle as unknown as CycleResponse;
}

/** Plot samples as the main thread solves them, on the same grid, from the oracle. */
function oraclePlot(l: LinkLengths): PlotSeries {
  return { theta2Deg: GRID_DEG, open: oracleBranch(l, 'open'), crossed: oracleBranch(l, 'crossed') };
}

/** A pose answer at theta2 degrees with the oracle's angles on the branch; no NR runs. */
function oraclePoint(l: LinkLengths, theta2Deg: number, branch: Branch): PointResponse {
  const pose = oraclePose(l, theta2Deg, branch);
  return {
    theta2Rad: deg(theta2Deg),
    branch,
    pose: pose ? { theta3: pose.theta3, theta4: pose.theta4 } : null,
    continuation: null,
    cold: null,
  } as unknown as PointResponse;
}

function expectSeries(values: ArrayLike<number>, l: LinkLengths, branch: Branch, key: 'theta3' | 'theta4') {
  expect(values.length).toBe(GRID_DEG.length);
  let finite = 0;
  for (let i = 0; i < GRID_DEG.length; i++) {
    const want = oracleDeg(l, GRID_DEG[i], branch, key);
    if (Number.isNaN(want)) {
      expect(values[i], `gap at ${GRID_DEG[i]}°`).toBeNaN();
      continue;
    }
    finite++;
    expect(Math.abs(values[i] - want), `${key} at ${GRID_DEG[i]}°`).toBeLessThanOrEqual(DEG_TOL);
  }
  expect(finite).toBeGreaterThan(40);
}

describe('angleChartInputs', () => {
  for (const [name, l] of [
    ['crank-rocker', CRANK_ROCKER],
    ['double rocker', DOUBLE_ROCKER],
  ] as const) {
    for (const withPlot of [false, true]) {
      const deg3 = withPlot ? plotDegrees(oraclePlot(l)) : cycleDegrees(oracleCycle(l));
      const source = withPlot ? 'plot samples' : 'cycle table';
      it(`feeds the theta3 chart theta3 and the theta4 chart theta4 (${name}, ${source})`, () => {
        for (const branch of ['open', 'crossed'] as const) {
          const in3 = angleChartInputs('theta3', deg3, branch, false, messagesEn);
          const in4 = angleChartInputs('theta4', deg3, branch, false, messagesEn);
          expect(in3.data.series).toHaveLength(1);
          expect(in4.data.series).toHaveLength(1);
          expectSeries(in3.data.series[0].valuesDeg, l, branch, 'theta3');
          expectSeries(in4.data.series[0].valuesDeg, l, branch, 'theta4');
          expect(Array.from(in3.data.theta2Deg)).toEqual(Array.from(GRID_DEG));
        }
      });
    }
  }

  it('puts theta3 then theta4 in the combined chart, each the other branch faint first when asked', () => {
    const d = plotDegrees(oraclePlot(CRANK_ROCKER));
    const both = angleChartInputs('both', d, 'crossed', true, messagesEn).data.series;
    expect(both.map((s) => [s.label.startsWith('θ3') ? 'θ3' : 'θ4', s.faint === true])).toEqual([
      ['θ3', true],
      ['θ3', false],
      ['θ4', true],
      ['θ4', false],
    ]);
    expectSeries(both[0].valuesDeg, CRANK_ROCKER, 'open', 'theta3');
    expectSeries(both[1].valuesDeg, CRANK_ROCKER, 'crossed', 'theta3');
    expectSeries(both[2].valuesDeg, CRANK_ROCKER, 'open', 'theta4');
    expectSeries(both[3].valuesDeg, CRANK_ROCKER, 'crossed', 'theta4');
  });

  it('draws theta3 in the coupler colour and theta4 in the rocker colour, as the links are drawn', () => {
    const d = cycleDegrees(oracleCycle(CRANK_ROCKER));
    const both = angleChartInputs('both', d, 'open', false, messagesEn).data.series;
    expect(both.map((s) => s.color)).toEqual([COLORS.coupler, COLORS.rocker]);
    expect(angleChartInputs('theta4', d, 'open', false, messagesEn).data.series[0].color).toBe(COLORS.rocker);
  });

  it('has no curve and no samples before the first cycle', () => {
    const in4 = angleChartInputs('theta4', null, 'open', false, messagesEn);
    expect(in4.data.theta2Deg.length).toBe(0);
    expect(in4.data.series.every((s) => s.valuesDeg.length === 0)).toBe(true);
  });
});

describe('angleMarker', () => {
  it('takes theta3 from theta3 and theta4 from theta4, in series order', () => {
    for (const branch of ['open', 'crossed'] as const) {
      const p = oraclePoint(CRANK_ROCKER, 123.4, branch);
      const t3 = oracleDeg(CRANK_ROCKER, 123.4, branch, 'theta3');
      const t4 = oracleDeg(CRANK_ROCKER, 123.4, branch, 'theta4');
      expect(Math.abs(t3 - t4)).toBeGreaterThan(10);
      const close = (got: number[], want: number[]) =>
        got.length === want.length && got.every((v, i) => Math.abs(v - want[i]) <= DEG_TOL);
      expect(close(angleMarker('theta3', p).valuesDeg, [t3])).toBe(true);
      expect(close(angleMarker('theta4', p).valuesDeg, [t4])).toBe(true);
      expect(close(angleMarker('both', p).valuesDeg, [t3, t4])).toBe(true);
    }
  });

  it('puts theta2 on the 0..360 axis and hides the values where the linkage cannot assemble', () => {
    expect(angleMarker('theta4', oraclePoint(CRANK_ROCKER, -30, 'open')).theta2Deg).toBeCloseTo(330, 9);
    const gap = oraclePoint(DOUBLE_ROCKER, 0, 'open');
    expect(gap.pose).toBeNull();
    expect(angleMarker('both', gap).valuesDeg.every(Number.isNaN)).toBe(true);
    expect(angleMarker('theta3', null).theta2Deg).toBeNaN();
  });
});

/** Polyline vertices of each subpath of SVG path data made of M and L commands. */
function subpaths(d: string): Array<Array<[number, number]>> {
  const out: Array<Array<[number, number]>> = [];
  for (const m of d.matchAll(/([ML])([^ML]+)/g)) {
    const [x, y] = m[2].split(',').map(Number);
    if (m[1] === 'M') out.push([]);
    out[out.length - 1].push([x, y]);
  }
  return out;
}

/**
 * The path's y at x (pixels), interpolated on the segment that spans x, with a bound on how far the
 * polyline may sit from the true curve there: chord error h^2 |f''| / 8, with h^2 f'' taken from the
 * second differences of the neighbouring vertices (doubled for safety), plus twice the path's 0.005 px rounding (it keeps hundredths of a pixel).
 */
function pathYAt(d: string, x: number): { y: number; bound: number } | null {
  for (const pts of subpaths(d)) {
    for (let i = 0; i + 1 < pts.length; i++) {
      const [x0, y0] = pts[i];
      const [x1, y1] = pts[i + 1];
      if (x < x0 || x > x1 || x1 === x0) continue;
      const y = y0 + ((x - x0) / (x1 - x0)) * (y1 - y0);
      let d2 = 0;
      for (let j = Math.max(1, i - 1); j <= Math.min(pts.length - 2, i + 2); j++) {
        d2 = Math.max(d2, Math.abs(pts[j + 1][1] - 2 * pts[j][1] + pts[j - 1][1]));
      }
      return { y, bound: (2 * d2) / 8 + 1e-2 };
    }
  }
  return null;
}

describe('angle chart marker (angleChartInputs, angleMarker, angleSpec, markerPlacement)', () => {
  const size = chartSize({ width: 560, height: 320 });
  for (const kind of ['theta3', 'theta4', 'both'] as AngleChartKind[]) {
    for (const branch of ['open', 'crossed'] as const) {
      it(`lies on its own curve in the ${kind} chart (${branch}, other branch shown)`, () => {
        const inputs = angleChartInputs(kind, plotDegrees(oraclePlot(CRANK_ROCKER)), branch, true, messagesEn);
        const series: AngleSeries[] = inputs.data.series;
        const frame = chartFrame(angleSpec, inputs.data, size);
        const paths = angleSpec.curves(inputs.data).map((c) => curvePath(c, frame));
        const where = angleSpec.marker!(angleMarker(kind, oraclePoint(CRANK_ROCKER, 123.4, branch)), inputs.data);
        const g = markerPlacement(where, frame);
        const solid = series.map((s, i) => ({ s, d: paths[i] })).filter((p) => !p.s.faint);
        expect(g.dots).toHaveLength(solid.length);
        expect(g.x).toBeCloseTo(frame.x(123.4), 9);
        for (const dot of g.dots) {
          const own = solid.filter((p) => p.s.color === dot.color);
          expect(own).toHaveLength(1);
          const at = pathYAt(own[0].d, dot.cx);
          expect(at).not.toBeNull();
          expect(Math.abs(at!.y - dot.cy)).toBeLessThanOrEqual(at!.bound);
          expect(at!.bound).toBeLessThan(0.5);
          // Discriminating: the marker is far from the other quantity's and the other branch's curves.
          for (const p of series.map((s, i) => ({ s, d: paths[i] })).filter((q) => q.d !== own[0].d)) {
            const other = pathYAt(p.d, dot.cx);
            if (other) expect(Math.abs(other.y - dot.cy)).toBeGreaterThan(5);
          }
        }
      });
    }
  }
});

describe('convergenceInputs', () => {
  const run = (start: 'continuation' | 'cold', residuals: number[]): NewtonSummary =>
    ({
      start,
      iterations: residuals.length - 1,
      tolerance: 1e-12,
      log: residuals.map((residual, iteration) => ({ iteration, residual })),
    }) as unknown as NewtonSummary;
  const point = {
    ...oraclePoint(CRANK_ROCKER, 45, 'open'),
    continuation: run('continuation', [1e-3, 1e-7, 1e-14]),
    cold: run('cold', [2, 0.5, 1e-2, 1e-5, 1e-11, 1e-16]),
  } as PointResponse;

  it('draws the chosen start solid on top and the other faint, each with its own residuals', () => {
    for (const start of ['continuation', 'cold'] as const) {
      const runs = convergenceInputs(point, start, messagesEn).runs;
      expect(runs.map((r) => r.faint)).toEqual([true, false]);
      const chosen = start === 'continuation' ? point.continuation! : point.cold!;
      const other = start === 'continuation' ? point.cold! : point.continuation!;
      expect(runs[1].residuals).toEqual(chosen.log.map((r) => r.residual));
      expect(runs[0].residuals).toEqual(other.log.map((r) => r.residual));
      expect(runs[1].iterations).toEqual(chosen.log.map((r) => r.iteration));
    }
  });

  it('draws the tolerance of the chosen run and names theta2 in the title', () => {
    const c = convergenceInputs(point, 'cold', messagesEn);
    expect(c.tolerance).toBe(1e-12);
    expect(c.title).toContain('45');
  });
});
