import { validateStructure } from '../../../mechanism/validate';
import type { MechanismSpec } from '../../../mechanism/types';
import { describe } from '../../../solver/validate';
import type { Codec, Decoded } from '../../url/urlCodec';
import { boolCodec, enumCodec, exactText, numberCodec } from '../../url/urlCodec';
import type { Lens, UrlKey } from '../../url/urlKey';
import { nestedLens, optionalKey, sliceLens } from '../../url/urlKey';
import type { Action } from '../appState';
import type { Slice } from '../slice';

/**
 * The keys of src/mechanism's MECHANISM_TEMPLATES, in its order (the gallery's), written out so that the first load
 * does not carry the templates (the page loads them with its chunk); tests/shared/state/mechSlice.test.ts checks
 * that the two lists agree.
 */
export const MECH_TEMPLATE_KEYS = [
  'fourBar',
  'sliderCrank',
  'invertedSliderCrank',
  'whitworth',
  'scotchYoke',
  'pistonDriven',
  'wattI',
  'wattII',
  'stephensonI',
  'stephensonII',
  'stephensonIII',
  'jansen',
  'klann',
  'peaucellier',
  'chebyshev',
  'hoekens',
] as const;

/** A key of MECHANISM_TEMPLATES (fourBar, sliderCrank, jansen, …). */
export type MechTemplateKey = (typeof MECH_TEMPLATE_KEYS)[number];

/** A template's URL value (tpl=…): its key in kebab case, runs of capitals kept together (wattII → watt-ii). */
export function templateUrlValue(key: string): string {
  return key.replace(/([a-z])([A-Z])/g, '$1-$2').toLowerCase();
}

/**
 * The mechanism page's slice: the template opened and the linkage as edited. An edited linkage may still be under
 * construction (mobility other than 1, no input chosen yet: input.joint ''); the page says what is missing.
 */
export interface MechState {
  /** The template opened (its name, its input range). */
  template: MechTemplateKey;
  /** The linkage as edited, or null: the template's own. */
  spec: MechanismSpec | null;
  /** The forces over the cycle (kept when another template opens). */
  forces: MechForcesSettings;
  /** The input where the linkage stands (URL mi): radians for a pin input, length for a slider input; 0 = as drawn. */
  input: number;
  /** Play's direction along the input (URL mdir: fwd or rev); at a rocking limit Play turns it. */
  direction: 1 | -1;
  /** Play's speed (URL mspd): degrees per second for a pin input, 1/360 of the slide range per second for a slider. */
  speed: number;
  /** The joints and tracers whose paths are drawn (URL mtr), or null: every tracer (the template's own choice). */
  traced: readonly string[] | null;
  /** The two plots' choices, kind:id ('angle:coupler', '' none) (URL mp), or null: the linkage's default two. */
  plots: readonly [string, string] | null;
  /** Velocity arrows at the points (URL mvel). */
  velocities: boolean;
}

/** The page's own settings: the drive (input, direction, speed) and what is drawn and plotted. */
export type MechPageSettings = Pick<MechState, 'input' | 'direction' | 'speed' | 'traced' | 'plots' | 'velocities'>;

/** Default Play speed: 60 °/s (a turn in 6 s). */
export const DEFAULT_MECH_SPEED = 60;

/** Largest Play speed (URL mspd), degrees per second. */
export const MECH_MAX_SPEED = 3600;

/** Largest |input| a link may set (URL mi): the input is clamped to the linkage's range anyway. */
export const MECH_MAX_INPUT = 1e9;

/** As drawn (input 0), forward at 60 °/s, the default traces and plots, no velocity arrows. */
export const DEFAULT_MECH_PAGE: MechPageSettings = {
  input: 0,
  direction: 1,
  speed: DEFAULT_MECH_SPEED,
  traced: null,
  plots: null,
  velocities: false,
};

/**
 * The mechanism page's forces, as on the simulator (SI, the linkage's lengths in the app's length unit lu): every
 * moving link a set of uniform bars of rhoKgPerM along the edges of its outline, gravity down, the input at a
 * constant speed.
 */
export interface MechForcesSettings {
  /** Solve and show the forces (URL mfrc); default off, and nothing about forces is computed while off. */
  enabled: boolean;
  /** Mass per length of the links' bars, kg/m (URL mrho); default 1, as the simulator's rho. */
  rhoKgPerM: number;
  /** Gravity, m/s² pointing -y (URL mgr, 0 turns it off); default 9.81. */
  gravityMPerS2: number;
  /** The input's constant speed (URL mw): rad/s for a pin input, lu/s for a slider input; default 10. */
  inputSpeed: number;
  /** The joint whose reaction is plotted and shown (URL mrj); '' (default): the first joint after the input. */
  joint: string;
  /** Reaction arrows at the joints on the canvas (URL mfv); default off. */
  arrows: boolean;
}

/** Forces off; bars of 1 kg/m; g = 9.81 m/s²; the input at 10 rad/s (or lu/s); the default joint; no arrows. */
export const DEFAULT_MECH_FORCES: MechForcesSettings = {
  enabled: false,
  rhoKgPerM: 1,
  gravityMPerS2: 9.81,
  inputSpeed: 10,
  joint: '',
  arrows: false,
};

/** Largest mass per length (kg/m), gravity (m/s²) and input speed (rad/s or lu/s) accepted. */
export const MECH_FORCES_LIMITS = { rho: 1e6, gravity: 1000, speed: 1e6 } as const;

/** Most links, joints or tracers a linkage in a link may have (a link is typed by people, and read by the app). */
export const MECH_MAX_PARTS = 64;

/** The offset slider-crank, unedited. */
export const DEFAULT_MECH: MechState = {
  template: 'sliderCrank',
  spec: null,
  forces: DEFAULT_MECH_FORCES,
  ...DEFAULT_MECH_PAGE,
};

/** Actions only the mechanism slice handles. */
export type MechAction =
  | { type: 'setMechTemplate'; template: MechTemplateKey }
  | { type: 'setMechSpec'; spec: MechanismSpec | null }
  | { type: 'setMechForces'; patch: Partial<MechForcesSettings> }
  | { type: 'setMechPage'; patch: Partial<MechPageSettings> };

/**
 * The mechanism slice's reducer: pure, returns the same object when nothing changes. A template opens afresh (as
 * drawn, the default traces and plots); the forces stay.
 */
export function mechReducer(s: MechState, action: Action): MechState {
  switch (action.type) {
    case 'setMechTemplate':
      return action.template === s.template && s.spec === null
        ? s
        : { ...s, ...DEFAULT_MECH_PAGE, template: action.template, spec: null };
    case 'setMechSpec':
      return action.spec === s.spec ? s : { ...s, spec: action.spec };
    case 'setMechForces': {
      const p = action.patch;
      const same = (Object.keys(p) as (keyof MechForcesSettings)[]).every((k) => Object.is(s.forces[k], p[k]));
      return same ? s : { ...s, forces: { ...s.forces, ...p } };
    }
    case 'setMechPage': {
      const p = action.patch;
      const same = (Object.keys(p) as (keyof MechPageSettings)[]).every((k) => Object.is(s[k], p[k]));
      return same ? s : { ...s, ...p };
    }
    default:
      return s;
  }
}

/** Version tag of the compact encoding (the first token); a later format gets a new tag, old links keep theirs. */
export const MECH_CODE_VERSION = 'm1';
const SEP = '*';

/** A name as a token: percent-encoded (so it holds no separator), * escaped too. */
const nameToken = (name: string) => encodeURIComponent(name).replace(/\*/g, '%2A');

/**
 * A spec as the compact, versioned text of mech=: tokens joined by * — m1, the links (count, names), the joints
 * (count, then id, R or P, the two links' indices, x, y, and for P the angle), the tracers (count, then id, link
 * index, x, y), and the input joint's index (-1: none chosen). Numbers exact (shortest round-trip text).
 */
export function encodeMechSpec(spec: MechanismSpec): string {
  const linkIndex = new Map(spec.links.map((l, i) => [l, i]));
  const t: string[] = [MECH_CODE_VERSION, String(spec.links.length), ...spec.links.map(nameToken)];
  t.push(String(spec.joints.length));
  for (const j of spec.joints) {
    t.push(nameToken(j.id), j.kind, String(linkIndex.get(j.links[0])), String(linkIndex.get(j.links[1])));
    t.push(exactText(j.x), exactText(j.y));
    if (j.kind === 'P') t.push(exactText(j.angle ?? 0));
  }
  const points = spec.points ?? [];
  t.push(String(points.length));
  for (const p of points) t.push(nameToken(p.id), String(linkIndex.get(p.link)), exactText(p.x), exactText(p.y));
  t.push(String(spec.joints.findIndex((j) => j.id === spec.input.joint)));
  return t.join(SEP);
}

/** Reads tokens in order, each read naming what it expected, so a bad link says where it went wrong. */
class TokenReader {
  private i = 0;
  constructor(private readonly tokens: readonly string[]) {}
  private next(what: string): string {
    if (this.i >= this.tokens.length) throw new Error(`the code ends before ${what}`);
    return this.tokens[this.i++];
  }
  count(what: string): number {
    const t = this.next(what);
    const n = /^\d{1,3}$/.test(t) ? Number(t) : NaN;
    if (!(n <= MECH_MAX_PARTS))
      throw new Error(`${what} must be a count from 0 to ${MECH_MAX_PARTS}, got ${describe(t)}`);
    return n;
  }
  index(what: string, size: number, allowNone = false): number {
    const t = this.next(what);
    const n = /^-?\d{1,3}$/.test(t) ? Number(t) : NaN;
    if (!(n >= (allowNone ? -1 : 0) && n < size))
      throw new Error(`${what} must be an index below ${size}, got ${describe(t)}`);
    return n;
  }
  name(what: string): string {
    const t = this.next(what);
    try {
      return decodeURIComponent(t);
    } catch {
      throw new Error(`${what} is not a percent-encoded name, got ${describe(t)}`);
    }
  }
  number(what: string): number {
    const t = this.next(what);
    const x = /^-?(\d+\.?\d*|\.\d+)(e[-+]?\d+)?$/i.test(t) ? Number(t) : NaN;
    if (!Number.isFinite(x)) throw new Error(`${what} must be a finite number, got ${describe(t)}`);
    return x;
  }
  kind(what: string): 'R' | 'P' {
    const t = this.next(what);
    if (t !== 'R' && t !== 'P') throw new Error(`${what} must be R or P, got ${describe(t)}`);
    return t;
  }
  end(): void {
    if (this.i !== this.tokens.length)
      throw new Error(`${this.tokens.length - this.i} tokens after the end of the code`);
  }
}

/** Reads the compact text of encodeMechSpec (the structure only: see checkMechSpec); throws naming the field. */
export function decodeMechSpec(text: string): MechanismSpec {
  const r = new TokenReader(text.split(SEP));
  const version = r.name('the version');
  if (version !== MECH_CODE_VERSION)
    throw new Error(`unknown version ${describe(version)} (this app reads ${MECH_CODE_VERSION})`);
  const links = Array.from({ length: r.count('the link count') }, (_, i) => r.name(`links[${i}]`));
  const nJoints = r.count('the joint count');
  const joints: MechanismSpec['joints'] = [];
  for (let i = 0; i < nJoints; i++) {
    const id = r.name(`joints[${i}].id`);
    const kind = r.kind(`joint ${describe(id)}: kind`);
    const a = links[r.index(`joint ${describe(id)}: links[0]`, links.length)];
    const b = links[r.index(`joint ${describe(id)}: links[1]`, links.length)];
    const x = r.number(`joint ${describe(id)}: x`);
    const y = r.number(`joint ${describe(id)}: y`);
    if (kind === 'P') joints.push({ id, kind, links: [a, b], x, y, angle: r.number(`joint ${describe(id)}: angle`) });
    else joints.push({ id, kind, links: [a, b], x, y });
  }
  const nPoints = r.count('the tracer count');
  const points: NonNullable<MechanismSpec['points']> = [];
  for (let i = 0; i < nPoints; i++) {
    const id = r.name(`points[${i}].id`);
    const link = links[r.index(`point ${describe(id)}: link`, links.length)];
    points.push({ id, link, x: r.number(`point ${describe(id)}: x`), y: r.number(`point ${describe(id)}: y`) });
  }
  const input = r.index('the input joint', joints.length, true);
  r.end();
  return {
    links,
    joints,
    ...(points.length > 0 ? { points } : {}),
    input: { joint: input < 0 ? '' : joints[input].id },
  };
}

/**
 * Throws an Error naming the field unless spec is a drawing the page can hold: well formed (validateStructure),
 * at most MECH_MAX_PARTS of each part, its input '' (none chosen yet) or a joint's id. Mobility and connection
 * are the page's to report, not the link's to refuse: a course may share a linkage still to be completed.
 */
export function checkMechSpec(spec: unknown): asserts spec is MechanismSpec {
  validateStructure(spec);
  const s = spec as MechanismSpec;
  for (const [what, list] of [
    ['links', s.links],
    ['joints', s.joints],
    ['points', s.points ?? []],
  ] as const) {
    if (list.length > MECH_MAX_PARTS) throw new Error(`${what}: at most ${MECH_MAX_PARTS}, got ${list.length}`);
  }
  const input = (s as { input?: unknown }).input;
  if (typeof input !== 'object' || input === null) throw new Error(`input must be { joint }, got ${describe(input)}`);
  const joint = (input as { joint?: unknown }).joint;
  if (joint !== '' && !s.joints.some((j) => j.id === joint))
    throw new Error(`input.joint: unknown joint ${describe(joint)}`);
}

/** Only the fields of a spec, in a fixed order (a JSON spec may carry others). */
function cleanSpec(s: MechanismSpec): MechanismSpec {
  return {
    links: [...s.links],
    joints: s.joints.map((j) =>
      j.kind === 'P'
        ? { id: j.id, kind: j.kind, links: [j.links[0], j.links[1]], x: j.x, y: j.y, angle: j.angle }
        : { id: j.id, kind: j.kind, links: [j.links[0], j.links[1]], x: j.x, y: j.y },
    ),
    ...(s.points && s.points.length > 0
      ? { points: s.points.map((p) => ({ id: p.id, link: p.link, x: p.x, y: p.y })) }
      : {}),
    input: { joint: s.input.joint },
  };
}

/**
 * mech=: the compact text (encodeMechSpec), or a plain MechanismSpec as JSON (text starting with '{', so course
 * pages and other tools can write links); either checked by checkMechSpec. Written always in the compact form;
 * empty: the template's own linkage.
 */
export const mechSpecCodec: Codec<MechanismSpec | null> = {
  parse(raw): Decoded<MechanismSpec | null> {
    try {
      const text = raw.trim();
      if (text === '') return { ok: true, value: null };
      let spec: unknown;
      if (text.startsWith('{')) {
        try {
          spec = JSON.parse(text);
        } catch (e) {
          throw new Error(`not JSON: ${(e as Error).message}`);
        }
      } else spec = decodeMechSpec(text);
      checkMechSpec(spec);
      return { ok: true, value: cleanSpec(spec) };
    } catch (e) {
      return { ok: false, why: (e as Error).message };
    }
  },
  format: (spec) => (spec ? encodeMechSpec(spec) : ''),
};

const field = sliceLens('mech');
const forcesField = nestedLens('mech', 'forces');

/**
 * tpl's lens: another template starts from its own linkage (the edit cleared, as the gallery's setMechTemplate does),
 * the same one keeps the edit. mech comes after tpl in the table, so a link or a host's patch with both keeps its mech.
 */
const templateLens: Lens<MechTemplateKey> = {
  get: (u) => u.state.mech.template,
  set: (u, template) =>
    template === u.state.mech.template
      ? u
      : { ...u, state: { ...u.state, mech: { ...u.state.mech, template, spec: null } } },
};

/** A joint's id as typed (any text up to 200 characters; the page falls back to its default joint when none has it). */
const jointIdCodec: Codec<string> = {
  parse: (raw) => (raw.length <= 200 ? { ok: true, value: raw } : { ok: false, why: 'at most 200 characters' }),
  format: (id) => id,
};

/**
 * A list of names as count*name*name… (each percent-encoded as in mech=), so that an empty list (0) and any name
 * (with * or commas) are told apart; '' is null (the default).
 */
function nameListCodec(what: string, fixedCount?: number): Codec<readonly string[] | null> {
  return {
    parse(raw): Decoded<readonly string[] | null> {
      if (raw === '') return { ok: true, value: null };
      try {
        const r = new TokenReader(raw.split(SEP));
        const n = r.count(`the ${what} count`);
        if (fixedCount !== undefined && n !== fixedCount)
          throw new Error(`the ${what} count must be ${fixedCount}, got ${n}`);
        const names = Array.from({ length: n }, (_, i) => r.name(`${what}[${i}]`));
        r.end();
        return { ok: true, value: names };
      } catch (e) {
        return { ok: false, why: (e as Error).message };
      }
    },
    format: (names) => (names === null ? '' : [String(names.length), ...names.map(nameToken)].join(SEP)),
  };
}

/** mtr: the traced joints and tracers (count*id*id…); '' the default (every tracer). */
const tracedCodec = nameListCodec('traced');

/** mp: the two plots' choices (2*kind:id*kind:id); '' the default pair. */
const plotPairCodec = nameListCodec('plots', 2);
const plotsCodec: Codec<readonly [string, string] | null> = {
  parse(raw) {
    const r = plotPairCodec.parse(raw);
    if (!r.ok) return r;
    return { ok: true, value: r.value === null ? null : [r.value[0], r.value[1]] };
  },
  format: (pair) => plotPairCodec.format(pair),
};

/** A page key, written only when its text differs from the default's. */
function pageKey<K extends keyof MechPageSettings>(name: string, codec: Codec<MechPageSettings[K]>, k: K) {
  return optionalKey(name, codec, field(k), DEFAULT_MECH_PAGE[k]);
}

/** A forces key, written only when its text differs from the default's. */
function forcesKey<K extends keyof MechForcesSettings>(
  name: string,
  codec: Codec<MechForcesSettings[K]>,
  k: K,
): UrlKey<unknown> {
  return optionalKey(name, codec, forcesField(k), DEFAULT_MECH_FORCES[k]);
}

/**
 * The mechanism page's URL keys: tpl (the template, kebab case), mech (the edited linkage) when edited, the forces'
 * mfrc, mrho, mgr, mw, mrj, mfv, and the page's mi (input), mdir, mspd, mtr (traces), mp (plots), mvel (each only
 * when it differs from its default).
 */
export const MECH_URL_KEYS: readonly UrlKey<unknown>[] = [
  optionalKey(
    'tpl',
    enumCodec(MECH_TEMPLATE_KEYS.map((k) => [templateUrlValue(k), k] as const)),
    templateLens,
    DEFAULT_MECH.template,
  ),
  optionalKey('mech', mechSpecCodec, field('spec'), DEFAULT_MECH.spec),
  forcesKey('mfrc', boolCodec, 'enabled'),
  forcesKey('mrho', numberCodec({ min: 0, max: MECH_FORCES_LIMITS.rho }), 'rhoKgPerM'),
  forcesKey('mgr', numberCodec({ min: 0, max: MECH_FORCES_LIMITS.gravity }), 'gravityMPerS2'),
  forcesKey('mw', numberCodec({ min: -MECH_FORCES_LIMITS.speed, max: MECH_FORCES_LIMITS.speed }), 'inputSpeed'),
  forcesKey('mrj', jointIdCodec, 'joint'),
  forcesKey('mfv', boolCodec, 'arrows'),
  pageKey('mi', numberCodec({ min: -MECH_MAX_INPUT, max: MECH_MAX_INPUT }), 'input'),
  pageKey(
    'mdir',
    enumCodec([
      ['fwd', 1],
      ['rev', -1],
    ] as const),
    'direction',
  ),
  pageKey('mspd', numberCodec({ min: 1e-9, max: MECH_MAX_SPEED }), 'speed'),
  pageKey('mtr', tracedCodec, 'traced'),
  pageKey('mp', plotsCodec, 'plots'),
  pageKey('mvel', boolCodec, 'velocities'),
];

/** The mech slice's registration in SLICES (appState.ts). */
export const MECH_SLICE: Slice<MechState, MechAction> = {
  summary: 'the mechanism page: the template, the linkage as edited, its forces, input and plots',
  defaults: DEFAULT_MECH,
  reducer: mechReducer,
  urlKeys: MECH_URL_KEYS,
};
