import './SvgChartView.css';
import { useCallback, useLayoutEffect, useRef, useState } from 'react';
import type { AngleMarker } from '../charts/angleChart';
import type { TransmissionChart } from '../charts/transmissionChart';
import { createTransmissionChart } from '../charts/transmissionChart';
import type { TransmissionChartInputs } from './transmissionInputs';
import { useElementSize } from './useElementSize';

/** Props of TransmissionChartView, shaped as AngleChartView's: inputs, marker (valuesDeg[0] is mu), label. */
export interface TransmissionChartViewProps {
  inputs: TransmissionChartInputs;
  marker: AngleMarker;
  /** Accessible name of the chart figure. */
  label: string;
}

/** A live transmission chart sized to its box; each input change redraws only what it touches. */
export function TransmissionChartView({ inputs, marker, label }: TransmissionChartViewProps) {
  const boxRef = useRef<HTMLDivElement>(null);
  const [chart, setChart] = useState<TransmissionChart | null>(null);
  const svgRef = useCallback((svg: SVGSVGElement | null) => {
    setChart(
      svg
        ? createTransmissionChart(svg, {
            width: 0,
            height: 0,
            title: '',
            xLabel: '',
            yLabel: '',
            legendMu: '',
            legendOutside: '',
            legendBand: '',
          })
        : null,
    );
  }, []);
  const { width, height } = useElementSize(boxRef);
  const { data, band, xMarks, title, xLabel, yLabel, legendMu, legendOutside, legendBand } = inputs;

  useLayoutEffect(() => {
    chart?.setText({ title, xLabel, yLabel, legendMu, legendOutside, legendBand });
  }, [chart, title, xLabel, yLabel, legendMu, legendOutside, legendBand]);
  useLayoutEffect(() => {
    chart?.setBand(band);
  }, [chart, band]);
  useLayoutEffect(() => {
    chart?.update(data);
  }, [chart, data]);
  useLayoutEffect(() => {
    chart?.setXMarks(xMarks);
  }, [chart, xMarks]);
  useLayoutEffect(() => {
    chart?.setMarker(marker);
  }, [chart, marker]);
  useLayoutEffect(() => {
    if (width > 0 && height > 0) chart?.resize(width, height);
  }, [chart, width, height]);

  return (
    <div className="chart-box" ref={boxRef}>
      <svg ref={svgRef} role="img" aria-label={label} className="chart-svg transmission-svg" />
    </div>
  );
}
