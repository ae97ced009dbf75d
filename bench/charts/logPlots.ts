import type { ConvergenceRun } from '../../src/shared/charts/convergenceChart';
import { createConvergenceChart } from '../../src/shared/charts/convergenceChart';
import { createChart } from '../../src/shared/charts/chart';
import { WORK_PRECISION_SIZE, workPrecisionSpec } from '../../src/features/lab/workPrecisionChart';
import type { WorkPrecisionData } from '../../src/features/lab/workPrecisionChart';
import { createCycleChart } from '../../src/features/lab/cycleChart';
import type { CycleChartData } from '../../src/features/lab/cycleChart';
import type { LabResult } from '../../src/study/workPrecision';
import type { SweepMethod } from '../../src/solver/types';

/**
 * The simulator's live convergence chart and the lab's two charts, driven the way their views drive them: one handle
 * each, created once; a redraw is the update a view makes (new runs, a new highlight, a new θ2 on the cycle chart).
 */
export function makeLogCharts(
  svgs: { conv: SVGSVGElement; wp: SVGSVGElement; cycle: SVGSVGElement },
  width: number,
  height: number,
) {
  const text = { title: 'NR convergence', xLabel: 'iteration', yLabel: '|f|', emptyText: '' };
  const conv = createConvergenceChart(svgs.conv, width, height, text);
  const wpText = { title: 'WP', xLabel: 'ns', yLabel: 'err' };
  const empty: WorkPrecisionData = { series: [] };
  const wp = createChart(svgs.wp, { ...WORK_PRECISION_SIZE, width, height }, wpText, workPrecisionSpec({}), empty);
  const cycleText = { title: 'cycle', xLabel: 'θ2', iterationsLabel: 'it', detJLabel: 'detJ' };
  const cycleChart = createCycleChart(svgs.cycle, { width, height, ...cycleText });
  let cycleData: LabResult | null = null;
  return {
    convergence(runs: ConvergenceRun[], tolerance: number) {
      conv.update({ runs, tolerance, toleranceLabel: 'tol' });
    },
    diagram(r: LabResult, method: SweepMethod, tol: number) {
      wp.update({ series: r.series, highlight: { method, tol } });
    },
    cycle(r: LabResult, theta2Deg: number) {
      if (cycleData !== r) {
        cycleData = r;
        const data: CycleChartData = {
          theta2Deg: r.theta2Deg,
          detJ: r.detJ,
          iterations: r.iterations,
          limitsDeg: r.limitsDeg,
        };
        cycleChart.update(data);
      }
      cycleChart.setMarker(theta2Deg);
    },
  };
}
