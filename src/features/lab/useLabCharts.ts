import { useCallback, useMemo } from 'react';
import { drawCycleChart } from './cycleChart';
import { formatMaxError, shownTol, workPrecisionDrawing } from './workPrecisionChart';
import type { WorkPrecisionChartOptions, WorkPrecisionHighlight } from './workPrecisionChart';
import type { LabPoint, LabResult, LabSeries } from '../../study/workPrecision';
import type { SweepMethod } from '../../solver/types';
import type { Messages } from '../../shared/i18n/messages';
import type { LabMessages } from './labMessages';

/** The lab's two charts: the diagram's options (shared with its export) and the draws of both SVG views. */
export interface LabCharts {
  chartOptions: WorkPrecisionChartOptions;
  drawDiagram: (svg: SVGSVGElement, width: number, height: number) => void;
  drawCycle: (svg: SVGSVGElement, width: number, height: number) => void;
}

/** The work-precision diagram's texts, highlight and tooltips, in the page's language (any size). */
function diagramOptions(t: Messages, lt: LabMessages, highlight: WorkPrecisionHighlight): LabCharts['chartOptions'] {
  return {
    title: lt.labDiagramTitle,
    xLabel: lt.labDiagramX,
    yLabel: lt.labDiagramY,
    highlight,
    methodLabels: t.methodNames,
    defaultTolText: lt.labToleranceDefault,
    defaultLegend: lt.labLegendDefault,
    failureLegend: lt.labLegendFailed,
    tooltip: (s: LabSeries, p: LabPoint) =>
      lt.labPointTooltip(
        t.methodNames[s.method],
        shownTol(p.tol, lt.labToleranceDefault),
        p.nsPerPoint.toFixed(0),
        formatMaxError(p.maxError),
      ),
    emptyText: t.labRun + '…',
  };
}

/** Options and draw callbacks of the work-precision diagram and the cycle chart, stable while their inputs are. */
export function useLabCharts(
  result: LabResult | null,
  t: Messages,
  lt: LabMessages,
  method: SweepMethod,
  tol: number | null,
  theta2Deg: number,
): LabCharts {
  const highlight = useMemo(() => ({ method, tol }), [method, tol]);
  const chartOptions = useMemo(() => diagramOptions(t, lt, highlight), [t, lt, highlight]);
  const drawDiagram = useMemo(
    () => workPrecisionDrawing(result ? result.series : [], chartOptions),
    [result, chartOptions],
  );
  const drawCycle = useCallback(
    (svg: SVGSVGElement, width: number, height: number) => {
      if (!result) return;
      drawCycleChart(
        svg,
        {
          theta2Deg: result.theta2Deg,
          detJ: result.detJ,
          iterations: result.iterations.map((it) => ({ ...it, label: t.methodNames[it.method] })),
          limitsDeg: result.limitsDeg,
          currentDeg: theta2Deg,
        },
        {
          width,
          height,
          title: lt.labCycleTitle,
          xLabel: t.axisTheta2,
          iterationsLabel: lt.labCycleIterations,
          detJLabel: lt.labCycleDetJ,
        },
      );
    },
    [result, t, lt, theta2Deg],
  );
  return { chartOptions, drawDiagram, drawCycle };
}
