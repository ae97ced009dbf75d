import { sweep, theta2Grid } from '../src/solver';
import { sweep as sweepMain } from './mainsolver.tmp';
import { leanReportSweep } from './leanReport';
const l = { r1: 6, r2: 2, r3: 5, r4: 5 };
const g = theta2Grid(0, 360, 1);
const runs: Record<string, () => unknown> = {
  lean: () => leanReportSweep(6, 2, 5, 5, g),
  cf: () => sweep(l, g, { branch: 'open' }),
  cfMain: () => sweepMain(l, g, { branch: 'open' }),
  nr: () => sweep(l, g, { branch: 'open', method: 'newton' }),
  nrMain: () => sweepMain(l, g, { branch: 'open', method: 'newton' }),
};
const t: Record<string, number[]> = {};
for (let round = 0; round < 600; round++) for (const k in runs) { const t0 = performance.now(); runs[k](); (t[k] ??= []).push(performance.now() - t0); }
const med = (x: number[]) => { const s = x.slice(100).sort((a, b) => a - b); return s[s.length >> 1]; };
for (const k in runs) console.log(k, (med(t[k]) * 1000).toFixed(1), 'us', (med(t[k]) / med(t.lean)).toFixed(2));
