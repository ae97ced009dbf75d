import './SynthesisPage.css';
import { Suspense, lazy, useCallback } from 'react';
import type { Dispatch } from 'react';
import type { Action, AppState, SynthesisMode } from '../../shared/state/appState';
import { Segmented } from '../../shared/ui/Segmented';
import type { OpenDesign } from './openDesign';
import { openDesignState } from './openDesign';
import { synthesisMessagesFor } from './synthesisMessages';
import type { SynthesisPool } from './path/usePathSynthesis';
import { PathMode } from './path/PathMode';

/** Props of SynthesisPage: the app state and dispatch, and how to make the pool of solver workers. */
export interface SynthesisPageProps {
  state: AppState;
  dispatch: Dispatch<Action>;
  createPool: () => SynthesisPool;
}

// The Motion and Function modes (built beside this page in motion/ and function/) load when first chosen.
const MotionMode = lazy(() => import('./motion/MotionMode').then((m) => ({ default: m.MotionMode })));
const FunctionMode = lazy(() => import('./function/FunctionMode').then((m) => ({ default: m.FunctionMode })));
const NinePointMode = lazy(() => import('./ninePoint/NinePointMode').then((m) => ({ default: m.NinePointMode })));

/**
 * The synthesis page: Path, Motion, Function and Nine points modes behind one segmented control (URL syn), each handing its
 * chosen design to "Open in simulator", which puts the design, its placement and its markers into the app state
 * and turns to the simulator.
 */
export function SynthesisPage({ state, dispatch, createPool }: SynthesisPageProps) {
  const st = synthesisMessagesFor(state.shell.locale);
  const mode = state.synPath.mode;
  const onOpen = useCallback(
    (open: OpenDesign) => {
      dispatch({ type: 'replace', state: openDesignState(state, open) });
      // The simulator opens at its top, where the canvas is, not at the synthesis page's scroll.
      window.scrollTo(0, 0);
    },
    [dispatch, state],
  );
  const modes: { value: SynthesisMode; label: string }[] = [
    { value: 'path', label: st.modePath },
    { value: 'motion', label: st.modeMotion },
    { value: 'function', label: st.modeFunction },
    { value: 'nine', label: st.modeNine },
  ];
  const Other = mode === 'motion' ? MotionMode : FunctionMode;
  return (
    <div className="synthesis" data-testid="synthesis-page">
      <div className="synthesis-head">
        <h2 className="section-title">{st.pageTitle}</h2>
        <Segmented
          legend={st.modeLegend}
          hideLegend
          value={mode}
          options={modes}
          onChange={(m) => dispatch({ type: 'setSynthesisMode', mode: m })}
        />
        {/* The print view (print/SynthesisPrint) is made by the mode shown when printing starts. */}
        <button
          type="button"
          className="btn btn-small syn-print-button"
          title={st.print.note}
          onClick={() => window.print()}
        >
          {st.print.button}
        </button>
      </div>
      {mode === 'path' ? (
        <PathMode state={state} dispatch={dispatch} onOpen={onOpen} createPool={createPool} />
      ) : mode === 'nine' ? (
        <Suspense fallback={<p className="note">{st.modeLoading}</p>}>
          <NinePointMode state={state} dispatch={dispatch} onOpen={onOpen} createPool={createPool} />
        </Suspense>
      ) : (
        <Suspense fallback={<p className="note">{st.modeLoading}</p>}>
          <Other state={state} dispatch={dispatch} onOpen={onOpen} />
        </Suspense>
      )}
    </div>
  );
}
