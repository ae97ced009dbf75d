import '../../shared/charts/SvgChartView.css';
import { useLayoutEffect } from 'react';
import type { MarkerAt } from '../../shared/charts/chart';
import type { XYChartData } from '../../shared/charts/xyChart';
import { createXYChart } from '../../shared/charts/xyChart';
import { useLiveChart } from '../../shared/charts/useLiveChart';

/** Props of SpatialChart: the series, the marker at θ2, the texts and a test id. */
export interface SpatialChartProps {
  data: XYChartData;
  marker: MarkerAt;
  texts: { title: string; xLabel: string; yLabel: string };
  testId: string;
}

/** A new x–y chart at size 0 (drawn once the view knows its box). */
const newChart = (svg: SVGSVGElement, markerHost: HTMLElement | undefined) =>
  createXYChart(svg, { width: 0, height: 0, title: '', xLabel: '', yLabel: '', markerHost, xDomain: [0, 360] });

/** One plot of the spatial page against θ2 (degrees), on the chart kit's x–y spec, with the marker at θ2. */
export function SpatialChart({ data, marker, texts, testId }: SpatialChartProps) {
  const { chart, boxRef, svgRef, markerRef } = useLiveChart(newChart, data, marker);
  const { title, xLabel, yLabel } = texts;
  useLayoutEffect(() => {
    chart?.setText({ title, xLabel, yLabel });
  }, [chart, title, xLabel, yLabel]);
  return (
    <div className="chart-box spatial-chart" ref={boxRef}>
      <svg ref={svgRef} role="img" aria-label={title} className="chart-svg" data-testid={testId} />
      <div className="chart-marker" ref={markerRef} />
    </div>
  );
}
