import './SvgChartView.css';
import { useLayoutEffect } from 'react';
import type { MarkerAt } from './chart';
import type { XYChartData } from './xyChart';
import { createXYChart } from './xyChart';
import { useLiveChart } from './useLiveChart';

/** Props of XYChartView: the series, the marker (null: none), the texts, the box's class and a test id. */
export interface XYChartViewProps {
  data: XYChartData;
  marker: MarkerAt | null;
  texts: { title: string; xLabel: string; yLabel: string };
  testId: string;
  /** The chart box's own class, beside chart-box. */
  className: string;
  /** x is an angle over one turn: the axis spans 0 to 360 unless the data give their own xDomain (an input that rocks). */
  fullTurn?: boolean;
}

/** A new x–y chart at size 0 (drawn once the view knows its box); module-level, as useLiveChart asks. */
const newChart = (svg: SVGSVGElement, markerHost: HTMLElement | undefined) =>
  createXYChart(svg, { width: 0, height: 0, title: '', xLabel: '', yLabel: '', markerHost });
/** The same over a full turn of x (degrees). */
const newTurnChart = (svg: SVGSVGElement, markerHost: HTMLElement | undefined) =>
  createXYChart(svg, { width: 0, height: 0, title: '', xLabel: '', yLabel: '', markerHost, xDomain: [0, 360] });

/** One x–y plot on the chart kit's spec, live: its marker follows the frame on screen (the mechanism and spatial pages). */
export function XYChartView({ data, marker, texts, testId, className, fullTurn = false }: XYChartViewProps) {
  const { chart, boxRef, svgRef, markerRef } = useLiveChart(fullTurn ? newTurnChart : newChart, data, marker);
  const { title, xLabel, yLabel } = texts;
  useLayoutEffect(() => {
    chart?.setText({ title, xLabel, yLabel });
  }, [chart, title, xLabel, yLabel]);
  return (
    <div className={`chart-box ${className}`} ref={boxRef}>
      <svg ref={svgRef} role="img" aria-label={title} className="chart-svg" data-testid={testId} />
      <div className="chart-marker" ref={markerRef} />
    </div>
  );
}
