import type { Codec, Decoded } from '../../url/urlCodec';
import { integerCodec, significantText } from '../../url/urlCodec';
import type { UrlKey } from '../../url/urlKey';
import { optionalKey, sliceLens } from '../../url/urlKey';
import type { Action } from '../appState';
import type { Slice } from '../slice';
import { decimalTuple } from './synMotionSlice';

/** The synthesis page's Function mode: y = f(x) on an x range, mapped onto the θ2 and θ4 ranges. */
export interface SynFunctionState {
  /** The right-hand side of y = f(x), as typed (checked by the expression parser where it is used). */
  expression: string;
  /** [x0, x1], x0 ≠ x1. */
  xRange: [number, number];
  /** θ2 at x0 and at x1, degrees from the ground line. */
  theta2RangeDeg: [number, number];
  /** θ4 at f(x0) and at f(x1), degrees from the ground line. */
  theta4RangeDeg: [number, number];
  /** Precision points, Chebyshev-spaced: 3 exact, more by least squares (3 to MAX_FN_POINTS). */
  precisionPoints: number;
}

/** Longest expression accepted, characters. */
export const MAX_EXPRESSION_CHARS = 200;
/** Most precision points (the synthesis module's MAX_PRECISION_POINTS). */
export const MAX_FN_POINTS = 50;
/** Largest |x| of the range. */
export const X_ABS_MAX = 1e12;
/** Largest |angle| of a range end, degrees; a range spans at most one turn. */
export const RANGE_DEG_MAX = 360;

/**
 * The characters an expression may hold: letters, digits, spaces, . + - * / ^ ( ) and the comma. No quotes,
 * brackets, braces, = or ;, so nothing that reaches the parser can be a string, an assignment, an object or a block.
 */
export const EXPRESSION_CHARS = /^[A-Za-z0-9_.+\-*/^(), ]*$/;

/** log10 on [1, 10], θ2 from 30° to 90°, θ4 from −60° to −150°, three points (docs/synthesis.md's example). */
export const DEFAULT_SYN_FUNCTION: SynFunctionState = {
  expression: 'log10(x)',
  xRange: [1, 10],
  theta2RangeDeg: [30, 90],
  theta4RangeDeg: [-60, -150],
  precisionPoints: 3,
};

/** Actions only the Function mode's slice handles (values checked by the caller, as the codecs check them). */
export type SynFunctionAction = { type: 'setSynFunction'; patch: Partial<SynFunctionState> };

const sameValue = (a: unknown, b: unknown) =>
  Array.isArray(a) && Array.isArray(b) ? a.length === b.length && a.every((v, i) => v === b[i]) : a === b;

/** The Function slice's reducer: pure, returns the same object when nothing changes. */
export function synFunctionReducer(s: SynFunctionState, action: Action): SynFunctionState {
  if (action.type !== 'setSynFunction') return s;
  const keys = Object.keys(action.patch) as (keyof SynFunctionState)[];
  if (keys.every((k) => sameValue(action.patch[k], s[k]))) return s;
  return { ...s, ...action.patch };
}

/** Why an expression's text is refused before parsing: empty, too long, or a character outside EXPRESSION_CHARS. */
export type ExpressionTextProblem = { code: 'empty' } | { code: 'long' } | { code: 'character'; character: string };

/** Why an expression's text is refused before parsing, or null (the first character outside EXPRESSION_CHARS named). */
export function expressionTextProblem(text: string): ExpressionTextProblem | null {
  const s = text.trim();
  if (s === '') return { code: 'empty' };
  if (s.length > MAX_EXPRESSION_CHARS) return { code: 'long' };
  const character = [...s].find((c) => !EXPRESSION_CHARS.test(c));
  return character === undefined ? null : { code: 'character', character };
}

/** The English reason of a refused text, for the URL notice and the console. */
function textWhy(p: ExpressionTextProblem): string {
  if (p.code === 'empty') return 'the expression is empty';
  if (p.code === 'long') return `the expression is longer than ${MAX_EXPRESSION_CHARS} characters`;
  return `the expression may use only letters, digits, spaces and . + - * / ^ ( ) , (not ${JSON.stringify(p.character)})`;
}

/** The expression text, trimmed; refused as expressionTextProblem says. */
const expressionCodec: Codec<string> = {
  parse(raw) {
    const problem = expressionTextProblem(raw);
    return problem ? { ok: false, why: textWhy(problem) } : { ok: true, value: raw.trim() };
  },
  format: (s) => s,
};

/** Why [start, end] cannot be a range: an end not a number, beyond the kind's limit, equal ends, or over a turn. */
export type RangeProblem = 'finite' | 'within' | 'ends' | 'span';

/** The largest |end| of a range of this kind: X_ABS_MAX for x, RANGE_DEG_MAX for angles. */
export const rangeLimit = (kind: 'x' | 'angle') => (kind === 'x' ? X_ABS_MAX : RANGE_DEG_MAX);

/** Why [start, end] cannot be a range of this kind (an angle range spans at most one turn), or null. */
export function rangeProblem(range: readonly [number, number], kind: 'x' | 'angle'): RangeProblem | null {
  const [a, b] = range;
  const max = rangeLimit(kind);
  if (!Number.isFinite(a) || !Number.isFinite(b)) return 'finite';
  if (Math.abs(a) > max || Math.abs(b) > max) return 'within';
  if (a === b) return 'ends';
  if (kind === 'angle' && Math.abs(b - a) > RANGE_DEG_MAX) return 'span';
  return null;
}

/** The English reason of a refused range, for the URL notice and the console. */
function rangeWhy(p: RangeProblem, kind: 'x' | 'angle'): string {
  if (p === 'finite') return 'both ends must be numbers';
  if (p === 'within') return `both ends must lie within ±${rangeLimit(kind)}`;
  if (p === 'ends') return 'the ends must differ';
  return `the range must span at most ${RANGE_DEG_MAX}°`;
}

/** A range as start,end (10 significant digits), checked by rangeProblem. */
function rangeCodec(kind: 'x' | 'angle'): Codec<[number, number]> {
  const text = (v: number) => significantText(v, 10);
  return {
    parse(raw): Decoded<[number, number]> {
      const r = decimalTuple(raw, 2, 'the range', Infinity);
      if (!r.ok) return r;
      const range: [number, number] = [Number(text(r.value[0])), Number(text(r.value[1]))];
      const problem = rangeProblem(range, kind);
      return problem ? { ok: false, why: rangeWhy(problem, kind) } : { ok: true, value: range };
    },
    format: (range) => `${text(range[0])},${text(range[1])}`,
  };
}

const field = sliceLens('synFunction');

/** The Function mode's URL keys, each written when it differs from the default: fx, xr, t2r, t4r, np. */
export const SYN_FUNCTION_URL_KEYS: readonly UrlKey<unknown>[] = [
  optionalKey('fx', expressionCodec, field('expression'), DEFAULT_SYN_FUNCTION.expression),
  optionalKey('xr', rangeCodec('x'), field('xRange'), DEFAULT_SYN_FUNCTION.xRange),
  optionalKey('t2r', rangeCodec('angle'), field('theta2RangeDeg'), DEFAULT_SYN_FUNCTION.theta2RangeDeg),
  optionalKey('t4r', rangeCodec('angle'), field('theta4RangeDeg'), DEFAULT_SYN_FUNCTION.theta4RangeDeg),
  optionalKey('np', integerCodec(3, MAX_FN_POINTS), field('precisionPoints'), DEFAULT_SYN_FUNCTION.precisionPoints),
];

/** The synFunction slice's registration in SLICES (appState.ts). */
export const SYN_FUNCTION_SLICE: Slice<SynFunctionState, SynFunctionAction> = {
  summary: "the synthesis page's Function mode: y = f(x), its ranges and precision points",
  defaults: DEFAULT_SYN_FUNCTION,
  reducer: synFunctionReducer,
  urlKeys: SYN_FUNCTION_URL_KEYS,
};
