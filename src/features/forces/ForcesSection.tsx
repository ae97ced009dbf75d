import './forces.css';
import type { Dispatch } from 'react';
import { Suspense, lazy } from 'react';
import type { Action, AppState } from '../../shared/state/appState';
import { PanelSection } from '../../shared/ui/PanelSection';
import { Toggle } from '../../shared/ui/Toggle';
import { forcesMessages } from './forcesMessages';

// The settings, the numbers at θ2 and the cycle's (with the cycle solver) load when Forces is first turned on.
const ForcesDetails = lazy(() => import('./ForcesDetails').then((m) => ({ default: m.ForcesDetails })));

/** Props of ForcesSection: the state, its dispatcher, and the section's class (a card in the results column). */
export interface ForcesSectionProps {
  state: AppState;
  dispatch: Dispatch<Action>;
  className?: string;
  /** Offer the mass, gravity and load settings (default); an embed shows toggles and numbers. */
  withSettings?: boolean;
  /** While true (Play runs), the section's content keeps its last render while it is off screen (PanelSection). */
  holdOffScreen?: boolean;
}

/**
 * The forces' section: the "Forces" toggle (the length unit sits with the lengths, LinksSection), then, while Forces is on, the mass model,
 * gravity and loads, the input torque, pin forces and shaking at θ2, and the cycle's torque and flywheel.
 */
export function ForcesSection({
  state,
  dispatch,
  className = 'card',
  withSettings = true,
  holdOffScreen,
}: ForcesSectionProps) {
  const t = forcesMessages.get(state.shell.locale);
  const f = state.forces;
  return (
    <PanelSection
      className={`${className} forces-section`}
      id="sec-forces"
      title={t.sectionForces}
      holdOffScreen={holdOffScreen}
    >
      <div className="toggles">
        <Toggle
          label={t.forcesToggle}
          checked={f.enabled}
          onChange={(enabled) => dispatch({ type: 'setForces', patch: { enabled } })}
        />
      </div>
      {f.enabled ? (
        <Suspense fallback={<p className="note">…</p>}>
          <ForcesDetails state={state} dispatch={dispatch} t={t} withSettings={withSettings} />
        </Suspense>
      ) : null}
    </PanelSection>
  );
}
