/**
 * Timing of the closed-form syntheses (function generation, three-position synthesis, Burmester points and curves):
 * each must take well under a millisecond. closedFormRows() times each case as the median over 31 rounds of a batch
 * of calls (after a warm-up), with the interquartile range as the spread. bench/synthesis.bench.ts prints the rows;
 * run directly (PRINT_CLOSED_FORMS=1 npx vite-node bench/synthesisClosedForms.ts) it prints them itself.
 */
import { PI, solveClosedForm } from '../src/solver';
import type { Pose } from '../src/synthesis';
import {
  burmesterCurves,
  burmesterPoints,
  freudenstein,
  functionGenerator,
  threePositionSynthesis,
} from '../src/synthesis';

/** One timed case: median time per call (ms) and the interquartile range "q1–q3". */
export interface ClosedFormRow {
  case: string;
  medianMs: number;
  spreadMs: string;
}

const ROUNDS = 31;

/** Median and interquartile range (ms per call) of fn over ROUNDS rounds of `batch` calls, after a warm-up. */
function time(fn: () => unknown, batch: number): { medianMs: number; spreadMs: string } {
  for (let i = 0; i < 3 * batch; i++) fn();
  const per: number[] = [];
  for (let r = 0; r < ROUNDS; r++) {
    const t0 = performance.now();
    for (let i = 0; i < batch; i++) fn();
    per.push((performance.now() - t0) / batch);
  }
  per.sort((a, b) => a - b);
  const q = (f: number) => per[Math.round(f * (per.length - 1))];
  return { medianMs: q(0.5), spreadMs: `${q(0.25).toPrecision(3)}–${q(0.75).toPrecision(3)}` };
}

const deg = PI / 180;
const POSES: Pose[] = [
  { x: 0, y: 0, angle: 0 },
  { x: 1, y: 0.2, angle: 0.3 },
  { x: 1.8, y: 0.7, angle: 0.5 },
  { x: 2.2, y: 1.5, angle: 0.9 },
  { x: 2.3, y: 2.4, angle: 1.4 },
];
/** Five poses with four real Burmester pairs: the crank-rocker 4, 1.2, 3.5, 3 (P at 2, 0.5 rad) at θ2 = 0, 1.2, … 4.8, rounded. */
const POSES_FOUR: Pose[] = [
  { x: 0.9792, y: 2.2287, angle: 1.1694 },
  { x: 0.8373, y: 3.0796, angle: 0.7486 },
  { x: -0.2612, y: 2.4656, angle: 0.6772 },
  { x: -0.6358, y: 1.2411, angle: 0.9135 },
  { x: -0.1116, y: 0.7975, angle: 1.2988 },
];

/** The closed-form synthesis timings, one row per case. */
export function closedFormRows(): ClosedFormRow[] {
  // Three pairs of the report's crank-rocker 6, 2, 5, 5 (open branch).
  const report = { r1: 6, r2: 2, r3: 5, r4: 5 };
  const pairs = [0.3, 1.4, 2.9].map((t) => ({ theta2: t, theta4: solveClosedForm(report, t, 'open')!.theta4 }));
  const log10 = {
    f: Math.log10,
    x: [1, 10] as [number, number],
    theta2: [30 * deg, 90 * deg] as [number, number],
    theta4: [-60 * deg, -150 * deg] as [number, number],
    points: 5,
  };
  const three: [Pose, Pose, Pose] = [POSES[0], POSES[2], POSES[4]];
  const moving: [{ x: number; y: number }, { x: number; y: number }] = [
    { x: -0.4, y: -1 },
    { x: 0.8, y: -0.9 },
  ];
  return [
    { case: 'freudenstein, 3 pairs', ...time(() => freudenstein(pairs), 2000) },
    { case: 'functionGenerator log10, 5 points', ...time(() => functionGenerator(log10), 200) },
    { case: 'threePositionSynthesis', ...time(() => threePositionSynthesis(three, { moving }), 2000) },
    {
      case: `burmesterPoints (${burmesterPoints(POSES_FOUR).length} pairs)`,
      ...time(() => burmesterPoints(POSES_FOUR), 500),
    },
    { case: 'burmesterCurves, 200 samples', ...time(() => burmesterCurves(POSES.slice(0, 4), { samples: 200 }), 100) },
  ];
}

// vite-node hides the script from process.argv, so a standalone run asks for the table by environment.
if (process.env.PRINT_CLOSED_FORMS === '1') {
  for (const r of closedFormRows())
    console.log(`${r.case.padEnd(40)} ${r.medianMs.toFixed(4)} ms  (IQR ${r.spreadMs})`);
}
