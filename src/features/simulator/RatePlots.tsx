import { useMemo } from 'react';
import type { Branch } from '../../solver/types';
import type { XMark } from '../../shared/charts/xMarks';
import type { PlotLayout } from '../../shared/state/appState';
import { useMessages } from '../../shared/i18n/MessagesContext';
import type { CycleRates, RateChartKind } from '../../shared/charts/rateInputs';
import { rateChartInputs, rateChartKinds, rateMarker } from '../../shared/charts/rateInputs';
import { RateChartView } from '../../shared/charts/RateChartView';
import { angleMarker } from '../../shared/charts/chartInputs';
import { useFrameDerived } from '../../shared/linkage/FramePoseContext';

/** Props of RatePlots: the plot kind, the cycle's rates and the display choices (the markers follow the frame on screen). */
export interface RatePlotsProps {
  kind: 'velocities' | 'accelerations';
  rates: CycleRates | null;
  branch: Branch;
  showOther: boolean;
  layout: PlotLayout;
  /** Faint theta2 rules (dead centres: ω4 is zero there). */
  xMarks?: readonly XMark[];
}

function OneRateChart({
  chart,
  rates,
  branch,
  showOther,
  xMarks,
}: Omit<RatePlotsProps, 'kind' | 'layout'> & { chart: RateChartKind }) {
  const t = useMessages();
  const inputs = useMemo(
    () => rateChartInputs(chart, rates, branch, showOther, t),
    [chart, rates, branch, showOther, t],
  );
  // The frame's θ2 and rates (null where they do not assemble), followed by the chart itself every frame of Play.
  const marker = useFrameDerived(
    (f) => rateMarker(chart, angleMarker('both', f.marker).theta2Deg, f.motion?.rates ?? null),
    [chart],
  );
  return <RateChartView inputs={inputs} marker={marker} label={t.chartRates[chart]} xMarks={xMarks} />;
}

/** ω3/ω4 or α3/α4 against θ2 (loaded only when chosen), in two charts or one, with the clipping footnote. */
export function RatePlots({ kind, layout, ...rest }: RatePlotsProps) {
  const t = useMessages();
  return (
    <>
      <div className={`plots-grid plots-${layout}`}>
        {rateChartKinds(kind, layout).map((c) => (
          <OneRateChart key={c} chart={c} {...rest} />
        ))}
      </div>
      <p className="footnote">{t.rateFootnote}</p>
    </>
  );
}
