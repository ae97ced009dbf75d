/**
 * Cost of velocity and acceleration analysis on a full cycle: the default closed-form sweep alone
 * against the same sweep followed by sweepRates, for 361 (1 deg) and 3601 (0.1 deg) points.
 * The two runs alternate in rounds so machine drift hits both alike; medians of the rounds are printed
 * with their ratio. Run: npx vite-node bench/rates.bench.ts   (BENCH_QUICK=1 for a shorter run)
 */
import { sweep, sweepRates, theta2Grid } from '../src/solver';
import type { InputMotion, Linkage } from '../src/solver';

const QUICK = process.env.BENCH_QUICK === '1';
const ROUNDS = QUICK ? 60 : 400;
const WARMUP = 20;
const INPUT: InputMotion = { omega2: 10, alpha2: 0 };

interface BenchCase {
  name: string;
  linkage: Linkage;
}

const CASES: BenchCase[] = [
  { name: 'report 6-2-5-5 (crank-rocker)', linkage: { r1: 6, r2: 2, r3: 5, r4: 5 } },
  { name: 'triple rocker 4-3-3.5-3', linkage: { r1: 4, r2: 3, r3: 3.5, r4: 3 } },
];

function median(xs: number[]): number {
  const s = [...xs].sort((a, b) => a - b);
  const n = s.length;
  return n % 2 ? s[(n - 1) / 2] : (s[n / 2 - 1] + s[n / 2]) / 2;
}

function measure(l: Linkage, grid: Float64Array): { sweepUs: number; withRatesUs: number; ratesUs: number } {
  const positions = () => sweep(l, grid, { branch: 'open' });
  const withRates = () => {
    const r = sweep(l, grid, { branch: 'open' });
    return sweepRates(l, r.theta2, r.theta3, r.theta4, (i) => r.status[i] === 'ok', INPUT);
  };
  const a: number[] = [];
  const b: number[] = [];
  let sink = 0;
  for (let round = 0; round < ROUNDS + WARMUP; round++) {
    let t0 = performance.now();
    sink += positions().theta3.length;
    const ta = performance.now() - t0;
    t0 = performance.now();
    sink += withRates().omega3.length;
    const tb = performance.now() - t0;
    if (round >= WARMUP) {
      a.push(ta);
      b.push(tb);
    }
  }
  if (sink === 0) throw new Error('nothing ran');
  const sweepMs = median(a);
  const withMs = median(b);
  return { sweepUs: sweepMs * 1000, withRatesUs: withMs * 1000, ratesUs: (withMs - sweepMs) * 1000 };
}

function main(): void {
  console.log(`Rates benchmark: closed-form sweep vs sweep + sweepRates, medians of ${ROUNDS} interleaved rounds`);
  console.log(
    `${'case'.padEnd(32)} ${'points'.padStart(6)} ${'sweep us'.padStart(9)} ${'+rates us'.padStart(10)} ${'ratio'.padStart(6)} ${'rates ns/pt'.padStart(12)}`,
  );
  for (const c of CASES) {
    for (const step of [1, 0.1]) {
      const grid = theta2Grid(0, 360, step);
      const m = measure(c.linkage, grid);
      console.log(
        `${c.name.padEnd(32)} ${String(grid.length).padStart(6)} ${m.sweepUs.toFixed(1).padStart(9)} ${m.withRatesUs
          .toFixed(1)
          .padStart(10)} ${(m.withRatesUs / m.sweepUs).toFixed(2).padStart(6)} ${((m.ratesUs * 1000) / grid.length)
          .toFixed(0)
          .padStart(12)}`,
      );
    }
  }
}

main();
