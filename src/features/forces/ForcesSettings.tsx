import type { Dispatch } from 'react';
import { memo } from 'react';
import type { Linkage } from '../../solver/types';
import type { Action } from '../../shared/state/appState';
import type {
  ForcesSettings as Settings,
  ForcesState,
  MassModel,
  MovingLink,
} from '../../shared/state/slices/forcesSlice';
import { DEFAULT_LINK_MASS, FORCES_LIMITS, MOVING_LINKS } from '../../shared/state/slices/forcesSlice';
import { Segmented } from '../../shared/ui/Segmented';
import { ForceField } from './ForceField';
import { barSeeds } from './forceModel';
import type { ForcesMessages } from './forcesMessages';

/** Props of ForcesSettings: the forces slice, the lengths (for the bars' seeds), the dispatcher and the strings. */
export interface ForcesSettingsProps {
  forces: ForcesState;
  linkage: Linkage;
  dispatch: Dispatch<Action>;
  t: ForcesMessages;
}

/** One link's mass, inertia and CG (distance in the length unit, angle in degrees from the link's line). */
function LinkFields({ link, forces, dispatch, t }: Omit<ForcesSettingsProps, 'linkage'> & { link: MovingLink }) {
  const p = forces[link];
  const set = (props: Partial<typeof p>) => dispatch({ type: 'setLinkMass', link, props });
  const name = t.linkNames[link];
  const unit = forces.lengthUnit;
  return (
    <fieldset className="forces-link">
      <legend>{name}</legend>
      <ForceField
        label={`${name}: ${t.mass}`}
        unit="kg"
        value={p.massKg}
        min={0}
        max={FORCES_LIMITS.mass}
        onCommit={(massKg) => set({ massKg })}
        t={t}
      />
      <ForceField
        label={`${name}: ${t.inertia}`}
        unit="kg·m²"
        value={p.inertiaKgM2}
        min={0}
        max={FORCES_LIMITS.inertia}
        onCommit={(inertiaKgM2) => set({ inertiaKgM2 })}
        t={t}
      />
      <ForceField
        label={`${name}: ${t.cgDistance}`}
        unit={unit}
        value={p.cgDistance}
        min={-FORCES_LIMITS.offset}
        max={FORCES_LIMITS.offset}
        onCommit={(cgDistance) => set({ cgDistance })}
        t={t}
      />
      <ForceField
        label={`${name}: ${t.cgAngle}`}
        unit="°"
        value={p.cgAngleDeg}
        min={-360}
        max={360}
        onCommit={(cgAngleDeg) => set({ cgAngleDeg })}
        t={t}
      />
    </fieldset>
  );
}

function ForcesSettingsImpl({ forces: f, linkage, dispatch, t }: ForcesSettingsProps) {
  const set = (patch: Partial<Settings>) => dispatch({ type: 'setForces', patch });
  const chooseModel = (model: MassModel) => {
    // Per-link values never given start as the bars shown now, so the numbers do not jump.
    const untouched = MOVING_LINKS.every((l) => f[l] === DEFAULT_LINK_MASS);
    const seed = model === 'links' && untouched ? barSeeds(linkage, f) : undefined;
    dispatch({ type: 'setMassModel', model, ...(seed ? { seed } : {}) });
  };
  return (
    <div className="forces-settings">
      <h3 className="subhead">{t.settingsTitle}</h3>
      <Segmented<MassModel>
        legend={t.massModel}
        value={f.massModel}
        options={[
          { value: 'bars', label: t.massBars },
          { value: 'links', label: t.massLinks },
        ]}
        onChange={chooseModel}
      />
      {f.massModel === 'bars' ? (
        <ForceField
          label={t.massPerLength}
          unit="kg/m"
          value={f.rhoKgPerM}
          min={0}
          max={FORCES_LIMITS.mass}
          onCommit={(rhoKgPerM) => set({ rhoKgPerM })}
          t={t}
          testId="forces-rho"
        />
      ) : (
        MOVING_LINKS.map((link) => <LinkFields key={link} link={link} forces={f} dispatch={dispatch} t={t} />)
      )}
      <ForceField
        label={t.gravity}
        unit="m/s²"
        value={f.gravityMPerS2}
        min={0}
        max={FORCES_LIMITS.gravity}
        onCommit={(gravityMPerS2) => set({ gravityMPerS2 })}
        t={t}
      />
      <ForceField
        label={t.gravityAngle}
        unit="°"
        value={f.gravityAngleDeg}
        min={-360}
        max={360}
        onCommit={(gravityAngleDeg) => set({ gravityAngleDeg })}
        t={t}
      />
      <p className="footnote">{t.gravityNote}</p>
      <h3 className="subhead">{t.loadsTitle}</h3>
      <ForceField
        label={t.pointForceX}
        unit="N"
        value={f.pointForceXN}
        min={-FORCES_LIMITS.force}
        max={FORCES_LIMITS.force}
        onCommit={(pointForceXN) => set({ pointForceXN })}
        t={t}
      />
      <ForceField
        label={t.pointForceY}
        unit="N"
        value={f.pointForceYN}
        min={-FORCES_LIMITS.force}
        max={FORCES_LIMITS.force}
        onCommit={(pointForceYN) => set({ pointForceYN })}
        t={t}
      />
      <ForceField
        label={t.loadTorque}
        unit="N·m"
        value={f.loadTorqueNm}
        min={-FORCES_LIMITS.torque}
        max={FORCES_LIMITS.torque}
        onCommit={(loadTorqueNm) => set({ loadTorqueNm })}
        t={t}
      />
      <ForceField
        label={t.speedFluctuation}
        unit=""
        value={f.speedFluctuation}
        min={1e-6}
        max={1}
        onCommit={(speedFluctuation) => set({ speedFluctuation })}
        t={t}
      />
    </div>
  );
}

/**
 * The forces' settings: the mass model (uniform bars of a mass per length, or each link's mass, inertia and CG),
 * gravity and its direction, the force at P, the load torque on the rocker and the coefficient of speed fluctuation
 * the flywheel is sized for; memoised, so a θ2 drag does not re-render its fields.
 */
export const ForcesSettings = memo(ForcesSettingsImpl);
