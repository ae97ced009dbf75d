import { sweep, theta2Grid } from '../src/solver';
import { planClosedForm, closedFormAt, newClosedFormPoint } from '../src/solver/closedForm';
import { leanReportSweep } from './leanReport';
const l = { r1: 6, r2: 2, r3: 5, r4: 5 };
const g = theta2Grid(0, 360, 1);
const plan = planClosedForm(l);
const EPS = Number.EPSILON;
function inline(theta2s: Float64Array, sigma: number) {
  const n = theta2s.length;
  const buf = new ArrayBuffer(n * 37);
  const th2 = new Float64Array(buf, 0, n), th3 = new Float64Array(buf, 8 * n, n), th4 = new Float64Array(buf, 16 * n, n), res = new Float64Array(buf, 24 * n, n);
  const codes = new Uint8Array(buf, 36 * n, n);
  const { r1, r2, r3, r4, k2, inv3, inv4, consts: k, unscale } = plan;
  const d12hi = plan.d12.hi, d12lo = plan.d12.lo;
  for (let i = 0; i < n; i++) {
    const t2 = theta2s[i];
    th2[i] = t2;
    const c = Math.cos(t2), sn = Math.sin(t2);
    let o, m, dx;
    if (c > 0.5) { const omc = (sn * sn) / (1 + c); o = 0; m = k2 * omc; dx = d12hi + r2 * omc + d12lo; }
    else if (c < -0.5) { o = 16; m = -k2 * ((sn * sn) / (1 - c)); dx = r1 - r2 * c; }
    else { o = 8; m = -k2 * c; dx = r1 - r2 * c; }
    const dy = -r2 * sn;
    let dP = k[o] - m + k[o + 1];
    let dM = k[o + 2] + m + k[o + 3];
    const mTol = 8 * EPS * Math.abs(m);
    const h = EPS * Math.abs(t2);
    const band = k2 * (Math.abs(sn) + h) * h;
    if (dP < mTol + band + 1e-40 || dM < mTol + band + 1e-40) { codes[i] = 1; continue; }
    const x3 = k[o + 4] + m + k[o + 5];
    const x4 = k[o + 6] + m + k[o + 7];
    const y = sigma * Math.sqrt(dP) * Math.sqrt(dM);
    const re3 = dx * x3 - dy * y, im3 = dx * y + dy * x3, re4 = -(dx * x4 + dy * y), im4 = dx * y - dy * x4;
    let a3 = Math.atan2(im3, re3); if (a3 === -Math.PI) a3 = Math.PI;
    let a4 = Math.atan2(im4, re4); if (a4 === -Math.PI) a4 = Math.PI;
    const half = 0.5 / (dx * dx + dy * dy);
    const f1 = r2 * c + (re3 - re4) * half - r1;
    const f2 = r2 * sn + (im3 - im4) * half;
    th3[i] = a3; th4[i] = a4; res[i] = Math.sqrt(f1 * f1 + f2 * f2) * unscale; codes[i] = 0;
  }
  return th3;
}
const p = newClosedFormPoint();
function viaAt(theta2s: Float64Array, sigma: number) {
  const n = theta2s.length;
  const buf = new ArrayBuffer(n * 37);
  const th2 = new Float64Array(buf, 0, n), th3 = new Float64Array(buf, 8 * n, n), th4 = new Float64Array(buf, 16 * n, n), res = new Float64Array(buf, 24 * n, n);
  const codes = new Uint8Array(buf, 36 * n, n);
  for (let i = 0; i < n; i++) { const t2 = theta2s[i]; th2[i] = t2; const a = closedFormAt(plan, t2, sigma, p); if (a === 2) { codes[i] = 1; continue; } th3[i] = p.theta3; th4[i] = p.theta4; res[i] = p.residual * plan.unscale; codes[i] = 0; }
  return th3;
}
const runs: Record<string, () => unknown> = {
  lean: () => leanReportSweep(6, 2, 5, 5, g),
  cf: () => sweep(l, g, { branch: 'open' }),
  nr: () => sweep(l, g, { branch: 'open', method: 'newton' }),


};
const t: Record<string, number[]> = {};
for (let round = 0; round < 600; round++) for (const k in runs) { const t0 = performance.now(); runs[k](); (t[k] ??= []).push(performance.now() - t0); }
const med = (x: number[]) => { const s = x.slice(100).sort((a, b) => a - b); return s[s.length >> 1]; };
for (const k in runs) console.log(k, (med(t[k]) * 1000).toFixed(1), 'us', (med(t[k]) / med(t.lean)).toFixed(2));
