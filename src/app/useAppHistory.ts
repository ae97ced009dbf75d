import { useCallback, useEffect, useReducer, useRef } from 'react';
import type { Dispatch } from 'react';
import type { Action, AppState } from '../shared/state/appState';
import { appHistoryReducer } from '../shared/state/appHistory';
import { canRedo, canUndo, initHistory } from '../shared/state/history';
import { isTextField } from '../shared/ui/textField';
import { followPointers } from '../shared/hooks/heldPointers';

/** The app state with undo and redo. */
export interface AppHistory {
  state: AppState;
  /** Applies an action; undo steps are recorded as docs/ARCHITECTURE.md "Undo" says. */
  dispatch: Dispatch<Action>;
  undo: () => void;
  redo: () => void;
  canUndo: boolean;
  canRedo: boolean;
}

/**
 * The gesture under way, as a number that changes with each gesture, or null: a pointer held down anywhere (a
 * joint dragged on the canvas, a slider's thumb, a pinch) or a text field being typed in, from focus to blur.
 * Every change inside one gesture is one undo step.
 */
function useGesture(): () => number | null {
  const next = useRef(0);
  const pointer = useRef<number | null>(null);
  const field = useRef<number | null>(null);
  useEffect(() => {
    const pointers = followPointers({
      press: () => {
        pointer.current = ++next.current;
      },
      release: () => {
        pointer.current = null;
      },
    });
    const focusIn = (e: FocusEvent) => {
      field.current = isTextField(e.target) ? ++next.current : null;
    };
    const focusOut = () => {
      field.current = null;
    };
    const opts = { capture: true, passive: true };
    window.addEventListener('focusin', focusIn, opts);
    window.addEventListener('focusout', focusOut, opts);
    return () => {
      pointers.dispose();
      window.removeEventListener('focusin', focusIn, opts);
      window.removeEventListener('focusout', focusOut, opts);
    };
  }, []);
  // A pointer held down wins: a drag on the canvas while a field keeps focus is the drag's own step.
  return useCallback(() => pointer.current ?? field.current, []);
}

/**
 * The app state (starting from initial) through the undoable reducer (shared/state/appHistory.ts): dispatch
 * stamps each action with the time and the gesture under way, so a drag or a typed value is one step.
 */
export function useAppHistory(initial: AppState): AppHistory {
  const [history, send] = useReducer(appHistoryReducer, initial, initHistory);
  const gesture = useGesture();
  const dispatch = useCallback<Dispatch<Action>>(
    (action) => send({ type: 'apply', action, at: performance.now(), gesture: gesture() }),
    [gesture],
  );
  const undo = useCallback(() => send({ type: 'undo' }), []);
  const redo = useCallback(() => send({ type: 'redo' }), []);
  return {
    state: history.present,
    dispatch,
    undo,
    redo,
    canUndo: canUndo(history),
    canRedo: canRedo(history),
  };
}
