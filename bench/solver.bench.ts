/**
 * Solver benchmark: speed against error. Prints a work-precision table and writes
 * bench/results/solver.json and bench/results/work-precision.svg.
 * Error is measured against the tests' 60-digit decimal.js oracle (tests/oracle/reference.ts).
 * Run: npm run bench   (BENCH_QUICK=1 for a shorter run)
 */
import { mkdirSync, writeFileSync } from 'node:fs';
import { dirname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { LAB_TOLERANCES } from '../src/lab/options';
import { medianTime, scoreSweep } from '../src/lab/workPrecision';
import { sweep, theta2Grid } from '../src/solver';
import type { Linkage, SweepMethod } from '../src/solver';
import { referenceAngles } from '../tests/oracle/reference';
import { workPrecisionSvg } from './workPrecisionSvg';

const here = dirname(fileURLToPath(import.meta.url));
const QUICK = process.env.BENCH_QUICK === '1';
const MIN_MS = QUICK ? 15 : 60;

interface BenchCase {
  name: string;
  linkage: Linkage;
}

const CASES: BenchCase[] = [
  { name: 'report 6-2-5-5 (crank-rocker)', linkage: { r1: 6, r2: 2, r3: 5, r4: 5 } },
  { name: 'near-toggle 4-1-3-(2+1e-9)', linkage: { r1: 4, r2: 1, r3: 3, r4: 2 + 1e-9 } },
  { name: 'triple rocker 4-3-3.5-3', linkage: { r1: 4, r2: 3, r3: 3.5, r4: 3 } },
  { name: 'drag link 1-2-sqrt(5.25)-1.5', linkage: { r1: 1, r2: 2, r3: Math.sqrt(5.25), r4: 1.5 } },
];
const STEPS_DEG = [0.1, 1, 5];

interface Config {
  label: string;
  method: SweepMethod;
  tol?: number;
  polish?: boolean;
}

function configs(): Config[] {
  const list: Config[] = [
    { label: 'closed form (default)', method: 'closed-form' },
    { label: 'closed form + 1 NR polish', method: 'closed-form-polish' },
    { label: 'NR continuation, polished (default NR)', method: 'newton' },
    { label: 'NR no predictor, polished', method: 'newton-no-predictor' },
    { label: 'seed NR (report, abs 1e-9)', method: 'seed' },
  ];
  for (const tol of LAB_TOLERANCES) {
    list.push({ label: 'NR + predictor', method: 'newton', tol, polish: false });
    list.push({ label: 'NR no predictor', method: 'newton-no-predictor', tol, polish: false });
    list.push({ label: 'seed NR', method: 'seed', tol });
  }
  return list;
}

interface Reference {
  open: Array<{ theta3: number; theta4: number } | null>;
  crossed: Array<{ theta3: number; theta4: number } | null>;
}

function reference(l: Linkage, grid: Float64Array): Reference {
  const open: Reference['open'] = [];
  const crossed: Reference['crossed'] = [];
  for (const t2 of grid) {
    open.push(referenceAngles(l, t2, 1));
    crossed.push(referenceAngles(l, t2, -1));
  }
  return { open, crossed };
}

function median(xs: number[]): number {
  const s = [...xs].sort((a, b) => a - b);
  const n = s.length;
  return n % 2 ? s[(n - 1) / 2] : (s[n / 2 - 1] + s[n / 2]) / 2;
}

/** Timing passes per configuration; each config's time is the fastest of its pass medians (noise only adds). */
const PASSES = 3;

interface Row {
  case: string;
  stepDeg: number;
  label: string;
  method: SweepMethod;
  tol: number | null;
  points: number;
  nsPerPoint: number;
  itersPerPoint: number;
  maxError: number;
  p99Error: number;
  failures: number;
  wrongBranch: number;
  falseConvergence: number;
}

function evaluate(c: BenchCase, stepDeg: number, grid: Float64Array, ref: Reference, cfg: Config): Row {
  const opts = { branch: 'open' as const, method: cfg.method, tol: cfg.tol, polish: cfg.polish };
  const r = sweep(c.linkage, grid, opts);
  return {
    case: c.name,
    stepDeg,
    label: cfg.tol === undefined ? cfg.label : `${cfg.label} tol ${cfg.tol}`,
    method: cfg.method,
    tol: cfg.tol ?? null,
    points: grid.length,
    nsPerPoint: Infinity,
    itersPerPoint: r.totalIterations / grid.length,
    ...scoreSweep(r, ref.open, ref.crossed),
  };
}

function fmtE(x: number): string {
  return Number.isNaN(x) ? '     -' : x === 0 ? '     0' : x.toExponential(1).padStart(7);
}

function printRows(rows: Row[]): void {
  console.log(
    `${'method'.padEnd(46)} ${'step'.padStart(5)} ${'ns/pt'.padStart(7)} ${'it/pt'.padStart(6)} ${'max err'.padStart(8)} ${'p99 err'.padStart(8)}  fail wrong false`,
  );
  for (const r of rows) {
    console.log(
      `${r.label.padEnd(46)} ${String(r.stepDeg).padStart(5)} ${r.nsPerPoint.toFixed(0).padStart(7)} ${r.itersPerPoint
        .toFixed(2)
        .padStart(
          6,
        )} ${fmtE(r.maxError).padStart(8)} ${fmtE(r.p99Error).padStart(8)}  ${String(r.failures).padStart(4)} ${String(
        r.wrongBranch,
      ).padStart(5)} ${String(r.falseConvergence).padStart(5)}`,
    );
  }
}

/** Side-by-side target check: alternate the three sweeps in rounds so drift hits all alike. */
function targets(l: Linkage, grid: Float64Array) {
  const runs = {
    seed: () => sweep(l, grid, { branch: 'open', method: 'seed' }),
    default: () => sweep(l, grid, { branch: 'open' }),
    newton: () => sweep(l, grid, { branch: 'open', method: 'newton' }),
  };
  const times: Record<keyof typeof runs, number[]> = { seed: [], default: [], newton: [] };
  for (let round = 0; round < (QUICK ? 60 : 300); round++) {
    for (const k of Object.keys(runs) as Array<keyof typeof runs>) {
      const t0 = performance.now();
      runs[k]();
      times[k].push(performance.now() - t0);
    }
  }
  const seedMs = median(times.seed.slice(10));
  const defaultMs = median(times.default.slice(10));
  const newtonMs = median(times.newton.slice(10));
  const newtonIters = runs.newton().totalIterations / grid.length;
  const seedIters = runs.seed().totalIterations / grid.length;
  return {
    points: grid.length,
    seedUsPerSweep: seedMs * 1000,
    defaultUsPerSweep: defaultMs * 1000,
    newtonUsPerSweep: newtonMs * 1000,
    seedItersPerPoint: seedIters,
    newtonItersPerPoint: newtonIters,
    defaultOverSeed: defaultMs / seedMs,
    newtonOverSeed: newtonMs / seedMs,
    pass: {
      defaultAtMostHalfOfSeed: defaultMs / seedMs <= 0.5,
      newtonAtMost2ItersPerPoint: newtonIters <= 2.0,
      newtonAtMostSeedTime: newtonMs / seedMs <= 1.0,
    },
  };
}

/** The README's table: every case at 1 deg, default settings, plus the target line. */
function markdownTable(rows: Row[], t: ReturnType<typeof targets>): string {
  const e = (x: number) => (Number.isNaN(x) ? '-' : x.toExponential(1));
  const lines = [
    '| case | method | ns/point | iterations/point | max error (rad) | p99 error (rad) | failed | wrong branch | false conv. |',
    '|---|---|---:|---:|---:|---:|---:|---:|---:|',
  ];
  for (const r of rows.filter((x) => x.stepDeg === 1 && (x.tol === null || x.case === CASES[0].name))) {
    lines.push(
      `| ${r.case} | ${r.label} | ${r.nsPerPoint.toFixed(0)} | ${r.itersPerPoint.toFixed(2)} | ${e(r.maxError)} | ${e(r.p99Error)} | ${r.failures} | ${r.wrongBranch} | ${r.falseConvergence} |`,
    );
  }
  lines.push(
    '',
    `Targets (report's case, 1 deg, 361 points, interleaved medians in one process): seed NR ${t.seedUsPerSweep.toFixed(1)} us/sweep at ${t.seedItersPerPoint.toFixed(2)} it/pt; ` +
      `default sweep ${t.defaultUsPerSweep.toFixed(1)} us = ${t.defaultOverSeed.toFixed(2)}x seed (target <= 0.5x); ` +
      `NR continuation ${t.newtonUsPerSweep.toFixed(1)} us = ${t.newtonOverSeed.toFixed(2)}x seed (target <= 1.0x) at ${t.newtonItersPerPoint.toFixed(2)} it/pt (target <= 2.0).`,
  );
  return lines.join('\n') + '\n';
}

function main(): void {
  const rows: Row[] = [];
  const t0 = performance.now();
  for (const c of QUICK ? CASES.slice(0, 1) : CASES) {
    console.log(`\n== ${c.name}  (open branch, theta2 over 0..360 deg)`);
    const caseRows: Row[] = [];
    for (const step of STEPS_DEG) {
      const grid = theta2Grid(0, 360, step);
      const ref = reference(c.linkage, grid);
      const list = c === CASES[0] ? configs() : configs().slice(0, 5);
      const stepRows = list.map((cfg) => evaluate(c, step, grid, ref, cfg));
      // Interleave the configurations over several passes so a noisy moment hits one pass of each, not one config.
      for (let pass = 0; pass < PASSES; pass++) {
        list.forEach((cfg, k) => {
          const opts = { branch: 'open' as const, method: cfg.method, tol: cfg.tol, polish: cfg.polish };
          const ms = medianTime(
            () => sweep(c.linkage, grid, opts),
            () => performance.now(),
            MIN_MS / PASSES,
          );
          stepRows[k].nsPerPoint = Math.min(stepRows[k].nsPerPoint, (ms * 1e6) / grid.length);
        });
      }
      caseRows.push(...stepRows);
    }
    printRows(caseRows);
    rows.push(...caseRows);
  }
  const report = CASES[0];
  const t = targets(report.linkage, theta2Grid(0, 360, 1));
  console.log(`\n== Targets on ${report.name} at 1 deg (361 points), medians of interleaved runs in one process`);
  console.log(
    `seed NR (report's Algorithm 2): ${t.seedUsPerSweep.toFixed(1)} us/sweep, ${t.seedItersPerPoint.toFixed(2)} it/pt`,
  );
  console.log(
    `default sweep (closed form):    ${t.defaultUsPerSweep.toFixed(1)} us/sweep = ${t.defaultOverSeed.toFixed(2)}x seed  (target <= 0.5x: ${
      t.pass.defaultAtMostHalfOfSeed ? 'PASS' : 'FAIL'
    })`,
  );
  console.log(
    `NR continuation (default NR):   ${t.newtonUsPerSweep.toFixed(1)} us/sweep = ${t.newtonOverSeed.toFixed(2)}x seed  (target <= 1.0x: ${
      t.pass.newtonAtMostSeedTime ? 'PASS' : 'FAIL'
    }), ${t.newtonItersPerPoint.toFixed(2)} it/pt (target <= 2.0: ${t.pass.newtonAtMost2ItersPerPoint ? 'PASS' : 'FAIL'})`,
  );

  const colors: Record<string, string> = {
    'NR + predictor': '#1f77b4',
    'NR no predictor': '#ff7f0e',
    'seed NR': '#d62728',
  };
  const oneDeg = rows.filter((r) => r.case === report.name && r.stepDeg === 1);
  const series = Object.entries(colors).map(([label, color]) => ({
    label,
    color,
    points: oneDeg
      .filter((r) => r.tol !== null && r.label.startsWith(label + ' tol'))
      .map((r) => ({ nsPerPoint: r.nsPerPoint, maxError: r.maxError, tol: r.tol ?? undefined })),
  }));
  for (const [label, color] of [
    ['closed form (default)', '#2ca02c'],
    ['closed form + 1 NR polish', '#9467bd'],
    ['NR continuation, polished (default NR)', '#17becf'],
  ] as const) {
    const r = oneDeg.find((x) => x.label === label);
    if (r) series.push({ label, color, points: [{ nsPerPoint: r.nsPerPoint, maxError: r.maxError, tol: undefined }] });
  }
  const outDir = resolve(here, 'results');
  mkdirSync(outDir, { recursive: true });
  writeFileSync(
    resolve(outDir, 'work-precision.svg'),
    workPrecisionSvg(series, { title: `Work-precision, ${report.name}, 1 deg steps (361 points)` }),
  );
  writeFileSync(
    resolve(outDir, 'solver.json'),
    JSON.stringify(
      { date: new Date().toISOString(), node: process.version, quick: QUICK, targets: t, rows },
      (_k, v) => (typeof v === 'number' && !Number.isFinite(v) ? null : v),
      2,
    ),
  );
  writeFileSync(resolve(outDir, 'solver-table.md'), markdownTable(rows, t));
  console.log(
    `\nwrote bench/results/solver.json, solver-table.md and bench/results/work-precision.svg (${((performance.now() - t0) / 1000).toFixed(1)} s)`,
  );
}

main();
