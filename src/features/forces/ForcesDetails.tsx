import type { Dispatch } from 'react';
import type { Action, AppState } from '../../shared/state/appState';
import { Toggle } from '../../shared/ui/Toggle';
import type { ForcesMessages } from './forcesMessages';
import { ForcesPanel } from './ForcesPanel';
import { ForcesSettings } from './ForcesSettings';

/** Props of ForcesDetails: the state, its dispatcher, the strings, whether to offer the settings (not in an embed). */
export interface ForcesDetailsProps {
  state: AppState;
  dispatch: Dispatch<Action>;
  t: ForcesMessages;
  withSettings: boolean;
}

/** What the forces section shows while Forces is on (loaded then): the arrows' toggle, the numbers, the settings. */
export function ForcesDetails({ state, dispatch, t, withSettings }: ForcesDetailsProps) {
  return (
    <>
      <div className="toggles">
        <Toggle
          label={t.forceVectors}
          checked={state.forces.showVectors}
          onChange={(showVectors) => dispatch({ type: 'setForces', patch: { showVectors } })}
        />
      </div>
      <ForcesPanel state={state} t={t} />
      {withSettings ? (
        <ForcesSettings
          forces={state.forces}
          linkage={state.design.linkage}
          lengthUnit={state.design.lengthUnit}
          dispatch={dispatch}
          t={t}
        />
      ) : null}
    </>
  );
}
