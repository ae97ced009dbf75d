import { useCallback, useMemo } from 'react';
import { createCycleChart } from './cycleChart';
import type { CycleChartData, CycleChartText } from './cycleChart';
import { WORK_PRECISION_SIZE, formatMaxError, shownTol, workPrecisionSpec } from './workPrecisionChart';
import type {
  WorkPrecisionChartOptions,
  WorkPrecisionData,
  WorkPrecisionHighlight,
  WorkPrecisionSpecOptions,
  WorkPrecisionText,
} from './workPrecisionChart';
import type { LabPoint, LabResult, LabSeries } from '../../study/workPrecision';
import type { SweepMethod } from '../../solver/types';
import type { Messages } from '../../shared/i18n/messages';
import { createChart } from '../../shared/charts/chart';
import type { TextedLiveChart } from '../../shared/charts/LiveChartView';
import type { LabMessages } from './labMessages';

/** What a LiveChartView of one of the lab's charts takes: its create function (stable per wording), data, marker, texts. */
export interface LabChartProps<D, M, T> {
  create: (svg: SVGSVGElement) => TextedLiveChart<D, M, T>;
  data: D;
  marker: M;
  text: T;
}

/** The lab's two charts: the diagram's options (shared with its export) and the live views' props of both. */
export interface LabCharts {
  chartOptions: WorkPrecisionChartOptions;
  diagram: LabChartProps<WorkPrecisionData, null, WorkPrecisionText>;
  /** The cycle chart; its marker is the current θ2 in degrees. */
  cycle: LabChartProps<CycleChartData, number, CycleChartText>;
}

/** The work-precision diagram's wording (method names, legend keys, tooltips) in the page's language. */
function diagramWording(t: Messages, lt: LabMessages): WorkPrecisionSpecOptions {
  return {
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
  };
}

/** Nothing drawn yet: the texts a lab chart is created with before its view sets them. */
const NO_TEXT = { title: '', xLabel: '', yLabel: '' };

/** The cycle chart of a view: created at size 0 without texts (its view sets them); the methods are named in its data. */
const createCycleView = (svg: SVGSVGElement) =>
  createCycleChart(svg, { width: 0, height: 0, ...NO_TEXT, iterationsLabel: '', detJLabel: '' });

/**
 * The lab's charts as live views, each created once per wording (a language change) and then updated in place:
 * a new result redraws the data, a new highlight the diagram's marks, a θ2 step only the cycle chart's marker.
 */
export function useLabCharts(
  result: LabResult | null,
  t: Messages,
  lt: LabMessages,
  method: SweepMethod,
  tol: number | null,
  theta2Deg: number,
): LabCharts {
  const highlight: WorkPrecisionHighlight = useMemo(() => ({ method, tol }), [method, tol]);
  const wording = useMemo(() => diagramWording(t, lt), [t, lt]);
  const diagramText = useMemo(
    () => ({ title: lt.labDiagramTitle, xLabel: lt.labDiagramX, yLabel: lt.labDiagramY, emptyText: t.labRun + '…' }),
    [t, lt],
  );
  const chartOptions = useMemo(() => ({ ...diagramText, ...wording, highlight }), [diagramText, wording, highlight]);
  const createDiagram = useCallback(
    (svg: SVGSVGElement) =>
      createChart(svg, { ...WORK_PRECISION_SIZE, width: 0, height: 0 }, NO_TEXT, workPrecisionSpec(wording), {
        series: [],
      } as WorkPrecisionData),
    [wording],
  );
  const diagramData = useMemo(() => ({ series: result ? result.series : [], highlight }), [result, highlight]);

  const methodNames = t.methodNames;
  const cycleText = useMemo(
    () => ({
      title: lt.labCycleTitle,
      xLabel: t.axisTheta2,
      iterationsLabel: lt.labCycleIterations,
      detJLabel: lt.labCycleDetJ,
    }),
    [t, lt],
  );
  const cycleData = useMemo(
    (): CycleChartData =>
      result
        ? {
            theta2Deg: result.theta2Deg,
            detJ: result.detJ,
            iterations: result.iterations.map((it) => ({ ...it, label: methodNames[it.method] })),
            limitsDeg: result.limitsDeg,
          }
        : { theta2Deg: new Float64Array(0), detJ: new Float64Array(0), iterations: [], limitsDeg: [] },
    [result, methodNames],
  );
  return {
    chartOptions,
    diagram: { create: createDiagram, data: diagramData, marker: null, text: diagramText },
    cycle: { create: createCycleView, data: cycleData, marker: theta2Deg, text: cycleText },
  };
}
