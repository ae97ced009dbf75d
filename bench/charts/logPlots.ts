import type { ConvergenceRun } from '../../src/shared/charts/convergenceChart';
import { createConvergenceChart } from '../../src/shared/charts/convergenceChart';
import { drawWorkPrecisionChart } from '../../src/features/lab/workPrecisionChart';
import { drawCycleChart } from '../../src/features/lab/cycleChart';
import type { LabResult } from '../../src/study/workPrecision';
import type { SweepMethod } from '../../src/solver/types';

/** The simulator's live convergence chart and the lab's two charts, driven the way their views drive them. */
export function makeLogCharts(
  svgs: { conv: SVGSVGElement; wp: SVGSVGElement; cycle: SVGSVGElement },
  width: number,
  height: number,
) {
  const text = { title: 'NR convergence', xLabel: 'iteration', yLabel: '|f|', toleranceLabel: 'tol', emptyText: '' };
  const conv = createConvergenceChart(svgs.conv, { ...text, width, height });
  return {
    convergence(runs: ConvergenceRun[], tolerance: number) {
      conv.update({ runs, tolerance });
    },
    diagram(r: LabResult, method: SweepMethod, tol: number) {
      drawWorkPrecisionChart(svgs.wp, r.series, {
        width,
        height,
        title: 'WP',
        xLabel: 'ns',
        yLabel: 'err',
        highlight: { method, tol },
      });
    },
    cycle(r: LabResult, theta2Deg: number) {
      drawCycleChart(
        svgs.cycle,
        {
          theta2Deg: r.theta2Deg,
          detJ: r.detJ,
          iterations: r.iterations,
          limitsDeg: r.limitsDeg,
          currentDeg: theta2Deg,
        },
        { width, height, title: 'cycle', xLabel: 'θ2', iterationsLabel: 'it', detJLabel: 'detJ' },
      );
    },
  };
}
