/**
 * A lean implementation of the report's Algorithm 2 (docs/hard-cases.md; the seed report's NR):
 * Newton-Raphson with Cramer's rule, absolute tolerance 1e-9 on |f1| and |f2|, at most 100 iterations,
 * singular below |det J| < 1e-9, each point started from the previous solution and the first from
 * (30, 90) deg. No validation, no unit handling, no status strings: the yardstick the sweep targets
 * are measured against.
 */

/** Angles (radians, unwrapped as the report leaves them) and iterations of one lean sweep. */
export interface LeanSweep {
  theta3: Float64Array;
  theta4: Float64Array;
  iterations: Int32Array;
  converged: Uint8Array;
}

/** The report's full cycle over theta2s (radians) for links r1..r4, open-branch first guess. */
export function leanReportSweep(r1: number, r2: number, r3: number, r4: number, theta2s: Float64Array): LeanSweep {
  const n = theta2s.length;
  const theta3 = new Float64Array(n);
  const theta4 = new Float64Array(n);
  const iterations = new Int32Array(n);
  const converged = new Uint8Array(n);
  let t3 = (30 * Math.PI) / 180;
  let t4 = (90 * Math.PI) / 180;
  for (let i = 0; i < n; i++) {
    const c2 = Math.cos(theta2s[i]);
    const s2 = Math.sin(theta2s[i]);
    let x3 = t3;
    let x4 = t4;
    let k = 0;
    let ok = 0;
    for (; k <= 100; k++) {
      const c3 = Math.cos(x3);
      const s3 = Math.sin(x3);
      const c4 = Math.cos(x4);
      const s4 = Math.sin(x4);
      const f1 = r2 * c2 + r3 * c3 - r4 * c4 - r1;
      const f2 = r2 * s2 + r3 * s3 - r4 * s4;
      if (Math.abs(f1) < 1e-9 && Math.abs(f2) < 1e-9) {
        ok = 1;
        break;
      }
      if (k === 100) break;
      const det = r3 * r4 * (s3 * c4 - c3 * s4);
      if (Math.abs(det) < 1e-9) break;
      x3 += (r4 * (f1 * c4 + f2 * s4)) / det;
      x4 += (r3 * (f1 * c3 + f2 * s3)) / det;
    }
    iterations[i] = k;
    converged[i] = ok;
    theta3[i] = x3;
    theta4[i] = x4;
    if (ok) {
      t3 = x3;
      t4 = x4;
    }
  }
  return { theta3, theta4, iterations, converged };
}
