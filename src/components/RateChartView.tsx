import './SvgChartView.css';
import { useCallback, useLayoutEffect, useRef, useState } from 'react';
import { createRateChart } from '../charts/rateChart';
import type { RateChart, RateMarker } from '../charts/rateChart';
import type { RateChartInputs } from './rateInputs';
import { useElementSize } from './useElementSize';

/** Props of RateChartView: everything the chart shows; it sizes itself to its box. */
export interface RateChartViewProps {
  inputs: RateChartInputs;
  marker: RateMarker;
  /** Accessible name of the chart figure. */
  label: string;
}

/** A live rate chart (ω or α against θ2), updated like AngleChartView: data, marker, size and texts separately. */
export function RateChartView({ inputs, marker, label }: RateChartViewProps) {
  const boxRef = useRef<HTMLDivElement>(null);
  const [chart, setChart] = useState<RateChart | null>(null);
  const svgRef = useCallback((svg: SVGSVGElement | null) => {
    setChart(svg ? createRateChart(svg, { width: 0, height: 0, title: '', xLabel: '', yLabel: '' }) : null);
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
    if (width > 0 && height > 0) chart?.resize(width, height);
  }, [chart, width, height]);

  return (
    <div className="chart-box" ref={boxRef}>
      <svg ref={svgRef} role="img" aria-label={label} className="chart-svg" />
    </div>
  );
}
