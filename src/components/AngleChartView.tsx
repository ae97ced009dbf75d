import './SvgChartView.css';
import { useLayoutEffect, useRef } from 'react';
import { drawAngleChart, updateAngleMarker } from '../charts/angleChart';
import type { AngleMarker } from '../charts/angleChart';
import type { AngleChartInputs } from './chartInputs';
import { useElementSize } from './useElementSize';

/** Props of AngleChartView: everything the chart shows; it sizes itself to its box. */
export interface AngleChartViewProps {
  inputs: AngleChartInputs;
  marker: AngleMarker;
  /** Accessible name of the chart figure. */
  label: string;
}

/** A live angle chart: redraws the curves when the data change and only moves the marker when theta2 does. */
export function AngleChartView({ inputs, marker, label }: AngleChartViewProps) {
  const boxRef = useRef<HTMLDivElement>(null);
  const svgRef = useRef<SVGSVGElement>(null);
  const { width, height } = useElementSize(boxRef);
  const { data, title, xLabel, yLabel, markerColors } = inputs;

  useLayoutEffect(() => {
    const svg = svgRef.current;
    if (!svg || width <= 0 || height <= 0) return;
    drawAngleChart(svg, data, { width, height, title, xLabel, yLabel });
    if (typeof performance !== 'undefined' && typeof performance.mark === 'function') {
      performance.mark('fourbar:chart');
    }
  }, [data, title, xLabel, yLabel, width, height]);

  useLayoutEffect(() => {
    const svg = svgRef.current;
    if (!svg || width <= 0 || height <= 0) return;
    updateAngleMarker(svg, marker, markerColors);
  }, [marker, markerColors, data, width, height]);

  return (
    <div className="chart-box" ref={boxRef}>
      <svg ref={svgRef} role="img" aria-label={label} className="chart-svg" />
    </div>
  );
}
