import type { Dispatch } from 'react';
import { memo } from 'react';
import type { Linkage } from '../../solver/types';
import type { Action } from '../../shared/state/appState';
import type { LengthUnit } from '../../shared/state/slices/designSlice';
import type { ForcesSettableFields, ForcesState, MassModel, MovingLink } from '../../shared/state/slices/forcesSlice';
import { DEFAULT_LINK_MASS, FORCES_LIMITS, MOVING_LINKS } from '../../shared/state/slices/forcesSlice';
import { formatNumber } from '../../shared/format';
import type { NumberFieldProps } from '../../shared/ui/NumberField';
import { NumberField } from '../../shared/ui/NumberField';
import { Segmented } from '../../shared/ui/Segmented';
import { barSeeds } from './forceModel';
import type { ForcesMessages } from './forcesMessages';

/** Props of ForcesSettings: the forces slice, the lengths and their unit (for the bars' seeds, the CG offsets), the dispatcher and the strings. */
export interface ForcesSettingsProps {
  forces: ForcesState;
  linkage: Linkage;
  lengthUnit: LengthUnit;
  dispatch: Dispatch<Action>;
  t: ForcesMessages;
}

/**
 * A forces field's name, range check and messages: a number from min to max (field units), the label naming it in
 * both messages (not a number; out of range).
 */
function forceField(
  t: Pick<ForcesMessages, 'badNumber' | 'outOfRange'>,
  label: string,
  min: number,
  max: number,
): Pick<NumberFieldProps, 'label' | 'check' | 'errorText' | 'className'> {
  return {
    label,
    check: (v) => (v < min || v > max ? t.outOfRange(label, formatNumber(min), formatNumber(max)) : null),
    errorText: (text, _kept, why) => why ?? t.badNumber(label, text),
    className: 'frc-field',
  };
}

/** One link's mass, inertia and CG (distance in the length unit, angle in degrees from the link's line). */
function LinkFields({
  link,
  forces,
  lengthUnit: unit,
  dispatch,
  t,
}: Omit<ForcesSettingsProps, 'linkage'> & { link: MovingLink }) {
  const p = forces[link];
  const set = (props: Partial<typeof p>) => dispatch({ type: 'setLinkMass', link, props });
  const name = t.linkNames[link];
  return (
    <fieldset className="forces-link">
      <legend>{name}</legend>
      <NumberField
        {...forceField(t, `${name}: ${t.mass}`, 0, FORCES_LIMITS.mass)}
        unit="kg"
        value={p.massKg}
        onCommit={(massKg) => set({ massKg })}
      />
      <NumberField
        {...forceField(t, `${name}: ${t.inertia}`, 0, FORCES_LIMITS.inertia)}
        unit="kg·m²"
        value={p.inertiaKgM2}
        onCommit={(inertiaKgM2) => set({ inertiaKgM2 })}
      />
      <NumberField
        {...forceField(t, `${name}: ${t.cgDistance}`, -FORCES_LIMITS.offset, FORCES_LIMITS.offset)}
        unit={unit}
        value={p.cgDistance}
        onCommit={(cgDistance) => set({ cgDistance })}
      />
      <NumberField
        {...forceField(t, `${name}: ${t.cgAngle}`, -360, 360)}
        unit="°"
        value={p.cgAngleDeg}
        onCommit={(cgAngleDeg) => set({ cgAngleDeg })}
      />
    </fieldset>
  );
}

function ForcesSettingsImpl({ forces: f, linkage, lengthUnit, dispatch, t }: ForcesSettingsProps) {
  const set = (patch: Partial<ForcesSettableFields>) => dispatch({ type: 'setForces', patch });
  const chooseModel = (model: MassModel) => {
    // Per-link values never given start as the bars shown now, so the numbers do not jump.
    const untouched = MOVING_LINKS.every((l) => f[l] === DEFAULT_LINK_MASS);
    const seed = model === 'links' && untouched ? barSeeds(linkage, lengthUnit, f) : undefined;
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
        <NumberField
          {...forceField(t, t.massPerLength, 0, FORCES_LIMITS.mass)}
          unit="kg/m"
          value={f.rhoKgPerM}
          onCommit={(rhoKgPerM) => set({ rhoKgPerM })}
        />
      ) : (
        MOVING_LINKS.map((link) => (
          <LinkFields key={link} link={link} forces={f} lengthUnit={lengthUnit} dispatch={dispatch} t={t} />
        ))
      )}
      <NumberField
        {...forceField(t, t.gravity, 0, FORCES_LIMITS.gravity)}
        unit="m/s²"
        value={f.gravityMPerS2}
        onCommit={(gravityMPerS2) => set({ gravityMPerS2 })}
      />
      <NumberField
        {...forceField(t, t.gravityAngle, -360, 360)}
        unit="°"
        value={f.gravityAngleDeg}
        onCommit={(gravityAngleDeg) => set({ gravityAngleDeg })}
      />
      <p className="footnote">{t.gravityNote}</p>
      <h3 className="subhead">{t.loadsTitle}</h3>
      <NumberField
        {...forceField(t, t.pointForceX, -FORCES_LIMITS.force, FORCES_LIMITS.force)}
        unit="N"
        value={f.pointForceXN}
        onCommit={(pointForceXN) => set({ pointForceXN })}
      />
      <NumberField
        {...forceField(t, t.pointForceY, -FORCES_LIMITS.force, FORCES_LIMITS.force)}
        unit="N"
        value={f.pointForceYN}
        onCommit={(pointForceYN) => set({ pointForceYN })}
      />
      <NumberField
        {...forceField(t, t.loadTorque, -FORCES_LIMITS.torque, FORCES_LIMITS.torque)}
        unit="N·m"
        value={f.loadTorqueNm}
        onCommit={(loadTorqueNm) => set({ loadTorqueNm })}
      />
      <NumberField
        {...forceField(t, t.speedFluctuation, 1e-6, 1)}
        unit=""
        value={f.speedFluctuation}
        onCommit={(speedFluctuation) => set({ speedFluctuation })}
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
