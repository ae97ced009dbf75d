import type { FieldName } from '../ui/validateNumber';
import { parseDecimal } from '../decimal';
import { checkValue } from '../ui/validateNumber';

/** What a codec made of a URL value: the value, or why the text was refused (English, for the console). */
export type Decoded<T> = { ok: true; value: T } | { ok: false; why: string };

/**
 * Text <-> value for one URL parameter. parse(format(v)) gives back v for every value format can
 * produce text for (lossy codecs quantise first, so the property holds on their grid); parse never throws.
 */
export interface Codec<T> {
  parse(text: string): Decoded<T>;
  format(value: T): string;
}

function ok<T>(value: T): Decoded<T> {
  return { ok: true, value };
}

function fail<T>(why: string): Decoded<T> {
  return { ok: false, why };
}

function trimZeros(s: string): string {
  // "1.2300" -> "1.23", "2.000e-7" -> "2e-7", "5.000" -> "5"; integers stay as they are.
  return s.replace(/(\.\d*?)0+(?=$|e)/, '$1').replace(/\.(?=$|e)/, '');
}

function orList(items: readonly string[]): string {
  return items.length <= 1 ? items.join('') : `${items.slice(0, -1).join(', ')} or ${items[items.length - 1]}`;
}

/** Shortest decimal text of x rounded to a fixed number of decimals: "248.98896" for 248.98895999999954 at 9; "-0" becomes "0". */
export function fixedText(x: number, decimals: number): string {
  const s = trimZeros(x.toFixed(decimals));
  return s === '-0' ? '0' : s;
}

/** Shortest decimal text of x rounded to sig significant digits, exponent form from toPrecision ("1e-7", "1.21"). */
export function significantText(x: number, sig: number): string {
  const s = trimZeros(x.toPrecision(sig)).replace('e+', 'e');
  return s === '-0' ? '0' : s;
}

/** Exact text of x: the shortest decimal that reads back as the same double (String(x)); -0 gives "0". */
export function exactText(x: number): string {
  return Object.is(x, -0) ? '0' : String(x).replace('e+', 'e');
}

/** Options of numberCodec: how format rounds (default exact) and how parse and format normalise. */
export interface NumberCodecOptions {
  /** Round to this many decimals when formatting (angles in degrees: 9 keeps every typed value). */
  decimals?: number;
  /** Round to this many significant digits when formatting (view zoom and pan). */
  significant?: number;
  /** Maps an accepted value to its canonical representative (theta2 into [0, 360)); applied after rounding too. */
  normalize?: (x: number) => number;
}

/** A closed range for numbers that are not a typed field (view zoom and pan). */
export interface NumberRange {
  min: number;
  max: number;
}

function checkRange(range: FieldName | NumberRange, raw: string): Decoded<number> {
  if (typeof range === 'string') {
    const r = checkValue(range, parseDecimal(raw), raw);
    if (r.ok) return ok(r.value);
    const e = r.error;
    return fail(e.kind === 'notNumber' ? 'not a number' : `${e.kind} (allowed ${e.min} to ${e.max})`);
  }
  const x = parseDecimal(raw);
  if (Number.isNaN(x)) return fail('not a number');
  return x >= range.min && x <= range.max ? ok(x) : fail(`out of range (allowed ${range.min} to ${range.max})`);
}

/**
 * A decimal number checked against a field's range (validate.ts FIELD_SPECS) or a given one. Formatting rounds
 * as the options say, then normalises, so a normalised value on the rounding grid round-trips exactly.
 */
export function numberCodec(range: FieldName | NumberRange, options: NumberCodecOptions = {}): Codec<number> {
  const normalize = options.normalize ?? ((x: number) => x);
  const text = (x: number): string =>
    options.decimals !== undefined
      ? fixedText(x, options.decimals)
      : options.significant !== undefined
        ? significantText(x, options.significant)
        : exactText(x);
  return {
    parse(raw) {
      const r = checkRange(range, raw);
      return r.ok ? ok(normalize(r.value)) : r;
    },
    format(x) {
      // Round, normalise (360 -> 0), and write the normalised value at the same rounding.
      return text(normalize(Number(text(x))));
    },
  };
}

/** A whole number from min to max inclusive, digits only. */
export function integerCodec(min: number, max: number): Codec<number> {
  return {
    parse(raw) {
      const s = raw.trim();
      const x = Number(s);
      return /^\d+$/.test(s) && x >= min && x <= max ? ok(x) : fail(`expected a whole number from ${min} to ${max}`);
    },
    format: (x) => String(x),
  };
}

/** 1/true/yes/on and 0/false/no/off (any case); written as 1 and 0. */
export const boolCodec: Codec<boolean> = {
  parse(raw) {
    const s = raw.trim().toLowerCase();
    if (s === '1' || s === 'true' || s === 'yes' || s === 'on') return ok(true);
    if (s === '0' || s === 'false' || s === 'no' || s === 'off') return ok(false);
    return fail('expected 0 or 1');
  },
  format: (b) => (b ? '1' : '0'),
};

/**
 * One text per value, from a single table of pairs, so parse and format cannot disagree. Matching is exact
 * unless looseCase (then trimmed and case-insensitive).
 */
export function enumCodec<T>(pairs: readonly (readonly [text: string, value: T])[], looseCase = false): Codec<T> {
  const key = (s: string) => (looseCase ? s.trim().toLowerCase() : s);
  return {
    parse(raw) {
      const hit = pairs.find(([text]) => key(text) === key(raw));
      return hit ? ok(hit[1]) : fail(`expected ${orList(pairs.map(([text]) => text))}`);
    },
    format(value) {
      const hit = pairs.find(([, v]) => Object.is(v, value));
      if (!hit) throw new Error(`no URL text for ${JSON.stringify(value)}`);
      return hit[0];
    },
  };
}

/** One of a fixed list of numbers, compared exactly after Number(). */
export function choiceCodec(values: readonly number[]): Codec<number> {
  return {
    parse(raw) {
      const x = Number(raw.trim());
      const hit = raw.trim() === '' ? undefined : values.find((v) => v === x);
      return hit !== undefined ? ok(hit) : fail(`expected one of ${values.join(', ')}`);
    },
    format: (x) => String(x),
  };
}

/** The inner codec's values, or null written as nullText. */
export function nullableCodec<T>(inner: Codec<T>, nullText: string): Codec<T | null> {
  return {
    parse(raw) {
      if (raw === nullText) return ok(null);
      const r = inner.parse(raw);
      return r.ok ? r : fail(`expected ${nullText} or ${r.why.replace(/^expected /, '')}`);
    },
    format: (v) => (v === null ? nullText : inner.format(v)),
  };
}

/** A comma-separated set of names from allowed (any case, duplicates dropped); the empty list is written as "none". */
export function listCodec<T extends string>(allowed: readonly T[]): Codec<T[]> {
  return {
    parse(raw) {
      const s = raw.trim();
      if (s === '' || s.toLowerCase() === 'none') return ok([]);
      const out: T[] = [];
      for (const item of s.split(',').map((x) => x.trim())) {
        const hit = allowed.find((a) => a.toLowerCase() === item.toLowerCase());
        if (!hit) return fail(`expected a comma-separated list of ${allowed.join(', ')}`);
        if (!out.includes(hit)) out.push(hit);
      }
      return ok(out);
    },
    format: (list) => (list.length ? list.join(',') : 'none'),
  };
}
