import { memo, useMemo } from 'react';
import { radToDeg360 } from '../../solver/angles';
import { formatDeg, formatNumber } from '../../shared/format';
import { localPose } from '../../shared/linkage/localPose';
import type { AppState } from '../../shared/state/appState';
import type { ForcesMessages } from './forcesMessages';
import { cycleFacts, poseFacts, poseReason, toggleNote } from './forceFacts';
import { poseForces } from './forceModel';
import { useForceCycle } from './useForceCycle';
import { useForceSetup } from './useForceSetup';

/** Props of ForcesPanel: the state (θ2 as committed: a few times a second while playing) and the forces' strings. */
export interface ForcesPanelProps {
  state: AppState;
  t: ForcesMessages;
}

/** One labelled value, as the analysis panel's facts. */
function Row({ label, value, testId, wide = true }: { label: string; value: string; testId: string; wide?: boolean }) {
  return (
    <div className={wide ? 'fact fact-wide' : 'fact'}>
      <dt>{label}</dt>
      <dd className="mono" data-testid={testId}>
        {value}
      </dd>
    </div>
  );
}

function ForcesPanelImpl({ state, t }: ForcesPanelProps) {
  const setup = useForceSetup(state);
  const { linkage, branch, coupler } = state.design;
  const theta2Deg = state.motion.theta2Deg;
  const local = useMemo(
    () => localPose(linkage, theta2Deg, branch, coupler, false),
    [linkage, theta2Deg, branch, coupler],
  );
  const p = useMemo(() => poseForces(setup, local.theta2Rad, local.pose), [setup, local]);
  const facts = poseFacts(p, t);
  const reason = poseReason(p, t);
  const near = toggleNote(p, local.pose?.mu ?? Number.NaN, t);
  const cycle = useForceCycle(state);
  const c = cycleFacts(cycle, setup.input.omega2, t);
  const [torque, ...rest] = facts;
  const pins = rest.slice(0, 4);
  const shaking = rest.slice(4);
  return (
    <div className="forces-panel" data-status={p.status}>
      <h3 className="subhead">{t.forcesAt(formatDeg(radToDeg360(local.theta2Rad), 2))}</h3>
      <dl className="facts">
        <Row label={torque.label} value={torque.value} testId="forces-torque" />
      </dl>
      {reason ? (
        <p className="note note-warn" role="status" data-testid="forces-reason">
          {reason}
        </p>
      ) : null}
      {near ? (
        <p className="note note-warn" data-testid="forces-toggle-note">
          {near}
        </p>
      ) : null}
      <h4 className="forces-subhead">{t.pinForces}</h4>
      <dl className="facts">
        {pins.map((f) => (
          <Row key={f.key} label={f.label} value={f.value} testId={`forces-${f.key}`} />
        ))}
      </dl>
      <dl className="facts">
        {shaking.map((f) => (
          <Row key={f.key} label={f.label} value={f.value} testId={`forces-${f.key}`} />
        ))}
      </dl>
      <h3 className="subhead">{t.cycleTitle}</h3>
      <dl className="facts">
        <Row label={t.meanTorque} value={c.mean} testId="forces-mean" wide={false} />
        <Row label={t.rmsTorque} value={c.rms} testId="forces-rms" wide={false} />
        <Row label={t.peakTorque} value={c.peak} testId="forces-peak" wide={false} />
      </dl>
      <h4 className="forces-subhead">{t.flywheelTitle}</h4>
      <dl className="facts">
        <Row label={t.energyFluctuation} value={c.energy} testId="forces-energy" />
        <Row
          label={t.flywheelInertia(formatNumber(state.forces.speedFluctuation, 4))}
          value={c.flywheel}
          testId="forces-flywheel"
        />
      </dl>
      {c.reason ? (
        <p className="note" data-testid="forces-cycle-reason">
          {c.reason}
        </p>
      ) : null}
      <p className="footnote">{t.conventionNote}</p>
    </div>
  );
}

/** The forces at θ2 (input torque T12, pin forces, shaking force and moment) and over a turn (torque, ΔE, flywheel). */
export const ForcesPanel = memo(ForcesPanelImpl);
