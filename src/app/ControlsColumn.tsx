import { useEffect, useId, useLayoutEffect, useRef, useState } from 'react';
import { ControlsPanel } from '../features/simulator/ControlsPanel';
import { PhoneBar } from '../features/simulator/phone/PhoneBar';
import { useElementSize } from '../shared/hooks/useElementSize';
import type { SimulatorSession } from './useSimulatorSession';

/** The CSS variable that holds the phone bar's height (layout.css pads the page's end by it). */
const PHONE_BAR_HEIGHT_VAR = '--phone-bar-height';

/** Props of ControlsColumn: the session, the controls landmark's name and whether the phone layout is on. */
export interface ControlsColumnProps {
  session: SimulatorSession;
  label: string;
  /** The phone layout on the simulator page: the bar at the bottom, the other controls in a sheet above it. */
  phone: boolean;
}

/**
 * The phone layout's dock, fixed at the bottom: the phone bar (Play, step, θ2, the branch) and above it, while
 * open, the sheet of every other control (rendered only then). Escape closes the sheet.
 */
function PhoneDock({ session, label }: Omit<ControlsColumnProps, 'phone'>) {
  const { state, dispatch, rocking, onStep } = session;
  const [sheetOpen, setSheetOpen] = useState(false);
  const sheetId = useId();
  const barRef = useRef<HTMLDivElement>(null);
  const { height: barHeight } = useElementSize(barRef);
  // The page keeps its end above the fixed bar: layout.css pads the app by this height.
  useLayoutEffect(() => {
    if (barHeight === 0) return;
    const root = document.documentElement;
    root.style.setProperty(PHONE_BAR_HEIGHT_VAR, `${barHeight}px`);
    return () => {
      root.style.removeProperty(PHONE_BAR_HEIGHT_VAR);
    };
  }, [barHeight]);
  useEffect(() => {
    if (!sheetOpen) return;
    const onKey = (e: KeyboardEvent) => {
      if (e.key === 'Escape') setSheetOpen(false);
    };
    window.addEventListener('keydown', onKey);
    return () => window.removeEventListener('keydown', onKey);
  }, [sheetOpen]);
  return (
    <div className="phone-dock">
      {sheetOpen ? (
        <aside className="sidebar phone-sheet" id={sheetId} aria-label={label}>
          <ControlsPanel state={state} dispatch={dispatch} rocking={rocking} onStep={onStep} phone />
        </aside>
      ) : null}
      <div ref={barRef}>
        <PhoneBar
          state={state}
          dispatch={dispatch}
          onStep={onStep}
          sheetId={sheetId}
          sheetOpen={sheetOpen}
          onToggleSheet={() => {
            // Opening, bring the canvas to the top: the linkage stays in view above the sheet while a control moves.
            if (!sheetOpen) document.querySelector('.app-main')?.scrollIntoView({ block: 'start' });
            setSheetOpen(!sheetOpen);
          }}
        />
      </div>
    </div>
  );
}

/** The full app's controls: the sidebar, or on a phone's simulator page the phone dock (PhoneDock). */
export function ControlsColumn({ session, label, phone }: ControlsColumnProps) {
  if (phone) return <PhoneDock session={session} label={label} />;
  const { state, dispatch, rocking, onStep } = session;
  return (
    <aside className="sidebar" aria-label={label}>
      <ControlsPanel state={state} dispatch={dispatch} rocking={rocking} onStep={onStep} />
    </aside>
  );
}
