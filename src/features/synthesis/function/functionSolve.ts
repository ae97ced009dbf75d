/**
 * The Function mode's design: functionGenerator (Freudenstein at Chebyshev-spaced precision points) for the
 * slice's ranges and a parsed f, on the main thread (0.05 ms for five points, docs/synthesis.md), with every
 * expected failure turned into a problem the page says in words.
 */
import { angleDiff, classify, degToRad, solveClosedForm } from '../../../solver';
import type { LinkageType } from '../../../solver';
import { NoLinkageError, chebyshevPoints, functionGenerator } from '../../../synthesis';
import type { FunctionGeneratorResult, NoLinkageReason, PlacedFourBar } from '../../../synthesis';
import type { SynFunctionState } from '../../../shared/state/slices/synFunctionSlice';
import { RANGE_DEG_MAX } from '../../../shared/state/slices/synFunctionSlice';

/** Evenly spaced samples of the structural error, both ends included. */
export const ERROR_SAMPLES = 201;

/** Largest structural error, as a share of y's range, that the page does not call a defect. */
export const LARGE_ERROR_SHARE = 0.05;

/** A nearby θ2 or θ4 range (degrees) that gives a linkage; clean: one with no defect and no check. */
export interface RangeHint {
  range: 'theta2' | 'theta4';
  deg: [number, number];
  clean: boolean;
}

/**
 * Why there is no function generator (said in words by the page, naming the expression). noLinkage: the reason
 * (the crank or the rocker would point backwards, the coupler cannot close, the pairs are singular, or 'other'),
 * the x near which f turns back (null if f is monotone on the range) and a range that would give a linkage.
 */
export type FunctionProblem =
  | { code: 'notFinite'; x: number }
  | { code: 'sameEnds'; y: number }
  | { code: 'noLinkage'; reason: NoLinkageReason | 'other'; turnsAt: number | null; hint: RangeHint | null };

/**
 * What the page says beside functionGenerator's defects: f turns back on the x range (near x: a rocker follows it
 * only through a dead centre), or the largest structural error is over LARGE_ERROR_SHARE of y's range (share).
 */
export type FunctionCheck = { code: 'notMonotone'; x: number } | { code: 'largeError'; share: number };

/** A precision point: x, the input and output angles it asks for (radians) and the error there (y units). */
export interface PrecisionPoint {
  x: number;
  theta2: number;
  theta4: number;
  error: number;
}

/** A function generator the page shows. */
export interface FunctionDesign {
  result: FunctionGeneratorResult;
  /** f at the ends of the x range (θ4's range is mapped onto [y0, y1]). */
  y0: number;
  y1: number;
  /** The design placed with O2 at the origin and the ground line along +x, the coupler point on A. */
  design: PlacedFourBar;
  precision: PrecisionPoint[];
  type: LinkageType;
  /** The page's own checks (empty when f is monotone and the error small). */
  checks: FunctionCheck[];
}

/** The design, or why there is none. */
export type FunctionOutcome = { ok: true; value: FunctionDesign } | { ok: false; problem: FunctionProblem };

/** The range in radians of a range in degrees. */
const radians = (r: readonly [number, number]): [number, number] => [degToRad(r[0]), degToRad(r[1])];

/**
 * The function generator of f for the slice's ranges and precision points, or the problem: f with no finite value
 * at some x the method evaluates (the ends, the precision points, the error samples), f(x0) = f(x1) (y cannot be
 * mapped onto θ4), or no real linkage fitting the pairs (Freudenstein's K's give a negative link, or the pairs are
 * singular; with a nearby θ2 or θ4 range that gives one, when one of a few tried does). The error at each precision
 * point is computed as functionGenerator computes the structural error.
 */
export function solveFunction(s: SynFunctionState, f: (x: number) => number): FunctionOutcome {
  const out = design(s, f);
  if (out.ok || out.problem.code !== 'noLinkage') return out;
  return { ok: false, problem: { ...out.problem, hint: rangeHint(s, f) } };
}

/** The x near which f first turns back on the samples (its first step against its first rising or falling step), or null. */
export function turningPoint(xs: readonly number[], ys: readonly number[]): number | null {
  // A step smaller than this is rounding of f, neither a rise nor a fall.
  const noise = 1e-12 * Math.max(...ys.map(Math.abs));
  let direction = 0;
  for (let k = 1; k < ys.length; k++) {
    const step = ys[k] - ys[k - 1];
    if (Math.abs(step) <= noise) continue;
    if (direction === 0) direction = Math.sign(step);
    else if (Math.sign(step) !== direction) return xs[k - 1];
  }
  return null;
}

/** solveFunction without the hint. */
function design(s: SynFunctionState, f: (x: number) => number): FunctionOutcome {
  const [x0, x1] = s.xRange;
  const even = Array.from({ length: ERROR_SAMPLES }, (_, k) => x0 + ((x1 - x0) * k) / (ERROR_SAMPLES - 1));
  // From x0 on, so a problem names the first x of the range where f fails.
  for (const x of [...even, ...chebyshevPoints(x0, x1, s.precisionPoints)]) {
    if (!Number.isFinite(f(x))) return { ok: false, problem: { code: 'notFinite', x } };
  }
  const y0 = f(x0);
  const y1 = f(x1);
  if (y0 === y1) return { ok: false, problem: { code: 'sameEnds', y: y0 } };
  const turnsAt = turningPoint(even, even.map(f));
  const theta4 = radians(s.theta4RangeDeg);
  let result: FunctionGeneratorResult;
  try {
    result = functionGenerator({
      f,
      x: [x0, x1],
      theta2: radians(s.theta2RangeDeg),
      theta4,
      points: s.precisionPoints,
      samples: ERROR_SAMPLES,
    });
  } catch (e) {
    const reason = e instanceof NoLinkageError ? e.reason : 'other';
    return { ok: false, problem: { code: 'noLinkage', reason, turnsAt, hint: null } };
  }
  const yPerRad = (y1 - y0) / (theta4[1] - theta4[0]);
  const precision = result.precision.map((p) => {
    const a = solveClosedForm(result.links, p.theta2, result.branch);
    return { ...p, error: a ? angleDiff(a.theta4, p.theta4) * yPerRad : Number.NaN };
  });
  const placed: PlacedFourBar = {
    links: result.links,
    branch: result.branch,
    O2: { x: 0, y: 0 },
    groundAngle: 0,
    pDist: 0,
    pAngle: 0,
  };
  const checks: FunctionCheck[] = [];
  if (turnsAt !== null) checks.push({ code: 'notMonotone', x: turnsAt });
  const share = result.maxError / Math.abs(y1 - y0);
  // An infinite error is the 'not-assemblable' defect already.
  if (Number.isFinite(share) && share > LARGE_ERROR_SHARE) checks.push({ code: 'largeError', share });
  return {
    ok: true,
    value: { result, y0, y1, design: placed, precision, type: classify(result.links).type, checks },
  };
}

/**
 * A θ4 or θ2 range near the slice's that gives a linkage: each range reversed, then moved by ±90° and 180°
 * (θ4 first: Freudenstein's K's depend most on it), the first clean one, else the first with a linkage, else null.
 * At most twelve solves of 0.05 ms each.
 */
function rangeHint(s: SynFunctionState, f: (x: number) => number): RangeHint | null {
  const tries: RangeHint[] = [];
  for (const range of ['theta4', 'theta2'] as const) {
    const [a, b] = range === 'theta4' ? s.theta4RangeDeg : s.theta2RangeDeg;
    const moved: [number, number][] = [[b, a], ...[90, -90, 180].map((d): [number, number] => [a + d, b + d])];
    for (const deg of moved) {
      if (Math.max(Math.abs(deg[0]), Math.abs(deg[1])) > RANGE_DEG_MAX) continue;
      tries.push({ range, deg, clean: false });
    }
  }
  let fallback: RangeHint | null = null;
  for (const t of tries) {
    const out = design(t.range === 'theta4' ? { ...s, theta4RangeDeg: t.deg } : { ...s, theta2RangeDeg: t.deg }, f);
    if (!out.ok) continue;
    if (out.value.result.defects.length === 0 && out.value.checks.length === 0) return { ...t, clean: true };
    fallback ??= t;
  }
  return fallback;
}

/**
 * At one x: θ2 (radians) and the y the linkage generates there (NaN where the loop cannot close), read as
 * functionGenerator reads the structural error: y generated = f(x) + (θ4 generated − θ4 wanted) (y1 − y0)/(θ4 range).
 */
export function generatedAt(
  s: SynFunctionState,
  fd: FunctionDesign,
  f: (x: number) => number,
  x: number,
): { theta2: number; want: number; got: number } {
  const [x0, x1] = s.xRange;
  const [t2a, t2b] = radians(s.theta2RangeDeg);
  const [t4a, t4b] = radians(s.theta4RangeDeg);
  const theta2 = t2a + ((x - x0) / (x1 - x0)) * (t2b - t2a);
  const want = f(x);
  const a = solveClosedForm(fd.result.links, theta2, fd.result.branch);
  const theta4Want = t4a + ((want - fd.y0) / (fd.y1 - fd.y0)) * (t4b - t4a);
  const got = a ? want + (angleDiff(a.theta4, theta4Want) * (fd.y1 - fd.y0)) / (t4b - t4a) : Number.NaN;
  return { theta2, want, got };
}
