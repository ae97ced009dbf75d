import './AnglePlotsPanel.css';
import type { Dispatch } from 'react';
import { memo, useMemo } from 'react';
import type { XMark } from '../charts/xMarks';
import type { Branch } from '../solver/types';
import type { Action, PlotLayout } from '../state/appState';
import type { PointResponse } from '../worker/protocol';
import { AngleChartView } from './AngleChartView';
import type { CycleDegrees } from './chartInputs';
import { angleChartInputs, angleMarker } from './chartInputs';
import { useMessages } from './MessagesContext';
import { Segmented } from './Segmented';

/** Props of AnglePlotsPanel: the cycle in degrees, the latest pose and the display choices. */
export interface AnglePlotsPanelProps {
  deg: CycleDegrees | null;
  point: PointResponse | null;
  branch: Branch;
  showOther: boolean;
  layout: PlotLayout;
  dispatch: Dispatch<Action>;
  /** Faint theta2 rules on every chart (dead centres); default none. */
  xMarks?: readonly XMark[];
}

function AnglePlotsPanelImpl({ deg, point, branch, showOther, layout, dispatch, xMarks }: AnglePlotsPanelProps) {
  const t = useMessages();
  const in3 = useMemo(() => angleChartInputs('theta3', deg, branch, showOther, t), [deg, branch, showOther, t]);
  const in4 = useMemo(() => angleChartInputs('theta4', deg, branch, showOther, t), [deg, branch, showOther, t]);
  const inBoth = useMemo(() => angleChartInputs('both', deg, branch, showOther, t), [deg, branch, showOther, t]);
  const m3 = useMemo(() => angleMarker('theta3', point), [point]);
  const m4 = useMemo(() => angleMarker('theta4', point), [point]);
  const mBoth = useMemo(() => angleMarker('both', point), [point]);
  return (
    <div className="plots-panel">
      <div className="plots-head">
        <Segmented<PlotLayout>
          legend={t.plotLayout}
          value={layout}
          options={[
            { value: 'separate', label: t.plotSeparate },
            { value: 'together', label: t.plotTogether },
          ]}
          onChange={(v) => dispatch({ type: 'setPlotLayout', layout: v })}
        />
      </div>
      <div className={`plots-grid plots-${layout}`}>
        {layout === 'separate' ? (
          <>
            <AngleChartView inputs={in3} marker={m3} label={t.chartTheta3} xMarks={xMarks} />
            <AngleChartView inputs={in4} marker={m4} label={t.chartTheta4} xMarks={xMarks} />
          </>
        ) : (
          <AngleChartView inputs={inBoth} marker={mBoth} label={t.chartBoth} xMarks={xMarks} />
        )}
      </div>
      <p className="footnote">{t.angleFootnote}</p>
    </div>
  );
}

/** theta3 and theta4 against theta2, in two charts or one, with the angle-range footnote. */
export const AnglePlotsPanel = memo(AnglePlotsPanelImpl);
