import './SvgChartView.css';
import { useLayoutEffect } from 'react';
import { createAngleChart } from '../charts/angleChart';
import type { AngleMarker } from '../charts/angleChart';
import type { XMark } from '../charts/xMarks';
import type { AngleChartInputs } from './chartInputs';
import { useLiveChart } from './useLiveChart';

/** Props of AngleChartView: everything the chart shows; it sizes itself to its box. */
export interface AngleChartViewProps {
  inputs: AngleChartInputs;
  marker: AngleMarker;
  /** Accessible name of the chart figure. */
  label: string;
  /** Faint theta2 rules (dead centres); default none. */
  xMarks?: readonly XMark[];
}

const NO_MARKS: readonly XMark[] = [];

/** A new angle chart at size 0 (drawn once the view knows its box). */
const newAngleChart = (svg: SVGSVGElement, markerHost: HTMLElement | undefined) =>
  createAngleChart(svg, { width: 0, height: 0, title: '', xLabel: '', yLabel: '', markerHost });

/**
 * A live angle chart: the chart is created once per SVG element; new data redraw the curves (the axes
 * only when their domain changes), a new marker only moves the marker, a new size redraws everything.
 */
export function AngleChartView({ inputs, marker, label, xMarks = NO_MARKS }: AngleChartViewProps) {
  const { data, title, xLabel, yLabel } = inputs;
  const { chart, boxRef, svgRef, markerRef } = useLiveChart(newAngleChart, data, marker);

  useLayoutEffect(() => {
    chart?.setText({ title, xLabel, yLabel });
  }, [chart, title, xLabel, yLabel]);
  useLayoutEffect(() => {
    chart?.setXMarks(xMarks);
  }, [chart, xMarks]);

  return (
    <div className="chart-box" ref={boxRef}>
      <svg ref={svgRef} role="img" aria-label={label} className="chart-svg" />
      <div className="chart-marker" ref={markerRef} />
    </div>
  );
}
