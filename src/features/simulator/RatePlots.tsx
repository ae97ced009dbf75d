import { useMemo } from 'react';
import type { LinkRates } from '../../solver/rates';
import type { Branch } from '../../solver/types';
import type { XMark } from '../../shared/charts/xMarks';
import type { PlotLayout } from '../../shared/state/appState';
import { useMessages } from '../../shared/i18n/MessagesContext';
import type { CycleRates, RateChartKind } from '../../shared/charts/rateInputs';
import { rateChartInputs, rateChartKinds, rateMarker } from '../../shared/charts/rateInputs';
import { RateChartView } from '../../shared/charts/RateChartView';

/** Props of RatePlots: the plot kind, the cycle's rates, this frame's rates and theta2, and the display choices. */
export interface RatePlotsProps {
  kind: 'velocities' | 'accelerations';
  rates: CycleRates | null;
  /** This frame's rates (the marker), null when not assembled. */
  current: LinkRates | null;
  theta2Deg: number;
  branch: Branch;
  showOther: boolean;
  layout: PlotLayout;
  /** Faint theta2 rules (dead centres: ω4 is zero there). */
  xMarks?: readonly XMark[];
}

function OneRateChart({
  chart,
  rates,
  current,
  theta2Deg,
  branch,
  showOther,
  xMarks,
}: Omit<RatePlotsProps, 'kind' | 'layout'> & { chart: RateChartKind }) {
  const t = useMessages();
  const inputs = useMemo(
    () => rateChartInputs(chart, rates, branch, showOther, t),
    [chart, rates, branch, showOther, t],
  );
  const marker = useMemo(() => rateMarker(chart, theta2Deg, current), [chart, theta2Deg, current]);
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
