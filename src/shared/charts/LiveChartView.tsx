import './SvgChartView.css';
import { useLayoutEffect } from 'react';
import type { LiveChart } from './useLiveChart';
import { useLiveChart } from './useLiveChart';

/** A chart handle with texts: data, marker, size and texts each change through their own update. */
export interface TextedLiveChart<D, M, T> extends LiveChart<D, M> {
  setText(text: T): void;
}

/** Props of LiveChartView: how to create the chart and what it shows; it sizes itself to its box. */
export interface LiveChartViewProps<D, M, T> {
  /** Creates the chart in the SVG (at size 0); a new function makes a new chart, so keep it stable (useCallback). */
  create: (svg: SVGSVGElement) => TextedLiveChart<D, M, T>;
  data: D;
  marker: M;
  text: T;
  /** The SVG's accessible name. */
  label: string;
  className?: string;
  testId?: string;
  /** No chart is made while true (the box keeps its place); default false. */
  held?: boolean;
}

/**
 * An SVG chart created once per SVG element and create function, kept in step with its props: new data redraw the
 * data (the axes only when their domain changes), a new marker moves the marker, new texts rewrite the texts.
 */
export function LiveChartView<D, M, T>({
  create,
  data,
  marker,
  text,
  label,
  className,
  testId,
  held = false,
}: LiveChartViewProps<D, M, T>) {
  const { chart, boxRef, svgRef } = useLiveChart(create, data, marker, held);
  useLayoutEffect(() => {
    chart?.setText(text);
  }, [chart, text]);
  return (
    <div className={className ? `chart-box ${className}` : 'chart-box'} ref={boxRef}>
      <svg ref={svgRef} role="img" aria-label={label} className="chart-svg" data-testid={testId} />
    </div>
  );
}
