import type { AppState } from '../../shared/state/appState';
import { DEFAULT_STATE } from '../../shared/state/appState';
import type { Page } from '../../shared/state/slices/shellSlice';
import { MECH_URL_KEYS, templateUrlValue } from '../../shared/state/slices/mechSlice';
import { PAGE_URL_VALUES, SHELL_URL_KEYS } from '../../shared/state/slices/shellSlice';
import { DEFAULT_EMBED } from '../../shared/url/embedOptions';
import type { UrlTarget } from '../../shared/url/urlKeys';
import { URL_CONSTRAINTS, URL_KEYS } from '../../shared/url/urlKeys';
import type { UrlValue } from '../../shared/url/urlValues';
import { stateValues, valueText } from '../../shared/url/urlValues';

/** The `format` of every design file (docs/design-file.md). */
export const DESIGN_FILE_FORMAT = 'fourbar-lab.design';

/** The newest file version this app writes and reads; a file with a higher one is refused, never guessed at. */
export const DESIGN_FILE_VERSION = 1;

/** The end of a design file's name: `<name>.fourbar.json`. */
export const DESIGN_FILE_EXTENSION = '.fourbar.json';

/**
 * URL keys a file does not hold: the language and the page (the reader's own choice) and Play (a design opens
 * paused). A file that has them anyway is read without them.
 */
export const NOT_IN_FILE: ReadonlySet<string> = new Set(['play', ...SHELL_URL_KEYS.map((k) => k.name)]);

/** A design file as JSON: docs/design-file.md describes each field. */
export interface DesignFile {
  format: typeof DESIGN_FILE_FORMAT;
  version: number;
  /** The design's name (the file name without `.fourbar.json`). */
  name: string;
  /** When it was saved, ISO 8601 in UTC. */
  savedAt: string;
  /**
   * The page the work belongs to, as the URL writes it ("syn"), written only for work saved on a page other than the
   * simulator's (the synthesis task); opening the file shows that page. Optional: files without it open as before.
   */
  page?: string;
  /** The work: the share link's keys (every slice's URL keys but NOT_IN_FILE and MECH_SECTION_KEYS) with JSON values. */
  state: Record<string, UrlValue>;
  /**
   * The Mechanisms page's work (the mech slice): its share link keys (MECH_SECTION_KEYS) with JSON values, `mech` as a
   * plain MechanismSpec. Written on the Mechanisms page and whenever the slice is not at its defaults. Optional:
   * files without it open as before (a file from before it may hold these keys in `state`, which is read too).
   */
  mechanism?: Record<string, UrlValue | MechSpecJson>;
}

/** A MechanismSpec as JSON, as the `mechanism` section's `mech` holds it. */
type MechSpecJson = Record<string, unknown>;

/** The URL keys of the mech slice: a file holds them in its `mechanism` section. */
export const MECH_SECTION_KEYS: ReadonlySet<string> = new Set(MECH_URL_KEYS.map((k) => k.name));

/** A field of a file that could not be read: its path in the file, its value as written, and why (English). */
export interface BadField {
  field: string;
  value: string;
  why: string;
}

/** Why a file was refused; nothing of it is applied. */
export type DesignFileError =
  | { kind: 'notJson' }
  | { kind: 'notObject' }
  | { kind: 'newer'; version: number }
  | { kind: 'fields'; fields: BadField[] };

/** What reading a file gave: the state, the design's name and when it was saved, or why it was refused. */
export type DesignFileRead =
  | { ok: true; state: AppState; name: string; savedAt: string | null; page: Page | null }
  | { ok: false; error: DesignFileError };

/** Pages whose work a file names (the simulator's design is on every page, so a simulator file names none). */
const FILE_PAGES: readonly Page[] = ['synthesis', 'mechanism'];

/** The page of a URL value ("syn"), or null. */
function pageOf(value: unknown): Page | null {
  const hit = (Object.keys(PAGE_URL_VALUES) as Page[]).find((p) => PAGE_URL_VALUES[p] === value);
  return hit ?? null;
}

/** The work of a state as a file's `state` holds it: stateValues without NOT_IN_FILE and the mechanism section's. */
export function designValues(state: AppState): Record<string, UrlValue> {
  const out: Record<string, UrlValue> = {};
  for (const [k, v] of Object.entries(stateValues(state)))
    if (!NOT_IN_FILE.has(k) && !MECH_SECTION_KEYS.has(k)) out[k] = v;
  return out;
}

/** The mechanism section of a state: the mech slice's link keys with JSON values, the linkage as a plain spec. */
export function mechanismValues(state: AppState): Record<string, UrlValue | MechSpecJson> {
  const out: Record<string, UrlValue | MechSpecJson> = {};
  for (const [k, v] of Object.entries(stateValues(state))) if (MECH_SECTION_KEYS.has(k)) out[k] = v;
  if (state.mech.spec) out.mech = JSON.parse(JSON.stringify(state.mech.spec)) as MechSpecJson;
  return out;
}

/** The design file of a state, as the JSON text Save writes (two-space indent, a final newline). */
export function writeDesignFile(state: AppState, name: string, savedAt: Date): string {
  const page = state.shell.page;
  const mechanism = mechanismValues(state);
  const file: DesignFile = {
    format: DESIGN_FILE_FORMAT,
    version: DESIGN_FILE_VERSION,
    name,
    savedAt: savedAt.toISOString(),
    ...(FILE_PAGES.includes(page) ? { page: PAGE_URL_VALUES[page] } : {}),
    state: designValues(state),
    ...(page === 'mechanism' || Object.keys(mechanism).length > 0 ? { mechanism } : {}),
  };
  return `${JSON.stringify(file, null, 2)}\n`;
}

/**
 * The name Save offers on the synthesis page: the task's (path-6-targets, motion-8-poses, function-log10(x),
 * nine-points); on the Mechanisms page the template's, as its exports name it (mechanism_jansen,
 * mechanism_jansen_edited); null on other pages (the lengths' file stem is the name there).
 */
export function taskName(state: AppState): string | null {
  if (state.shell.page === 'mechanism')
    return `mechanism_${templateUrlValue(state.mech.template)}${state.mech.spec ? '_edited' : ''}`;
  if (state.shell.page !== 'synthesis') return null;
  switch (state.synPath.mode) {
    case 'path':
      return `path-${state.synPath.targets.length}-targets`;
    case 'motion':
      return `motion-${state.synMotion.poses.length}-poses`;
    case 'function':
      return `function-${state.synFunction.expression}`;
    case 'nine':
      return 'nine-points';
  }
}

/** A design name as a file name: `<name>.fourbar.json`, without the characters file systems refuse. */
export function designFileName(name: string): string {
  // Control characters, and the characters Windows, macOS or Linux refuse in a file name.
  const safe = name.replace(/[\u0000-\u001f<>:"/\\|?*]+/g, '_').trim();
  return `${safe || 'design'}${DESIGN_FILE_EXTENSION}`;
}

/** The design name of a file name: the name without `.fourbar.json` (or `.json`). */
export function designNameOf(fileName: string): string {
  return fileName.replace(/\.fourbar\.json$/i, '').replace(/\.json$/i, '');
}

function isRecord(x: unknown): x is Record<string, unknown> {
  return typeof x === 'object' && x !== null && !Array.isArray(x);
}

/** A value as the message echoes it: JSON text, or "missing". */
function shown(value: unknown): string {
  return value === undefined ? 'missing' : (JSON.stringify(value) ?? String(value));
}

/** The file's header fields (format, version, name, savedAt, state, mechanism) that are wrong, or a newer version. */
function checkHeader(file: Record<string, unknown>): DesignFileError | null {
  const bad: BadField[] = [];
  if (file.format !== DESIGN_FILE_FORMAT)
    bad.push({ field: 'format', value: shown(file.format), why: `expected "${DESIGN_FILE_FORMAT}"` });
  const v = file.version;
  if (typeof v !== 'number' || !Number.isInteger(v) || v < 1)
    bad.push({ field: 'version', value: shown(v), why: 'expected a whole number from 1' });
  else if (v > DESIGN_FILE_VERSION && bad.length === 0) return { kind: 'newer', version: v };
  if (file.name !== undefined && typeof file.name !== 'string')
    bad.push({ field: 'name', value: shown(file.name), why: 'expected text' });
  if (file.page !== undefined && !FILE_PAGES.includes(pageOf(file.page) as Page))
    bad.push({
      field: 'page',
      value: shown(file.page),
      why: `expected ${FILE_PAGES.map((p) => `"${PAGE_URL_VALUES[p]}"`).join(' or ')}`,
    });
  if (file.savedAt !== undefined && (typeof file.savedAt !== 'string' || Number.isNaN(Date.parse(file.savedAt))))
    bad.push({ field: 'savedAt', value: shown(file.savedAt), why: 'expected an ISO 8601 time' });
  if (!isRecord(file.state))
    bad.push({ field: 'state', value: shown(file.state), why: 'expected an object of design fields' });
  if (file.mechanism !== undefined && !isRecord(file.mechanism))
    bad.push({ field: 'mechanism', value: shown(file.mechanism), why: 'expected an object of mechanism fields' });
  return bad.length ? { kind: 'fields', fields: bad } : null;
}

/**
 * Reads a design file's text. The state starts from the defaults with base's language and page (so a field a
 * file leaves out, as an older file may, is its default) and takes every field of `state` through the URL key
 * table's codecs, the same checks as a share link; the rules between keys (URL_CONSTRAINTS) hold after. Any
 * wrong field refuses the whole file and every wrong field is named: a file is never half applied. Never throws.
 */
export function readDesignFile(text: string, base: AppState): DesignFileRead {
  let json: unknown;
  try {
    json = JSON.parse(text);
  } catch {
    return { ok: false, error: { kind: 'notJson' } };
  }
  if (!isRecord(json)) return { ok: false, error: { kind: 'notObject' } };
  const header = checkHeader(json);
  if (header) return { ok: false, error: header };
  // The mechanism section's keys after state's (a file from before the section holds them in state).
  const mechanism = (json.mechanism ?? {}) as Record<string, unknown>;
  const entries = [
    ...Object.entries(json.state as Record<string, unknown>).map(([name, value]) => ['state', name, value] as const),
    ...Object.entries(mechanism).map(([name, value]) => ['mechanism', name, value] as const),
  ];
  const values: Record<string, unknown> = Object.fromEntries(entries.map(([, name, value]) => [name, value]));
  const start: UrlTarget = { state: { ...DEFAULT_STATE, shell: base.shell }, embed: DEFAULT_EMBED };
  let target = start;
  const bad: BadField[] = [];
  for (const [section, name, value] of entries) {
    if (NOT_IN_FILE.has(name)) continue;
    const field = `${section}.${name}`;
    const k = URL_KEYS.find((x) => x.name === name);
    if (!k || k.scope !== 'state' || (section === 'mechanism' && !MECH_SECTION_KEYS.has(name))) {
      bad.push({ field, value: shown(value), why: 'unknown field' });
      continue;
    }
    // The linkage may be a plain MechanismSpec object: its codec reads it as JSON text.
    const t = name === 'mech' && isRecord(value) ? JSON.stringify(value) : valueText(value);
    const r = t === null ? null : k.parse(t);
    if (!r || !r.ok) {
      bad.push({ field, value: shown(value), why: r ? r.why : 'expected a number, true or false, or text' });
      continue;
    }
    target = k.set(target, r.value);
  }
  for (const c of URL_CONSTRAINTS) {
    if (c.holds(target.state)) continue;
    for (const name of c.keys)
      if (name in values)
        bad.push({
          field: `${name in mechanism ? 'mechanism' : 'state'}.${name}`,
          value: shown(values[name]),
          why: c.why,
        });
  }
  if (bad.length) return { ok: false, error: { kind: 'fields', fields: bad } };
  const name = typeof json.name === 'string' ? json.name : '';
  const savedAt = typeof json.savedAt === 'string' ? json.savedAt : null;
  return { ok: true, state: target.state, name, savedAt, page: pageOf(json.page) };
}
