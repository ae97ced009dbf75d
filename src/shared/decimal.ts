/**
 * The one number reader: text to a number by one set of rules. A decimal is an optional sign, digits with an
 * optional point (or a point and digits) and an optional exponent: no hex, no Infinity, no thousands separators, no
 * empty text. Its value is Number's (so a decimal too large is ±Infinity, which range checks refuse by name).
 */

const PLAIN_DECIMAL = /^[+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:e[+-]?\d+)?$/i;
const FULL_WIDTH = /[\uFF10-\uFF19\uFF0E\uFF0D\uFF0B\uFF45\uFF25]/g;

/** A decimal as machines write it (URL values, files, pasted tables), surrounding white space trimmed; else NaN. */
export function plainDecimal(text: string): number {
  const s = text.trim();
  return PLAIN_DECIMAL.test(s) ? Number(s) : Number.NaN;
}

/**
 * Typed text as a plain decimal's text: trimmed, full-width digits and signs (from CJK input methods) and the minus
 * sign U+2212 mapped to ASCII, and one comma, where there is no point, read as the decimal point ("2,5").
 */
export function normalizeNumberText(raw: string): string {
  let s = raw.trim().replace(FULL_WIDTH, (c) => String.fromCharCode(c.charCodeAt(0) - 0xfee0));
  s = s.replace(/\u2212/g, '-');
  if (!s.includes('.') && (s.match(/,/g)?.length ?? 0) === 1) s = s.replace(',', '.');
  return s;
}

/** A decimal as a person types it (normalizeNumberText, then plainDecimal's rules); NaN when the text is not one. */
export function parseDecimal(raw: string): number {
  return plainDecimal(normalizeNumberText(raw));
}
