/**
 * The Function mode's design: functionGenerator (Freudenstein at Chebyshev-spaced precision points) for the
 * slice's ranges and a parsed f, on the main thread (0.05 ms for five points, docs/synthesis.md), with every
 * expected failure turned into a problem the page says in words.
 */
import { angleDiff, classify, degToRad, solveClosedForm } from '../../../solver';
import type { LinkageType } from '../../../solver';
import { chebyshevPoints, functionGenerator } from '../../../synthesis';
import type { FunctionGeneratorResult, PlacedFourBar } from '../../../synthesis';
import type { SynFunctionState } from '../../../shared/state/slices/synFunctionSlice';

/** Evenly spaced samples of the structural error, both ends included. */
export const ERROR_SAMPLES = 201;

/** Why there is no function generator (said in words by the page, naming the expression). */
export type FunctionProblem =
  { code: 'notFinite'; x: number } | { code: 'sameEnds'; y: number } | { code: 'noLinkage'; detail: string };

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
}

/** The design, or why there is none. */
export type FunctionOutcome = { ok: true; value: FunctionDesign } | { ok: false; problem: FunctionProblem };

/** The range in radians of a range in degrees. */
const radians = (r: readonly [number, number]): [number, number] => [degToRad(r[0]), degToRad(r[1])];

/**
 * The function generator of f for the slice's ranges and precision points, or the problem: f with no finite value
 * at some x the method evaluates (the ends, the precision points, the error samples), f(x0) = f(x1) (y cannot be
 * mapped onto θ4), or no real linkage fitting the pairs (Freudenstein's K's give a negative link, or the pairs are
 * singular). The error at each precision point is computed as functionGenerator computes the structural error.
 */
export function solveFunction(s: SynFunctionState, f: (x: number) => number): FunctionOutcome {
  const [x0, x1] = s.xRange;
  // From x0 on, so a problem names the first x of the range where f fails.
  const xs = [
    ...Array.from({ length: ERROR_SAMPLES }, (_, k) => x0 + ((x1 - x0) * k) / (ERROR_SAMPLES - 1)),
    ...chebyshevPoints(x0, x1, s.precisionPoints),
  ];
  for (const x of xs) {
    if (!Number.isFinite(f(x))) return { ok: false, problem: { code: 'notFinite', x } };
  }
  const y0 = f(x0);
  const y1 = f(x1);
  if (y0 === y1) return { ok: false, problem: { code: 'sameEnds', y: y0 } };
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
    return { ok: false, problem: { code: 'noLinkage', detail: e instanceof Error ? e.message : String(e) } };
  }
  const yPerRad = (y1 - y0) / (theta4[1] - theta4[0]);
  const precision = result.precision.map((p) => {
    const a = solveClosedForm(result.links, p.theta2, result.branch);
    return { ...p, error: a ? angleDiff(a.theta4, p.theta4) * yPerRad : Number.NaN };
  });
  const design: PlacedFourBar = {
    links: result.links,
    branch: result.branch,
    O2: { x: 0, y: 0 },
    groundAngle: 0,
    pDist: 0,
    pAngle: 0,
  };
  return { ok: true, value: { result, y0, y1, design, precision, type: classify(result.links).type } };
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
