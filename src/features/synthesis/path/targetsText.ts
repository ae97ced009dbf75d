import type { Point } from '../../../solver/kinematics';
import { plainDecimal } from '../../../shared/decimal';
import { MAX_TARGETS } from '../../../shared/state/slices/synthesisSlice';

/** Targets read from text: the points, and θ2 per point (degrees) when every line gave a third number. */
export interface ParsedTargets {
  targets: Point[];
  theta2Deg: number[] | null;
}

/** Why pasted text was refused: a line that is not a point (1-based number, its text), or too many points. */
export type TargetsTextError = { kind: 'line'; line: number; text: string } | { kind: 'too-many'; max: number };

/** The numbers of one line split at commas, semicolons, tabs or spaces; null when an item is not a number. */
function numbersOf(line: string): number[] | null {
  const items = line
    .trim()
    .split(/\s*[,;\t]\s*|\s+/)
    .filter((s) => s !== '');
  const xs = items.map(plainDecimal);
  return xs.every(Number.isFinite) ? xs : null;
}

/**
 * Targets from pasted lines of "x, y" (comma, semicolon, tab or spaces between; blank lines skipped), with an
 * optional third number θ2 in degrees. With skipHeader, a first line that is not numbers (a CSV header) is skipped.
 * Returns the error of the first bad line (1-based), or too-many past MAX_TARGETS.
 */
export function parseTargetsText(
  text: string,
  skipHeader = false,
): { ok: true; value: ParsedTargets } | { ok: false; error: TargetsTextError } {
  const lines = text.split(/\r\n|\r|\n/);
  const targets: Point[] = [];
  const theta2: number[] = [];
  let allTimed = true;
  let firstContent = true;
  for (let i = 0; i < lines.length; i++) {
    const raw = lines[i];
    if (raw.trim() === '') continue;
    const xs = numbersOf(raw);
    if (firstContent && skipHeader && xs === null && /[a-z]/i.test(raw)) {
      firstContent = false;
      continue;
    }
    firstContent = false;
    if (xs === null || xs.length < 2 || xs.length > 3) {
      return { ok: false, error: { kind: 'line', line: i + 1, text: raw.trim() } };
    }
    targets.push({ x: xs[0], y: xs[1] });
    if (xs.length === 3) theta2.push(xs[2]);
    else allTimed = false;
  }
  if (targets.length > MAX_TARGETS) return { ok: false, error: { kind: 'too-many', max: MAX_TARGETS } };
  return { ok: true, value: { targets, theta2Deg: allTimed && targets.length > 0 ? theta2 : null } };
}

/** θ2 of target i when given (a finite number), else none: a missing θ2 is never written as 0. */
function givenAt(theta2Deg: readonly number[] | null, i: number): number[] {
  const a = theta2Deg?.[i];
  return a !== undefined && Number.isFinite(a) ? [a] : [];
}

/**
 * Targets as lines "x, y" (or "x, y, θ2" when theta2Deg is given; a target without its θ2 keeps two numbers), the
 * shortest exact text of each number.
 */
export function formatTargetsText(targets: readonly Point[], theta2Deg: readonly number[] | null = null): string {
  return targets.map((p, i) => [p.x, p.y, ...givenAt(theta2Deg, i)].map((v) => String(v)).join(', ')).join('\n');
}

/** The targets as CSV: header x,y (and theta2_deg when given; empty for a target without one), one row per target. */
export function targetsToCsv(targets: readonly Point[], theta2Deg: readonly number[] | null = null): string {
  const header = theta2Deg ? 'x,y,theta2_deg' : 'x,y';
  const rows = targets.map((p, i) =>
    [p.x, p.y, ...(theta2Deg ? [givenAt(theta2Deg, i)[0] ?? ''] : [])].map((v) => String(v)).join(','),
  );
  return `${[header, ...rows].join('\n')}\n`;
}
