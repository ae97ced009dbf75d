import './SvgChartView.css';
import { useLayoutEffect } from 'react';
import { createRateChart } from '../charts/rateChart';
import type { RateMarker } from '../charts/rateChart';
import type { RateChartInputs } from './rateInputs';
import { useLiveChart } from './useLiveChart';

/** Props of RateChartView: everything the chart shows; it sizes itself to its box. */
export interface RateChartViewProps {
  inputs: RateChartInputs;
  marker: RateMarker;
  /** Accessible name of the chart figure. */
  label: string;
}

/** A new rate chart at size 0 (drawn once the view knows its box). */
const newRateChart = (svg: SVGSVGElement, markerHost: HTMLElement | undefined) =>
  createRateChart(svg, { width: 0, height: 0, title: '', xLabel: '', yLabel: '', markerHost });

/** A live rate chart (ω or α against θ2), updated like AngleChartView: data, marker, size and texts separately. */
export function RateChartView({ inputs, marker, label }: RateChartViewProps) {
  const { data, title, xLabel, yLabel } = inputs;
  const { chart, boxRef, svgRef, markerRef } = useLiveChart(newRateChart, data, marker);

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
