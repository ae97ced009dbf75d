/**
 * The timed parts of the solver benchmark, run bundled in a child node process (bench/nodeBundle.ts):
 *   targets <rounds>          interleaved medians of the default 361-point sweep, NR continuation, the
 *                             project's seed method and a lean implementation of the report's algorithm
 *   scale <points> <rounds>   every method on one long grid, interleaved: best ns per point
 *   memory <method> <points>  peak resident memory before and after one sweep, and after reading `status`
 * Prints one JSON line.
 */
import { sweep, theta2Grid } from '../src/solver';
import type { SweepMethod } from '../src/solver';
import { leanReportSweep } from './leanReport';

const REPORT = { r1: 6, r2: 2, r3: 5, r4: 5 };

function median(xs: number[]): number {
  const s = [...xs].sort((a, b) => a - b);
  const n = s.length;
  return n % 2 ? s[(n - 1) / 2] : (s[n / 2 - 1] + s[n / 2]) / 2;
}

function targets(rounds: number): void {
  const grid = theta2Grid(0, 360, 1);
  const runs = {
    lean: () => leanReportSweep(REPORT.r1, REPORT.r2, REPORT.r3, REPORT.r4, grid),
    seed: () => sweep(REPORT, grid, { branch: 'open', method: 'seed' }),
    default: () => sweep(REPORT, grid, { branch: 'open' }),
    newton: () => sweep(REPORT, grid, { branch: 'open', method: 'newton' }),
    newtonNoPredictor: () => sweep(REPORT, grid, { branch: 'open', method: 'newton-no-predictor' }),
    closedFormPolish: () => sweep(REPORT, grid, { branch: 'open', method: 'closed-form-polish' }),
  };
  type Key = keyof typeof runs;
  const keys = Object.keys(runs) as Key[];
  const times = Object.fromEntries(keys.map((k) => [k, [] as number[]])) as Record<Key, number[]>;
  // Rounds alternate the order so a slow moment or a GC hits each method alike.
  for (let round = 0; round < rounds; round++) {
    const order = round % 2 ? [...keys].reverse() : keys;
    for (const k of order) {
      const t0 = performance.now();
      runs[k]();
      times[k].push(performance.now() - t0);
    }
  }
  const warm = Math.floor(rounds / 10);
  const us = Object.fromEntries(keys.map((k) => [k, median(times[k].slice(warm)) * 1000])) as Record<Key, number>;
  const lean = leanReportSweep(REPORT.r1, REPORT.r2, REPORT.r3, REPORT.r4, grid);
  const leanIters = lean.iterations.reduce((a, b) => a + b, 0) / grid.length;
  const itersOf = (m: SweepMethod) => sweep(REPORT, grid, { branch: 'open', method: m }).totalIterations / grid.length;
  console.log(
    JSON.stringify({
      points: grid.length,
      rounds,
      usPerSweep: us,
      overLean: Object.fromEntries(keys.map((k) => [k, us[k] / us.lean])),
      itersPerPoint: {
        lean: leanIters,
        seed: itersOf('seed'),
        newton: itersOf('newton'),
        newtonNoPredictor: itersOf('newton-no-predictor'),
      },
    }),
  );
}

/** Ten turns at a uniform step: every point reachable, steps as small as a long animation's. */
function longGrid(points: number): Float64Array {
  const grid = new Float64Array(points);
  for (let i = 0; i < points; i++) grid[i] = (20 * Math.PI * i) / points;
  return grid;
}

const METHODS: SweepMethod[] = ['closed-form', 'closed-form-polish', 'newton', 'newton-no-predictor', 'seed'];

/** Every method on the same long grid, in alternating order over the rounds: best wall time per point. */
function scale(points: number, rounds: number): void {
  const grid = longGrid(points);
  const best: Record<string, number> = {};
  for (let round = 0; round < rounds; round++) {
    for (const m of round % 2 ? [...METHODS].reverse() : METHODS) {
      const t0 = performance.now();
      sweep(REPORT, grid, { branch: 'open', method: m });
      const ns = ((performance.now() - t0) * 1e6) / points;
      best[m] = Math.min(best[m] ?? Infinity, ns);
    }
  }
  console.log(JSON.stringify({ points, rounds, nsPerPoint: best }));
}

/** Peak memory of one sweep (MiB of resident set): before it, after it, and after reading the string statuses. */
function memory(method: SweepMethod, points: number): void {
  const grid = longGrid(points);
  const rss = () => process.resourceUsage().maxRSS / 1024;
  const before = rss();
  const r = sweep(REPORT, grid, { branch: 'open', method });
  const afterSweep = rss();
  let ok = 0;
  for (let i = 0; i < points; i++) if (r.status[i] === 'ok') ok++;
  const afterStatus = rss();
  console.log(JSON.stringify({ method, points, before, afterSweep, afterStatus, ok }));
}

const [mode, a, b] = process.argv.slice(2);
if (mode === 'targets') targets(Number(a));
else if (mode === 'scale') scale(Number(a), Number(b));
else if (mode === 'memory') memory(a as SweepMethod, Number(b));
else throw new Error(`usage: targets <rounds> | scale <points> <rounds> | memory <method> <points>, got ${mode}`);
