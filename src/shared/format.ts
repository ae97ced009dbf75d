const MINUS = '\u2212';

/** Decimals of θ2 wherever it is shown: the field, the analysis panel, the canvas description. */
export const THETA2_DECIMALS = 2;

function trimZeros(s: string): string {
  // "1.2300" -> "1.23", "2.000e-7" -> "2e-7"; leaves integers alone.
  return s.replace(/(\.\d*?)0+(?=$|e)/, '$1').replace(/\.(?=$|e)/, '');
}

/** Text of a field's value: exact (String) without decimals, else rounded to that many decimals with trailing zeros dropped. */
export function fieldText(x: number, decimals?: number): string {
  if (decimals === undefined) return String(x);
  const s = trimZeros(x.toFixed(decimals));
  return s === '-0' ? '0' : s;
}

/** Share of a panel's scale at or below which a value is rounding noise of a zero (about 4500 ulps of the scale). */
export const ROUNDING_NOISE = 1e-12;

/** x, or 0 when |x| is at most ROUNDING_NOISE × |scale| (the size of the values computed beside it); scale 0 keeps x. */
export function roundingNoiseToZero(x: number, scale: number): number {
  return Math.abs(x) <= ROUNDING_NOISE * Math.abs(scale) ? 0 : x;
}

/**
 * Formats a number for display with sig significant digits (default 6), exponent form outside [1e-4, 1e6); '—'
 * when not finite; 0 when it is rounding noise beside scale (default 0: never); every minus sign is U+2212.
 */
export function formatNumber(x: number, sig = 6, scale = 0): string {
  if (!Number.isFinite(x)) return '—';
  x = roundingNoiseToZero(x, scale);
  if (x === 0) return '0';
  const a = Math.abs(x);
  const s =
    a >= 1e-4 && a < 1e6 ? trimZeros(x.toPrecision(sig)) : trimZeros(x.toExponential(sig - 1)).replace('e+', 'e');
  return s.replace(/-/g, MINUS);
}

/** Formats an angle in degrees with a fixed number of decimals (default 2); '—' when not finite; never '-0'. */
export function formatDeg(deg: number, decimals = 2): string {
  if (!Number.isFinite(deg)) return '—';
  const s = deg.toFixed(decimals);
  return (/^-0(\.0*)?$/.test(s) ? s.slice(1) : s).replace('-', MINUS);
}

/** Formats a small positive quantity (residual, det J) in exponent form with digits decimals (default 2); '—' when not finite. */
export function formatSci(x: number, digits = 2): string {
  if (!Number.isFinite(x)) return '—';
  if (x === 0) return '0';
  return x.toExponential(digits).replace('e+', 'e').replace(/-/g, MINUS);
}

/** A number as a file-name fragment: plain ASCII, no spaces or slashes ("2.5", "1e-7", "m1.5" for -1.5). */
export function fileNumber(x: number): string {
  if (!Number.isFinite(x)) return 'nan';
  const s =
    Math.abs(x) >= 1e-4 && Math.abs(x) < 1e6
      ? trimZeros(x.toPrecision(6))
      : trimZeros(x.toExponential(4)).replace('e+', 'e');
  return s.replace(/^-/, 'm');
}

/** Shortens text to at most maxChars characters (default 24; code points, not UTF-16 units), ending in '…' when cut. */
export function truncateText(s: string, maxChars = 24): string {
  const chars = Array.from(s);
  return chars.length <= maxChars ? s : `${chars.slice(0, Math.max(1, maxChars - 1)).join('')}…`;
}
