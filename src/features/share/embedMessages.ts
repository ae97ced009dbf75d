import type { AppState } from '../../shared/state/appState';
import type { LockableParam } from '../../shared/url/embedOptions';
import { DEFAULT_EMBED, pageEmbedOptions } from '../../shared/url/embedOptions';
import type { UrlTarget } from '../../shared/url/urlKeys';
import { URL_CONSTRAINTS, urlKeysOn } from '../../shared/url/urlKeys';
import type { UrlValue } from '../../shared/url/urlValues';
import { valueText } from '../../shared/url/urlValues';

export { stateValues } from '../../shared/url/urlValues';

/** The tag on every message the widget posts (`source`) and on every command it accepts (`target`). */
export const EMBED_MESSAGE_TAG = 'fourbar-lab';

/** A value in a state event or a set-state command: what JSON carries for a URL key. */
export type EmbedValue = UrlValue;

/** What the widget posts to its host when its state changes: URL keys and their values. */
export interface StateEvent {
  source: typeof EMBED_MESSAGE_TAG;
  type: 'state';
  state: Record<string, EmbedValue>;
}

/** The only command the widget accepts: set some URL keys (r1..r4, t2, br, pd, pa, play, ...). */
export interface SetStateCommand {
  target: typeof EMBED_MESSAGE_TAG;
  type: 'set-state';
  state: Record<string, unknown>;
}

/** Longest string value a command may carry, characters (a URL value is never longer; more is refused unread). */
export const MAX_VALUE_CHARS = 64;

/** The lock that guards each of the simulator's URL keys a command could set: a locked value is refused. */
export const LOCK_OF_KEY: Readonly<Partial<Record<string, LockableParam>>> = pageEmbedOptions('simulator').keyLocks;

function isRecord(x: unknown): x is Record<string, unknown> {
  return typeof x === 'object' && x !== null && !Array.isArray(x);
}

/** The message the widget posts to its host for a state's URL values (stateValues). */
export function stateEvent(values: Record<string, EmbedValue>): StateEvent {
  return { source: EMBED_MESSAGE_TAG, type: 'state', state: values };
}

/** The keys and values of a set-state command, or null when data is not one (anything else is ignored). */
export function readSetState(data: unknown): Record<string, unknown> | null {
  if (!isRecord(data) || data.target !== EMBED_MESSAGE_TAG || data.type !== 'set-state') return null;
  return isRecord(data.state) ? data.state : null;
}

/** A key of a patch that was not applied, and why (English, for the console). */
export interface RefusedKey {
  key: string;
  why: string;
}

/** What applyPatch made of a patch: the new state, the keys applied, the keys refused and why. */
export interface PatchResult {
  state: AppState;
  applied: string[];
  refused: RefusedKey[];
}

/**
 * Applies a patch of URL keys to the state through the URL table's codecs (the same parse as a link's query):
 * numbers, booleans and strings up to MAX_VALUE_CHARS are read as the URL text they stand for, with the keys of the
 * state's page (page=3d's r2 is the RSSR crank). Unknown keys, embed-only keys (panels, lock), bad values and keys
 * guarded by a lock in `locked` (the page's keyLocks, PAGE_EMBEDS) are refused and listed;
 * the rules between keys (URL_CONSTRAINTS) revert the keys that break them. Never throws, never evaluates.
 */
export function applyPatch(
  state: AppState,
  patch: Readonly<Record<string, unknown>>,
  locked: readonly LockableParam[] = [],
): PatchResult {
  const start: UrlTarget = { state, embed: DEFAULT_EMBED };
  const keys = urlKeysOn(state.shell.page);
  const keyLocks = pageEmbedOptions(state.shell.page).keyLocks;
  let target = start;
  const applied: string[] = [];
  const refused: RefusedKey[] = [];
  // In the URL table's order, as a link is read: tpl before mech (a new template clears the edit mech then sets).
  const rank = (name: string) => {
    const i = keys.findIndex((x) => x.name === name);
    return i < 0 ? keys.length : i;
  };
  for (const name of Object.keys(patch).sort((a, b) => rank(a) - rank(b))) {
    const k = keys.find((x) => x.name === name);
    if (!k || k.scope !== 'state') {
      refused.push({ key: name, why: 'unknown key' });
      continue;
    }
    if (name === 'page') {
      // Its panels and locks are the page's: another page would come unlocked.
      refused.push({ key: name, why: 'the page is fixed by the embed (its panels and locks are that page’s)' });
      continue;
    }
    const lock = Object.hasOwn(keyLocks, name) ? keyLocks[name] : undefined;
    if (lock && locked.includes(lock)) {
      refused.push({ key: name, why: `locked (${lock})` });
      continue;
    }
    const text = valueText(patch[name], MAX_VALUE_CHARS);
    const r = text === null ? null : k.parse(text);
    if (!r || !r.ok) {
      refused.push({ key: name, why: r ? r.why : 'expected a finite number, a boolean or a short string' });
      continue;
    }
    target = k.set(target, r.value);
    applied.push(name);
  }
  for (const c of URL_CONSTRAINTS) {
    if (c.holds(target.state)) continue;
    for (const name of c.keys) {
      const k = keys.find((x) => x.name === name);
      if (!k || !applied.includes(name)) continue;
      target = k.set(target, k.get(start));
      applied.splice(applied.indexOf(name), 1);
      refused.push({ key: name, why: c.why });
    }
  }
  // Reported in the patch's order.
  const given = Object.keys(patch);
  applied.sort((a, b) => given.indexOf(a) - given.indexOf(b));
  refused.sort((a, b) => given.indexOf(a.key) - given.indexOf(b.key));
  return { state: applied.length ? target.state : state, applied, refused };
}
