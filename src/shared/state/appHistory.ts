import type { Action, AppState } from './appState';
import { reducer } from './appState';
import type { History, HistoryAction, HistoryPolicy } from './history';
import { historyReducer } from './history';

/**
 * Actions that are not undo steps: Play's frames and Step ('animate'), Play and Pause, the view's pan and zoom,
 * the language and the page. Their changes stay in the present; an undo keeps the view, the language and the
 * page as they are (carryPresent) and restores the rest, θ2 included.
 */
export const NOT_UNDO_STEPS: ReadonlySet<Action['type']> = new Set<Action['type']>([
  'animate',
  'setPlaying',
  'setView',
  'setLocale',
  'setPage',
]);

/** An action with every number replaced by '#': changes of the same field (any value) share the key. */
function shapeOf(value: unknown): unknown {
  if (typeof value === 'number') return '#';
  if (Array.isArray(value)) return value.map(shapeOf);
  if (value !== null && typeof value === 'object') {
    const out: Record<string, unknown> = {};
    for (const k of Object.keys(value).sort()) out[k] = shapeOf((value as Record<string, unknown>)[k]);
    return out;
  }
  return value;
}

/**
 * The coalescing key of an app action: its type and fields with every number blanked, so a dragged or typed
 * value (setLength r2 2 → 2.1 → 2.15) is one burst while a choice (a branch, a flag, a page) is a step of its
 * own each time; null for the actions in NOT_UNDO_STEPS.
 */
export function appStepKey(action: Action): string | null {
  return NOT_UNDO_STEPS.has(action.type) ? null : JSON.stringify(shapeOf(action));
}

/**
 * The state an undo or redo shows: the restored snapshot with the present's language, page and view (not undo
 * steps), and paused (an undone θ2 shows exactly, not a frame later). Untouched slices keep their identity.
 */
export function carryPresent(restored: AppState, present: AppState): AppState {
  const view = present.display.view;
  return {
    ...restored,
    shell: present.shell,
    display: restored.display.view === view ? restored.display : { ...restored.display, view },
    motion: restored.motion.playing ? { ...restored.motion, playing: false } : restored.motion,
  };
}

/** The app's undo policy: appStepKey and carryPresent with the default cap and burst. */
export const APP_HISTORY_POLICY: HistoryPolicy<AppState, Action> = { stepKey: appStepKey, carry: carryPresent };

/** The app reducer with undo and redo (src/app/useAppHistory.ts uses it). */
export const appHistoryReducer: (h: History<AppState>, action: HistoryAction<Action>) => History<AppState> =
  historyReducer(reducer, APP_HISTORY_POLICY);
