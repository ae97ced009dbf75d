import { describe, expect, it } from 'vitest';
import { outsideBandRuns } from '../../../src/shared/charts/transmissionChart';
import { xMarkPositions } from '../../../src/shared/charts/xMarks';
import { solveClosedForm } from '../../../src/solver/closedForm';
import { transmissionAngle } from '../../../src/solver/kinematics';
import { deadCentreXMarks, transmissionData } from '../../../src/shared/charts/transmissionInputs';
import { designMetrics } from '../../../src/solver/metrics';
import { messagesEn } from '../../../src/shared/i18n/messagesEn';
import type { CycleDegrees } from '../../../src/shared/charts/chartInputs';
import { scaleLinear } from 'd3-scale';

const deg = (r: number) => (r * 180) / Math.PI;
const rad = (d: number) => (d * Math.PI) / 180;

/** mu of the report's 6-2-5-5 from the law of cosines (oracle: s^2 = 40 - 24 cos theta2, cos mu = (50 - s^2) / 50). */
const muReport = (t2Deg: number) => deg(Math.acos((50 - (40 - 24 * Math.cos(rad(t2Deg)))) / 50));
/** theta2 in [0, 180] where the report's mu equals muDeg (the inverse of muReport). */
const theta2AtMu = (muDeg: number) => deg(Math.acos((40 - (50 - 50 * Math.cos(rad(muDeg)))) / 24));

describe('outsideBandRuns', () => {
  it("finds the report's stretches outside a 60-100 degree band to within the sampling's interpolation error", () => {
    // 0.5 degree samples: linear interpolation of a smooth mu errs by under 0.01 degree of theta2 here.
    const t2: number[] = [];
    const mu: number[] = [];
    for (let d = 0; d <= 360; d += 0.5) {
      t2.push(d);
      mu.push(muReport(d));
    }
    const a = theta2AtMu(60);
    const b = theta2AtMu(100);
    const runs = outsideBandRuns(t2, mu, 60, 100);
    const expected = [
      [0, a],
      [b, 360 - b],
      [360 - a, 360],
    ];
    expect(runs).toHaveLength(3);
    runs.forEach((r, i) => {
      expect(Math.abs(r.x0 - expected[i][0])).toBeLessThan(0.01);
      expect(Math.abs(r.x1 - expected[i][1])).toBeLessThan(0.01);
    });
    // The default band holds the report's whole mu range (47.2 to 106.3 degrees).
    expect(outsideBandRuns(t2, mu, 40, 140)).toEqual([]);
  });

  it('ends a run at a gap and at the data ends, and counts a sample on an edge as inside', () => {
    const t2 = [0, 1, 2, 3, 4, 5, 6];
    const mu = [30, 30, Number.NaN, 50, 40, 35, 35];
    // A run before the gap ends at the last sample before it; a run leaving the band at a sample on its edge
    // starts at that sample (4) and runs to the end of the data.
    expect(outsideBandRuns(t2, mu, 40, 140)).toEqual([
      { x0: 0, x1: 1 },
      { x0: 4, x1: 6 },
    ]);
    // An interior crossing: 45 -> 35 crosses 40 halfway.
    expect(outsideBandRuns([0, 1, 2], [45, 35, 45], 40, 140)).toEqual([{ x0: 0.5, x1: 1.5 }]);
    expect(outsideBandRuns([0, 1], [40, 140], 40, 140)).toEqual([]);
  });
});

describe('transmissionData', () => {
  it('gives |theta4 - theta3| folded into [0, 180] on the branch, matching the law of cosines', () => {
    const l = { r1: 6, r2: 2, r3: 5, r4: 5 };
    const n = 72;
    const t2 = new Float64Array(n + 1);
    const open = { theta3: new Float64Array(n + 1), theta4: new Float64Array(n + 1) };
    const crossed = { theta3: new Float64Array(n + 1), theta4: new Float64Array(n + 1) };
    for (let i = 0; i <= n; i++) {
      t2[i] = (360 * i) / n;
      for (const [b, arr] of [
        ['open', open],
        ['crossed', crossed],
      ] as const) {
        const a = solveClosedForm(l, rad(t2[i]), b)!;
        arr.theta3[i] = ((deg(a.theta3) + 540) % 360) - 180;
        arr.theta4[i] = ((deg(a.theta4) + 540) % 360) - 180;
        expect(Math.abs(deg(transmissionAngle(a)) - muReport(t2[i]))).toBeLessThan(1e-9);
      }
    }
    const cd: CycleDegrees = { theta2Deg: t2, open, crossed };
    for (const b of ['open', 'crossed'] as const) {
      const d = transmissionData(cd, b);
      for (let i = 0; i <= n; i++) expect(Math.abs(d.muDeg[i] - muReport(t2[i]))).toBeLessThan(1e-9);
    }
    expect(transmissionData(null, 'open').muDeg.length).toBe(0);
  });
});

describe('xMarkPositions and deadCentreXMarks', () => {
  it('places the dead-centre rules at x(theta2) and leaves out marks off the axis', () => {
    const marks = deadCentreXMarks(designMetrics({ r1: 6, r2: 2, r3: 5, r4: 5 }, 'open'), messagesEn);
    expect(marks.map((m) => m.label)).toEqual(['ext.', 'fold.']);
    const x = scaleLinear().domain([0, 360]).range([0, 720]);
    const pos = xMarkPositions(
      [...marks, { xDeg: 400, label: 'off' }, { xDeg: -10, label: 'below' }, { xDeg: Number.NaN, label: 'nan' }],
      x,
    );
    expect(pos.map((p) => p.label)).toEqual(['ext.', 'fold.']);
    // The extended dead centre from the law of cosines: angle at O2 of the triangle (6, 7, 5).
    expect(Math.abs(pos[0].xPx - 2 * deg(Math.acos((36 + 49 - 25) / 84)))).toBeLessThan(1e-9);
    expect(deadCentreXMarks(null, messagesEn)).toEqual([]);
  });
});
