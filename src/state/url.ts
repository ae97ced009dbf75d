import type { AppState, Direction, NrStart, PlotLayout } from './appState';
import { LAB_STEPS_DEG, LAB_TOLERANCES } from '../lab/options';
import { SWEEP_METHODS } from '../solver/methods';
import { wrapDeg180 } from '../solver/angles';
import { DEFAULT_STATE, SAMPLES_MAX, SAMPLES_MIN, normalizeTheta2Deg } from './appState';
import { parseLocale } from './i18n';
import type { FieldName } from './validate';
import { checkValue, parseDecimal } from './validate';

/** Panels an embed can show besides the canvas. */
export type EmbedPanel = 'controls' | 'info' | 'plots' | 'export';

/** Parameters an embed can lock (shown, not editable). */
export type LockableParam = 'r1' | 'r2' | 'r3' | 'r4' | 'theta2' | 'branch' | 'coupler' | 'play';

/** Embed-only options: which panels show and which parameters are locked. */
export interface EmbedOptions {
  panels: EmbedPanel[];
  locked: LockableParam[];
}

/** All embed panels in display order. */
export const EMBED_PANELS: readonly EmbedPanel[] = ['controls', 'info', 'plots', 'export'];
/** All lockable parameters. */
export const LOCKABLE_PARAMS: readonly LockableParam[] = [
  'r1',
  'r2',
  'r3',
  'r4',
  'theta2',
  'branch',
  'coupler',
  'play',
];
/** An embed shows the controls and the plots, with nothing locked, unless the URL says otherwise. */
export const DEFAULT_EMBED: EmbedOptions = { panels: ['controls', 'plots'], locked: [] };

/** Result of parsing a query string: the state, the embed options and one warning per ignored parameter. */
export interface ParsedUrl {
  state: AppState;
  embed: EmbedOptions;
  warnings: string[];
}

const ZOOM_MIN = 1e-3;
const ZOOM_MAX = 1e3;
const PAN_MAX = 100;

function parseBool(v: string): boolean | null {
  const s = v.trim().toLowerCase();
  if (s === '1' || s === 'true' || s === 'yes' || s === 'on') return true;
  if (s === '0' || s === 'false' || s === 'no' || s === 'off') return false;
  return null;
}

function parseList<T extends string>(v: string, allowed: readonly T[]): T[] | null {
  const s = v.trim();
  if (s === '' || s.toLowerCase() === 'none') return [];
  const items = s.split(',').map((x) => x.trim());
  const out: T[] = [];
  for (const item of items) {
    const hit = allowed.find((a) => a.toLowerCase() === item.toLowerCase());
    if (!hit) return null;
    if (!out.includes(hit)) out.push(hit);
  }
  return out;
}

/**
 * Parses a query string (with or without '?') into the app state on top of base; every bad parameter is
 * ignored with a warning (passed to warn, console.warn by default) and base's value kept. Never throws.
 */
export function parseUrl(
  search: string,
  base: AppState = DEFAULT_STATE,
  warn: (message: string) => void = (m) => console.warn(m),
): ParsedUrl {
  const params = new URLSearchParams(search.startsWith('?') ? search.slice(1) : search);
  const state: AppState = {
    ...base,
    linkage: { ...base.linkage },
    coupler: { ...base.coupler },
    view: { ...base.view },
  };
  const embed: EmbedOptions = { panels: [...DEFAULT_EMBED.panels], locked: [...DEFAULT_EMBED.locked] };
  const warnings: string[] = [];
  const bad = (key: string, value: string, why: string): void => {
    const msg = `Ignoring URL parameter ${key}=${JSON.stringify(value)}: ${why}; using the default.`;
    warnings.push(msg);
    warn(msg);
  };
  const num = (key: string, field: FieldName, value: string): number | null => {
    const x = parseDecimal(value);
    const r = checkValue(field, x, value);
    if (!r.ok) {
      bad(
        key,
        value,
        r.error.kind === 'notNumber' ? 'not a number' : `${r.error.kind} (allowed ${r.error.min} to ${r.error.max})`,
      );
      return null;
    }
    return r.value;
  };

  for (const [key, value] of params) {
    switch (key) {
      case 'r1':
      case 'r2':
      case 'r3':
      case 'r4': {
        const x = num(key, key, value);
        if (x !== null) state.linkage[key] = x;
        break;
      }
      case 't2': {
        const x = num(key, 'theta2', value);
        if (x !== null) state.theta2Deg = normalizeTheta2Deg(x);
        break;
      }
      case 'br':
        if (value === 'open' || value === 'crossed') state.branch = value;
        else bad(key, value, 'expected open or crossed');
        break;
      case 'pd': {
        const x = num(key, 'couplerDistance', value);
        if (x !== null) state.coupler.distance = x;
        break;
      }
      case 'pa': {
        const x = num(key, 'couplerAngle', value);
        if (x !== null) state.coupler.angleDeg = wrapDeg180(x);
        break;
      }
      case 'play': {
        const b = parseBool(value);
        if (b === null) bad(key, value, 'expected 0 or 1');
        else state.playing = b;
        break;
      }
      case 'spd': {
        const x = num(key, 'speed', value);
        if (x !== null) state.speedDegPerFrame = x;
        break;
      }
      case 'dir':
        if (value === 'ccw' || value === 'cw') state.direction = (value === 'ccw' ? 1 : -1) as Direction;
        else bad(key, value, 'expected ccw or cw');
        break;
      case 'grid':
      case 'ang':
      case 'ghost':
      case 'trace': {
        const b = parseBool(value);
        const flag = ({ grid: 'showGrid', ang: 'showAngles', ghost: 'showGhost', trace: 'showTrace' } as const)[key];
        if (b === null) bad(key, value, 'expected 0 or 1');
        else state[flag] = b;
        break;
      }
      case 'nr':
        if (value === 'cont' || value === 'cold')
          state.nrStart = (value === 'cont' ? 'continuation' : 'cold') as NrStart;
        else bad(key, value, 'expected cont or cold');
        break;
      case 'plots':
        if (value === 'separate' || value === 'together') state.plotLayout = value as PlotLayout;
        else bad(key, value, 'expected separate or together');
        break;
      case 'n': {
        const x = Number(value.trim());
        if (/^\d+$/.test(value.trim()) && x >= SAMPLES_MIN && x <= SAMPLES_MAX) state.samples = x;
        else bad(key, value, `expected a whole number from ${SAMPLES_MIN} to ${SAMPLES_MAX}`);
        break;
      }
      case 'lang': {
        const l = parseLocale(value);
        if (l) state.locale = l;
        else bad(key, value, 'expected en or zh-TW');
        break;
      }
      case 'z': {
        const x = parseDecimal(value);
        if (Number.isFinite(x) && x >= ZOOM_MIN && x <= ZOOM_MAX) state.view.zoom = x;
        else bad(key, value, `expected a zoom factor from ${ZOOM_MIN} to ${ZOOM_MAX}`);
        break;
      }
      case 'px':
      case 'py': {
        const x = parseDecimal(value);
        if (Number.isFinite(x) && Math.abs(x) <= PAN_MAX) state.view[key === 'px' ? 'panX' : 'panY'] = x;
        else bad(key, value, `expected a pan fraction from -${PAN_MAX} to ${PAN_MAX}`);
        break;
      }
      case 'm': {
        const m = SWEEP_METHODS.find((x) => x === value);
        if (m) state.method = m;
        else bad(key, value, `expected one of ${SWEEP_METHODS.join(', ')}`);
        break;
      }
      case 'tol': {
        if (value === 'default') {
          state.tol = null;
          break;
        }
        const x = Number(value.trim());
        const t = LAB_TOLERANCES.find((v) => v === x);
        if (t !== undefined) state.tol = t;
        else bad(key, value, `expected default or one of ${LAB_TOLERANCES.join(', ')}`);
        break;
      }
      case 'page':
        if (value === 'sim' || value === 'lab') state.page = value === 'lab' ? 'lab' : 'simulator';
        else bad(key, value, 'expected sim or lab');
        break;
      case 'lstep': {
        const x = Number(value.trim());
        const st = LAB_STEPS_DEG.find((v) => v === x);
        if (st !== undefined) state.labStepDeg = st;
        else bad(key, value, `expected one of ${LAB_STEPS_DEG.join(', ')}`);
        break;
      }
      case 'panels': {
        const list = parseList(value, EMBED_PANELS);
        if (list) embed.panels = list;
        else bad(key, value, `expected a comma-separated list of ${EMBED_PANELS.join(', ')}`);
        break;
      }
      case 'lock': {
        const list = parseList(value, LOCKABLE_PARAMS);
        if (list) embed.locked = list;
        else bad(key, value, `expected a comma-separated list of ${LOCKABLE_PARAMS.join(', ')}`);
        break;
      }
      default:
        bad(key, value, 'unknown parameter');
    }
  }
  return { state, embed, warnings };
}

/** Serialises the whole state (and embed options when given) to a query string without '?'; parseUrl restores it exactly. */
export function serializeState(state: AppState, embed?: EmbedOptions): string {
  const p = new URLSearchParams();
  p.set('r1', String(state.linkage.r1));
  p.set('r2', String(state.linkage.r2));
  p.set('r3', String(state.linkage.r3));
  p.set('r4', String(state.linkage.r4));
  p.set('t2', String(state.theta2Deg));
  p.set('br', state.branch);
  p.set('pd', String(state.coupler.distance));
  p.set('pa', String(state.coupler.angleDeg));
  p.set('play', state.playing ? '1' : '0');
  p.set('spd', String(state.speedDegPerFrame));
  p.set('dir', state.direction === 1 ? 'ccw' : 'cw');
  p.set('grid', state.showGrid ? '1' : '0');
  p.set('ang', state.showAngles ? '1' : '0');
  p.set('ghost', state.showGhost ? '1' : '0');
  p.set('trace', state.showTrace ? '1' : '0');
  p.set('nr', state.nrStart === 'continuation' ? 'cont' : 'cold');
  p.set('plots', state.plotLayout);
  p.set('n', String(state.samples));
  p.set('lang', state.locale);
  p.set('m', state.method);
  p.set('tol', state.tol === null ? 'default' : String(state.tol));
  if (state.page === 'lab') p.set('page', 'lab');
  if (state.labStepDeg !== DEFAULT_STATE.labStepDeg) p.set('lstep', String(state.labStepDeg));
  if (state.view.zoom !== 1 || state.view.panX !== 0 || state.view.panY !== 0) {
    p.set('z', String(state.view.zoom));
    p.set('px', String(state.view.panX));
    p.set('py', String(state.view.panY));
  }
  if (embed) {
    p.set('panels', embed.panels.length ? embed.panels.join(',') : 'none');
    if (embed.locked.length) p.set('lock', embed.locked.join(','));
  }
  return p.toString();
}

/** The URL of the embed page beside the app page: same directory, embed.html, with the state and embed options. */
export function embedUrl(appHref: string, state: AppState, embed: EmbedOptions): string {
  const u = new URL(appHref);
  u.search = '';
  u.hash = '';
  u.pathname = u.pathname.replace(/[^/]*$/, 'embed.html');
  return `${u.toString()}?${serializeState(state, embed)}`;
}

/** The URL of the full app beside the embed page, carrying the state. */
export function appUrl(embedHref: string, state: AppState): string {
  const u = new URL(embedHref);
  u.search = '';
  u.hash = '';
  u.pathname = u.pathname.replace(/[^/]*$/, '');
  return `${u.toString()}?${serializeState(state)}`;
}

/** Escapes text for an HTML attribute value in double quotes. */
export function escapeAttribute(s: string): string {
  return s.replace(/&/g, '&amp;').replace(/"/g, '&quot;').replace(/</g, '&lt;').replace(/>/g, '&gt;');
}

/** The iframe snippet that embeds the widget; sandboxed, lazy, with a title; width and height in CSS pixels. */
export function embedCode(src: string, title: string, width = 760, height = 520): string {
  return (
    `<iframe src="${escapeAttribute(src)}" title="${escapeAttribute(title)}" width="${width}" height="${height}" ` +
    `style="border:0;max-width:100%" loading="lazy" sandbox="allow-scripts allow-same-origin allow-downloads"></iframe>`
  );
}
