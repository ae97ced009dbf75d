/**
 * In-page part of the log-chart redraw benchmark: synthetic data of the NR convergence chart (two runs that
 * change with θ2) and of the lab (five methods' work-precision points, 361 samples of iterations and |det J|),
 * then the JavaScript time of each redraw the pages do: the convergence chart on a θ2 step, the work-precision
 * diagram on a new highlight, the cycle chart on a θ2 step.
 */
import type { LabResult, LabSeries } from '../../src/study/workPrecision';
import type { SweepMethod } from '../../src/solver/types';
import type { ConvergenceRun } from '../../src/shared/charts/convergenceChart';
import { CHART_STYLE } from '../../src/shared/charts/chartFrame';
import { makeLogCharts } from './logPlots';

/** Milliseconds of JS per redraw of each chart. */
export interface LogBenchRun {
  convergence: number[];
  diagram: number[];
  cycle: number[];
}

const METHODS: SweepMethod[] = ['closed-form', 'closed-form-polish', 'newton', 'newton-no-predictor', 'seed'];
const TOLS = [1e-3, 1e-6, 1e-9, 1e-12, 1e-15];

/** Two NR runs at step k: quadratic convergence from a residual that moves with k, the last one exactly 0. */
function runs(k: number): ConvergenceRun[] {
  const run = (r0: number, n: number, color: string, faint: boolean): ConvergenceRun => {
    const residuals = [r0];
    for (let i = 1; i < n; i++) residuals.push(i === n - 1 ? 0 : residuals[i - 1] ** 2 * 3);
    return { label: `run ${n}`, color, faint, iterations: residuals.map((_r, i) => i), residuals };
  };
  return [
    run(0.3 + 0.01 * (k % 20), 6, CHART_STYLE.marker, true),
    run(1e-3 * (1 + (k % 7)), 3, CHART_STYLE.residual, false),
  ];
}

/** A lab result: three traced methods over five tolerances plus each method's default, 361 cycle samples. */
function labResult(): LabResult {
  const series: LabSeries[] = METHODS.map((method, m) => {
    const score = { p99Error: 0, failures: 0, wrongBranch: 0, falseConvergence: 0 };
    const traced =
      m >= 2
        ? TOLS.map((tol, j) => ({
            ...score,
            tol,
            nsPerPoint: 300 + 60 * m + 40 * j,
            itersPerPoint: 2 + j,
            maxError: tol * (m + 1),
          }))
        : [];
    return {
      method,
      label: method,
      points: [
        ...traced,
        { ...score, tol: null, nsPerPoint: 200 + 70 * m, itersPerPoint: 1, maxError: m === 0 ? 0 : 4e-16 * m },
      ],
    };
  });
  const theta2Deg = Float64Array.from({ length: 361 }, (_v, i) => i);
  const detJ = theta2Deg.map((t) => 25 * Math.abs(Math.sin(((t - 180) * Math.PI) / 360)));
  const iterations = METHODS.slice(2).map((method, m) => ({
    method,
    label: method,
    iterations: Int32Array.from(theta2Deg, (t) => 1 + m + (Math.abs(t - 180) < 3 ? 8 : 0)),
  }));
  return {
    linkage: { r1: 6, r2: 2, r3: 5, r4: 5 },
    branch: 'open',
    stepDeg: 1,
    theta2Deg,
    series,
    detJ,
    iterations,
    limitsDeg: [],
    minSinMu: { value: 0, theta2Deg: 180 },
  };
}

/** Which chart a run redraws. */
export type LogChartName = keyof LogBenchRun;

async function run(steps: number, width: number, height: number, which: LogChartName): Promise<number[]> {
  const el = (id: string) => document.getElementById(id) as unknown as SVGSVGElement;
  const charts = makeLogCharts({ conv: el('conv'), wp: el('wp'), cycle: el('cycle') }, width, height);
  const result = labResult();
  const data = Array.from({ length: steps }, (_v, k) => runs(k));
  const redraw: Record<LogChartName, (k: number) => void> = {
    convergence: (k) => charts.convergence(data[k], 2e-12),
    diagram: (k) => charts.diagram(result, METHODS[2 + (k % 3)], TOLS[k % 5]),
    cycle: (k) => charts.cycle(result, k % 360),
  };
  const out: number[] = [];
  for (let k = 0; k < steps; k++) {
    const t0 = performance.now();
    redraw[which](k);
    out.push(performance.now() - t0);
    // One frame between steps, as between two user moves.
    await new Promise((r) => requestAnimationFrame(r));
  }
  return out;
}

(window as unknown as { runLogBench: typeof run }).runLogBench = run;
