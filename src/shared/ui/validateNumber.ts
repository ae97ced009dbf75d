import { truncateText } from '../format';
import { normalizeNumberText, parseDecimal } from '../decimal';

/** Which numeric field a value belongs to; names the field in messages. */
export type FieldName =
  | 'r1'
  | 'r2'
  | 'r3'
  | 'r4'
  | 'theta2'
  | 'couplerDistance'
  | 'couplerAngle'
  | 'speed'
  | 'omega2'
  | 'alpha2'
  | 'muBandLo'
  | 'muBandHi';

/** Why a typed value was rejected. */
export type FieldErrorKind = 'empty' | 'notNumber' | 'notPositive' | 'negative' | 'tooSmall' | 'outOfRange';

/** A rejected value: the field, the text as typed, why, and the accepted range (field units). */
export interface FieldError {
  field: FieldName;
  raw: string;
  kind: FieldErrorKind;
  min: number;
  max: number;
}

/** Result of parsing a field: the accepted value or the reason it was rejected. */
export type FieldResult = { ok: true; value: number } | { ok: false; error: FieldError };

/** Accepted range of one field (inclusive) and whether zero is allowed. */
export interface FieldSpec {
  min: number;
  max: number;
  /** Lengths must be strictly positive; a coupler distance may be 0. */
  allowZero: boolean;
  /** Angles may be negative; lengths may not. */
  signed: boolean;
  /** A field with a real range (speed 0.5 to 10): any value outside it, 0 and negatives too, is named out of range. */
  bounded?: boolean;
}

/** Shortest and longest link length accepted, in the user's unit: the solver is scale-free; 1e308 is refused (squares of the sum overflow elsewhere). */
export const LENGTH_MIN = 1e-300;
export const LENGTH_MAX = 1e300;
/** Largest angle magnitude accepted in a field, degrees (larger values are reduced modulo 360 without meaning). */
export const ANGLE_ABS_MAX = 1e6;

/** Largest input angular velocity magnitude accepted, rad/s (about 9.5 million rpm). */
export const OMEGA_ABS_MAX = 1e6;
/** Largest input angular acceleration magnitude accepted, rad/s². */
export const ALPHA_ABS_MAX = 1e9;

/** Ranges of every numeric field. */
export const FIELD_SPECS: Record<FieldName, FieldSpec> = {
  r1: { min: LENGTH_MIN, max: LENGTH_MAX, allowZero: false, signed: false },
  r2: { min: LENGTH_MIN, max: LENGTH_MAX, allowZero: false, signed: false },
  r3: { min: LENGTH_MIN, max: LENGTH_MAX, allowZero: false, signed: false },
  r4: { min: LENGTH_MIN, max: LENGTH_MAX, allowZero: false, signed: false },
  theta2: { min: -ANGLE_ABS_MAX, max: ANGLE_ABS_MAX, allowZero: true, signed: true },
  couplerDistance: { min: 0, max: LENGTH_MAX, allowZero: true, signed: false },
  couplerAngle: { min: -ANGLE_ABS_MAX, max: ANGLE_ABS_MAX, allowZero: true, signed: true },
  speed: { min: 0.5, max: 10, allowZero: false, signed: false, bounded: true },
  omega2: { min: -OMEGA_ABS_MAX, max: OMEGA_ABS_MAX, allowZero: true, signed: true },
  alpha2: { min: -ALPHA_ABS_MAX, max: ALPHA_ABS_MAX, allowZero: true, signed: true },
  // Transmission angle band edges, degrees; lo < hi is checked where both are known (URL, controls).
  muBandLo: { min: 0, max: 180, allowZero: true, signed: false, bounded: true },
  muBandHi: { min: 0, max: 180, allowZero: true, signed: false, bounded: true },
};

/** Parses and range-checks the text typed into a field; never throws. */
export function parseField(field: FieldName, raw: string): FieldResult {
  const spec = FIELD_SPECS[field];
  const fail = (kind: FieldErrorKind): FieldResult => ({
    ok: false,
    error: { field, raw, kind, min: spec.min, max: spec.max },
  });
  if (normalizeNumberText(raw) === '') return fail('empty');
  const value = parseDecimal(raw);
  if (Number.isNaN(value)) return fail('notNumber');
  return checkValue(field, value, raw);
}

/** Range-checks a number already parsed (for example from a slider or the URL); never throws. */
export function checkValue(field: FieldName, value: number, raw: string = String(value)): FieldResult {
  const spec = FIELD_SPECS[field];
  const fail = (kind: FieldErrorKind): FieldResult => ({
    ok: false,
    error: { field, raw, kind, min: spec.min, max: spec.max },
  });
  if (typeof value !== 'number' || Number.isNaN(value)) return fail('notNumber');
  if (spec.bounded && !(value >= spec.min && value <= spec.max)) return fail('outOfRange');
  if (!spec.signed && value < 0) return fail('negative');
  if (!spec.allowZero && value === 0) return fail('notPositive');
  if (value > spec.max || !Number.isFinite(value)) return fail('outOfRange');
  if (value < spec.min) return fail(spec.signed ? 'outOfRange' : 'tooSmall');
  return { ok: true, value: value === 0 ? 0 : value };
}

/** Most characters of a refused text that a field's message echoes (longer texts are cut with an ellipsis). */
export const ECHO_MAX_CHARS = 24;

/**
 * What a number field's text says: a number to commit, an emptied field (only where empty is allowed), or a
 * refusal with the text to echo (trimmed, cut to ECHO_MAX_CHARS) and the check's reason (null: not a number).
 */
export type NumberReading =
  { kind: 'number'; value: number } | { kind: 'empty' } | { kind: 'refused'; text: string; why: string | null };

/** How readNumberText judges a text: the field's own check and whether an empty field means "none". */
export interface NumberReadingOptions {
  /** Why a finite number is refused (out of range, say), or null to accept it; default accepts every number. */
  check?: (value: number) => string | null;
  /** An empty (or blank) text reads as 'empty' instead of being refused; default false. */
  allowEmpty?: boolean;
}

/**
 * Reads the text typed into a number field: a finite decimal (parseDecimal; 1e999 is not one) that check accepts
 * is a number (-0 read as 0); anything else is refused with the text as echoed and check's reason. Never throws.
 */
export function readNumberText(raw: string, { check, allowEmpty = false }: NumberReadingOptions = {}): NumberReading {
  const text = raw.trim();
  if (allowEmpty && text === '') return { kind: 'empty' };
  const value = parseDecimal(raw);
  const why = Number.isFinite(value) ? (check?.(value) ?? null) : null;
  if (Number.isFinite(value) && why === null) return { kind: 'number', value: value === 0 ? 0 : value };
  return { kind: 'refused', text: truncateText(text, ECHO_MAX_CHARS), why };
}
