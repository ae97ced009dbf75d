/**
 * Solver benchmark: speed against error. Prints a work-precision table, the continuation stress rows
 * (a 100-turn sweep and a sweep starting at a fold: iterations per point, max error, error / bound),
 * the 361-point targets against a lean implementation of the report's algorithm (bench/leanReport.ts),
 * the 10-million-point time and memory per method and the cost of sweepForces per point, and writes bench/results/solver.json,
 * solver-table.md and work-precision.svg. Error is measured against the tests' 60-digit decimal.js
 * oracle (tests/oracle/reference.ts). The targets and the large sweeps run bundled in a child node
 * process (bench/nodeBundle.ts, bench/nodeChild.ts), as the app ships the solver.
 * Run: npm run bench   (BENCH_QUICK=1 for a shorter run)
 */
import { mkdirSync, writeFileSync } from 'node:fs';
import { dirname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { LAB_TOLERANCES } from '../src/study/options';
import { medianTime, scoreSweep } from '../src/study/workPrecision';
import { STATUS_CODE, sweep, sweepForces, theta2Grid } from '../src/solver';
import type { LinkInertia, Linkage, SweepMethod } from '../src/solver';
import { classify } from '../src/solver';
import { angleDiff, referenceAngles } from '../tests/oracle/reference';
import { errorBound } from '../tests/oracle/tolerance';
import { bundleForNode, runBundle } from './nodeBundle';
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

interface Targets {
  points: number;
  rounds: number;
  usPerSweep: Record<'lean' | 'seed' | 'default' | 'newton' | 'newtonNoPredictor' | 'closedFormPolish', number>;
  overLean: Targets['usPerSweep'];
  itersPerPoint: { lean: number; seed: number; newton: number; newtonNoPredictor: number };
}

interface Scale {
  points: number;
  rounds: number;
  nsPerPoint: Record<SweepMethod, number>;
}

interface Memory {
  method: SweepMethod;
  points: number;
  before: number;
  afterSweep: number;
  afterStatus: number;
}

interface StressRow {
  sweep: string;
  method: SweepMethod;
  points: number;
  checked: number;
  itersPerPoint: number;
  maxError: number;
  maxOverBound: number;
  notOk: number;
}

/**
 * Continuation stress: each method on a long sweep, error against the oracle on every `every`-th point
 * (and every point of the last turn), as the max angle error and the max of error / errorBound.
 */
function stress(name: string, l: Linkage, grid: Float64Array, every: number): StressRow[] {
  const idx: number[] = [];
  for (let i = 0; i < grid.length; i += every) idx.push(i);
  for (let i = Math.max(0, grid.length - 360); i < grid.length; i++) if (i % every) idx.push(i);
  const refs = idx.map((i) => referenceAngles(l, grid[i], 1));
  const methods: SweepMethod[] = ['closed-form', 'newton', 'newton-no-predictor', 'seed'];
  return methods.map((method) => {
    const r = sweep(l, grid, { branch: 'open', method });
    let maxError = 0;
    let maxOverBound = 0;
    let notOk = 0;
    idx.forEach((i, k) => {
      const ref = refs[k];
      if (!ref) return;
      if (r.statusCodes[i] !== 0) {
        notOk++;
        return;
      }
      const e = Math.max(Math.abs(angleDiff(r.theta3[i], ref.theta3)), Math.abs(angleDiff(r.theta4[i], ref.theta4)));
      maxError = Math.max(maxError, e);
      maxOverBound = Math.max(maxOverBound, e / errorBound(l, ref));
    });
    return {
      sweep: name,
      method,
      points: grid.length,
      checked: idx.length,
      itersPerPoint: r.totalIterations / grid.length,
      maxError,
      maxOverBound,
      notOk,
    };
  });
}

function stressRows(): StressRow[] {
  const deg = Math.PI / 180;
  const turns = QUICK ? 10 : 100;
  const long = new Float64Array(360 * turns + 1).map((_, i) => i * deg);
  const rocker = { r1: 4, r2: 3, r3: 3.5, r4: 3 };
  const lim = classify(rocker).inputRange.intervals[0].hi;
  const fromFold = new Float64Array(Math.floor((2 * lim) / deg) + 1).map((_, i) => lim - i * deg);
  return [
    ...stress(`${turns}-turn sweep, report 6-2-5-5, 1 deg`, { r1: 6, r2: 2, r3: 5, r4: 5 }, long, QUICK ? 10 : 40),
    ...stress(
      `${turns}-turn sweep, drag link 1-2-sqrt(5.25)-1.5`,
      { r1: 1, r2: 2, r3: Math.sqrt(5.25), r4: 1.5 },
      long,
      QUICK ? 10 : 20,
    ),
    ...stress('from the fold 135.95 deg, triple rocker 4-3-3.5-3', rocker, fromFold, 1),
  ];
}

function printStress(rows: StressRow[]): void {
  console.log(
    `${'sweep'.padEnd(52)} ${'method'.padEnd(20)} ${'points'.padStart(7)} ${'it/pt'.padStart(6)} ${'max err'.padStart(8)} ${'err/bound'.padStart(9)}  not ok`,
  );
  for (const r of rows) {
    console.log(
      `${r.sweep.padEnd(52)} ${r.method.padEnd(20)} ${String(r.points).padStart(7)} ${r.itersPerPoint.toFixed(2).padStart(6)} ${fmtE(r.maxError).padStart(8)} ${fmtE(r.maxOverBound).padStart(9)}  ${String(r.notOk).padStart(6)}`,
    );
  }
}

interface ForcesRow {
  points: number;
  nsPerPoint: number;
}

/**
 * sweepForces over a solved 1-degree turn of the report's case (uniform bars of 2 kg/m, gravity, a coupler
 * force and a load torque), its rates included: ns per point, the positions not counted.
 */
function forcesRow(): ForcesRow {
  const l = CASES[0].linkage;
  const grid = theta2Grid(0, 360, 1);
  const r = sweep(l, grid, { branch: 'open' });
  const ok = (i: number) => r.statusCodes[i] === STATUS_CODE.ok;
  const bar = (L: number): LinkInertia => ({ mass: 2 * L, inertia: (2 * L ** 3) / 12, cg: { dist: L / 2, angle: 0 } });
  const inertia = { crank: bar(l.r2), coupler: bar(l.r3), rocker: bar(l.r4) };
  const loads = { gravity: { g: 9.81 }, couplerForce: { pDist: 3, pAngle: 0.5, fx: 10, fy: -20 }, outputTorque: -5 };
  const input = { omega2: 10, alpha2: 0 };
  const ms = medianTime(
    () => sweepForces(l, r.theta2, r.theta3, r.theta4, ok, input, inertia, loads),
    () => performance.now(),
    MIN_MS,
  );
  return { points: grid.length, nsPerPoint: (ms * 1e6) / grid.length };
}

/** The README's tables: every case at 1 deg, default settings; the stress rows; targets and scale. */
function markdownTable(rows: Row[], st: StressRow[], t: Targets, sc: Scale, mem: Memory, fr: ForcesRow): string {
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
    '| continuation stress (open branch) | method | points | iterations/point | max error (rad) | max error / bound | not ok |',
    '|---|---|---:|---:|---:|---:|---:|',
  );
  for (const r of st) {
    lines.push(
      `| ${r.sweep} | ${r.method} | ${r.points} | ${r.itersPerPoint.toFixed(2)} | ${e(r.maxError)} | ${e(r.maxOverBound)} | ${r.notOk} |`,
    );
  }
  const u = t.usPerSweep;
  const o = t.overLean;
  lines.push(
    '',
    `Targets (report's case, 1 deg, 361 points, medians of ${t.rounds} interleaved rounds in one bundled node process): ` +
      `lean report NR ${u.lean.toFixed(1)} us/sweep at ${t.itersPerPoint.lean.toFixed(2)} it/pt; ` +
      `default sweep (closed form) ${u.default.toFixed(1)} us = ${o.default.toFixed(2)}x lean (target <= 0.5x); ` +
      `NR continuation ${u.newton.toFixed(1)} us = ${o.newton.toFixed(2)}x lean (target <= 1.0x) at ${t.itersPerPoint.newton.toFixed(2)} it/pt; ` +
      `NR without predictor ${o.newtonNoPredictor.toFixed(2)}x at ${t.itersPerPoint.newtonNoPredictor.toFixed(2)} it/pt; ` +
      `the project's seed method ${o.seed.toFixed(2)}x.`,
    '',
    `Scale (${sc.points.toExponential(0)} points over ten turns, best of ${sc.rounds} interleaved rounds, ns/point): ` +
      Object.entries(sc.nsPerPoint)
        .map(([m, ns]) => `${m} ${ns.toFixed(0)}`)
        .join(', ') +
      `. Peak resident memory of a ${mem.points.toExponential(0)}-point ${mem.method} sweep: ${mem.before.toFixed(0)} MiB before (grid), ` +
      `${mem.afterSweep.toFixed(0)} MiB after, ${mem.afterStatus.toFixed(0)} MiB once the string \`status\` array is read.`,
    '',
    `Forces (sweepForces with its rates, report's case, ${fr.points} points, inertia, gravity, a coupler force and a ` +
      `load torque): ${fr.nsPerPoint.toFixed(0)} ns/point.`,
  );
  return lines.join('\n') + '\n';
}

async function main(): Promise<void> {
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
  console.log(
    '\n== Continuation stress (open branch): iterations per point and error against the oracle and the bound',
  );
  const st = stressRows();
  printStress(st);
  const fr = forcesRow();
  console.log(
    `\n== sweepForces (rates included), ${report.name}, ${fr.points} points: ${fr.nsPerPoint.toFixed(0)} ns/point`,
  );

  const bundle = await bundleForNode(resolve(here, 'nodeChild.ts'));
  let t: Targets;
  let sc: Scale;
  let mem: Memory;
  try {
    t = runBundle<Targets>(bundle, ['targets', String(QUICK ? 100 : 400)]);
    sc = runBundle<Scale>(bundle, ['scale', String(QUICK ? 1e6 : 1e7), String(QUICK ? 1 : 2)]);
    mem = runBundle<Memory>(bundle, ['memory', 'closed-form', String(QUICK ? 1e6 : 1e7)]);
  } finally {
    bundle.dispose();
  }
  const pass = (ok: boolean) => (ok ? 'PASS' : 'FAIL');
  console.log(
    `\n== Targets on ${report.name} at 1 deg (361 points), medians of ${t.rounds} interleaved rounds, bundled`,
  );
  console.log(
    `lean report NR (the yardstick): ${t.usPerSweep.lean.toFixed(1)} us/sweep, ${t.itersPerPoint.lean.toFixed(2)} it/pt`,
  );
  console.log(
    `default sweep (closed form):    ${t.usPerSweep.default.toFixed(1)} us/sweep = ${t.overLean.default.toFixed(2)}x lean  (target <= 0.5x: ${pass(t.overLean.default <= 0.5)})`,
  );
  console.log(
    `NR continuation ('newton'):     ${t.usPerSweep.newton.toFixed(1)} us/sweep = ${t.overLean.newton.toFixed(2)}x lean  (target <= 1.0x: ${pass(
      t.overLean.newton <= 1,
    )}), ${t.itersPerPoint.newton.toFixed(2)} it/pt (target <= 2.0: ${pass(t.itersPerPoint.newton <= 2)})`,
  );
  console.log(
    `NR without predictor:           ${t.usPerSweep.newtonNoPredictor.toFixed(1)} us/sweep = ${t.overLean.newtonNoPredictor.toFixed(2)}x lean, ${t.itersPerPoint.newtonNoPredictor.toFixed(2)} it/pt (target <= 2.0: ${pass(
      t.itersPerPoint.newtonNoPredictor <= 2,
    )})`,
  );
  console.log(
    `project's seed method:          ${t.usPerSweep.seed.toFixed(1)} us/sweep = ${t.overLean.seed.toFixed(2)}x lean`,
  );
  console.log(`\n== ${sc.points} points over ten turns, best of ${sc.rounds} interleaved rounds (ns/point)`);
  for (const [m, ns] of Object.entries(sc.nsPerPoint)) console.log(`${m.padEnd(22)} ${ns.toFixed(0).padStart(6)}`);
  const fastest = Object.entries(sc.nsPerPoint).sort((a, b) => a[1] - b[1])[0][0];
  console.log(`fastest: ${fastest} (target: closed-form: ${pass(fastest === 'closed-form')})`);
  console.log(
    `peak resident memory, ${mem.points}-point ${mem.method} sweep: ${mem.before.toFixed(0)} MiB before, ${mem.afterSweep.toFixed(0)} MiB after, ${mem.afterStatus.toFixed(0)} MiB after reading status`,
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
      {
        date: new Date().toISOString(),
        node: process.version,
        quick: QUICK,
        targets: t,
        scale: sc,
        memory: mem,
        forces: fr,
        stress: st,
        rows,
      },
      (_k, v) => (typeof v === 'number' && !Number.isFinite(v) ? null : v),
      2,
    ),
  );
  writeFileSync(resolve(outDir, 'solver-table.md'), markdownTable(rows, st, t, sc, mem, fr));
  console.log(
    `\nwrote bench/results/solver.json, solver-table.md and bench/results/work-precision.svg (${((performance.now() - t0) / 1000).toFixed(1)} s)`,
  );
}

await main();
