import type { UrlKey } from '../url/urlKey';
import type { Action } from './appState';

/**
 * One slice's registration in SLICES (appState.ts): what the app derives its state type, defaults, Action union,
 * reducer, URL table and the docs' lists from. S is the slice's state, A the actions only it handles.
 */
export interface Slice<S, A extends { type: string }> {
  /** One line for the docs: what the slice holds (docs/ARCHITECTURE.md "State" lists it). */
  summary: string;
  /** The slice's state before anything is set: DEFAULT_STATE's field. */
  defaults: S;
  /** Pure; sees every action (Redux's combineReducers) and returns s itself when nothing changed. */
  reducer(s: S, action: Action): S;
  /** The slice's URL keys, in the order serializeState writes them. */
  urlKeys: readonly UrlKey<unknown>[];
  /** Type only, never set: the actions only this slice handles, for the Action union. */
  readonly actionType?: A;
}
