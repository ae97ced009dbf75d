import '../../../shared/charts/SvgChartView.css';
import { useLayoutEffect } from 'react';
import type { MarkerAt } from '../../../shared/charts/chart';
import type { XYChartData } from '../../../shared/charts/xyChart';
import { createXYChart } from '../../../shared/charts/xyChart';
import { useLiveChart } from '../../../shared/charts/useLiveChart';

/** Props of StructuralErrorChart: the series, the marker at the current x, and the texts. */
export interface StructuralErrorChartProps {
  data: XYChartData;
  marker: MarkerAt;
  texts: { title: string; xLabel: string; yLabel: string };
}

/** A new x–y chart at size 0 (drawn once the view knows its box). */
const newChart = (svg: SVGSVGElement, markerHost: HTMLElement | undefined) =>
  createXYChart(svg, { width: 0, height: 0, title: '', xLabel: '', yLabel: '', markerHost });

/** The structural error (結構誤差) against x with the precision points (精確點) as dots, on the chart kit's x–y spec. */
export function StructuralErrorChart({ data, marker, texts }: StructuralErrorChartProps) {
  const { chart, boxRef, svgRef, markerRef } = useLiveChart(newChart, data, marker);
  const { title, xLabel, yLabel } = texts;
  useLayoutEffect(() => {
    chart?.setText({ title, xLabel, yLabel });
  }, [chart, title, xLabel, yLabel]);
  return (
    <div className="chart-box synmode-error-chart" ref={boxRef}>
      <svg ref={svgRef} role="img" aria-label={title} className="chart-svg" data-testid="structural-error-chart" />
      <div className="chart-marker" ref={markerRef} />
    </div>
  );
}
