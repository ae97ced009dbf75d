import './SvgChartView.css';
import { useLayoutEffect } from 'react';
import { createAngleChart } from './theta2Chart';
import type { AngleChartText, AngleMarker, Theta2Chart, Theta2ChartData } from './theta2Chart';
import type { XMark } from './xMarks';
import type { AngleChartInputs } from './chartInputs';
import { useLiveChart } from './useLiveChart';
import type { LiveMarker } from './useLiveChart';

/** Props of a chart against θ2: everything it shows (it sizes itself to its box) and how to make it. */
export interface Theta2ChartViewProps<S, M> {
  /** Makes the chart at size 0 (drawn once the view knows its box); a stable, module-level function. */
  create: (svg: SVGSVGElement, markerHost: HTMLElement | undefined) => Theta2Chart<S, M>;
  inputs: AngleChartText & { data: Theta2ChartData<S> };
  /** The marker, or its source (Play's frame moves it without a render of this view). */
  marker: LiveMarker<M>;
  /** Accessible name of the chart figure. */
  label: string;
  /** Faint theta2 rules (dead centres); default none. */
  xMarks?: readonly XMark[];
  /** Not drawn yet, its box keeping its place (a chart below the fold on the first load); default false. */
  held?: boolean;
}

const NO_MARKS: readonly XMark[] = [];

/**
 * A live chart against θ2 (angle or rate): the chart is created once per SVG element; new data redraw the
 * curves (the axes only when their domain changes), a new marker only moves the marker, a new size redraws
 * everything.
 */
export function Theta2ChartView<S, M>({
  create,
  inputs,
  marker,
  label,
  xMarks = NO_MARKS,
  held = false,
}: Theta2ChartViewProps<S, M>) {
  const { data, title, xLabel, yLabel } = inputs;
  const { chart, boxRef, svgRef, markerRef } = useLiveChart(create, data, marker, held);

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

/** A new angle chart at size 0. */
const newAngleChart = (svg: SVGSVGElement, markerHost: HTMLElement | undefined) =>
  createAngleChart(svg, { width: 0, height: 0, title: '', xLabel: '', yLabel: '', markerHost });

/** A live angle chart (θ3, θ4 or both against θ2). */
export function AngleChartView(
  props: Omit<Theta2ChartViewProps<unknown, AngleMarker>, 'create' | 'inputs'> & {
    inputs: AngleChartInputs;
  },
) {
  return <Theta2ChartView create={newAngleChart} {...props} />;
}
