import { useLayoutEffect } from 'react';
import type { MarkerAt } from '../../shared/charts/chart';
import { useLiveChart } from '../../shared/charts/useLiveChart';
import type { LiveMarker } from '../../shared/charts/useLiveChart';
import { createXYChart } from '../../shared/charts/xyChart';
import { BEARING_FIT } from './forceCharts';
import type { BearingInputs } from './forceCharts';

/** Props of BearingChartView: the diagram's data and texts, the marker (this pose's F12) and the figure's name. */
export interface BearingChartViewProps {
  inputs: BearingInputs;
  /** The marker, or its source (Play's frame moves it). */
  marker: LiveMarker<MarkerAt>;
  label: string;
}

/** A new bearing-load diagram at size 0 (drawn once the view knows its box): equal aspect, the origin in view. */
const newBearingChart = (svg: SVGSVGElement, markerHost: HTMLElement | undefined) =>
  createXYChart(svg, { width: 0, height: 0, title: '', xLabel: '', yLabel: '', markerHost, ...BEARING_FIT });

/** The crank bearing's load F12 over a turn as a live x–y chart (shared/charts xyChart), sized to its box. */
export function BearingChartView({ inputs, marker, label }: BearingChartViewProps) {
  const { data, title, xLabel, yLabel } = inputs;
  const { chart, boxRef, svgRef, markerRef } = useLiveChart(newBearingChart, data, marker);
  useLayoutEffect(() => {
    chart?.setText({ title, xLabel, yLabel });
  }, [chart, title, xLabel, yLabel]);
  return (
    <div className="chart-box" ref={boxRef}>
      <svg ref={svgRef} role="img" aria-label={label} className="chart-svg" />
      <div className="chart-marker" ref={markerRef} />
    </div>
  );
}
