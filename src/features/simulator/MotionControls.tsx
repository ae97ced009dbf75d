import type { Dispatch } from 'react';
import type { Action, AppState } from '../../shared/state/appState';
import type { OmegaUnit } from '../../shared/state/inputMotion';
import { ALPHA_SLIDER, OMEGA_SLIDER, OMEGA_UNITS, omegaFromUnit, omegaToUnit } from '../../shared/state/inputMotion';
import { useMessages } from '../../shared/i18n/MessagesContext';
import { NumberControl } from '../../shared/ui/NumberControl';
import { FlagToggles } from '../../shared/ui/Toggle';
import { PanelSection } from '../../shared/ui/PanelSection';
import { SelectMenu } from '../../shared/ui/SelectMenu';

/** Props of MotionControls: the state and its dispatcher. */
export interface MotionControlsProps {
  state: AppState;
  dispatch: Dispatch<Action>;
}

/** Decimals the ω2 and α2 fields show (trailing zeros dropped). */
const MOTION_DECIMALS = 6;

/**
 * The input motion: ω2 (slider and field in the unit chosen beside it: rad/s, rpm or °/s, kept in the motion
 * slice as omegaUnit; ω2 itself is kept in rad/s), α2 in rad/s², and the toggles of the canvas's velocity and
 * acceleration vectors.
 */
export function MotionControls({ state, dispatch }: MotionControlsProps) {
  const t = useMessages();
  const unit = state.motion.omegaUnit;
  const slider = OMEGA_SLIDER[unit];
  return (
    <PanelSection holdOffScreen={state.motion.playing} id="sec-motion" title={t.sectionMotion}>
      <NumberControl
        field="omega2"
        value={omegaToUnit(state.motion.omega2RadPerS, unit)}
        decimals={MOTION_DECIMALS}
        min={slider.min}
        max={slider.max}
        step={slider.step}
        onCommit={(v) => dispatch({ type: 'setInputMotion', omega2RadPerS: omegaFromUnit(v, unit) })}
      />
      <label className="inline-field">
        <span>{t.omegaUnit}</span>
        <SelectMenu<OmegaUnit>
          label={t.omegaUnit}
          value={unit}
          options={OMEGA_UNITS.map((u) => ({ value: u, label: t.omegaUnits[u] }))}
          onChange={(u) => dispatch({ type: 'setOmegaUnit', unit: u })}
        />
      </label>
      <NumberControl
        field="alpha2"
        value={state.motion.alpha2RadPerS2}
        decimals={MOTION_DECIMALS}
        min={ALPHA_SLIDER.min}
        max={ALPHA_SLIDER.max}
        step={ALPHA_SLIDER.step}
        onCommit={(v) => dispatch({ type: 'setInputMotion', alpha2RadPerS2: v })}
      />
      <FlagToggles flags={['showVelocity', 'showAcceleration']} state={state.display} dispatch={dispatch} />
    </PanelSection>
  );
}
