import { planClosedForm, closedFormAt, newClosedFormPoint } from '../src/solver/closedForm';
import { sweep, theta2Grid } from '../src/solver';
import { leanReportSweep } from './leanReport';
const l = { r1: 6, r2: 2, r3: 5, r4: 5 };
const g = theta2Grid(0, 360, 1);
const plan = planClosedForm(l); const p = newClosedFormPoint();
const out = new Float64Array(361 * 4);
const runs: Record<string, () => unknown> = {
  lean: () => leanReportSweep(6, 2, 5, 5, g),
  cfatStore: () => { for (let i = 0; i < g.length; i++) { closedFormAt(plan, g[i], 1, p); out[i] = p.theta3; out[i + 361] = p.theta4; out[i + 722] = p.residual; } },
  alloc: () => new ArrayBuffer(361 * 37),
  alloc4: () => [new Float64Array(361), new Float64Array(361), new Int32Array(361), new Uint8Array(361)],
  cf: () => sweep(l, g, { branch: 'open' }),
};
const t: Record<string, number[]> = {};
for (let round = 0; round < 1000; round++) for (const k in runs) { const t0 = performance.now(); runs[k](); (t[k] ??= []).push(performance.now() - t0); }
const med = (x: number[]) => { const s = x.slice(100).sort((a, b) => a - b); return s[s.length >> 1]; };
for (const k in runs) console.log(k, (med(t[k]) * 1000).toFixed(1), 'us', (med(t[k]) / med(t.lean)).toFixed(2));
