import './SvgChartView.css';
import { useCallback, useLayoutEffect, useRef, useState } from 'react';
import { createAngleChart } from '../charts/angleChart';
import type { AngleChart, AngleMarker } from '../charts/angleChart';
import type { XMark } from '../charts/xMarks';
import type { AngleChartInputs } from './chartInputs';
import { useElementSize } from './useElementSize';

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

/**
 * A live angle chart: the chart is created once per SVG element; new data redraw the curves (the axes
 * only when their domain changes), a new marker only moves the marker, a new size redraws everything.
 */
export function AngleChartView({ inputs, marker, label, xMarks = NO_MARKS }: AngleChartViewProps) {
  const boxRef = useRef<HTMLDivElement>(null);
  const [chart, setChart] = useState<AngleChart | null>(null);
  const svgRef = useCallback((svg: SVGSVGElement | null) => {
    setChart(svg ? createAngleChart(svg, { width: 0, height: 0, title: '', xLabel: '', yLabel: '' }) : null);
  }, []);
  const { width, height } = useElementSize(boxRef);
  const { data, title, xLabel, yLabel } = inputs;

  useLayoutEffect(() => {
    chart?.setText({ title, xLabel, yLabel });
  }, [chart, title, xLabel, yLabel]);
  useLayoutEffect(() => {
    chart?.update(data);
  }, [chart, data]);
  useLayoutEffect(() => {
    chart?.setMarker(marker);
  }, [chart, marker]);
  useLayoutEffect(() => {
    chart?.setXMarks(xMarks);
  }, [chart, xMarks]);
  useLayoutEffect(() => {
    if (width > 0 && height > 0) chart?.resize(width, height);
  }, [chart, width, height]);

  return (
    <div className="chart-box" ref={boxRef}>
      <svg ref={svgRef} role="img" aria-label={label} className="chart-svg" />
    </div>
  );
}
