import './PlotsPanel.css';
import type { Dispatch, ReactNode } from 'react';
import { Suspense, lazy, memo, useMemo } from 'react';
import type { XMark } from '../../shared/charts/xMarks';
import type { Action, MotionPlotKind, PlotKind, PlotLayout } from '../../shared/state/appState';
import { AngleChartView } from '../../shared/charts/Theta2ChartView';
import type { CycleDegrees } from '../../shared/charts/chartInputs';
import { angleChartInputs, angleMarker } from '../../shared/charts/chartInputs';
import { useFrameDerived, useFrameSelect } from '../../shared/linkage/FramePoseContext';
import { useMessages } from '../../shared/i18n/MessagesContext';
import type { CycleRates } from '../../shared/charts/rateInputs';
import { Segmented } from '../../shared/ui/Segmented';
import type { SegmentedOption } from '../../shared/ui/Segmented';

// The rate charts load only when a rate plot is chosen: they are not part of the first load.
const RatePlots = lazy(() => import('./RatePlots').then((m) => ({ default: m.RatePlots })));

/** The plot chooser's own choices, in order; a new kind of plot is one more entry (and its view below). */
export const PLOT_KINDS: readonly MotionPlotKind[] = ['angles', 'velocities', 'accelerations'];

/**
 * Plots another feature adds to the chooser (the forces' torque, pin forces and bearing load), composed in the app:
 * their choices after the panel's own, and the view of a chosen one.
 */
export interface ExtraPlots {
  options: readonly SegmentedOption<PlotKind>[];
  render: (kind: PlotKind) => ReactNode;
}

/** Props of AnglePlotsPanel: the cycle in degrees and the display choices (the marker is the frame on screen). */
export interface AnglePlotsPanelProps {
  deg: CycleDegrees | null;
  showOther: boolean;
  layout: PlotLayout;
  dispatch: Dispatch<Action>;
  /** Faint theta2 rules on every chart (dead centres); default none. */
  xMarks?: readonly XMark[];
  /** Which plots show (the chooser above them); default 'angles'. */
  kind?: PlotKind;
  /** The cycle's rates on the plot samples (null until a rate plot's cycle arrives). */
  rates?: CycleRates | null;
  /** Plots another feature adds (shown when chosen); default none: an extra kind in the state shows the angles. */
  extra?: ExtraPlots | null;
  /**
   * The second of the separate angle charts (θ4, below the fold on a phone) waits, its box in place; default false.
   * The app holds it for the first screen (SimulatorPage).
   */
  secondHeld?: boolean;
}

/**
 * The plots' choosers: which plots (angles, velocities, accelerations, extras) and whether θ3 and θ4 share a chart.
 * Memoised: the panel re-renders when the branch on screen or its props change, the choosers only when a choice changes.
 */
const PlotsHead = memo(function PlotsHead({
  kind,
  layout,
  dispatch,
  extra,
}: {
  kind: PlotKind;
  layout: PlotLayout;
  dispatch: Dispatch<Action>;
  extra: readonly SegmentedOption<PlotKind>[];
}) {
  const t = useMessages();
  return (
    <div className="plots-head">
      <Segmented<PlotKind>
        legend={t.plotKind}
        value={kind}
        options={[...PLOT_KINDS.map((k) => ({ value: k, label: t.plotKinds[k] })), ...extra]}
        onChange={(v) => dispatch({ type: 'setPlotKind', kind: v })}
      />
      {/* Separate or together lays out θ3 and θ4 (or their rates); another feature's plot lays out its own. */}
      {(PLOT_KINDS as readonly PlotKind[]).includes(kind) ? (
        <Segmented<PlotLayout>
          legend={kind === 'velocities' || kind === 'accelerations' ? t.plotLayout[kind] : t.plotLayout.angles}
          value={layout}
          options={[
            { value: 'separate', label: t.plotSeparate },
            { value: 'together', label: t.plotTogether },
          ]}
          onChange={(v) => dispatch({ type: 'setPlotLayout', layout: v })}
        />
      ) : null}
    </div>
  );
});

const NO_EXTRA: readonly SegmentedOption<PlotKind>[] = [];

function AnglePlotsPanelImpl({
  deg,
  showOther,
  layout,
  dispatch,
  xMarks,
  kind = 'angles',
  rates = null,
  extra = null,
  secondHeld = false,
}: AnglePlotsPanelProps) {
  const t = useMessages();
  // The branch on screen (a rocking input switches it during Play) re-renders the panel; the markers follow every
  // frame of Play by themselves (sources the charts follow), so the panel does not re-render per frame.
  const branch = useFrameSelect((f) => f.state.design.branch);
  const in3 = useMemo(() => angleChartInputs('theta3', deg, branch, showOther, t), [deg, branch, showOther, t]);
  const in4 = useMemo(() => angleChartInputs('theta4', deg, branch, showOther, t), [deg, branch, showOther, t]);
  const inBoth = useMemo(() => angleChartInputs('both', deg, branch, showOther, t), [deg, branch, showOther, t]);
  const m3 = useFrameDerived((f) => angleMarker('theta3', f.marker), []);
  const m4 = useFrameDerived((f) => angleMarker('theta4', f.marker), []);
  const mBoth = useFrameDerived((f) => angleMarker('both', f.marker), []);
  // A kind whose feature is off (plot=trq without the forces) shows the angles.
  const extraView = extra?.options.some((o) => o.value === kind) ? extra.render(kind) : null;
  const shown: PlotKind = extraView !== null || (PLOT_KINDS as readonly PlotKind[]).includes(kind) ? kind : 'angles';
  return (
    <div className="plots-panel">
      <PlotsHead kind={shown} layout={layout} dispatch={dispatch} extra={extra?.options ?? NO_EXTRA} />
      {extraView !== null ? (
        extraView
      ) : shown === 'velocities' || shown === 'accelerations' ? (
        <Suspense fallback={<p className="note">…</p>}>
          <RatePlots kind={shown} rates={rates} branch={branch} showOther={showOther} layout={layout} xMarks={xMarks} />
        </Suspense>
      ) : (
        <>
          <div className={`plots-grid plots-${layout}`}>
            {layout === 'separate' ? (
              <>
                <AngleChartView inputs={in3} marker={m3} label={t.chartTheta3} xMarks={xMarks} />
                <AngleChartView inputs={in4} marker={m4} label={t.chartTheta4} xMarks={xMarks} held={secondHeld} />
              </>
            ) : (
              <AngleChartView inputs={inBoth} marker={mBoth} label={t.chartBoth} xMarks={xMarks} />
            )}
          </div>
          <p className="footnote">{t.angleFootnote}</p>
        </>
      )}
    </div>
  );
}

/** The plots under the canvas: the chooser (angles, velocities, accelerations, extras), then the chosen charts. */
export const AnglePlotsPanel = memo(AnglePlotsPanelImpl);
