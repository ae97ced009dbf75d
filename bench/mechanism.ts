/**
 * Mechanism benchmark: poses per second of sweepMechanism on every template at 3601 inputs over its input range
 * (one core, in-process under vite-node), and the ratio to solveClosedForm on
 * the report's 6-2-5-5 four-bar written as a MechanismSpec. Run: npm run bench (or vite-node bench/mechanism.ts).
 */
import { MECHANISM_TEMPLATES, fourBarSpec, sweepMechanism } from '../src/mechanism';
import { solveClosedForm } from '../src/solver';

const POINTS = 3601;
const QUICK = process.env.BENCH_QUICK === '1';
const MIN_MS = QUICK ? 40 : 200;

/** Fastest seconds per call of fn over repeats for MIN_MS (at least 5 calls): on a shared machine noise only adds. */
function timeIt(fn: () => void): number {
  const times: number[] = [];
  const start = performance.now();
  while (times.length < 5 || performance.now() - start < MIN_MS) {
    const t0 = performance.now();
    fn();
    times.push(performance.now() - t0);
  }
  return Math.min(...times) / 1000;
}

function grid(a: number, b: number): Float64Array {
  return Float64Array.from({ length: POINTS }, (_, i) => a + ((b - a) * i) / (POINTS - 1));
}

export interface MechanismBenchRow {
  key: string;
  links: number;
  unknowns: number;
  okFraction: number;
  itersPerPoint: number;
  posesPerSecond: number;
}

/** The table's rows. */
export function mechanismRows(): MechanismBenchRow[] {
  const rows: MechanismBenchRow[] = [];
  for (const [key, t] of Object.entries(MECHANISM_TEMPLATES)) {
    const inputs = grid(t.inputRange[0], t.inputRange[1]);
    const r = sweepMechanism(t.spec, inputs);
    const ok = r.ok.reduce((s, v) => s + v, 0);
    const its = r.iterations.reduce((s, v) => s + v, 0);
    const sec = timeIt(() => sweepMechanism(t.spec, inputs));
    rows.push({
      key,
      links: t.spec.links.length,
      unknowns: 3 * (t.spec.links.length - 1),
      okFraction: ok / POINTS,
      itersPerPoint: its / POINTS,
      posesPerSecond: POINTS / sec,
    });
  }
  return rows;
}

/**
 * Poses per second of solveClosedForm on 6-2-5-5 and of sweepMechanism on the same four-bar, timed alternately
 * (one call of each per round, fastest of each) so that a shared machine's load falls on both alike.
 */
export function fourBarRatio(): { closedForm: number; mechanism: number } {
  const inputs = grid(0, 2 * Math.acos(-1));
  const l = { r1: 6, r2: 2, r3: 5, r4: 5 };
  const spec = fourBarSpec(6, 2, 5, 5);
  let sink = 0;
  let cf = Infinity;
  let mech = Infinity;
  const start = performance.now();
  for (let round = 0; round < 5 || performance.now() - start < 2 * MIN_MS; round++) {
    const t0 = performance.now();
    for (let i = 0; i < POINTS; i++) sink += solveClosedForm(l, inputs[i], 'open')!.theta3;
    const t1 = performance.now();
    sweepMechanism(spec, inputs);
    const t2 = performance.now();
    cf = Math.min(cf, t1 - t0);
    mech = Math.min(mech, t2 - t1);
  }
  if (sink === 0.5) console.log('');
  return { closedForm: (1000 * POINTS) / cf, mechanism: (1000 * POINTS) / mech };
}

function main(): void {
  console.log(`\nMechanism sweeps: ${POINTS} inputs over each template's range, one core (poses/s, fastest run)`);
  console.log(
    `${'template'.padEnd(22)} ${'links'.padStart(5)} ${'ok %'.padStart(6)} ${'it/pt'.padStart(6)} ${'poses/s'.padStart(10)}`,
  );
  for (const r of mechanismRows()) {
    console.log(
      `${r.key.padEnd(22)} ${String(r.links).padStart(5)} ${(100 * r.okFraction).toFixed(1).padStart(6)} ${r.itersPerPoint.toFixed(2).padStart(6)} ${Math.round(r.posesPerSecond).toString().padStart(10)}`,
    );
  }
  const f = fourBarRatio();
  console.log(
    `four-bar 6-2-5-5: solveClosedForm ${Math.round(f.closedForm)} poses/s, sweepMechanism ${Math.round(f.mechanism)} poses/s, ratio ${(f.closedForm / f.mechanism).toFixed(2)}x`,
  );
}

main();
