import { plainDecimal } from '../decimal';
import type { AppState, Page } from '../state/appState';
import { DEFAULT_EMBED } from './embedOptions';
import { serializeState } from './url';
import { urlKeysOn } from './urlKeys';

/** A URL key's value as JSON carries it: a number where the URL text is a number, a boolean, or the text. */
export type UrlValue = number | string | boolean;

/**
 * The state as URL keys and JSON values, the keys serializeState writes for a share link of the pages without keys
 * of their own (a design file is the simulator's; the spatial page's keys are not in it): numbers where the
 * URL text is a number and the value is not text (t2 rounded to 1e-9 degree), booleans for on/off keys, the URL text otherwise
 * (br 'open', dir 'ccw'). valueText gives each value's URL text back. With page, the keys a link of that page writes
 * (the embed of page=3d reports its spatial keys).
 */
export function stateValues(state: AppState, page: Page = 'simulator'): Record<string, UrlValue> {
  const out: Record<string, UrlValue> = {};
  const keys = urlKeysOn(page);
  for (const [name, text] of new URLSearchParams(serializeState(state, undefined, page))) {
    const k = keys.find((x) => x.name === name);
    const raw = k?.get({ state, embed: DEFAULT_EMBED });
    // A text value stays text even when it reads as a number (the expression "1.50" or "-0" is not 1.5 or 0).
    out[name] =
      typeof raw === 'boolean'
        ? raw
        : typeof raw !== 'string' && Number.isFinite(plainDecimal(text))
          ? Number(text)
          : text;
  }
  return out;
}

/**
 * The URL text a JSON value stands for: a finite number's shortest text, '1' or '0' for a boolean, a string up
 * to maxChars characters as it is; null for anything else (objects, arrays, null, NaN, longer strings).
 */
export function valueText(value: unknown, maxChars = Infinity): string | null {
  if (typeof value === 'number') return Number.isFinite(value) ? String(value) : null;
  if (typeof value === 'boolean') return value ? '1' : '0';
  if (typeof value === 'string') return value.length <= maxChars ? value : null;
  return null;
}
