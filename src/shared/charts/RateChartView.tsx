import { createRateChart } from './rateChart';
import type { RateMarker } from './rateChart';
import type { XMark } from './xMarks';
import { Theta2ChartView } from './Theta2ChartView';
import type { RateChartInputs } from './rateInputs';
import type { LiveMarker } from './useLiveChart';

/** Props of RateChartView: everything the chart shows; it sizes itself to its box. */
export interface RateChartViewProps {
  inputs: RateChartInputs;
  /** The marker, or its source (Play's frame moves it). */
  marker: LiveMarker<RateMarker>;
  /** Accessible name of the chart figure. */
  label: string;
  /** Faint theta2 rules (dead centres); default none. */
  xMarks?: readonly XMark[];
}

/** A new rate chart at size 0 (drawn once the view knows its box). */
const newRateChart = (svg: SVGSVGElement, markerHost: HTMLElement | undefined) =>
  createRateChart(svg, { width: 0, height: 0, title: '', xLabel: '', yLabel: '', markerHost });

/** A live rate chart (ω or α against θ2), updated like the angle charts: data, marker, size and texts separately. */
export function RateChartView(props: RateChartViewProps) {
  return <Theta2ChartView create={newRateChart} {...props} />;
}
