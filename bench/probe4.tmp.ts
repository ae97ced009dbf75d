import { planClosedForm, closedFormAt, newClosedFormPoint, assemblyFactors, newAssemblyFactors } from '../src/solver/closedForm';
import { theta2Grid } from '../src/solver';
const l = { r1: 6, r2: 2, r3: 5, r4: 5 };
const g = theta2Grid(0, 360, 1);
const plan = planClosedForm(l); const p = newClosedFormPoint(); const f = newAssemblyFactors();
const runs: Record<string, () => unknown> = {
  af: () => { for (let i = 0; i < g.length; i++) assemblyFactors(plan, g[i], f); },
  afplus: () => { let s = 0; for (let i = 0; i < g.length; i++) { assemblyFactors(plan, g[i], f); const y = Math.sqrt(f.dPlus) * Math.sqrt(f.dMinus); const re3 = f.dx * f.x3 - f.dy * y; const im3 = f.dx * y + f.dy * f.x3; s += Math.atan2(im3, re3) + Math.atan2(re3, im3 + 1); } return s; },
  cfat: () => { for (let i = 0; i < g.length; i++) closedFormAt(plan, g[i], 1, p); },
};
const t: Record<string, number[]> = {};
for (let round = 0; round < 600; round++) for (const k in runs) { const t0 = performance.now(); runs[k](); (t[k] ??= []).push(performance.now() - t0); }
const med = (x: number[]) => { const s = x.slice(100).sort((a, b) => a - b); return s[s.length >> 1]; };
for (const k in runs) console.log(k, (med(t[k]) * 1000).toFixed(1), 'us');
