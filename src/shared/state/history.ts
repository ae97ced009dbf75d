/**
 * Undo and redo as a pure wrapper around any reducer: past, present and future snapshots with a cap. The
 * wrapper knows nothing of the app; a policy (appHistory.ts for the app state) says which actions are undo
 * steps, how changes coalesce, and which parts of the present an undo keeps (the view, the language).
 */

/** Past states (oldest first), the present, and the states undone (the next redo first). */
export interface History<S> {
  past: readonly S[];
  present: S;
  future: readonly S[];
  /** Coalescing group of the newest step (null: the next change starts a new step). */
  group: string | null;
  /** The step key of the newest step's last change (null after an undo or redo). */
  key: string | null;
  /** When the newest step last changed, ms on the clock the `at` of apply actions uses. */
  at: number;
}

/** What the history reducer takes: an inner action to apply, or undo, redo. */
export type HistoryAction<A> =
  | {
      type: 'apply';
      action: A;
      /** When it happened, ms on any monotonic clock (performance.now()); bursts are measured on it. */
      at: number;
      /** The gesture under way (a pointer held down, a text field being typed in), or null. */
      gesture: number | null;
    }
  | { type: 'undo' }
  | { type: 'redo' };

/** How a history treats an inner action. */
export interface HistoryPolicy<S, A> {
  /**
   * The action's coalescing key when it is an undo step (two changes with the same key in one burst make one
   * step), or null when it is not a step: its change is kept in the present but never undone on its own.
   */
  stepKey(action: A): string | null;
  /** The state an undo or redo shows: the restored snapshot with what is not undone carried from the present. */
  carry(restored: S, present: S): S;
  /** Most past steps kept (the oldest are dropped); default HISTORY_CAP. */
  cap?: number;
  /** Longest pause inside a burst of changes with the same key, ms; default BURST_MS. */
  burstMs?: number;
}

/** Most undo steps kept. */
export const HISTORY_CAP = 100;

/** Changes with the same key less than this apart (ms) are one step: arrow keys held on a slider, typing. */
export const BURST_MS = 1000;

/** A history whose present is state, with nothing to undo or redo. */
export function initHistory<S>(state: S): History<S> {
  return { past: [], present: state, future: [], group: null, key: null, at: -Infinity };
}

/** Whether there is a step to undo. */
export function canUndo<S>(h: History<S>): boolean {
  return h.past.length > 0;
}

/** Whether there is a step to redo. */
export function canRedo<S>(h: History<S>): boolean {
  return h.future.length > 0;
}

/**
 * The reducer of a history of reducer's states under a policy. An apply that changes nothing returns the same
 * history. A change that is no step replaces the present only (past and future stay). A step joins the newest
 * step when it comes in the same gesture, or outside any gesture with the same key less than burstMs after it
 * (so the value a drag commits on its release, after the pointer's gesture ended, is the drag's); otherwise the present
 * goes to the past (at most cap kept) and the future is dropped. Undo and redo move one snapshot and seal the
 * newest step, so the next change never joins a step that was undone. Pure.
 */
export function historyReducer<S, A>(reducer: (state: S, action: A) => S, policy: HistoryPolicy<S, A>) {
  const cap = policy.cap ?? HISTORY_CAP;
  const burstMs = policy.burstMs ?? BURST_MS;
  return (h: History<S>, action: HistoryAction<A>): History<S> => {
    switch (action.type) {
      case 'undo': {
        if (h.past.length === 0) return h;
        const restored = h.past[h.past.length - 1];
        return {
          past: h.past.slice(0, -1),
          present: policy.carry(restored, h.present),
          future: [h.present, ...h.future],
          group: null,
          key: null,
          at: -Infinity,
        };
      }
      case 'redo': {
        if (h.future.length === 0) return h;
        return {
          past: [...h.past, h.present],
          present: policy.carry(h.future[0], h.present),
          future: h.future.slice(1),
          group: null,
          key: null,
          at: -Infinity,
        };
      }
      case 'apply': {
        const next = reducer(h.present, action.action);
        if (next === h.present) return h;
        const key = policy.stepKey(action.action);
        if (key === null) return { ...h, present: next };
        const group = action.gesture !== null ? `gesture:${action.gesture}` : `key:${key}`;
        const joins =
          h.past.length > 0 &&
          (action.gesture !== null ? group === h.group : key === h.key && action.at - h.at <= burstMs);
        if (joins) return { ...h, present: next, future: [], key, at: action.at };
        const past = [...h.past, h.present];
        return {
          past: past.length > cap ? past.slice(past.length - cap) : past,
          present: next,
          future: [],
          group,
          key,
          at: action.at,
        };
      }
    }
  };
}
