import './Toggle.css';
import type { Dispatch } from 'react';
import type { Action, AppState, ViewFlag } from '../state/appState';
import { useMessages } from '../i18n/MessagesContext';
/** Props of Toggle: a labelled checkbox. */
export interface ToggleProps {
  label: string;
  checked: boolean;
  onChange: (checked: boolean) => void;
  disabled?: boolean;
}

/** A checkbox with its label; the label is its accessible name. */
export function Toggle({ label, checked, onChange, disabled }: ToggleProps) {
  return (
    <label className="toggle">
      <input type="checkbox" checked={checked} disabled={disabled} onChange={(e) => onChange(e.target.checked)} />
      <span>{label}</span>
    </label>
  );
}

/** Props of FlagToggles: which of the state's display flags to offer, the state and its dispatcher. */
export interface FlagTogglesProps {
  flags: readonly ViewFlag[];
  state: Pick<AppState['display'], ViewFlag>;
  dispatch: Dispatch<Action>;
}

/** A row of toggles for the state's display flags, each labelled with the message of the same name. */
export function FlagToggles({ flags, state, dispatch }: FlagTogglesProps) {
  const t = useMessages();
  return (
    <div className="toggles">
      {flags.map((flag) => (
        <Toggle
          key={flag}
          label={t[flag]}
          checked={state[flag]}
          onChange={(value) => dispatch({ type: 'setFlag', flag, value })}
        />
      ))}
    </div>
  );
}
