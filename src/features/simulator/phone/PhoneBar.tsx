import './PhoneBar.css';
import type { Dispatch } from 'react';
import type { Action, AppState } from '../../../shared/state/appState';
import { BranchControl, PlayRow, Theta2Control } from '../ControlsSections';
import { phoneMessages } from './phoneMessages';

/** Props of PhoneBar: the state, its dispatcher, the step handler, and the controls sheet it opens and closes. */
export interface PhoneBarProps {
  state: AppState;
  dispatch: Dispatch<Action>;
  onStep: (sign: 1 | -1) => void;
  /** Id of the sheet of all the other controls, and whether it is open. */
  sheetId: string;
  sheetOpen: boolean;
  onToggleSheet: () => void;
}

/** Nothing is locked in the full app. */
const unlocked = () => false;

/** Three bars: the sheet button's icon. */
function SheetIcon({ open }: { open: boolean }) {
  return (
    <svg width="18" height="18" viewBox="0 0 16 16" aria-hidden="true" focusable="false">
      <path
        d={open ? 'M3.5 5.5 8 10l4.5-4.5 1 1L8 12 2.5 6.5z' : 'M2 3.5h12V5H2zM2 7.25h12v1.5H2zM2 11h12v1.5H2z'}
        fill="currentColor"
      />
    </svg>
  );
}

/**
 * The phone layout's bar, fixed at the bottom within reach of a thumb: step back, Play/Pause, step forward,
 * the branch and the button of the controls sheet on one row, θ2's field and slider under them. The controls
 * are the sidebar's own (same accessible names), which the sheet then leaves out.
 */
export function PhoneBar({ state, dispatch, onStep, sheetId, sheetOpen, onToggleSheet }: PhoneBarProps) {
  const p = phoneMessages(state.shell.locale);
  const section = { state, dispatch, isLocked: unlocked };
  return (
    <div className="phone-bar" role="region" aria-label={p.barLabel}>
      <div className="phone-bar-row">
        <PlayRow {...section} onStep={onStep} />
        <BranchControl {...section} hideLegend />
        <button
          type="button"
          className="icon-btn phone-sheet-btn"
          aria-label={p.allControls}
          title={p.allControls}
          aria-expanded={sheetOpen}
          aria-controls={sheetId}
          onClick={onToggleSheet}
        >
          <SheetIcon open={sheetOpen} />
        </button>
      </div>
      <Theta2Control {...section} />
    </div>
  );
}
