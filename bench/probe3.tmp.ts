import { planClosedForm, closedFormAt, newClosedFormPoint, assemblyFactors, newAssemblyFactors } from '../src/solver/closedForm';
import { sweep, theta2Grid } from '../src/solver';
import { leanReportSweep } from './leanReport';
const l = { r1: 6, r2: 2, r3: 5, r4: 5 };
const g = theta2Grid(0, 360, 1);
const plan = planClosedForm(l); const p = newClosedFormPoint(); const f = newAssemblyFactors();
const runs: Record<string, () => unknown> = {
  lean: () => leanReportSweep(6, 2, 5, 5, g),
  af: () => { for (let i = 0; i < g.length; i++) assemblyFactors(plan, g[i], f); },
  cfat: () => { for (let i = 0; i < g.length; i++) closedFormAt(plan, g[i], 1, p); },
  cf: () => sweep(l, g, { branch: 'open' }),
  cfp: () => sweep(l, g, { branch: 'open', method: 'closed-form-polish' }),
  nr: () => sweep(l, g, { branch: 'open', method: 'newton' }),
};
const t: Record<string, number[]> = {};
for (let round = 0; round < 600; round++) for (const k in runs) { const t0 = performance.now(); runs[k](); (t[k] ??= []).push(performance.now() - t0); }
const med = (x: number[]) => { const s = x.slice(100).sort((a, b) => a - b); return s[s.length >> 1]; };
for (const k in runs) console.log(k, (med(t[k]) * 1000).toFixed(1), 'us', (med(t[k]) / med(t.lean)).toFixed(2));
