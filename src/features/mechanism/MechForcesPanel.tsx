import { memo, useMemo } from 'react';
import type { Dispatch } from 'react';
import type { MechanismForces, MechanismSpec } from '../../mechanism';
import type { Action } from '../../shared/state/appState';
import type { MechForcesSettings } from '../../shared/state/slices/mechSlice';
import { MECH_FORCES_LIMITS } from '../../shared/state/slices/mechSlice';
import type { MarkerAt } from '../../shared/charts/chart';
import type { XYChartData } from '../../shared/charts/xyChart';
import { XYChartView } from '../../shared/charts/XYChartView';
import { formatNumber } from '../../shared/format';
import { NumberField } from '../../shared/ui/NumberField';
import { COLORS } from '../../shared/theme/tokens';
import type { MechMessages } from './mechMessages';
import { reactionMagnitude } from './mechForces';

/** Props of MechForcesPanel. */
export interface MechForcesPanelProps {
  spec: MechanismSpec;
  settings: MechForcesSettings;
  /** The joint whose reaction is shown (reactionJoint of the settings). */
  joint: string;
  kind: 'R' | 'P';
  /** The app's length unit (mm, cm, m, in): the linkage's lengths are in it. */
  lengthUnit: string;
  /** The forces over the grid (SI), or null while they are being solved. */
  forces: MechanismForces | null;
  pending: boolean;
  error: string | null;
  /** The plots' x values over the run (degrees or length) and the run's grid indices. */
  x: Float64Array;
  run: [number, number] | null;
  /** The input now on the plots' axis (degrees or length), and the values there (interpolated on the grid). */
  xNow: number;
  effortNow: number;
  reactionNow: { fx: number; fy: number };
  dispatch: Dispatch<Action>;
  m: MechMessages;
}

/** A field of the forces' settings: a number from min to max, named in its messages. */
function SettingField(props: {
  label: string;
  unit: string;
  value: number;
  min: number;
  max: number;
  m: MechMessages;
  onCommit: (v: number) => void;
}) {
  const { label, unit, value, min, max, m, onCommit } = props;
  return (
    <NumberField
      label={label}
      unit={unit}
      value={value}
      className="mech-force-field"
      check={(v) => (v < min || v > max ? m.outOfRange(label, formatNumber(min), formatNumber(max)) : null)}
      errorText={(text, _kept, why) => why ?? m.notANumber(label, text)}
      onCommit={onCommit}
    />
  );
}

/** The settings' fields: memoised, so Play does not re-render them. */
const ForceSettings = memo(function ForceSettings({
  spec,
  settings,
  joint,
  kind,
  lengthUnit,
  dispatch,
  m,
}: Pick<MechForcesPanelProps, 'spec' | 'settings' | 'joint' | 'kind' | 'lengthUnit' | 'dispatch' | 'm'>) {
  const set = (patch: Partial<MechForcesSettings>) => dispatch({ type: 'setMechForces', patch });
  return (
    <div className="mech-force-settings">
      <SettingField
        label={m.massPerLength}
        unit="kg/m"
        value={settings.rhoKgPerM}
        min={0}
        max={MECH_FORCES_LIMITS.rho}
        m={m}
        onCommit={(rhoKgPerM) => set({ rhoKgPerM })}
      />
      <SettingField
        label={m.gravity}
        unit="m/s²"
        value={settings.gravityMPerS2}
        min={0}
        max={MECH_FORCES_LIMITS.gravity}
        m={m}
        onCommit={(gravityMPerS2) => set({ gravityMPerS2 })}
      />
      <SettingField
        label={m.inputSpeed}
        unit={kind === 'R' ? 'rad/s' : `${lengthUnit}/s`}
        value={settings.inputSpeed}
        min={-MECH_FORCES_LIMITS.speed}
        max={MECH_FORCES_LIMITS.speed}
        m={m}
        onCommit={(inputSpeed) => set({ inputSpeed })}
      />
      <label className="mech-force-joint">
        {m.reactionJoint}{' '}
        <select value={joint} onChange={(e) => set({ joint: e.target.value })}>
          {spec.joints.map((j) => (
            <option key={j.id} value={j.id}>
              {j.id}
            </option>
          ))}
        </select>
      </label>
      <label className="mech-check">
        <input type="checkbox" checked={settings.arrows} onChange={(e) => set({ arrows: e.target.checked })} />{' '}
        {m.reactionArrows}
      </label>
      <p className="note mech-force-note">{m.forcesNote(lengthUnit)}</p>
    </div>
  );
});

/**
 * The Forces section of the mechanism page: the toggle, and when on the settings (mass per length, gravity, the
 * input's speed, the joint, the arrows), the values at the current input and two plots over the cycle — the input
 * torque (pin input, N·m) or force (slider input, N), and the chosen joint's reaction |F| (N) — whose markers follow
 * Play.
 */
export function MechForcesPanel(props: MechForcesPanelProps) {
  const { spec, settings, joint, kind, forces, pending, error, x, run, xNow, effortNow, reactionNow, dispatch, m } =
    props;
  const effortTitle = kind === 'R' ? m.inputTorque : m.inputForce;
  const effortUnit = kind === 'R' ? 'N·m' : 'N';
  const reactionTitle = m.reactionAt(joint);
  // The series change with the forces only: Play moves the markers alone.
  const series = useMemo(() => {
    if (!forces || !run) return null;
    const [a, b] = run;
    return {
      effort: forces.input.subarray(a, b + 1),
      reaction: reactionMagnitude(forces, joint).subarray(a, b + 1),
    };
  }, [forces, run, joint]);
  const effortData = useMemo<XYChartData>(
    () => (series ? { series: [{ label: effortTitle, color: COLORS.force, x, y: series.effort }] } : { series: [] }),
    [series, x, effortTitle],
  );
  const reactionData = useMemo<XYChartData>(
    () =>
      series ? { series: [{ label: reactionTitle, color: COLORS.accent2, x, y: series.reaction }] } : { series: [] },
    [series, x, reactionTitle],
  );
  const magnitude = Math.hypot(reactionNow.fx, reactionNow.fy);
  const effortMarker: MarkerAt | null = series ? { x: xNow, dots: [{ y: effortNow, color: COLORS.force }] } : null;
  const reactionMarker: MarkerAt | null = series ? { x: xNow, dots: [{ y: magnitude, color: COLORS.accent2 }] } : null;
  const xLabel = kind === 'R' ? m.axisInputDeg : m.axisInputLength;
  return (
    <section className="mech-forces" aria-label={m.forcesTitle}>
      <div className="mech-forces-head">
        <h3 className="mech-card-title">{m.forcesTitle}</h3>
        <label className="mech-check">
          <input
            type="checkbox"
            checked={settings.enabled}
            onChange={(e) => dispatch({ type: 'setMechForces', patch: { enabled: e.target.checked } })}
          />{' '}
          {m.forcesToggle}
        </label>
      </div>
      {settings.enabled && (
        <>
          <ForceSettings
            spec={spec}
            settings={settings}
            joint={joint}
            kind={kind}
            lengthUnit={props.lengthUnit}
            dispatch={dispatch}
            m={m}
          />
          <dl className="mech-force-values" aria-label={m.valuesNow}>
            <div>
              <dt>{effortTitle}</dt>
              <dd data-testid="mech-effort">
                {formatNumber(effortNow)} {effortUnit}
              </dd>
            </div>
            <div>
              <dt>{reactionTitle}</dt>
              <dd data-testid="mech-reaction">{formatNumber(magnitude)} N</dd>
            </div>
            <div>
              <dt>{m.components}</dt>
              <dd>
                {formatNumber(reactionNow.fx)}, {formatNumber(reactionNow.fy)} N
              </dd>
            </div>
          </dl>
          {error && (
            <p className="mech-error" role="alert">
              {m.forcesFailed(error)}
            </p>
          )}
          {pending && !error && <p className="note">{m.forcesPending}</p>}
          <div className="mech-charts">
            <div className="mech-chart-cell">
              <XYChartView
                className="mech-chart"
                data={effortData}
                marker={effortMarker}
                texts={{ title: effortTitle, xLabel, yLabel: kind === 'R' ? m.axisTorque : m.axisForce }}
                testId="mech-force-chart-1"
              />
            </div>
            <div className="mech-chart-cell">
              <XYChartView
                className="mech-chart"
                data={reactionData}
                marker={reactionMarker}
                texts={{ title: reactionTitle, xLabel, yLabel: m.axisReaction }}
                testId="mech-force-chart-2"
              />
            </div>
          </div>
        </>
      )}
    </section>
  );
}
