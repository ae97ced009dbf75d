import '../../shared/charts/SvgChartView.css';
import { useLayoutEffect } from 'react';
import type { MarkerAt } from '../../shared/charts/chart';
import type { XYChartData } from '../../shared/charts/xyChart';
import { createXYChart } from '../../shared/charts/xyChart';
import { useLiveChart } from '../../shared/charts/useLiveChart';

/** Props of MechChart: the series against the input, the marker at the input on screen, the texts. */
export interface MechChartProps {
  data: XYChartData;
  marker: MarkerAt | null;
  texts: { title: string; xLabel: string; yLabel: string };
  testId: string;
}

/** A new x–y chart at size 0 (drawn once the view knows its box). */
const newChart = (svg: SVGSVGElement, markerHost: HTMLElement | undefined) =>
  createXYChart(svg, { width: 0, height: 0, title: '', xLabel: '', yLabel: '', markerHost });

/** One plot of the mechanism page against the input, on the chart kit's x–y spec; the marker follows Play. */
export function MechChart({ data, marker, texts, testId }: MechChartProps) {
  const { chart, boxRef, svgRef, markerRef } = useLiveChart(newChart, data, marker);
  const { title, xLabel, yLabel } = texts;
  useLayoutEffect(() => {
    chart?.setText({ title, xLabel, yLabel });
  }, [chart, title, xLabel, yLabel]);
  return (
    <div className="chart-box mech-chart" ref={boxRef}>
      <svg ref={svgRef} role="img" aria-label={title} className="chart-svg" data-testid={testId} />
      <div className="chart-marker" ref={markerRef} />
    </div>
  );
}
