import './SvgChartView.css';
import { useLayoutEffect } from 'react';
import type { AngleMarker } from './theta2Chart';
import { createTransmissionChart } from './transmissionChart';
import type { TransmissionChartInputs } from './transmissionInputs';
import { useLiveChart } from './useLiveChart';
import type { LiveMarker } from './useLiveChart';

/** Props of TransmissionChartView, shaped as AngleChartView's: inputs, marker or its source (valuesDeg[0] is mu), label. */
export interface TransmissionChartViewProps {
  inputs: TransmissionChartInputs;
  marker: LiveMarker<AngleMarker>;
  /** Accessible name of the chart figure. */
  label: string;
}

/** A new transmission chart at size 0 (drawn once the view knows its box). */
const newTransmissionChart = (svg: SVGSVGElement, markerHost: HTMLElement | undefined) =>
  createTransmissionChart(svg, {
    width: 0,
    height: 0,
    title: '',
    xLabel: '',
    yLabel: '',
    legendMu: '',
    legendOutside: '',
    legendBand: '',
    markerHost,
  });

/** A live transmission chart sized to its box; each input change redraws only what it touches. */
export function TransmissionChartView({ inputs, marker, label }: TransmissionChartViewProps) {
  const { data, band, xMarks, title, xLabel, yLabel, legendMu, legendOutside, legendBand } = inputs;
  const { chart, boxRef, svgRef, markerRef } = useLiveChart(newTransmissionChart, data, marker);

  useLayoutEffect(() => {
    chart?.setText({ title, xLabel, yLabel, legendMu, legendOutside, legendBand });
  }, [chart, title, xLabel, yLabel, legendMu, legendOutside, legendBand]);
  useLayoutEffect(() => {
    chart?.setBand(band);
  }, [chart, band]);
  useLayoutEffect(() => {
    chart?.setXMarks(xMarks);
  }, [chart, xMarks]);

  return (
    <div className="chart-box" ref={boxRef}>
      <svg ref={svgRef} role="img" aria-label={label} className="chart-svg transmission-svg" />
      <div className="chart-marker" ref={markerRef} />
    </div>
  );
}
